//! The interpreter: one block after another in the order the control runs
//! them, the modal state it keeps, and what each block's motion does on the
//! machine (see the module above for what is modelled).

mod calls;
mod compensation;
mod counters;
mod motion;
mod polar;
mod repeat;
mod swivel;
mod timing;
mod traori;

use calls::is_numbered_call;

use std::borrow::Cow;
use std::collections::{BTreeMap, HashMap, HashSet};

use nalgebra::Matrix3;

use crate::run::arc::Arc;
use crate::run::frame::Frame;
use crate::run::setup::Setup;
use crate::run::{BlockEnd, Options, Programs, Report, ToolTime, Travel, Unknown, Violation};
use crate::semantic::addresses::{of_plain_into, Address};
use crate::semantic::calls::{call_kind, CallKind};
use crate::semantic::eval::{evaluate, key, variable_key, Lookup};
use crate::semantic::model::Model;
use crate::semantic::value::{Origin, Unknown as Missing, Value};
use crate::semantic::Supplied;
use crate::span::Span;
use crate::syntax::tree::{
    upper, Block, Expr, ExprKind, FrameKind, GotoKind, GotoTarget, Initializer, LineKind,
    StatementKind, TypeKind, WordValue,
};

/// In [`Interpreter::beyond`], an excursion counted and not listed.
const UNTOLD: usize = usize::MAX;

/// The addresses of one letter, by letter.
const LETTERS: [&str; 26] = [
    "A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "M", "N", "O", "P", "Q", "R", "S",
    "T", "U", "V", "W", "X", "Y", "Z",
];

/// At most this many things unknown are told: a loop repeats its own.
const MOST_UNKNOWN: usize = 1000;

/// Runs the program `model` holds on `setup`, `known` giving what the
/// program reads and does not assign (machine data, values the user
/// gives); `each` is handed every block's end.
pub fn run(
    programs: &Programs,
    setup: &Setup,
    known: &Supplied,
    options: &Options,
    mut each: impl FnMut(BlockEnd),
) -> Report {
    let mut machine = Interpreter::new(programs, setup, known, options);
    machine.reset();
    let mut watch = repeat::Watch::default();
    let mut row = 0;
    loop {
        if row >= machine.model.lines.len() {
            // The end of a file: a subprogram returns, the main program ends.
            match machine.give_back() {
                Some(back) => {
                    row = back;
                    continue;
                }
                None => break,
            }
        }
        if machine.report.blocks >= options.block_limit {
            let span = machine.model.lines.raw(row).content;
            machine.unknown(
                row,
                span,
                format!(
                    "the run stopped after {} blocks: a loop that does not end offline (its condition reads a value unknown here?)",
                    options.block_limit
                ),
            );
            break;
        }
        machine.report.blocks += 1;
        let flow = machine.block(row);
        machine.tell(&mut each);
        if machine.compensation.holds() {
            let arc = machine.last_arc.take();
            machine
                .compensation
                .wait(machine.program.clone(), row + 1, arc);
        } else {
            each(BlockEnd {
                program: machine.program.as_deref(),
                line: row + 1,
                mcs: &machine.mcs,
                t_s: machine.report.time_s,
                arc: machine.last_arc.take().as_ref(),
            });
        }
        let next = match flow {
            Flow::Next => row + 1,
            Flow::To(next) => next,
            Flow::End => match machine.give_back() {
                Some(back) => back,
                None => break,
            },
            Flow::Stop => break,
        };
        // The last block of a section REPEAT repeats: again, or back.
        let next = match machine.stack.last().and_then(|r| r.section) {
            Some((_, end)) if row == end && next == end + 1 => machine.end_section(),
            _ => next,
        };
        let from = row;
        row = match machine.calling.take() {
            Some(call) => match machine.enter(row, call, next) {
                Some(row) => row,
                None => break,
            },
            None => next,
        };
        if row <= from {
            if let Some(endless) = watch.jumped_back(&machine, from, row) {
                machine.report.endless = Some(endless);
                break;
            }
        }
    }
    machine.end_held(None);
    machine.tell(&mut each);
    machine.finish()
}

/// Where the run goes after a block.
enum Flow {
    Next,
    To(usize),
    /// The program level ends: a subprogram returns, a main program
    /// ends the run.
    End,
    /// The control stops with an alarm: the run ends.
    Stop,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Motion {
    Rapid,
    Linear,
    Clockwise,
    Counterclockwise,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum FeedMode {
    PerMinute,
    PerRevolution,
    InverseTime,
}

/// How an axis word's value is meant: as the modal G90/G91 says, or AC/IC.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Coordinate {
    Modal,
    Absolute,
    Incremental,
}

/// One address word of a block, its value evaluated.
struct Word {
    /// Upper case, the extension included (`X`, `X1`, `G`, `CR`).
    name: Cow<'static, str>,
    value: Result<f64, String>,
    coordinate: Coordinate,
}

/// A block's words, by what they are for.
#[derive(Default)]
struct Content {
    words: Vec<Word>,
    frame: Option<(FrameKind, Vec<Word>)>,
    commands: Vec<String>,
    /// Subprograms and cycles called.
    calls: Vec<(String, Arguments)>,
    /// `MCALL NAME(...)`: a modal call from the next block on; `MCALL`
    /// alone (`Some(None)`) ends it.
    modal: Option<Option<ModalCall>>,
}

impl Content {
    /// A word of the block: after a frame statement (`TRANS X10`), the
    /// frame's.
    fn push(&mut self, word: Word) {
        match &mut self.frame {
            Some((_, words)) => words.push(word),
            None => self.words.push(word),
        }
    }
}

struct Variables<'a> {
    local: HashMap<String, Value>,
    /// The channel's state as system variables read it, once the program
    /// has set it itself (`$P_TOOLNO` after a tool change): before, the
    /// control's state when the program starts is not known offline.
    channel: HashMap<&'static str, f64>,
    known: &'a Supplied,
}

impl Variables<'_> {
    /// The program sets what the system variable `name` reads: `None`, a
    /// state the run cannot name (M6 with no T programmed).
    fn set_channel(&mut self, name: &'static str, value: Option<u32>) {
        match value {
            Some(value) => self.channel.insert(name, f64::from(value)),
            None => self.channel.remove(name),
        };
    }
}

impl Lookup for Variables<'_> {
    fn variable(&self, key: &str) -> Result<Value, Missing> {
        if let Some(value) = self.local.get(key) {
            return Ok(value.clone());
        }
        if let Some(&value) = self.channel.get(key) {
            return Ok(Value::Number(value));
        }
        match self.known.get(key) {
            Some((value, _)) => Ok(value.clone()),
            None => Err(Missing::Variables(vec![(
                key.to_string(),
                Origin::NeverAssigned,
            )])),
        }
    }
}

/// A call's arguments by position: each value, `None` where unknown
/// offline or left out; and which the call leaves out (`NAME(1,,3)`, or
/// after its last), which the control passes as 0 (Programming Manual,
/// "Subprogram call": incomplete parameter transfer).
#[derive(Clone, Debug, Default, PartialEq)]
struct Arguments {
    values: Vec<Option<Value>>,
    omitted: Vec<bool>,
}

impl Arguments {
    fn of(source: &[u8], call: &crate::syntax::tree::Call, known: &impl Lookup) -> Arguments {
        let items = &call.arguments.items;
        // `NAME()`: no argument, not one left out.
        let items = match items.as_slice() {
            [only] if only.value.is_none() => &items[..0],
            _ => &items[..],
        };
        Arguments {
            values: items
                .iter()
                .map(|a| evaluate(source, a.value.as_ref()?, known).ok())
                .collect(),
            omitted: items.iter().map(|a| a.value.is_none()).collect(),
        }
    }
}

/// A subprogram's call: what it is given, and how often it runs.
struct Calling {
    name: String,
    arguments: Arguments,
    times: u32,
}

/// A modal call (`MCALL`): the subprogram called after each block that
/// moves, at the program level it was set on.
#[derive(Clone, Debug, PartialEq)]
struct ModalCall {
    name: String,
    arguments: Arguments,
    level: usize,
}

/// Where a subprogram returns to, and what the caller had.
struct Return<'a, 'src> {
    model: &'a Model<'src>,
    program: Option<String>,
    row: usize,
    locals: HashMap<String, Value>,
    openers: HashMap<usize, usize>,
    in_for: HashSet<usize>,
    /// Runs of the subprogram still to come (`P`).
    again: u32,
    arguments: Arguments,
    /// A section of the same program repeated (`REPEAT`): its first and
    /// last rows; the caller's variables are the section's own.
    section: Option<(usize, usize)>,
    /// What a subprogram with SAVE restores on its return.
    saved: Option<calls::Saved>,
}

/// G group 59 in its order, which is MD32300's and MD32431's index.
const DYNAMIC_GROUPS: [&str; 5] = ["DYNNORM", "DYNPOS", "DYNROUGH", "DYNSEMIFIN", "DYNFINISH"];

/// The most program levels the control nests: the main program and 15
/// subprograms (Siemens, Programming Manual Fundamentals, "Nesting depth").
const MOST_LEVELS: usize = 16;

/// The modes a move's path and its time follow.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Modes {
    motion: Motion,
    /// Feeds to the machine's (G700, G710).
    feed_scale: f64,
    feed_mode: FeedMode,
    /// As programmed, per minute (or per revolution, or inverse time).
    feed: Option<f64>,
    spindle: Option<f64>,
    exact_stop: bool,
    soft: bool,
    /// G0 interpolates linearly (RTLION) or each axis on its own (RTLIOF).
    rapid_linear: bool,
    /// The dynamic response group whose MD32300/MD32431 the path takes
    /// (G group 59: 0 DYNNORM, 1 DYNPOS, 2 DYNROUGH, 3 DYNSEMIFIN, 4
    /// DYNFINISH), from `--dynamic-group` until the program chooses one.
    dynamic_group: usize,
}

struct Interpreter<'a, 'src> {
    programs: &'a Programs<'src>,
    model: &'a Model<'src>,
    stack: Vec<Return<'a, 'src>>,
    /// The subprogram running, by name; `None` in the main program.
    program: Option<String>,
    /// The call the block just run makes, entered after it.
    calling: Option<Calling>,
    /// The modal call in force (`MCALL`).
    modal_call: Option<ModalCall>,
    /// The pole and the polar words last programmed (G110-G112, AP, RP).
    polar: polar::Polar,
    /// The arc the block just run moves along, for [`BlockEnd::arc`].
    last_arc: Option<Arc>,
    source: &'src [u8],
    setup: &'a Setup,
    options: &'a Options,
    variables: Variables<'a>,
    /// Closing row to opening row, of the control blocks.
    openers: HashMap<usize, usize>,
    /// FOR loops entered and not yet left, by their opening row.
    in_for: HashSet<usize>,
    /// Each run axis's machine position; `None` until known.
    mcs: Vec<Option<f64>>,
    /// Each run axis's position as last programmed, in the work's
    /// coordinates (what G91 adds to).
    programmed: Vec<Option<f64>>,
    /// The frames' linear part (rotation, scale, mirror) at the last move.
    last_linear: Matrix3<f64>,
    /// What a move's path and time follow, kept with a move held back.
    modes: Modes,
    incremental: bool,
    /// 0: G17 (XY, infeed Z), 1: G18 (ZX, infeed Y), 2: G19 (YZ, infeed X).
    plane: usize,
    /// Program lengths to the machine's: 25.4 for G70/G700 on a metric machine.
    length_scale: f64,
    settable: Frame,
    programmable: Frame,
    /// The swivel of the last CYCLE800, until `CYCLE800()`.
    swivelled: Option<swivel::Swivelled>,
    /// The orientation transformation TRAORI made active, until TRAFOOF.
    transformed: Option<traori::Transformed>,
    /// Tool radius compensation, and the element it holds back.
    compensation: compensation::Compensation,
    /// How the tool turns between a block's ends under TRAORI.
    turning: traori::Turning,
    /// The block moving now programs the orientation as a vector.
    by_vector: bool,
    preselected: Option<u32>,
    tool: Option<u32>,
    edge: Option<u32>,
    /// The last tool offset found, by tool, edge and plane.
    tool_offset: Option<((u32, u32, usize), [f64; 3])>,
    report: Report,
    /// What was told, by program, row and text: a loop repeats it.
    told: HashSet<(Option<String>, usize, String)>,
    minimum: Vec<Option<f64>>,
    maximum: Vec<Option<f64>>,
    violations: Vec<Violation>,
    /// The violations of the axes (axis, plus side) beyond a limit at the
    /// last block's end: a block that stays beyond continues them.
    beyond: HashMap<(usize, bool), usize>,
    /// A violation by the block it began in and its key: a loop that passes
    /// again adds to it.
    began: HashMap<(Option<String>, usize, usize, bool), usize>,
    tool_times: BTreeMap<String, f64>,
    upper_complete: bool,
    /// How often the run took something it could not know for something
    /// (each [`Interpreter::unknown`], told or not).
    guesses: u64,
    /// A synchronized action was programmed: it may act in any later block,
    /// and the run does not model it.
    synchronized: bool,
    words: Vec<Address>,
}

impl<'a, 'src> Interpreter<'a, 'src> {
    fn new(
        programs: &'a Programs<'src>,
        setup: &'a Setup,
        known: &'a Supplied,
        options: &'a Options,
    ) -> Self {
        let model = programs.main;
        let axes = setup.axes.len();
        let openers = openers(model);
        let mut report = Report::default();
        // The modes at the start: MD20150's where the data hold them, else
        // the Programming Manual's defaults (G60, BRISK).
        let exact_stop = setup.reset_exact_stop.unwrap_or(true);
        let soft = setup.reset_soft.unwrap_or(false);
        let said = |given: bool| {
            if given {
                "MD20150"
            } else {
                "the control's default; MD20150 not in the data"
            }
        };
        let reset: Vec<String> = setup
            .reset_g_functions
            .iter()
            .map(|g| format!("G{g}"))
            .collect();
        let modes = if reset.is_empty() {
            "G0 G17 G90 G94 G71 G500 G450 (the control's defaults: the data hold no MD20150 for them)"
                .to_string()
        } else {
            format!(
                "{} (MD20150), else G0 G17 G90 G94 G71 G500 G450 (the control's defaults)",
                reset.join(" ")
            )
        };
        report.assumptions.push(format!(
            "at the start: {modes}, no programmable frame, no tool, positions unknown until programmed; {} ({}), {} ({})",
            if exact_stop { "G60 exact stop" } else { "continuous path" },
            said(setup.reset_exact_stop.is_some()),
            if soft { "SOFT" } else { "BRISK" },
            said(setup.reset_soft.is_some()),
        ));
        if !setup.base_frames.is_empty() {
            report.unknown.push(Unknown {
                program: None,
                line: 0,
                span: Span::default(),
                why: format!(
                    "the base frames {} of the machine's data are not applied: which are active is the control's state ($P_NCBFRMASK, $P_CHBFRMASK, MD20110); positions are of the settable and programmable frames alone",
                    setup.base_frames.join(", ")
                ),
            });
        }
        report.assumptions.push(
            "G0 interpolates linearly (RTLION, until RTLIOF), each block's path at the slowest axis's share of MD32000, MD32300, MD32431".to_string(),
        );
        if options.values_from_data > 0 {
            report.assumptions.push(format!(
                "{} values of GUD variables and R parameters as the machine's data hold them (the control's state when they were written; --set overrides)",
                options.values_from_data
            ));
        }
        Interpreter {
            programs,
            model,
            stack: Vec::new(),
            program: None,
            calling: None,
            modal_call: None,
            polar: polar::Polar::default(),
            last_arc: None,
            source: model.source,
            setup,
            options,
            variables: Variables {
                local: HashMap::new(),
                channel: HashMap::new(),
                known,
            },
            openers,
            in_for: HashSet::new(),
            mcs: vec![None; axes],
            programmed: vec![None; axes],
            last_linear: Matrix3::identity(),
            modes: Modes {
                motion: Motion::Rapid,
                feed_scale: 1.0,
                feed_mode: FeedMode::PerMinute,
                feed: None,
                spindle: None,
                exact_stop,
                soft,
                rapid_linear: true,
                dynamic_group: options.dynamic_group,
            },
            incremental: false,
            plane: 0,
            length_scale: 1.0,
            settable: Frame::identity(axes),
            programmable: Frame::identity(axes),
            swivelled: None,
            transformed: None,
            compensation: compensation::Compensation::default(),
            turning: traori::Turning::default(),
            by_vector: false,
            preselected: None,
            tool: None,
            edge: None,
            tool_offset: None,
            report,
            told: HashSet::new(),
            minimum: vec![None; axes],
            maximum: vec![None; axes],
            violations: Vec::new(),
            beyond: HashMap::new(),
            began: HashMap::new(),
            tool_times: BTreeMap::new(),
            upper_complete: true,
            guesses: 0,
            synchronized: false,
            words: Vec::with_capacity(16),
        }
    }

    /// The G functions MD20150 makes active at the start.
    fn reset(&mut self) {
        for &g in &self.setup.reset_g_functions {
            match g {
                0 => self.modes.motion = Motion::Rapid,
                1 => self.modes.motion = Motion::Linear,
                2 => self.modes.motion = Motion::Clockwise,
                3 => self.modes.motion = Motion::Counterclockwise,
                17..=19 => self.plane = g as usize - 17,
                70 | 71 | 700 | 710 if self.setup.metric.is_some() => {
                    self.units(0, Span::default(), g)
                }
                90 | 91 => self.incremental = g == 91,
                93 => self.modes.feed_mode = FeedMode::InverseTime,
                94 => self.modes.feed_mode = FeedMode::PerMinute,
                95 => self.modes.feed_mode = FeedMode::PerRevolution,
                450 | 451 => self.compensation.corners(g),
                54..=57 | 505..=599 if !self.setup.frames.contains_key(&format!("G{g}")) => {
                    self.note(format!("MD20150 selects G{g} at the start, a frame the machine's data do not hold: taken as zero"));
                }
                54..=57 | 505..=599 => self.select_frame(0, Span::default(), g),
                _ => {}
            }
        }
    }

    fn unknown(&mut self, row: usize, span: Span, why: String) {
        self.guesses += 1;
        let told = (self.program.clone(), row, why.clone());
        if self.report.unknown.len() >= MOST_UNKNOWN || !self.told.insert(told) {
            return;
        }
        self.report.unknown.push(Unknown {
            program: self.program.clone(),
            line: row + 1,
            span,
            why,
        });
    }

    /// Said once a run, not tied to a block.
    fn note(&mut self, why: String) {
        if !self.told.insert((None, usize::MAX, why.clone())) {
            return;
        }
        self.report.unknown.push(Unknown {
            program: None,
            line: 0,
            span: Span::default(),
            why,
        });
    }

    /// Executes line `row`.
    fn block(&mut self, row: usize) -> Flow {
        let raw = self.model.lines.raw(row);
        if self.model.lines.is_plain(row) {
            let mut words = std::mem::take(&mut self.words);
            of_plain_into(self.source, raw.content, &mut words);
            let content = Content {
                words: words.iter().map(|a| self.plain_word(a)).collect(),
                ..Content::default()
            };
            self.words = words;
            return self.apply(row, raw.content, content);
        }
        let line = self.model.lines.line(row);
        let LineKind::Block(block) = &line.kind else {
            return Flow::Next;
        };
        self.tree_block(row, raw.content, block)
    }

    fn plain_word(&self, address: &Address) -> Word {
        // A plain line's address is one letter: named without an allocation,
        // its millions of words read by the million.
        let letter = address.letter(self.source);
        let name = match letter {
            // `L105`: the subprogram's number as written.
            b'L' => Cow::Owned(format!(
                "L{}",
                upper(address.number.map_or(&b""[..], |n| n.of(self.source)))
            )),
            b'A'..=b'Z' => Cow::Borrowed(LETTERS[usize::from(letter - b'A')]),
            _ => Cow::Owned(upper(address.name.of(self.source))),
        };
        let value = address
            .number
            .and_then(|n| {
                std::str::from_utf8(n.of(self.source))
                    .ok()?
                    .parse::<f64>()
                    .ok()
            })
            .ok_or_else(|| format!("`{}` has no value", upper(address.span.of(self.source))));
        Word {
            name,
            value,
            coordinate: Coordinate::Modal,
        }
    }

    fn tree_block(&mut self, row: usize, span: Span, block: &Block) -> Flow {
        let mut content = Content::default();
        let source = self.source;
        let mut condition: Option<bool> = None;
        for statement in &block.statements {
            match &statement.kind {
                StatementKind::Word(word) => {
                    let mut name = upper(word.address.text(source));
                    if let Some(extension) = word.extension {
                        name.push_str(&upper(extension.of(source)));
                    }
                    let (value, coordinate) = match &word.value {
                        WordValue::Number(n) => {
                            if name == "L" {
                                name.push_str(&upper(n.span.of(source)));
                            }
                            (Ok(n.value), Coordinate::Modal)
                        }
                        WordValue::Expr(expr) => self.word_value(expr),
                    };
                    content.push(Word {
                        name: Cow::Owned(name),
                        value,
                        coordinate,
                    });
                }
                StatementKind::Assign(assign) => {
                    let name = assign.target.name.upper(source);
                    if assign.target.indices.is_empty()
                        && matches!(name.as_str(), "CR" | "AR" | "AP" | "RP" | "TURN" | "RPL")
                    {
                        let (value, coordinate) = self.word_value(&assign.value);
                        content.push(Word {
                            name: Cow::Owned(name),
                            value,
                            coordinate,
                        });
                        continue;
                    }
                    let key = variable_key(source, &assign.target, &self.variables);
                    let value = evaluate(source, &assign.value, &self.variables);
                    match (key, value) {
                        (Ok(key), Ok(value)) => {
                            self.variables.local.insert(key, value);
                        }
                        (Ok(key), Err(missing)) => {
                            self.variables.local.remove(&key);
                            self.unknown(row, statement.span, format!("`{key}` is assigned a value unknown offline ({missing}): what reads it is unknown; give it with --set"));
                        }
                        (Err(missing), _) => {
                            self.unknown(
                                row,
                                statement.span,
                                format!("an assignment's target is unknown offline ({missing})"),
                            );
                        }
                    }
                }
                StatementKind::Def(def) => {
                    for declarator in &def.variables {
                        let name = declarator.name.upper(source);
                        let value = match &declarator.init {
                            Some(Initializer::Expr(expr)) => {
                                evaluate(source, expr, &self.variables).ok()
                            }
                            Some(Initializer::List(_)) => None,
                            // The control sets what a DEF does not initialise to 0 (text: empty).
                            None if declarator.dimensions.is_empty() => Some(
                                if matches!(
                                    def.data_type.kind,
                                    TypeKind::String | TypeKind::Axis | TypeKind::Frame
                                ) {
                                    Value::Text(String::new())
                                } else {
                                    Value::Number(0.0)
                                },
                            ),
                            None => None,
                        };
                        match value {
                            Some(value) => {
                                self.variables.local.insert(key(&name, &[]), value);
                            }
                            None => {
                                self.variables.local.remove(&name);
                            }
                        }
                    }
                }
                StatementKind::Frame(frame) => {
                    content.frame = Some((frame.kind, Vec::new()));
                }
                StatementKind::Command(name) => {
                    content.commands.push(name.upper(source));
                }
                StatementKind::Call(call) => {
                    let arguments = Arguments::of(source, call, &self.variables);
                    content.calls.push((call.name.upper(source), arguments));
                }
                StatementKind::IndirectCall { keyword, target } if keyword.is(source, "MCALL") => {
                    content.modal = Some(match target {
                        None => None,
                        Some(target) => self.modal_call(row, statement.span, *target),
                    });
                }
                StatementKind::IndirectCall { keyword, target } => {
                    let keyword = keyword.upper(source);
                    let name = target
                        .and_then(|t| crate::run::programs::indirect_call(source, &keyword, t));
                    match name {
                        Some(name) => content.calls.push((name, Arguments::default())),
                        None => self.unknown(row, statement.span, format!("{keyword} is not followed (a call whose program is computed at run time): what it moves, and its time, are not in the run")),
                    }
                }
                StatementKind::If { condition: expr } => {
                    let jumps = block
                        .statements
                        .iter()
                        .any(|s| matches!(s.kind, StatementKind::Goto(_)));
                    let holds = self.condition(row, statement.span, expr, false);
                    if jumps {
                        condition = Some(holds);
                        continue;
                    }
                    let flow = if holds {
                        Flow::Next
                    } else {
                        match self.model.blocks.opened_on(row) {
                            Some(closed) => Flow::To(closed.else_row.unwrap_or(closed.end) + 1),
                            None => Flow::End,
                        }
                    };
                    return self.then(row, span, content, flow);
                }
                StatementKind::Else => {
                    // Reached from the IF's branch: on past the ENDIF.
                    let flow = match self.model.blocks.else_end(row) {
                        Some(end) => Flow::To(end + 1),
                        None => Flow::Next,
                    };
                    return self.then(row, span, content, flow);
                }
                StatementKind::While { condition: expr } => {
                    let holds = self.condition(row, statement.span, expr, false);
                    let flow = match (holds, self.model.blocks.opened_on(row)) {
                        (true, _) => Flow::Next,
                        (false, Some(closed)) => Flow::To(closed.end + 1),
                        (false, None) => Flow::End,
                    };
                    return self.then(row, span, content, flow);
                }
                StatementKind::EndWhile => {
                    let flow = self.openers.get(&row).map_or(Flow::Next, |&o| Flow::To(o));
                    return self.then(row, span, content, flow);
                }
                StatementKind::For {
                    variable,
                    start,
                    end,
                } => {
                    let name = key(&variable.upper(source), &[]);
                    if self.in_for.insert(row) {
                        match evaluate(source, start, &self.variables) {
                            Ok(value) => {
                                self.variables.local.insert(name.clone(), value);
                            }
                            Err(missing) => {
                                self.unknown(row, statement.span, format!("the FOR loop's start is unknown offline ({missing}): the loop is left"));
                                self.in_for.remove(&row);
                                return self.leave(row, span, content);
                            }
                        }
                    }
                    let counter = self.variables.local.get(&name).and_then(Value::number);
                    let last = evaluate(source, end, &self.variables)
                        .ok()
                        .and_then(|v| v.number());
                    match counter.zip(last) {
                        Some((counter, last)) if counter <= last => {
                            return self.then(row, span, content, Flow::Next);
                        }
                        Some(_) => {}
                        None => self.unknown(
                            row,
                            statement.span,
                            "the FOR loop's end is unknown offline: the loop is left".to_string(),
                        ),
                    }
                    self.in_for.remove(&row);
                    return self.leave(row, span, content);
                }
                StatementKind::EndFor => {
                    let Some(&opener) = self.openers.get(&row) else {
                        return self.then(row, span, content, Flow::Next);
                    };
                    let counter = self.for_counter(opener);
                    if let Some(name) = counter {
                        let next = self
                            .variables
                            .local
                            .get(&name)
                            .and_then(Value::number)
                            .map(|n| n + 1.0);
                        match next {
                            Some(next) => {
                                self.variables.local.insert(name, Value::Number(next));
                            }
                            None => {
                                self.in_for.remove(&opener);
                                return self.then(row, span, content, Flow::Next);
                            }
                        }
                    }
                    return self.then(row, span, content, Flow::To(opener));
                }
                StatementKind::Loop => return self.then(row, span, content, Flow::Next),
                StatementKind::EndLoop => {
                    let flow = self
                        .openers
                        .get(&row)
                        .map_or(Flow::Next, |&o| Flow::To(o + 1));
                    return self.then(row, span, content, flow);
                }
                StatementKind::Repeat { targets, .. } if targets.is_empty() => {
                    return self.then(row, span, content, Flow::Next);
                }
                StatementKind::Repeat { targets, count } => {
                    let flow = self.repeat(row, statement.span, targets, count.as_deref());
                    return self.then(row, span, content, flow);
                }
                StatementKind::Until { condition: expr } => {
                    let holds = self.condition(row, statement.span, expr, true);
                    let flow = match (holds, self.openers.get(&row)) {
                        (false, Some(&opener)) => Flow::To(opener + 1),
                        _ => Flow::Next,
                    };
                    return self.then(row, span, content, flow);
                }
                StatementKind::Goto(goto) => {
                    if condition == Some(false) {
                        continue;
                    }
                    let flow = self.jump(row, statement.span, goto.kind, goto.target.as_ref());
                    return self.then(row, span, content, flow);
                }
                StatementKind::Case(case) => {
                    // The first constant equal to the selector's value jumps,
                    // else DEFAULT's, else the next block.
                    let flow = match evaluate(source, &case.selector, &self.variables) {
                        Ok(selected) => {
                            let taken = case
                                .branches
                                .iter()
                                .find(|(constant, _)| {
                                    evaluate(source, constant, &self.variables).ok().as_ref()
                                        == Some(&selected)
                                })
                                .map(|(_, goto)| goto)
                                .or(case.default.as_ref());
                            match taken {
                                Some(goto) => {
                                    self.jump(row, statement.span, goto.kind, goto.target.as_ref())
                                }
                                None => Flow::Next,
                            }
                        }
                        Err(missing) => {
                            self.unknown(row, statement.span, format!("CASE's value is unknown offline ({missing}): the run goes on with the next block; give the value with --set"));
                            Flow::Next
                        }
                    };
                    return self.then(row, span, content, flow);
                }
                StatementKind::SyncAction(_) => {
                    self.synchronized = true;
                    self.unknown(
                        row,
                        statement.span,
                        "a synchronized action acts in the main run: not modelled".to_string(),
                    );
                }
                _ => {}
            }
        }
        self.apply(row, span, content)
    }

    /// The counter of the FOR loop on `row`.
    fn for_counter(&self, row: usize) -> Option<String> {
        let line = self.model.lines.line(row);
        let LineKind::Block(block) = &line.kind else {
            return None;
        };
        block.statements.iter().find_map(|s| match &s.kind {
            StatementKind::For { variable, .. } => Some(key(&variable.upper(self.source), &[])),
            _ => None,
        })
    }

    /// The block's words applied, then on past the end of the loop it opens.
    fn leave(&mut self, row: usize, span: Span, content: Content) -> Flow {
        let flow = match self.model.blocks.opened_on(row) {
            Some(closed) => Flow::To(closed.end + 1),
            None => Flow::End,
        };
        self.then(row, span, content, flow)
    }

    /// The block's words applied, then `flow` (unless the block ends the program).
    fn then(&mut self, row: usize, span: Span, content: Content, flow: Flow) -> Flow {
        match self.apply(row, span, content) {
            end @ (Flow::End | Flow::Stop) => end,
            _ => flow,
        }
    }

    /// The condition's truth; unknown offline, `otherwise` (said with
    /// the block).
    fn condition(&mut self, row: usize, span: Span, expr: &Expr, otherwise: bool) -> bool {
        match evaluate(self.source, expr, &self.variables) {
            Ok(Value::Number(n)) => n != 0.0,
            Ok(Value::Text(t)) => !t.is_empty(),
            Err(missing) => {
                let taken = if otherwise {
                    "taken as true"
                } else {
                    "taken as false"
                };
                self.unknown(row, span, format!("the condition is unknown offline ({missing}): {taken}; give the value with --set"));
                otherwise
            }
        }
    }

    fn jump(
        &mut self,
        row: usize,
        span: Span,
        kind: GotoKind,
        target: Option<&GotoTarget>,
    ) -> Flow {
        let Some(target) = target else {
            return Flow::Next;
        };
        if let GotoTarget::Computed(_) = target {
            self.unknown(
                row,
                span,
                "a computed jump target is not followed: the run goes on with the next block"
                    .to_string(),
            );
            return Flow::Next;
        }
        match self.model.landing(target, kind, row) {
            Some(landing) => {
                // A jump out of a FOR loop leaves it: met again, it starts anew.
                let blocks = &self.model.blocks;
                self.in_for.retain(|&opener| {
                    blocks
                        .opened_on(opener)
                        .is_some_and(|c| (c.row + 1..=c.end).contains(&landing))
                });
                Flow::To(landing)
            }
            None if kind == GotoKind::Conditional => Flow::Next,
            None => {
                self.unknown(
                    row,
                    span,
                    "the jump's target is not found: the control stops with an alarm here"
                        .to_string(),
                );
                Flow::Stop
            }
        }
    }

    /// An axis word's value written as an expression: `AC(..)`/`IC(..)`
    /// say how it is meant.
    fn word_value(&self, expr: &Expr) -> (Result<f64, String>, Coordinate) {
        let (inner, coordinate) = match &expr.kind {
            ExprKind::Call(call) if call.arguments.items.len() == 1 => {
                let coordinate = match call.name.upper(self.source).as_str() {
                    "AC" | "DC" | "ACP" | "ACN" => Some(Coordinate::Absolute),
                    "IC" => Some(Coordinate::Incremental),
                    _ => None,
                };
                match (coordinate, &call.arguments.items[0].value) {
                    (Some(coordinate), Some(inner)) => (inner, coordinate),
                    _ => (expr, Coordinate::Modal),
                }
            }
            _ => (expr, Coordinate::Modal),
        };
        let value = match evaluate(self.source, inner, &self.variables) {
            Ok(Value::Number(n)) => Ok(n),
            Ok(Value::Text(_)) => Err("text where a number belongs".to_string()),
            Err(missing) => Err(format!("unknown offline ({missing})")),
        };
        (value, coordinate)
    }

    /// What a block's words do: its modal G functions, frames, tool, feed,
    /// and its motion.
    fn apply(&mut self, row: usize, span: Span, content: Content) -> Flow {
        if self.compensation.holds() && !self.keeps_contour(&content) {
            self.end_held(Some("before the next move in the plane, a block changes the frames, the tool or the plane, or calls a cycle"));
        }
        let mut dwell = false;
        let mut exact_here = false;
        let mut suppress_frames = false;
        let mut ends = false;
        let mut changes_tool = false;
        let mut targets: Vec<Option<(Result<f64, String>, Coordinate)>> =
            vec![None; self.setup.axes.len()];
        let mut centre: [Option<(Result<f64, String>, Coordinate)>; 3] = [None, None, None];
        let mut shape = motion::ArcShape::default();
        let mut dwell_value = None;
        let mut called: Vec<(String, Arguments)> = Vec::new();
        let mut times = 1;
        let (mut ap, mut rp, mut pole): (polar::Given, polar::Given, Option<u32>) =
            (None, None, None);
        let mut orientation: [Option<Result<f64, String>>; 3] = [None, None, None];
        for word in &content.words {
            let value = &word.value;
            match word.name.as_ref() {
                "G" => {
                    let Ok(g) = value else {
                        self.unknown(row, span, "a G function's number is unknown offline".into());
                        continue;
                    };
                    match *g as u32 {
                        0 => self.modes.motion = Motion::Rapid,
                        1 => self.modes.motion = Motion::Linear,
                        2 => self.modes.motion = Motion::Clockwise,
                        3 => self.modes.motion = Motion::Counterclockwise,
                        4 => dwell = true,
                        9 => exact_here = true,
                        17..=19 => {
                            let plane = *g as usize - 17;
                            if plane != self.plane {
                                self.plane = plane;
                                self.polar.plane_changed();
                            }
                        }
                        40..=42 => self.select_compensation(row, span, *g as u32),
                        450 | 451 => self.compensation.corners(*g as u32),
                        53 | 153 => suppress_frames = true,
                        500 => {
                            self.settable = Frame::identity(self.setup.axes.len());
                            self.variables.set_channel("$P_UIFRNUM", Some(0));
                        }
                        54..=57 | 505..=599 => {
                            self.select_frame(row, span, *g as u32);
                            let number = if *g < 500.0 { *g - 53.0 } else { *g - 500.0 };
                            self.variables
                                .set_channel("$P_UIFRNUM", Some(number as u32));
                        }
                        60 => self.modes.exact_stop = true,
                        64 | 641..=645 => self.modes.exact_stop = false,
                        70 | 700 | 71 | 710 => self.units(row, span, *g as u32),
                        90 => self.incremental = false,
                        91 => self.incremental = true,
                        93 => self.modes.feed_mode = FeedMode::InverseTime,
                        94 => self.modes.feed_mode = FeedMode::PerMinute,
                        95 => self.modes.feed_mode = FeedMode::PerRevolution,
                        110..=112 => pole = Some(*g as u32),
                        _ => {}
                    }
                }
                "M" => match value {
                    Ok(m) if [2.0, 17.0, 30.0].contains(m) => ends = true,
                    Ok(m) if *m == 6.0 => changes_tool = true,
                    _ => {}
                },
                "T" => match value {
                    Ok(t) if *t >= 0.0 && t.fract() == 0.0 => {
                        self.preselected = Some(*t as u32);
                        self.variables.set_channel("$P_TOOLP", self.preselected);
                        match self.setup.tool_change_with_m6 {
                            Some(false) => changes_tool = true,
                            Some(true) => {}
                            None => self.note("MD22550 $MC_TOOL_CHANGE_MODE is not in the machine's data: T selects a tool and M6 changes it, as on most milling machines".into()),
                        }
                    }
                    _ => self.unknown(
                        row,
                        span,
                        "a tool named by text or unknown offline: its length is not known".into(),
                    ),
                },
                "D" => match value {
                    Ok(d) if *d >= 0.0 && d.fract() == 0.0 => {
                        self.edge = Some(*d as u32);
                        self.variables.set_channel("$P_TOOL", self.edge);
                        if *d > 0.0
                            && self.tool.is_none()
                            && !changes_tool
                            && !content
                                .words
                                .iter()
                                .any(|w| w.name == "M" && w.value == Ok(6.0))
                        {
                            self.unknown(row, span, format!("D{} without a tool changed in (T and M6 not met before it): no tool length applied", *d as u32));
                        }
                    }
                    _ => self.unknown(row, span, "the cutting edge (D) is unknown offline".into()),
                },
                "F" if dwell => dwell_value = Some(value.clone()),
                "F" => match value {
                    Ok(f) => self.modes.feed = Some(*f),
                    Err(why) => {
                        self.modes.feed = None;
                        self.unknown(row, span, format!("the feed is {why}"));
                    }
                },
                "S" | "S1" => match value {
                    Ok(s) if dwell => {
                        dwell_value =
                            Some(match self.modes.spindle {
                                Some(speed) if speed > 0.0 => Ok(s * 60.0 / speed),
                                _ => Err("a dwell in spindle revolutions without a known speed"
                                    .to_string()),
                            })
                    }
                    Ok(s) => self.modes.spindle = Some(*s),
                    Err(_) => self.modes.spindle = None,
                },
                "I" | "J" | "K" => {
                    let k = (word.name.as_bytes()[0] - b'I') as usize;
                    centre[k] = Some((value.clone(), word.coordinate));
                }
                "OFFN" => match value {
                    Ok(offset) => self.compensation.set_extra(*offset * self.length_scale),
                    Err(why) => self.unknown(
                        row,
                        span,
                        format!("OFFN is {why}: the contour's offset is left as it was"),
                    ),
                },
                "CR" => shape.radius = Some(value.clone()),
                "AR" => shape.opening = Some(value.clone()),
                "TURN" => shape.turns = Some(value.clone()),
                "AP" => ap = Some((value.clone(), word.coordinate)),
                "RP" => rp = Some((value.clone(), word.coordinate)),
                "A3" | "B3" | "C3" => {
                    orientation[(word.name.as_bytes()[0] - b'A') as usize] = Some(value.clone());
                }
                name if is_numbered_call(name) => {
                    called.push((name.to_string(), Arguments::default()))
                }
                "P" => match value {
                    Ok(p) if *p >= 1.0 && p.fract() == 0.0 => times = *p as u32,
                    _ => self.unknown(
                        row,
                        span,
                        "a subprogram's repetitions (P) unknown offline: run once".into(),
                    ),
                },
                name => match self.setup.axis(name) {
                    Some(axis) => targets[axis] = Some((value.clone(), word.coordinate)),
                    None if name.starts_with(['A', 'B', 'C', 'U', 'V', 'W', 'X', 'Y', 'Z']) => {
                        self.note(format!("`{name}` is no axis of the machine's channel (MD20080): its moves are not in the run"));
                    }
                    None => {}
                },
            }
        }
        for command in &content.commands {
            match command.as_str() {
                // The subprogram's end, as M17 (the main program's, as M30).
                "RET" => ends = true,
                "BRISK" => self.modes.soft = false,
                "SOFT" => self.modes.soft = true,
                "SUPA" => suppress_frames = true,
                "RTLION" => self.modes.rapid_linear = true,
                "RTLIOF" => self.modes.rapid_linear = false,
                "TRAORI" => self.traori(row, span, &[]),
                "TRANSMIT" | "TRACYL" | "TRACON" | "TRAANG" => self.unknown(row, span, format!("{command} (a kinematic transformation) is not modelled yet: the positions after it are of the axes as programmed")),
                "TRAFOOF" => self.trafoof(row, span),
                "KONT" | "KONTC" | "KONTT" => self.unknown(row, span, format!("{command}: the approach and retraction around the contour's start are not modelled: taken as NORM (a line square to the contour)")),
                "CUT3DC" | "CUT3DCC" | "CUT3DCCD" | "CUT3DF" | "CUT3DFF" | "CUT3DFS" | "CUT3DFD" => self.unknown(row, span, format!("{command}: 3-D tool radius compensation is not modelled: the run compensates in the plane (CUT2D)")),
                "ORIWKS" => self.turning.workpiece = true,
                "ORIMKS" => {
                    self.turning.workpiece = false;
                    self.unknown(row, span, "ORIMKS: orientation vectors in the machine's coordinates are not modelled; the run reads them in the work's (ORIWKS)".into());
                }
                "ORIAXES" => self.turning.g_code = Some(traori::Way::Axes),
                "ORIVECT" | "ORIPLANE" => self.turning.g_code = Some(traori::Way::GreatCircle),
                "ORICONCW" | "ORICONCCW" | "ORICONIO" | "ORICONTO" | "ORICURVE" => self.unknown(row, span, format!("{command}: the control turns the tool on a cone or a curve between a block's ends; the run turns it on a great circle")),
                name => {
                    if let Some(group) = DYNAMIC_GROUPS.iter().position(|g| *g == name) {
                        self.modes.dynamic_group = group;
                    }
                }
            }
        }
        // A bare name calls a subprogram unless the control knows it.
        let commands = content
            .commands
            .iter()
            .filter(|name| call_kind(name) == CallKind::Subprogram || name.starts_with("CYCLE"))
            .map(|name| (name.clone(), Arguments::default()));
        called.extend(content.calls.into_iter().chain(commands));
        self.given_times(&content.words, &called);
        for (name, arguments) in called {
            match name.as_str() {
                "CYCLE800" => self.cycle800(row, span, &arguments.values),
                "TRAORI" => self.traori(row, span, &arguments.values),
                // What moves nothing: messages, settings, the control's own procedures.
                "CYCLE832" => self.cycle832(row, span, &arguments.values),
                "MSG" | "STOPRE" => {}
                _ if crate::semantic::calls::is_predefined(&name) => self.unknown(
                    row,
                    span,
                    format!("`{name}`: the control's own procedure is not run offline: what it sets or changes is not in the run"),
                ),
                _ if self.calling.is_some() => self.unknown(
                    row,
                    span,
                    format!("`{name}`: a second call in one block is not followed"),
                ),
                _ => {
                    self.calling = Some(Calling {
                        name,
                        arguments,
                        times,
                    })
                }
            }
        }
        if let Some((kind, words)) = content.frame {
            self.frame_statement(row, span, kind, &words);
        }
        if changes_tool {
            self.tool = self.preselected;
            self.variables.set_channel("$P_TOOLNO", self.tool);
            if let (Some(d), true) = (self.setup.default_edge, self.tool.is_some()) {
                self.edge = Some(d);
                self.variables.set_channel("$P_TOOL", self.edge);
            }
        }
        if dwell {
            match dwell_value {
                Some(Ok(seconds)) => self.add_time(seconds, Some(seconds)),
                Some(Err(why)) => self.unknown(row, span, format!("the dwell's time: {why}")),
                None => {}
            }
        }
        if let Some(kind) = pole {
            self.define_pole(row, span, kind, &mut targets, (&ap, &rp));
        } else if ap.is_some() || rp.is_some() {
            self.polar_move(row, span, (&ap, &rp), &mut targets, &mut centre);
        }
        self.by_vector = orientation.iter().any(Option::is_some);
        if self.by_vector {
            self.orientation_vector(row, span, &orientation, &mut targets);
        }
        let circular = matches!(
            self.modes.motion,
            Motion::Clockwise | Motion::Counterclockwise
        );
        let by_centre = circular && shape.opening.is_some() && centre.iter().any(Option::is_some);
        if by_centre && !self.end_of_opening(row, span, &mut targets, &centre, &mut shape) {
            targets.iter_mut().take(3).for_each(|target| *target = None);
            centre = [None, None, None];
        }
        let moves = targets.iter().any(Option::is_some);
        if moves {
            self.motion_block(
                row,
                span,
                &targets,
                &centre,
                &shape,
                suppress_frames,
                exact_here,
            );
        }
        // The modal call follows a block that moves (Siemens, Programming
        // Manual, "Subprogram technique", "Modal subprogram call (MCALL)":
        // after each block with path motion), not the block that sets it,
        // and not the moves of the subprogram it calls.
        if let Some(modal) = &self.modal_call {
            if moves && self.calling.is_none() && self.level() == modal.level {
                self.calling = Some(Calling {
                    name: modal.name.clone(),
                    arguments: modal.arguments.clone(),
                    times: 1,
                });
            }
        }
        if let Some(modal) = content.modal {
            self.modal_call = modal;
        }
        if ends {
            Flow::End
        } else {
            Flow::Next
        }
    }

    /// CYCLE832's machining type (`S_TOLM`'s units digit) as the dynamic
    /// response the standard cycle selects: 0 (or no arguments) DYNNORM,
    /// 1 finishing DYNFINISH, 2 semi-finishing DYNSEMIFIN, 3 roughing
    /// DYNROUGH; said among the assumptions, since a machine builder's
    /// CUST_832 may choose otherwise.
    fn cycle832(&mut self, row: usize, span: Span, arguments: &[Option<Value>]) {
        const ASSUMED: &str = "CYCLE832 selects the dynamic response as the standard cycle does (S_TOLM 0 DYNNORM, 1 DYNFINISH, 2 DYNSEMIFIN, 3 DYNROUGH); a machine builder's CUST_832 may choose otherwise";
        let machining = match arguments.get(1) {
            None => Some(0.0),
            Some(Some(Value::Number(tolm))) => Some(tolm.abs() % 10.0),
            Some(_) => None,
        };
        let group = match machining.map(|m| m as u32) {
            Some(0) => Some(0),
            Some(1) => Some(4),
            Some(2) => Some(3),
            Some(3) => Some(2),
            _ => None,
        };
        match group {
            Some(group) => {
                self.modes.dynamic_group = group;
                if !self.report.assumptions.iter().any(|a| a == ASSUMED) {
                    self.report.assumptions.push(ASSUMED.to_string());
                }
            }
            None => self.unknown(row, span, "CYCLE832's machining type (S_TOLM) is unknown offline or not 0 to 3: the dynamic response is left as it was".into()),
        }
    }

    /// The modal call `MCALL` sets with the text at `target`, its arguments
    /// evaluated now; `None`, named, where it is not followed.
    fn modal_call(&mut self, row: usize, span: Span, target: Span) -> Option<ModalCall> {
        let Some((name, statement)) = crate::run::programs::modal_call(self.source, target) else {
            self.unknown(row, span, "MCALL's program is read at run time (a path or an expression): the modal call is not followed".into());
            return None;
        };
        if !self.programs.subprograms.contains_key(&name) {
            self.unknown(row, span, format!("`{name}`, called by MCALL after each block that moves, is not followed: no subprogram of that name beside the program or in the cycle directories (--cycles); what it moves, and its time, are not in the run"));
            return None;
        }
        let arguments = match &statement.kind {
            StatementKind::Call(call) => Arguments::of(self.source, call, &self.variables),
            _ => Arguments::default(),
        };
        Some(ModalCall {
            name,
            arguments,
            level: self.level(),
        })
    }

    /// The program level running: the subprograms entered, not the
    /// sections of a program repeated (REPEAT), which run at its level.
    fn level(&self) -> usize {
        self.stack.iter().filter(|r| r.section.is_none()).count()
    }

    /// The blocks finished since last told, in the order they ran.
    fn tell(&mut self, each: &mut impl FnMut(BlockEnd)) {
        for told in std::mem::take(&mut self.compensation.told) {
            each(BlockEnd {
                program: told.program.as_deref(),
                line: told.line,
                mcs: &told.mcs,
                t_s: told.t_s,
                arc: told.arc.as_ref(),
            });
        }
    }

    fn finish(mut self) -> Report {
        // An axis that moved with no machine axis behind it: nothing held
        // it to limits, and the run says so rather than pass in silence.
        for k in 0..self.setup.axes.len() {
            let axis = &self.setup.axes[k];
            if self.minimum[k].is_some() && axis.machine.is_none() {
                let name = axis.name.clone();
                self.note(format!("axis `{name}` moves, and the machine's data tie it to no machine axis (MD20050, MD20070, MD20080, MD10000): its limits and dynamics are not known"));
            }
        }
        let mut report = std::mem::take(&mut self.report);
        report.violations = std::mem::take(&mut self.violations);
        report.violations.sort_by_key(|v| v.line);
        report.axes = self
            .setup
            .axes
            .iter()
            .enumerate()
            .filter(|&(k, _)| {
                let absent = self.setup.absent_geometry.get(k).copied().unwrap_or(false);
                !absent || self.minimum[k].is_some()
            })
            .map(|(k, axis)| Travel {
                axis: axis.machine_name(),
                min: self.minimum[k],
                max: self.maximum[k],
                limits: axis.limits(self.options.second_limits),
            })
            .collect();
        report.tools = self
            .tool_times
            .iter()
            .map(|(t, time)| ToolTime {
                t: t.clone(),
                time_s: *time,
            })
            .collect();
        if !self.upper_complete {
            report.time_bounds_s[1] = f64::NAN;
        }
        report
    }
}

/// Closing row to opening row, of a program's control blocks.
fn openers(model: &Model) -> HashMap<usize, usize> {
    model
        .blocks
        .closed()
        .iter()
        .map(|c| (c.end, c.row))
        .collect()
}
