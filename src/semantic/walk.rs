//! A walk through the program in execution order, tracking what is known.
//!
//! A branch whose condition is known is followed; with an unknown condition
//! both branches are walked and what differs afterwards is unknown. Loops are
//! walked once, with everything they write unknown from their start (the walk
//! never iterates, so it always ends). A forward jump that may or may not be
//! taken makes what it jumps over unknown at its target; a region that a
//! backward jump can repeat is a loop. CYCLE600 calls are evaluated where the
//! walk meets them; CYCLE800 and CYCLE600 set the active rotation.
//!
//! Not followed: computed jump targets (`GOTOF "L"<<I`), and what a user
//! subprogram does beyond possibly changing R parameters.

use std::borrow::Cow;
use std::sync::Arc;

use crate::diagnostic::Diagnostic;
use crate::hash::{HashMap, HashSet};
use crate::rotation::{self, Kind, Sequence};
use crate::semantic::calls::{call_kind, CallKind};
use crate::semantic::cycle600::{self, Bound, Evaluation};
use crate::semantic::env::{Active, Env, Supplied};
use crate::semantic::eval::{evaluate, key, variable_key};
use crate::semantic::frames::{self, FrameEffect, FrameSeen};
use crate::semantic::head_def::Heads;
use crate::semantic::model::Model;
use crate::semantic::structure::{control, sync_writes, Control, Structure};
use crate::semantic::value::{Binding, Origin, Unknown, Value};
use crate::span::Span;
use crate::syntax::lexer::is_blank;
use crate::syntax::tree::{starts_with_upper, upper};
use crate::syntax::tree::{Block, Call, Expr, Initializer, Statement, StatementKind, TypeKind};
use crate::syntax::visit::{each_variable, for_each_expression};

/// One CYCLE600 call met on the walk.
#[derive(Debug)]
pub struct CallSite {
    /// 0-based index of the line.
    pub line: usize,
    /// The line's content (without its terminator).
    pub content: Span,
    /// The call statement.
    pub statement: Span,
    pub bound: Option<Bound>,
    pub evaluation: Option<Evaluation>,
    /// The rotation active when the walk reached the call, as an additive
    /// call adds to it (unknown after a frame statement of the program's own).
    pub active: Active,
    /// A frame statement of the program's own in the programmable frame at
    /// the call: the frames and TRAORI forms would replace it.
    pub user_frame: Option<FrameSeen>,
    /// For a call whose angles or translations are known only at run time:
    /// everything else, for computing it on the control.
    pub runtime: Option<cycle600::RuntimeParameters>,
    /// A value the call reads is measured in the main run and no STOPRE
    /// stands between the measurement and the call.
    pub needs_stopre: bool,
    /// Refusals (errors) and warnings about this call.
    pub diagnostics: Vec<Diagnostic>,
}

/// A read of `_CYC600_n` whose value a CYCLE600 evaluated offline.
#[derive(Debug, Clone, PartialEq)]
pub struct ResultRead {
    pub span: Span,
    pub value: Value,
}

#[derive(Debug, Default)]
pub struct Analysis {
    pub calls: Vec<CallSite>,
    pub result_reads: Vec<ResultRead>,
}

/// Walks the program its model describes.
pub fn analyze(model: &Model, supplied: &Supplied, heads: Option<&Heads>) -> Analysis {
    let analysis = run_probed(model, supplied, heads, &[], None, Walked::AsFarAsAsked);
    analysis.expect("only a stop ends a walk early").0
}

/// How far a walk goes.
#[derive(Clone, Copy, PartialEq)]
enum Walked {
    /// To the program's end: the state it ends in is wanted.
    Whole,
    /// To the last line whose walk can change what was asked: the last
    /// CYCLE600, the last read of a `_CYC600_` result, the last probe. The
    /// walk follows no jump backwards (a loop's start forgets what the
    /// loop may write, from the structure, not from the walk), so the lines
    /// after those change nothing before them: a CAM program's thousands of
    /// blocks after its one CYCLE600 are not walked.
    AsFarAsAsked,
}

/// The walk, and the state it ends in: what the program leaves in its
/// variables when run offline.
///
/// Before the walk meets a CYCLE600 inside a loop it must assume the call may
/// swivel and may write its results; when the call turns out to do one of
/// them only (`_SW_REC` known), the walk is repeated knowing that. Rewriting
/// the call leaves code that does just that one thing, so a second rewrite
/// sees what the repeated walk sees: the repetition is what makes the
/// rewrite idempotent. Each repetition learns at least one more line, so there
/// are at most as many as there are CYCLE600 calls (in practice one or two).
pub fn run(model: &Model, supplied: &Supplied, heads: Option<&Heads>) -> (Analysis, Env) {
    let (analysis, env, _) = run_probed(model, supplied, heads, &[], None, Walked::Whole)
        .expect("only a stop ends a walk early");
    (analysis, env)
}

/// Asked now and then during an analysis whether to stop (its result is no
/// longer wanted): `true` stops it.
pub type Stop<'a> = &'a (dyn Fn() -> bool + Sync);

/// Lines walked between two questions to a [`Stop`].
const LINES_BETWEEN_STOPS: usize = 4096;

/// [`analyze`], stopped as soon as `stop` says so: `None` then.
pub fn analyze_until(
    model: &Model,
    supplied: &Supplied,
    heads: Option<&Heads>,
    stop: Stop,
) -> Option<Analysis> {
    Some(
        run_probed(
            model,
            supplied,
            heads,
            &[],
            Some(stop),
            Walked::AsFarAsAsked,
        )?
        .0,
    )
}

/// Where a value is looked at on the walk: the variable named at `name` (a
/// span of line `row`), as the use reads it, or as the statement holding
/// it leaves it (`after`: an assignment's target, a DEF).
#[derive(Clone, Debug)]
pub struct Probe {
    pub row: usize,
    pub name: Span,
    pub after: bool,
}

/// What the walk finds in a variable at a [`Probe`].
#[derive(Clone, Debug, PartialEq)]
pub enum Seen {
    /// The walk does not reach the line (a branch it knows is not taken,
    /// or nesting too deep to follow).
    NotReached,
    /// Its value there, or why it has none offline, and where it comes
    /// from: what `eval` shows for a CYCLE600 argument.
    Value {
        key: String,
        value: Result<Value, Unknown>,
        origin: Option<Origin>,
    },
    /// The walk reaches the line more than once and finds different values.
    Differs,
}

/// What the variable at each of `probes` holds there, as the walk that
/// evaluates the CYCLE600 calls finds it: one walk answers them all (an
/// editor asks for every use it hovers). `None` if `stop` stopped it.
pub fn values_at(
    model: &Model,
    supplied: &Supplied,
    heads: Option<&Heads>,
    probes: &[Probe],
    stop: Option<Stop>,
) -> Option<Vec<Seen>> {
    Some(run_probed(model, supplied, heads, probes, stop, Walked::AsFarAsAsked)?.2)
}

fn run_probed(
    model: &Model,
    supplied: &Supplied,
    heads: Option<&Heads>,
    probes: &[Probe],
    stop: Option<Stop>,
    walked: Walked,
) -> Option<(Analysis, Env, Vec<Seen>)> {
    let end = match walked {
        Walked::Whole => model.lines.len(),
        Walked::AsFarAsAsked => asked_end(model, probes),
    };
    let mut modes = HashMap::default();
    loop {
        let (walker, env) = walk_once(model, supplied, heads, &modes, probes, stop, end);
        if walker.stopped {
            return None;
        }
        let assumed = walker.assumed();
        let learned: Vec<(usize, Mode)> = walker
            .analysis
            .calls
            .iter()
            .chain(&walker.replayed)
            .filter(|c| assumed.contains(&c.line))
            .filter_map(|c| Some((c.line, c.mode()?)))
            .collect();
        if learned.is_empty() {
            let mut analysis = walker.analysis;
            analysis.calls.sort_by_key(|c| (c.line, c.statement.start));
            let seen = walker.looks.tallies.into_iter().map(Tally::seen);
            return Some((analysis, env, seen.collect()));
        }
        modes.extend(learned);
    }
}

/// One walk through the program, knowing what the calls on `modes`' lines do.
fn walk_once<'a>(
    model: &'a Model<'a>,
    supplied: &'a Supplied,
    heads: Option<&'a Heads>,
    modes: &'a HashMap<usize, Mode>,
    probes: &'a [Probe],
    stop: Option<Stop<'a>>,
    end: usize,
) -> (Walker<'a>, Env) {
    let structure = model.structure();
    let mut calls = [Vec::new(), Vec::new(), Vec::new()];
    for &line in &structure.cycle600_lines {
        let kind = match modes.get(&line) {
            Some(Mode::Swivel) => 0,
            Some(Mode::Recalculate) => 1,
            None => 2,
        };
        calls[kind].push(line);
    }
    let [swivel_calls, recalculating_calls, unknown_calls] = calls;
    let mut walker = Walker {
        model,
        structure,
        source: model.source,
        supplied,
        heads,
        pending: HashMap::default(),
        analysis: Analysis::default(),
        depth: 0,
        swivel_calls,
        recalculating_calls,
        unknown_calls,
        forgotten: Vec::new(),
        replayed: Vec::new(),
        too_deep: HashSet::default(),
        looks: Looks::new(probes),
        stop,
        lines_walked: 0,
        stopped: false,
        asked_end: end,
    };
    let mut env = Env::of_program(Arc::clone(&structure.writers));
    walker.walk(0, model.lines.len(), &mut env);
    (walker, env)
}

/// The line after the last that a walk [`Walked::AsFarAsAsked`] must reach.
fn asked_end(model: &Model, probes: &[Probe]) -> usize {
    let source = model.source;
    let last_result = memchr::memrchr_iter(b'_', source)
        .find(|&at| {
            source[at..]
                .get(..8)
                .is_some_and(|name| name.eq_ignore_ascii_case(b"_CYC600_"))
        })
        .map(|at| row_of(model, at));
    let last_call = model.structure().cycle600_lines.iter().max().copied();
    let last_probe = probes.iter().map(|probe| probe.row).max();
    let last = [last_result, last_call, last_probe]
        .into_iter()
        .flatten()
        .max();
    last.map_or(0, |row| (row + 1).min(model.lines.len()))
}

/// The line holding byte `offset`.
fn row_of(model: &Model, offset: usize) -> usize {
    let lines = &model.lines;
    // The first line starting after `offset`, less one.
    let (mut low, mut high) = (0, lines.len());
    while low < high {
        let middle = (low + high) / 2;
        if lines.raw(middle).content.start <= offset {
            low = middle + 1;
        } else {
            high = middle;
        }
    }
    low.saturating_sub(1)
}

/// The uses a walk is asked about, by line, and what it found at each.
struct Looks<'a> {
    probes: &'a [Probe],
    /// Line -> the indices of its probes.
    on_line: HashMap<usize, Vec<usize>>,
    tallies: Vec<Tally>,
}

impl<'a> Looks<'a> {
    fn new(probes: &'a [Probe]) -> Self {
        let mut on_line: HashMap<usize, Vec<usize>> = HashMap::default();
        for (index, probe) in probes.iter().enumerate() {
            on_line.entry(probe.row).or_default().push(index);
        }
        Self {
            probes,
            on_line,
            tallies: vec![Tally::default(); probes.len()],
        }
    }
}

/// What the arrivals of a walk at one probe found: the first arrival's
/// value, the latest's (a closer look at its statement replaces it), and
/// whether any two differ.
#[derive(Clone, Default)]
struct Tally {
    first: Option<Seen>,
    latest: Option<Seen>,
    differs: bool,
}

impl Tally {
    /// Compares the latest arrival's value with the first, before another.
    fn settle(&mut self) {
        let Some(latest) = self.latest.take() else {
            return;
        };
        match &self.first {
            None => self.first = Some(latest),
            Some(first) => self.differs |= *first != latest,
        }
    }

    fn seen(mut self) -> Seen {
        self.settle();
        match self.first {
            None => Seen::NotReached,
            Some(_) if self.differs => Seen::Differs,
            Some(first) => first,
        }
    }
}

/// The key of the variable `statement` names at `name`, with its indices
/// evaluated in `scope`; `None` if it names none there (or an array whole).
fn probe_key(
    source: &[u8],
    statement: &Statement,
    name: Span,
    scope: &dyn crate::semantic::eval::Lookup,
) -> Option<Result<String, Unknown>> {
    let whole = |at: Span| (at == name).then(|| Ok(key(&upper(at.of(source)), &[])));
    match &statement.kind {
        StatementKind::Assign(assign) if assign.target.name.span == name => {
            return Some(variable_key(source, &assign.target, scope));
        }
        StatementKind::For { variable, .. } if variable.span == name => return whole(name),
        StatementKind::Def(def) => {
            let declared = def.variables.iter().find(|d| d.name.span == name);
            if let Some(declarator) = declared {
                return declarator
                    .dimensions
                    .is_empty()
                    .then(|| whole(name))
                    .flatten();
            }
        }
        _ => {}
    }
    crate::syntax::visit::reads(statement)
        .into_iter()
        .find(|variable| variable.name.span == name)
        .map(|variable| variable_key(source, variable, scope))
}

/// What a CYCLE600 call does, by its `_SW_REC`.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Mode {
    /// `_SW_REC=1`: results to `_CYC600_1..6`, nothing moves.
    Recalculate,
    /// `_SW_REC=0`: a swivel.
    Swivel,
}

impl CallSite {
    /// What the call does, when its `_SW_REC` is known.
    fn mode(&self) -> Option<Mode> {
        match self.bound.as_ref()?.arguments[2].value {
            Ok(Value::Number(1.0)) => Some(Mode::Recalculate),
            Ok(Value::Number(0.0)) => Some(Mode::Swivel),
            _ => None,
        }
    }
}

struct Walker<'a> {
    model: &'a Model<'a>,
    source: &'a [u8],
    supplied: &'a Supplied,
    heads: Option<&'a Heads>,
    structure: &'a Structure,
    /// Line -> what jumps that may skip to it have jumped over.
    pending: HashMap<usize, Vec<(usize, usize, Origin)>>,
    analysis: Analysis,
    /// How many blocks the walk is inside; bounded, so that no program can
    /// exhaust the stack.
    depth: usize,
    /// Lines of the CYCLE600 calls an earlier walk found to swivel, to
    /// recalculate only, and the others (in order): what a region with
    /// them in it may change.
    swivel_calls: Vec<usize>,
    recalculating_calls: Vec<usize>,
    unknown_calls: Vec<usize>,
    /// The regions forgotten (`start..end`), in the order they were.
    forgotten: Vec<(usize, usize)>,
    /// The calls kept in `; sinuprep:` lines, as the walk met them.
    replayed: Vec<CallSite>,
    /// Lines of calls reported as nested too deep.
    too_deep: HashSet<usize>,
    /// The uses whose values are asked for, and what the walk found there.
    looks: Looks<'a>,
    /// Asked every [`LINES_BETWEEN_STOPS`] lines whether to stop; once it
    /// says so, every region ends where it is.
    stop: Option<Stop<'a>>,
    lines_walked: usize,
    stopped: bool,
    /// The top-level walk ends here ([`Walked`]).
    asked_end: usize,
}

/// Blocks nested deeper than this are not walked into: what they write
/// becomes unknown, and CYCLE600 calls inside them stay as they are, each
/// with an error (C618).
pub const MAX_NESTING: usize = 512;

impl<'a> Walker<'a> {
    /// The CYCLE600 lines a forgotten region held without knowing what the
    /// call there does: the forget assumed both.
    fn assumed(&self) -> HashSet<usize> {
        let mut regions = self.forgotten.clone();
        regions.sort_unstable();
        let mut assumed = HashSet::default();
        let mut calls = self.unknown_calls.iter().copied().peekable();
        let mut covered_to = 0;
        for (start, end) in regions {
            let start = start.max(covered_to);
            while calls.next_if(|&line| line < start).is_some() {}
            while let Some(line) = calls.next_if(|&line| line < end) {
                assumed.insert(line);
            }
            covered_to = covered_to.max(end);
        }
        assumed
    }

    fn block(&self, line: usize) -> Option<Cow<'a, Block>> {
        self.model.lines.block(line)
    }

    fn walk(&mut self, start: usize, end: usize, env: &mut Env) {
        if self.depth >= MAX_NESTING {
            let structure = self.structure;
            for &line in Structure::within(&structure.cycle600_lines, start, end) {
                self.too_deep(line, env);
            }
            self.forget(
                start,
                end,
                env,
                &Origin::ControlFlow {
                    line: start + 1,
                    what: "block nested too deep to follow",
                },
            );
            return;
        }
        self.depth += 1;
        self.walk_region(start, end, env);
        self.depth -= 1;
    }

    fn walk_region(&mut self, start: usize, end: usize, env: &mut Env) {
        let mut pc = start;
        while pc < end {
            // Past what was asked the program's own lines are left; a block
            // begun before is walked to its end, and a jump lands as in the
            // whole walk.
            if self.depth == 1 && pc >= self.asked_end {
                return;
            }
            if self.stop.is_some() && self.stops() {
                return;
            }
            self.enter(pc, env);
            let marked = self.structure.marked_call(pc);
            if let Some(statement) = marked {
                self.look(pc, None, env, true, |_| true);
                self.replay(pc, statement, env);
            }
            // Motion blocks change nothing the walk tracks: no need to parse
            // them (and they name no variable to look at).
            if self.model.lines.is_plain(pc) {
                pc += 1;
                continue;
            }
            let Some(block) = self.block(pc) else {
                pc += 1;
                continue;
            };
            if marked.is_none() {
                self.look(pc, Some(&block), env, true, |_| true);
            }
            match control(&block) {
                Control::IfBlock(condition) => {
                    if let Some(pair) = self.model.blocks.opened_on(pc) {
                        let (else_line, end_line) = (pair.else_row, pair.end);
                        self.visit_expressions(&block, env);
                        let then_end = else_line.unwrap_or(end_line);
                        match self.truth(condition, env, pc) {
                            Some(true) => self.walk(pc + 1, then_end, env),
                            Some(false) => {
                                if let Some(else_line) = else_line {
                                    self.walk(else_line + 1, end_line, env);
                                }
                            }
                            None => {
                                let fork = env.fork();
                                self.walk(pc + 1, then_end, env);
                                let then = env.rewind(fork);
                                if let Some(else_line) = else_line {
                                    self.walk(else_line + 1, end_line, env);
                                }
                                env.join(then, pc + 1);
                            }
                        }
                        pc = end_line + 1;
                        continue;
                    }
                }
                Control::Loop {
                    condition,
                    runs_once,
                } => {
                    if let Some(end_line) = self.model.blocks.opened_on(pc).map(|b| b.end) {
                        if condition.is_some_and(|c| self.truth(c, env, pc) == Some(false)) {
                            pc = end_line + 1;
                            continue;
                        }
                        let origin = Origin::ControlFlow {
                            line: pc + 1,
                            what: "loop",
                        };
                        self.forget(pc, end_line + 1, env, &origin);
                        self.visit(pc, &block, env);
                        self.walk(pc + 1, end_line, env);
                        if !runs_once {
                            self.forget(pc, end_line + 1, env, &origin);
                        }
                        pc = end_line + 1;
                        continue;
                    }
                }
                // Reached at the end of a THEN branch walked in sequence.
                Control::Else => {
                    if let Some(end_line) = self.model.blocks.else_end(pc) {
                        pc = end_line + 1;
                        continue;
                    }
                }
                Control::None => {}
            }
            self.visit(pc, &block, env);
            pc = match self.jump(pc, &block, env, end) {
                Some(target) => target,
                None => pc + 1,
            };
        }
    }

    /// Whether the walk is to stop, asking its [`Stop`] every few thousand
    /// lines.
    fn stops(&mut self) -> bool {
        if !self.stopped && self.lines_walked.is_multiple_of(LINES_BETWEEN_STOPS) {
            self.stopped = self.stop.is_some_and(|stop| stop());
        }
        self.lines_walked += 1;
        self.stopped
    }

    /// Forget what loops and skipped regions write, on arriving at `line`.
    fn enter(&mut self, line: usize, env: &mut Env) {
        // Most programs have neither: skip hashing every line number.
        if self.structure.loop_starts.is_empty() && self.pending.is_empty() {
            return;
        }
        if let Some(&last) = self.structure.loop_starts.get(&line) {
            self.forget(
                line,
                last + 1,
                env,
                &Origin::ControlFlow {
                    line: last + 1,
                    what: "backward jump",
                },
            );
        }
        if let Some(skipped) = self.pending.remove(&line) {
            for (start, end, origin) in &skipped {
                self.forget(*start, *end, env, origin);
            }
        }
    }

    fn truth(&self, condition: &Expr, env: &Env, line: usize) -> Option<bool> {
        match evaluate(self.source, condition, &env.scope(self.supplied, line + 1)) {
            Ok(Value::Number(n)) => Some(n != 0.0),
            _ => None,
        }
    }

    /// The next line when the block certainly jumps forward within `end`.
    fn jump(&mut self, pc: usize, block: &Block, env: &Env, end: usize) -> Option<usize> {
        let mut condition: Option<Option<bool>> = None;
        let mut targets: Vec<(Option<usize>, bool)> = Vec::new();
        for statement in &block.statements {
            match &statement.kind {
                StatementKind::If { condition: c } => condition = Some(self.truth(c, env, pc)),
                StatementKind::Goto(goto) => {
                    let certain = match condition.take() {
                        Some(Some(false)) => continue,
                        Some(None) => false,
                        Some(Some(true)) | None => true,
                    };
                    let target = goto
                        .target
                        .as_ref()
                        .and_then(|t| self.model.landing(t, goto.kind, pc));
                    targets.push((target, certain));
                }
                StatementKind::Case(case) => {
                    let selector = evaluate(
                        self.source,
                        &case.selector,
                        &env.scope(self.supplied, pc + 1),
                    )
                    .ok();
                    let chosen = selector.and_then(|s| {
                        case.branches
                            .iter()
                            .find(|(v, _)| {
                                evaluate(self.source, v, &env.scope(self.supplied, pc + 1)).ok()
                                    == Some(s.clone())
                            })
                            .map(|(_, g)| g)
                            .or(case.default.as_ref())
                    });
                    match chosen {
                        Some(goto) => {
                            let target = goto
                                .target
                                .as_ref()
                                .and_then(|t| self.model.landing(t, goto.kind, pc));
                            targets.push((target, true));
                        }
                        None => {
                            for goto in case.branches.iter().map(|(_, g)| g).chain(&case.default) {
                                let target = goto
                                    .target
                                    .as_ref()
                                    .and_then(|t| self.model.landing(t, goto.kind, pc));
                                targets.push((target, false));
                            }
                        }
                    }
                }
                _ => {}
            }
        }
        for (target, certain) in targets {
            let Some(target) = target else { continue };
            if target <= pc {
                continue; // backward: a loop, handled by `loop_starts`
            }
            if certain && target < end {
                return Some(target);
            }
            // Taken or not, or leaving the region walked: what lies between
            // is unknown at the target.
            self.pending.entry(target).or_default().push((
                pc + 1,
                target,
                Origin::ControlFlow {
                    line: pc + 1,
                    what: "jump",
                },
            ));
        }
        None
    }

    /// Makes unknown what lines `start..end` may write (the structure
    /// pass's indices): their variables (lazily: see `env::Mark`), the
    /// active rotation if anything there may swivel, `_CYC600_1..6` if a
    /// CYCLE600 there may recalculate, and the frames if a frame statement
    /// is there. Loops nest and each forgets its region twice: this costs
    /// a few binary searches, not the region's length.
    fn forget(&mut self, start: usize, end: usize, env: &mut Env, origin: &Origin) {
        let structure = self.structure;
        let any = |lines: &[usize]| !Structure::within(lines, start, end).is_empty();
        let unknown = any(&self.unknown_calls);
        let swivels = unknown || any(&structure.rotation_lines) || any(&self.swivel_calls);
        let recalculates = unknown || any(&self.recalculating_calls);
        let frames = any(&structure.frame_lines);
        self.forgotten.push((start, end));
        env.forget_region(start, end, origin.clone());
        if recalculates {
            for n in 1..=6 {
                env.forget(&format!("_CYC600_{n}"), origin.clone());
            }
        }
        if swivels {
            env.active = Active::Unknown {
                why: origin.to_string(),
            };
        }
        if frames {
            let seen = FrameSeen::Region(origin.to_string());
            env.user_frame.get_or_insert_with(|| seen.clone());
            env.frame_since_swivel.get_or_insert(seen);
        }
    }

    fn visit(&mut self, pc: usize, block: &Block, env: &mut Env) {
        let line = pc + 1;
        if !self.structure.is_emitted(pc) {
            if let Some(effect) = frames::frame_effect(self.source, block) {
                let seen = FrameSeen::Statement {
                    text: frames::statements_text(self.source, block),
                    line,
                };
                match effect {
                    FrameEffect::ClearsProgrammable => env.user_frame = None,
                    FrameEffect::SetsProgrammable => env.user_frame = Some(seen.clone()),
                    FrameEffect::SetsOther => {}
                }
                env.frame_since_swivel = Some(seen);
            }
        }
        for statement in &block.statements {
            let held = |probe: &Probe| {
                statement.span.start <= probe.name.start && probe.name.end <= statement.span.end
            };
            self.look(pc, Some(block), env, false, |p| held(p) && !p.after);
            self.record_result_reads(statement, env);
            self.step(pc, statement, env);
            self.look(pc, Some(block), env, false, |p| held(p) && p.after);
        }
    }

    /// What the probed variables of line `pc` (its `block`, parsed here if
    /// not given) that are `wanted` hold here: a new arrival at their line
    /// (`arriving`), or a closer look at the statement that holds them.
    fn look(
        &mut self,
        pc: usize,
        block: Option<&Block>,
        env: &Env,
        arriving: bool,
        wanted: impl Fn(&Probe) -> bool,
    ) {
        let Looks {
            probes,
            on_line,
            tallies,
        } = &mut self.looks;
        let Some(on_line) = on_line.get(&pc) else {
            return;
        };
        if !on_line.iter().any(|&index| wanted(&probes[index])) {
            return;
        }
        let parsed;
        let block = match block {
            Some(block) => block,
            None => match self.model.lines.block(pc) {
                Some(block) => {
                    parsed = block;
                    &*parsed
                }
                None => return,
            },
        };
        let scope = env.scope(self.supplied, pc + 1);
        for &index in on_line {
            let probe = &probes[index];
            if !wanted(probe) {
                continue;
            }
            let name = probe.name;
            let key = block
                .statements
                .iter()
                .filter(|s| s.span.start <= name.start && name.end <= s.span.end)
                .find_map(|statement| probe_key(self.source, statement, name, &scope));
            let seen = match key {
                Some(Ok(key)) => Seen::Value {
                    value: crate::semantic::eval::Lookup::variable(&scope, &key),
                    origin: scope.origin(&key),
                    key,
                },
                // An index unknown here: which element is read is unknown.
                Some(Err(why)) => Seen::Value {
                    key: upper(name.of(self.source)),
                    value: Err(why),
                    origin: None,
                },
                None => continue,
            };
            let tally = &mut tallies[index];
            if arriving {
                tally.settle();
            }
            tally.latest = Some(seen);
        }
    }

    /// One statement of a block, in the walk's order.
    fn step(&mut self, pc: usize, statement: &Statement, env: &mut Env) {
        let line = pc + 1;
        match &statement.kind {
            StatementKind::Def(def) => {
                for declarator in &def.variables {
                    let name = upper(declarator.name.text(self.source));
                    let default = if def.data_type.kind == TypeKind::String {
                        Value::Text(String::new())
                    } else {
                        Value::Number(0.0)
                    };
                    if !declarator.dimensions.is_empty() {
                        match declarator.init {
                            None => env.declare_array(name, default),
                            Some(_) => env.forget(
                                &name,
                                Origin::Unevaluable {
                                    line,
                                    why: "array initialisers are not evaluated offline".into(),
                                },
                            ),
                        }
                        continue;
                    }
                    let binding = match &declarator.init {
                        None => Binding::Known {
                            value: default,
                            origin: Origin::Assigned { line },
                        },
                        Some(Initializer::Expr(expr)) => self.binding(&name, expr, env, line),
                        Some(Initializer::List(_)) => Binding::Unknown {
                            origin: Origin::Unevaluable {
                                line,
                                why: "a list initialiser".into(),
                            },
                        },
                    };
                    env.set(name, binding);
                }
            }
            StatementKind::Assign(assign) => {
                let scope = env.scope(self.supplied, line);
                match variable_key(self.source, &assign.target, &scope) {
                    Ok(key) => {
                        let binding = self.binding(&key, &assign.value, env, line);
                        env.set(key, binding);
                    }
                    Err(_) => {
                        let name = upper(assign.target.name.text(self.source));
                        env.forget(
                            &name,
                            Origin::Unevaluable {
                                line,
                                why: "its index is unknown offline".into(),
                            },
                        );
                    }
                }
            }
            StatementKind::For { variable, .. } => {
                env.forget(
                    &key(&upper(variable.text(self.source)), &[]),
                    Origin::ControlFlow {
                        line,
                        what: "FOR loop",
                    },
                );
            }
            StatementKind::SyncAction(sync) => {
                for name in sync_writes(self.source, sync) {
                    env.forget(
                        &name,
                        Origin::ControlFlow {
                            line,
                            what: "synchronized action",
                        },
                    );
                }
            }
            StatementKind::Call(call) => self.call(
                pc,
                statement,
                &upper(call.name.text(self.source)),
                Some(call),
                env,
            ),
            StatementKind::Command(name) => {
                self.call(pc, statement, &upper(name.text(self.source)), None, env)
            }
            _ => {}
        }
    }

    /// Only the expressions of a control block (its reads).
    fn visit_expressions(&mut self, block: &Block, env: &Env) {
        for statement in &block.statements {
            self.record_result_reads(statement, env);
        }
    }

    /// The binding an assignment gives `key`: a measured value the user
    /// supplied takes the place of the measurement.
    fn binding(&self, key: &str, value: &Expr, env: &Env, line: usize) -> Binding {
        match evaluate(self.source, value, &env.scope(self.supplied, line)) {
            Ok(value) => Binding::Known {
                value,
                origin: Origin::Assigned { line },
            },
            Err(Unknown::Variables(vars)) => {
                let measured = vars.iter().find_map(|(_, origin)| match origin {
                    Origin::Measured { .. } => Some(origin.clone()),
                    _ => None,
                });
                match (measured, self.supplied.get(key)) {
                    (Some(_), Some((value, by))) => Binding::Known {
                        value: value.clone(),
                        origin: Origin::Supplied { by: by.to_string() },
                    },
                    (Some(origin), None) => Binding::Unknown { origin },
                    (None, _) => Binding::Unknown {
                        origin: vars[0].1.clone(),
                    },
                }
            }
            Err(Unknown::Invalid(why)) => Binding::Unknown {
                origin: Origin::Unevaluable { line, why },
            },
        }
    }

    fn call(
        &mut self,
        pc: usize,
        statement: &Statement,
        name: &str,
        call: Option<&Call>,
        env: &mut Env,
    ) {
        let line = pc + 1;
        match (call_kind(name), call) {
            (CallKind::Cycle600, Some(call)) => self.cycle600(pc, statement, call, env),
            // sinuprep's own CYCLE800 for a CYCLE600 stands for that call,
            // which the walk took from the `; sinuprep:` line above it.
            (CallKind::Cycle800, Some(_)) if self.structure.is_emitted(pc) => {}
            (CallKind::Cycle800, Some(call)) => {
                env.active = self.cycle800(call, env, line);
                env.frame_since_swivel = None;
            }
            (CallKind::Measuring, _) => env.measure_arrays(line, name),
            (CallKind::Subprogram, _) => env.clobber_r_parameters(Origin::ControlFlow {
                line,
                what: "subprogram call (it may change R parameters)",
            }),
            _ => {}
        }
    }

    fn cycle600(&mut self, pc: usize, statement: &Statement, call: &Call, env: &mut Env) {
        let site = self.evaluate_call(pc, statement, call, env);
        self.analysis.calls.push(site);
    }

    /// A call in blocks nested deeper than [`MAX_NESTING`]: reported, once,
    /// and left as it is.
    fn too_deep(&mut self, pc: usize, env: &Env) {
        if !self.too_deep.insert(pc) {
            return;
        }
        let Some(block) = self.block(pc) else { return };
        for statement in &block.statements {
            let StatementKind::Call(call) = &statement.kind else {
                continue;
            };
            if call_kind(&upper(call.name.text(self.source))) != CallKind::Cycle600 {
                continue;
            }
            let mut site = self.site(pc, statement, env.active.clone(), env);
            site.diagnostics
                .push(cycle600::nested_too_deep(statement.span, MAX_NESTING));
            self.analysis.calls.push(site);
        }
    }

    /// The CYCLE600 kept in a `; sinuprep:` line stands for the blocks
    /// sinuprep emitted below it: the walk takes it as the call, and the
    /// emitted blocks as its own, not the program's.
    fn replay(&mut self, pc: usize, statement: &Statement, env: &mut Env) {
        if let StatementKind::Call(call) = &statement.kind {
            let site = self.evaluate_call(pc, statement, call, env);
            self.replayed.push(site);
        }
    }

    /// The call at line `pc`, before it is bound.
    fn site(&self, pc: usize, statement: &Statement, active: Active, env: &Env) -> CallSite {
        CallSite {
            line: pc,
            content: self.model.lines.raw(pc).content,
            statement: statement.span,
            bound: None,
            evaluation: None,
            active,
            user_frame: env.user_frame.clone(),
            runtime: None,
            needs_stopre: false,
            diagnostics: Vec::new(),
        }
    }

    /// Binds and evaluates the call, and steps `env` past it.
    fn evaluate_call(
        &mut self,
        pc: usize,
        statement: &Statement,
        call: &Call,
        env: &mut Env,
    ) -> CallSite {
        let line = pc + 1;
        let active = match &env.frame_since_swivel {
            Some(seen) => Active::Unknown {
                why: format!("{seen} stands between the last swivel and this call"),
            },
            None => env.active.clone(),
        };
        let mut site = self.site(pc, statement, active, env);
        let rest = Span::new(statement.span.end, site.content.end).of(self.source);
        let blank = rest.iter().take_while(|&&b| is_blank(b)).count();
        if rest.get(blank).is_some_and(|&b| b != b';') {
            let start = statement.span.end + blank;
            let end = statement.span.end + rest.trim_ascii_end().len();
            site.diagnostics
                .push(cycle600::shares_block(Span::new(start, end)));
        }
        let scope = env.scope(self.supplied, line);
        match cycle600::bind(self.source, call, &scope) {
            Err(problem) => site.diagnostics.push(problem),
            Ok(bound) => {
                site.needs_stopre = self.needs_stopre(&bound, pc);
                let (parameters, problems) = cycle600::check(&bound, self.heads);
                if parameters.is_none() {
                    site.runtime = cycle600::runtime_parameters(&bound, self.heads);
                }
                site.diagnostics.extend(problems);
                site.bound = Some(bound);
                if let Some(parameters) = parameters {
                    match cycle600::evaluate_parameters(parameters, &site.active, statement.span) {
                        Ok((evaluation, warnings)) => {
                            site.diagnostics.extend(warnings);
                            site.evaluation = Some(evaluation);
                        }
                        Err(problem) => site.diagnostics.push(problem),
                    }
                }
            }
        }
        self.results(&site, env);
        if site.mode() != Some(Mode::Recalculate) {
            env.active = self.rotation_after(&site);
            env.frame_since_swivel = None;
        }
        site
    }

    /// What the call leaves in `_CYC600_1..6`. The spec documents them as the
    /// results of a recalculation (`_SW_REC=1`); a swivel is rewritten into a
    /// native swivel that writes none, so it is taken to leave them as they
    /// were (a second rewrite must see what the first saw).
    fn results(&self, site: &CallSite, env: &mut Env) {
        let line = site.line + 1;
        if site.mode() == Some(Mode::Swivel) {
            return;
        }
        let known = |env: &mut Env, n: usize, value: Value| {
            let origin = Origin::Cycle600 { line };
            env.set(format!("_CYC600_{n}"), Binding::Known { value, origin });
        };
        let unknown = |env: &mut Env, n: usize, why: &str| {
            let origin = Origin::Unevaluable {
                line,
                why: why.into(),
            };
            env.forget(&format!("_CYC600_{n}"), origin);
        };
        match (&site.evaluation, &site.runtime) {
            (Some(evaluation), _) if evaluation.parameters.recalculate_only => {
                for (n, value) in evaluation.gud().into_iter().enumerate() {
                    known(env, n + 1, value);
                }
            }
            // Computed on the control: the angles only, the rest is known.
            (None, Some(runtime)) if runtime.recalculate_only => {
                known(env, 1, Value::Text(runtime.head.clone()));
                for n in 2..=4 {
                    unknown(env, n, "the CYCLE600 there computes it at run time");
                }
                known(env, 5, Value::Number(1.0));
                known(env, 6, Value::Number(runtime.output.code() as f64));
            }
            _ => {
                for n in 1..=6 {
                    unknown(env, n, "the CYCLE600 there is not evaluated offline");
                }
            }
        }
    }

    /// The rotation active after a call that may swivel (one that only
    /// recalculates never does, even when its results are unknown).
    fn rotation_after(&self, site: &CallSite) -> Active {
        let line = site.line + 1;
        match &site.evaluation {
            Some(evaluation) if !evaluation.additive_on_control => Active::Known {
                rotation: evaluation.target,
                line,
            },
            Some(_) => Active::Unknown {
                why: format!("the CYCLE600 on line {line} adds to a rotation unknown offline"),
            },
            // One whose translations alone are measured swivels to a rotation
            // known offline: a rotation never depends on translations.
            None => site
                .runtime
                .as_ref()
                .and_then(|runtime| runtime.rotation_parameters())
                .and_then(|p| cycle600::evaluate_parameters(p, &site.active, site.statement).ok())
                .filter(|(evaluation, _)| !evaluation.additive_on_control)
                .map_or_else(
                    || Active::Unknown {
                        why: format!("the CYCLE600 on line {line} is not known offline"),
                    },
                    |(evaluation, _)| Active::Known {
                        rotation: evaluation.target,
                        line,
                    },
                ),
        }
    }

    /// Whether a measured value the call reads lacks a STOPRE since its measurement.
    fn needs_stopre(&self, bound: &Bound, pc: usize) -> bool {
        bound
            .arguments
            .iter()
            .any(|argument| match &argument.value {
                Err(Unknown::Variables(vars)) => vars.iter().any(|(_, origin)| match origin {
                    // `line` is 1-based: the measurement is at index line - 1.
                    Origin::Measured { line, .. } => {
                        !self.model.stopre.iter().any(|&s| s + 1 > *line && s < pc)
                    }
                    _ => false,
                }),
                _ => false,
            })
    }

    /// The rotation after a CYCLE800 (axis by axis, intrinsic; `_ST` ones
    /// digit 1 adds to the active swivel).
    fn cycle800(&self, call: &Call, env: &Env, line: usize) -> Active {
        let items = &call.arguments.items;
        if items.is_empty() {
            return Active::None;
        }
        let scope = env.scope(self.supplied, line);
        let number = |i: usize| -> Option<f64> {
            match items.get(i)?.value.as_ref() {
                None => Some(0.0),
                Some(expr) => evaluate(self.source, expr, &scope).ok()?.number(),
            }
        };
        let unknown = || Active::Unknown {
            why: format!("the CYCLE800 on line {line} is not known offline"),
        };
        let (Some(st), Some(mode), Some(a), Some(b), Some(c)) =
            (number(2), number(3), number(7), number(8), number(9))
        else {
            return unknown();
        };
        let Ok(sequence) = Sequence::from_code(mode as i64, Kind::Intrinsic) else {
            return unknown();
        };
        let rotation = rotation::matrix(sequence, [a, b, c]);
        if (st as i64) % 10 == 1 {
            match env.active.rotation() {
                Some(active) => Active::Known {
                    rotation: active * rotation,
                    line,
                },
                None => unknown(),
            }
        } else {
            Active::Known { rotation, line }
        }
    }

    /// Reads of `_CYC600_n` holding a value from an evaluated CYCLE600.
    fn record_result_reads(&mut self, statement: &Statement, env: &Env) {
        if let StatementKind::Call(call) = &statement.kind {
            if call_kind(&upper(call.name.text(self.source))) == CallKind::Cycle600 {
                return;
            }
        }
        // Kept only where a result is read: most statements read none.
        let (source, mut reads) = (self.source, Vec::new());
        for_each_expression(&statement.kind, &mut |expr| {
            each_variable(expr, &mut |variable| {
                let text = variable.name.text(source);
                if starts_with_upper(text, "_CYC600_") && variable.indices.is_empty() {
                    reads.push(variable);
                }
            })
        });
        for variable in reads {
            let name = upper(variable.name.text(self.source));
            if let Some(Binding::Known {
                value,
                origin: Origin::Cycle600 { .. },
            }) = env.binding(&name)
            {
                self.analysis.result_reads.push(ResultRead {
                    span: variable.span,
                    value: value.clone(),
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};

    const CALL: &str =
        "CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, R1000, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\n";

    /// `depth` FOR loops around `lines` blocks, each reading and writing
    /// one of 100 R parameters, and a CYCLE600 reading one of them.
    fn nested_loops(depth: usize, lines: usize) -> String {
        let mut program = String::new();
        for i in 0..depth {
            program.push_str(&format!("FOR R{i}=0 TO 2\n"));
        }
        for j in 0..lines {
            program.push_str(&format!("R{n}=R{n}+1\n", n = 1000 + j % 100));
        }
        program.push_str(CALL);
        for _ in 0..depth {
            program.push_str("ENDFOR\n");
        }
        program.push_str("M30\n");
        program
    }

    /// A walk told to stop stops at once, inside nested blocks too: the
    /// question answered `stop` is the last one asked.
    #[test]
    fn a_walk_stops_when_told() {
        let program = nested_loops(3, 20_000);
        let model = Model::of(program.as_bytes());
        // Counted atomically: a stop may be asked from any thread (`Stop`).
        let asked = AtomicUsize::new(0);
        let never = || {
            asked.fetch_add(1, Relaxed);
            false
        };
        let walked = analyze_until(&model, &Supplied::default(), None, &never);
        assert_eq!(walked.map(|a| a.calls.len()), Some(1));
        // 20,007 lines, every one walked: a question every 4,096 of them,
        // in each walk (twice: the call's `_SW_REC` is learned in the first).
        let questions = asked.load(Relaxed);
        assert_eq!(questions, 10);
        for stop_at in 1..=questions {
            asked.store(0, Relaxed);
            let told = || asked.fetch_add(1, Relaxed) + 1 == stop_at;
            let stopped = analyze_until(&model, &Supplied::default(), None, &told);
            assert!(stopped.is_none(), "told at question {stop_at}");
            assert_eq!(asked.load(Relaxed), stop_at, "no question after the stop");
        }
    }

    /// One walk asked about every variable's uses at once finds at each
    /// what a walk asked about that use alone finds, on programs with
    /// branches, loops, a skipped region and CYCLE600 calls.
    #[test]
    fn one_walk_answers_every_use_as_a_walk_for_each_would() {
        let programs = [
            "DEF REAL _DEPTH=5\nDEF INT _N\nR1=_DEPTH*2\nIF R5>0\n_N=1\nENDIF\n\
             G1 Z=-_DEPTH X=R1 Y=_N\nR1=R1+1 R2=R1\nGOTOF END\nR3=R1\nEND:\n\
             FOR R4=0 TO 2\nR6=R1+R4\nENDFOR\nR7=R6 R1=3\nM30\n"
                .to_string(),
            nested_loops(2, 30),
            std::fs::read_to_string(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/samples/PROBE_ALIGN.MPF"
            ))
            .expect("sample"),
        ];
        for program in &programs {
            let model = Model::of(program.as_bytes());
            let uses = crate::semantic::uses::Uses::of(&model);
            let probes: Vec<Probe> = uses
                .all()
                .iter()
                .filter(|u| u.namespace == crate::semantic::uses::Namespace::Variable)
                .map(|u| Probe {
                    row: u.row,
                    name: u.span,
                    after: matches!(
                        u.role,
                        crate::semantic::uses::Role::Writes | crate::semantic::uses::Role::Defines
                    ),
                })
                .collect();
            assert!(probes.len() > 10, "{}", probes.len());
            let supplied = Supplied::default();
            let all = values_at(&model, &supplied, None, &probes, None).expect("not stopped");
            for (probe, together) in probes.iter().zip(&all) {
                let alone = values_at(&model, &supplied, None, std::slice::from_ref(probe), None)
                    .expect("not stopped");
                assert_eq!(&alone[0], together, "{probe:?}");
            }
        }
        // The first program's skipped line is not reached; what a use
        // reads is there with its value.
        let model = Model::of(programs[0].as_bytes());
        let probe = |row, column: usize, length: usize, after| {
            let start = model.lines.raw(row).content.start + column;
            Probe {
                row,
                name: Span::new(start, start + length),
                after,
            }
        };
        let probes = [
            probe(9, 3, 2, false),
            probe(7, 11, 2, false),
            probe(7, 0, 2, true),
        ];
        let seen = values_at(&model, &Supplied::default(), None, &probes, None).expect("walked");
        assert_eq!(seen[0], Seen::NotReached);
        let value = |seen: &Seen| match seen {
            Seen::Value { value, .. } => value.clone().ok(),
            _ => None,
        };
        assert_eq!(value(&seen[1]), Some(Value::Number(11.0)), "{:?}", seen[1]);
        assert_eq!(value(&seen[2]), Some(Value::Number(11.0)), "{:?}", seen[2]);
    }

    /// A walk that ends after the last line asked about finds what the
    /// whole walk finds: the calls (inside a block that closes later, met
    /// again by a jump back from past them) and the reads of their results
    /// (spelt out; through a macro, none), on constructed programs and on
    /// every program of the samples, the fixtures and the corpus.
    #[test]
    fn a_walk_ended_after_what_was_asked_finds_what_the_whole_walk_finds() {
        let tail = "G1 X1 Y2\nR5=R5+1\nIF R5>3\nR6=1\nENDIF\n".repeat(50);
        // Recalculation only: its results are known offline.
        let recalculates =
            "CYCLE600 (0, \"UFK600\", 1, 57, 0, 0, 0, R1000, 45, 60, 0, 0, 0, 0, 1, 39, 0, 0, 0)\n";
        let constructed = [
            format!("R1000=30\n{recalculates}{tail}R2=_CYC600_2*2\n{tail}M30\n"),
            format!("R1000=30\nWHILE R7<2\n{CALL}R7=R7+1\n{tail}ENDWHILE\n{tail}M30\n"),
            format!("START:\nR1000=R1000+5\n{CALL}{tail}IF R1000<60 GOTOB START\n{tail}M30\n"),
            format!("DEFINE SECOND AS _CYC600_2\nR1000=30\n{recalculates}{tail}R2=SECOND\nM30\n"),
            format!("R1000=30\n{tail}M30\n"),
        ];
        let mut programs: Vec<Vec<u8>> =
            constructed.iter().map(|p| p.clone().into_bytes()).collect();
        let manifest = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut folders = vec![manifest.join("samples"), manifest.join("tests/fixtures")];
        folders.push(manifest.join("../shared/corpus"));
        while let Some(folder) = folders.pop() {
            let Ok(entries) = std::fs::read_dir(&folder) else {
                continue;
            };
            for entry in entries.flatten() {
                let path = entry.path();
                if path.is_dir() {
                    folders.push(path);
                } else if let Ok(bytes) = std::fs::read(&path) {
                    if crate::semantic::mentions_cycle600(&bytes) {
                        programs.push(bytes);
                    }
                }
            }
        }
        assert!(
            programs.len() > constructed.len() + 10,
            "{} programs",
            programs.len()
        );
        for program in &programs {
            let model = Model::of(program);
            let asked = analyze(&model, &Supplied::default(), None);
            let whole = run(&model, &Supplied::default(), None).0;
            let text = String::from_utf8_lossy(&program[..program.len().min(200)]);
            assert_eq!(format!("{asked:?}"), format!("{whole:?}"), "{text}");
        }
        // The read after the call is found; one through a macro is not a
        // read the rewrite can replace (its line spells no `_CYC600_`), in
        // the whole walk as in the shorter one.
        for (index, reads) in [(0, 1), (3, 0)] {
            let model = Model::of(constructed[index].as_bytes());
            let asked = analyze(&model, &Supplied::default(), None);
            assert_eq!(asked.result_reads.len(), reads, "program {index}");
        }
    }

    /// Forgetting what nested loops write costs the program's length times
    /// a constant, not times the depth: each loop forgot every line of its
    /// region, twice (100 loops around 2,000 lines: 400,000 names forgotten).
    #[test]
    fn nested_loops_cost_their_length_not_length_times_depth() {
        for depth in [100, 400] {
            let program = nested_loops(depth, 2000);
            let model = Model::of(program.as_bytes());
            let (analysis, env) = run(&model, &Supplied::default(), None);
            let lines = program.lines().count() as u64;
            assert!(
                env.work() <= 100 * lines,
                "depth {depth}: {} units of work for {lines} lines",
                env.work()
            );
            // The loops' writes are unknown at the call, named by the
            // innermost loop (it forgot them last).
            let call = &analysis.calls[0];
            let bound = call.bound.as_ref().expect("bound");
            let inner = depth; // 1-based line of the innermost FOR
            assert!(
                matches!(
                    &bound.arguments[7].value,
                    Err(Unknown::Variables(vars))
                        if vars[0].1 == Origin::ControlFlow { line: inner, what: "loop" }
                ),
                "{:?}",
                bound.arguments[7].value
            );
            // After the loops, the outermost one forgot them last.
            assert_eq!(
                env.binding("R1000"),
                Some(&Binding::Unknown {
                    origin: Origin::ControlFlow {
                        line: 1,
                        what: "loop"
                    }
                })
            );
        }
    }

    /// A region forgotten lazily reads as forgetting it eagerly did: an
    /// array's elements go, an R parameter a subprogram call there may
    /// change goes unless written after the call, a name bound after the
    /// loop keeps its value.
    #[test]
    fn a_forgotten_region_reads_as_forgotten_name_by_name() {
        let program = "DEF REAL A[3]\nA[1]=5\nR1=1\nR2=2\nR3=3\nWHILE R9<3\nA[2]=1\nR1=4\nMYSUB\nR2=5\nENDWHILE\nR3=7\nM30\n";
        let model = Model::of(program.as_bytes());
        let (_, env) = run(&model, &Supplied::default(), None);
        let loop_origin = Origin::ControlFlow {
            line: 6,
            what: "loop",
        };
        let unknown = Binding::Unknown {
            origin: loop_origin.clone(),
        };
        assert_eq!(env.binding("A"), Some(&unknown));
        assert_eq!(env.binding("A[1]"), None);
        // R1 written before the call in the loop: the call removes it.
        assert_eq!(env.binding("R1"), None);
        assert_eq!(env.binding("R2"), Some(&unknown));
        assert_eq!(env.value("R3"), Some(&Value::Number(7.0)));
        let supplied = Supplied::default();
        let scope = env.scope(&supplied, 13);
        assert_eq!(
            crate::semantic::eval::Lookup::variable(&scope, "R1"),
            Err(Unknown::Variables(vec![("R1".into(), loop_origin)]))
        );
    }
}
