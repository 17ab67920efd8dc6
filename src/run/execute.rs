//! The interpreter: one block after another in the order the control runs
//! them, the modal state it keeps, and what each block's motion does on the
//! machine (see the module above for what is modelled).

use std::borrow::Cow;
use std::collections::{BTreeMap, HashMap, HashSet};

use nalgebra::{Rotation3, Vector3};

use crate::run::arc::Arc;
use crate::run::frame::{rpy, Frame};
use crate::run::profile::{rest_to_rest, Limits};
use crate::run::setup::Setup;
use crate::run::{
    BlockEnd, Options, Programs, Report, Side, ToolTime, Travel, Unknown, Violation,
    MOST_VIOLATIONS,
};
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
        each(BlockEnd {
            program: machine.program.as_deref(),
            line: row + 1,
            mcs: &machine.mcs,
            t_s: machine.report.time_s,
            arc: machine.last_arc.take().as_ref(),
        });
        let next = match flow {
            Flow::Next => row + 1,
            Flow::To(next) => next,
            Flow::End => match machine.give_back() {
                Some(back) => back,
                None => break,
            },
        };
        row = match machine.calling.take() {
            Some(call) => machine.enter(row, call, next),
            None => next,
        };
    }
    machine.finish()
}

/// Where the run goes after a block.
enum Flow {
    Next,
    To(usize),
    End,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Motion {
    Rapid,
    Linear,
    Clockwise,
    Counterclockwise,
}

#[derive(Clone, Copy, PartialEq, Eq)]
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
    calls: Vec<(String, Vec<Option<Value>>)>,
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
    known: &'a Supplied,
}

impl Lookup for Variables<'_> {
    fn variable(&self, key: &str) -> Result<Value, Missing> {
        if let Some(value) = self.local.get(key) {
            return Ok(value.clone());
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

/// A subprogram's call: what it is given, and how often it runs.
struct Calling {
    name: String,
    arguments: Vec<Option<Value>>,
    times: u32,
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
    arguments: Vec<Option<Value>>,
}

/// The most program levels the control nests: the main program and 15
/// subprograms (Siemens, Programming Manual Fundamentals, "Nesting depth").
const MOST_LEVELS: usize = 16;

struct Interpreter<'a, 'src> {
    programs: &'a Programs<'src>,
    model: &'a Model<'src>,
    stack: Vec<Return<'a, 'src>>,
    /// The subprogram running, by name; `None` in the main program.
    program: Option<String>,
    /// The call the block just run makes, entered after it.
    calling: Option<Calling>,
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
    /// The frames' rotation at the last move.
    last_rotation: Rotation3<f64>,
    motion: Motion,
    incremental: bool,
    /// 0: G17 (XY, infeed Z), 1: G18 (ZX, infeed Y), 2: G19 (YZ, infeed X).
    plane: usize,
    /// Program lengths to the machine's: 25.4 for G70/G700 on a metric machine.
    length_scale: f64,
    /// Feeds too (G700, G710).
    feed_scale: f64,
    feed_mode: FeedMode,
    /// As programmed, per minute (or per revolution, or inverse time).
    feed: Option<f64>,
    spindle: Option<f64>,
    exact_stop: bool,
    soft: bool,
    /// G0 interpolates linearly (RTLION) or each axis on its own (RTLIOF).
    rapid_linear: bool,
    settable: Frame,
    programmable: Frame,
    preselected: Option<u32>,
    tool: Option<u32>,
    edge: Option<u32>,
    /// The MD10600 rotation order is known (RPY) or a rotation is about one axis.
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
        report.assumptions.push(
            "at the start: no frame, no tool, G0 G17 G90 G94 G71 (metric), G64 continuous path, BRISK; positions unknown until programmed".to_string(),
        );
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
        Interpreter {
            programs,
            model,
            stack: Vec::new(),
            program: None,
            calling: None,
            last_arc: None,
            source: model.source,
            setup,
            options,
            variables: Variables {
                local: HashMap::new(),
                known,
            },
            openers,
            in_for: HashSet::new(),
            mcs: vec![None; axes],
            programmed: vec![None; axes],
            last_rotation: Rotation3::identity(),
            motion: Motion::Rapid,
            incremental: false,
            plane: 0,
            length_scale: 1.0,
            feed_scale: 1.0,
            feed_mode: FeedMode::PerMinute,
            feed: None,
            spindle: None,
            exact_stop: false,
            soft: false,
            rapid_linear: true,
            settable: Frame::identity(axes),
            programmable: Frame::identity(axes),
            preselected: None,
            tool: None,
            edge: None,
            report,
            told: HashSet::new(),
            minimum: vec![None; axes],
            maximum: vec![None; axes],
            violations: Vec::new(),
            beyond: HashMap::new(),
            began: HashMap::new(),
            tool_times: BTreeMap::new(),
            upper_complete: true,
            words: Vec::with_capacity(16),
        }
    }

    /// Into the subprogram `call` names, from the block on `row`: where
    /// the run goes on (`next` where it is not followed).
    fn enter(&mut self, row: usize, call: Calling, next: usize) -> usize {
        let span = self.model.lines.raw(row).content;
        let Some(callee) = self.programs.subprograms.get(&call.name) else {
            self.unknown(row, span, format!("`{}` is not followed: no subprogram of that name beside the program or in the cycle directories (--cycles); what it moves, and its time, are not in the run", call.name));
            return next;
        };
        if self.stack.len() + 1 >= MOST_LEVELS {
            self.unknown(row, span, format!("`{}` would nest deeper than {MOST_LEVELS} program levels: the control stops with an alarm (14000s); not followed", call.name));
            return next;
        }
        let caller = Return {
            model: self.model,
            program: self.program.replace(call.name.clone()),
            row: next,
            locals: std::mem::take(&mut self.variables.local),
            openers: std::mem::replace(&mut self.openers, openers(callee)),
            in_for: std::mem::take(&mut self.in_for),
            again: call.times.saturating_sub(1),
            arguments: call.arguments,
        };
        self.model = callee;
        self.source = callee.source;
        self.variables.local = globals(&caller.locals);
        self.bind(&caller.arguments);
        self.stack.push(caller);
        0
    }

    /// The PROC line's parameters of the program now running, given
    /// `arguments` (by position; one not given or unknown stays unknown).
    fn bind(&mut self, arguments: &[Option<Value>]) {
        let source = self.source;
        let Some(parameters) = self
            .model
            .lines
            .other_lines()
            .take(50)
            .find_map(|(_, line)| {
                let LineKind::Block(block) = &line.kind else {
                    return None;
                };
                block.statements.iter().find_map(|s| match &s.kind {
                    StatementKind::Proc(proc) => Some(
                        proc.parameters
                            .iter()
                            .map(|p| p.declarator.name.upper(source))
                            .collect::<Vec<_>>(),
                    ),
                    _ => None,
                })
            })
        else {
            return;
        };
        for (name, value) in parameters.into_iter().zip(arguments) {
            if let Some(value) = value {
                self.variables.local.insert(key(&name, &[]), value.clone());
            }
        }
    }

    /// Back from a subprogram at its end (M17, RET, M2, M30 or its last
    /// line), or into it again while its `P` asks: where the caller goes on;
    /// `None` at the main program's end. R parameters are the channel's:
    /// what the subprogram wrote, the caller reads.
    fn give_back(&mut self) -> Option<usize> {
        let mut caller = self.stack.pop()?;
        let written = std::mem::take(&mut self.variables.local);
        if caller.again > 0 {
            caller.again -= 1;
            self.variables.local = globals(&written);
            self.in_for.clear();
            let arguments = std::mem::take(&mut caller.arguments);
            self.bind(&arguments);
            caller.arguments = arguments;
            self.stack.push(caller);
            return Some(0);
        }
        self.variables.local = caller.locals;
        self.variables.local.extend(globals(&written));
        self.model = caller.model;
        self.program = caller.program;
        self.source = caller.model.source;
        self.openers = caller.openers;
        self.in_for = caller.in_for;
        Some(caller.row)
    }

    fn unknown(&mut self, row: usize, span: Span, why: String) {
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
                    let arguments = call
                        .arguments
                        .items
                        .iter()
                        .map(|a| {
                            let value = a.value.as_ref()?;
                            evaluate(source, value, &self.variables).ok()
                        })
                        .collect();
                    content.calls.push((call.name.upper(source), arguments));
                }
                StatementKind::IndirectCall { keyword, target } => {
                    let keyword = keyword.upper(source);
                    // `CALL "NAME"`: the name as a string written out.
                    let named =
                        target.map(|t| String::from_utf8_lossy(t.of(source)).trim().to_string());
                    match named.as_deref().and_then(|t| t.strip_prefix('"')?.strip_suffix('"')) {
                        Some(name) if keyword == "CALL" => {
                            content.calls.push((name.to_ascii_uppercase(), Vec::new()));
                        }
                        _ => self.unknown(row, statement.span, format!("{keyword} is not followed (a modal, external or computed call): what it moves, and its time, are not in the run")),
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
                StatementKind::Repeat { .. } => {
                    self.unknown(row, statement.span, "REPEAT of a section is not followed: the section runs once where it stands".to_string());
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
            Flow::End => Flow::End,
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
            Some(landing) => Flow::To(landing),
            None if kind == GotoKind::Conditional => Flow::Next,
            None => {
                self.unknown(
                    row,
                    span,
                    "the jump's target is not found: the control stops with an alarm here"
                        .to_string(),
                );
                Flow::End
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
        let mut dwell = false;
        let mut exact_here = false;
        let mut suppress_frames = false;
        let mut ends = false;
        let mut changes_tool = false;
        let mut targets: Vec<Option<(Result<f64, String>, Coordinate)>> =
            vec![None; self.setup.axes.len()];
        let mut centre: [Option<(Result<f64, String>, Coordinate)>; 3] = [None, None, None];
        let mut radius = None;
        let mut dwell_value = None;
        let mut called: Vec<(String, Vec<Option<Value>>)> = Vec::new();
        let mut times = 1;
        for word in &content.words {
            let value = &word.value;
            match word.name.as_ref() {
                "G" => {
                    let Ok(g) = value else {
                        self.unknown(row, span, "a G function's number is unknown offline".into());
                        continue;
                    };
                    match *g as u32 {
                        0 => self.motion = Motion::Rapid,
                        1 => self.motion = Motion::Linear,
                        2 => self.motion = Motion::Clockwise,
                        3 => self.motion = Motion::Counterclockwise,
                        4 => dwell = true,
                        9 => exact_here = true,
                        17 => self.plane = 0,
                        18 => self.plane = 1,
                        19 => self.plane = 2,
                        41 | 42 => self.note("cutter radius compensation (G41/G42) is not modelled: positions are the programmed contour's".into()),
                        53 | 153 => suppress_frames = true,
                        500 => self.settable = Frame::identity(self.setup.axes.len()),
                        54..=57 | 505..=599 => self.select_frame(row, span, *g as u32),
                        60 => self.exact_stop = true,
                        64 | 641..=645 => self.exact_stop = false,
                        70 | 700 | 71 | 710 => self.units(row, span, *g as u32),
                        90 => self.incremental = false,
                        91 => self.incremental = true,
                        93 => self.feed_mode = FeedMode::InverseTime,
                        94 => self.feed_mode = FeedMode::PerMinute,
                        95 => self.feed_mode = FeedMode::PerRevolution,
                        110..=112 => self.unknown(row, span, "polar coordinates (G110-G112) are not modelled".into()),
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
                    Ok(f) => self.feed = Some(*f),
                    Err(why) => {
                        self.feed = None;
                        self.unknown(row, span, format!("the feed is {why}"));
                    }
                },
                "S" | "S1" => match value {
                    Ok(s) if dwell => {
                        dwell_value =
                            Some(match self.spindle {
                                Some(speed) if speed > 0.0 => Ok(s * 60.0 / speed),
                                _ => Err("a dwell in spindle revolutions without a known speed"
                                    .to_string()),
                            })
                    }
                    Ok(s) => self.spindle = Some(*s),
                    Err(_) => self.spindle = None,
                },
                "I" | "J" | "K" => {
                    let k = (word.name.as_bytes()[0] - b'I') as usize;
                    centre[k] = Some((value.clone(), word.coordinate));
                }
                "CR" => radius = Some(value.clone()),
                "AR" | "AP" | "RP" => self.unknown(
                    row,
                    span,
                    format!(
                        "`{}` (an arc by its angle, polar coordinates) is not modelled",
                        word.name
                    ),
                ),
                "TURN" => self.unknown(
                    row,
                    span,
                    "TURN (a helix's full turns) is not modelled".into(),
                ),
                name if is_numbered_call(name) => called.push((name.to_string(), Vec::new())),
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
                "BRISK" => self.soft = false,
                "SOFT" => self.soft = true,
                "SUPA" => suppress_frames = true,
                "RTLION" => self.rapid_linear = true,
                "RTLIOF" => self.rapid_linear = false,
                "TRAORI" | "TRANSMIT" | "TRACYL" | "TRACON" | "TRAANG" => self.unknown(row, span, format!("{command} (a kinematic transformation) is not modelled yet: the positions after it are of the axes as programmed")),
                "TRAFOOF" => {}
                _ => {}
            }
        }
        // A bare name calls a subprogram unless the control knows it.
        let commands = content
            .commands
            .iter()
            .filter(|name| call_kind(name) == CallKind::Subprogram || name.starts_with("CYCLE"))
            .map(|name| (name.clone(), Vec::new()));
        called.extend(content.calls.into_iter().chain(commands));
        self.given_times(&content.words, &called);
        for (name, arguments) in called {
            match name.as_str() {
                "CYCLE800" => self.unknown(row, span, "CYCLE800 (a swivel) is not modelled yet in the run: the rotary axes and frames it sets are not applied".into()),
                // What moves nothing: messages, settings, the control's own procedures.
                "MSG" | "CYCLE832" | "STOPRE" => {}
                _ if crate::semantic::calls::is_predefined(&name) => {}
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
            if let (Some(d), true) = (self.setup.default_edge, self.tool.is_some()) {
                self.edge = Some(d);
            }
        }
        if dwell {
            match dwell_value {
                Some(Ok(seconds)) => self.add_time(seconds, Some(seconds)),
                Some(Err(why)) => self.unknown(row, span, format!("the dwell's time: {why}")),
                None => {}
            }
        }
        let moves = targets.iter().any(Option::is_some);
        if moves {
            self.motion_block(
                row,
                span,
                &targets,
                &centre,
                radius,
                suppress_frames,
                exact_here,
            );
        }
        if ends {
            Flow::End
        } else {
            Flow::Next
        }
    }

    fn units(&mut self, row: usize, span: Span, g: u32) {
        let inch = matches!(g, 70 | 700);
        let scale = match (self.setup.metric, inch) {
            (Some(true), true) => 25.4,
            (Some(false), false) => 1.0 / 25.4,
            (Some(_), _) => 1.0,
            (None, _) => {
                self.unknown(row, span, "G70/G71: the machine's system of units (MD10240) is not in its data: lengths taken as they are written".into());
                1.0
            }
        };
        self.length_scale = scale;
        self.feed_scale = if matches!(g, 700 | 710) { scale } else { 1.0 };
    }

    /// G54..G57, G505..G599: the settable frame the machine's data hold.
    fn select_frame(&mut self, row: usize, span: Span, g: u32) {
        let name = format!("G{g}");
        let Some(components) = self.setup.frames.get(&name) else {
            self.unknown(
                row,
                span,
                format!("{name}: the machine's data hold no such frame (`$P_UIFR`): taken as zero"),
            );
            self.settable = Frame::identity(self.setup.axes.len());
            return;
        };
        let mut frame = Frame::identity(self.setup.axes.len());
        let mut angles = [0.0; 3];
        for (axis, c) in components {
            let Some(at) = self.setup.axis(axis) else {
                self.unknown(
                    row,
                    span,
                    format!("{name} moves axis `{axis}`, which is no axis of the channel"),
                );
                continue;
            };
            frame.translation[at] = c.tr.unwrap_or(0.0) + c.fi.unwrap_or(0.0);
            if let Some(g) = self.setup.axes[at].geometry {
                angles[g] = c.rt.unwrap_or(0.0);
            }
            if c.sc.is_some_and(|s| s != 1.0) || c.mi.is_some_and(|m| m != 0.0) {
                self.unknown(
                    row,
                    span,
                    format!("{name}: scale and mirror of a frame are not modelled"),
                );
            }
        }
        frame.rotation = self.rotation(row, span, angles);
        self.settable = frame;
    }

    /// A rotation by RPY angles; with more than one axis, MD10600 decides
    /// the order, RPY where the data say so.
    fn rotation(&mut self, row: usize, span: Span, angles: [f64; 3]) -> Rotation3<f64> {
        if angles.iter().filter(|a| **a != 0.0).count() > 1 {
            match self.setup.angles_rpy {
                Some(true) => {}
                Some(false) => self.unknown(row, span, "a rotation about several axes in Euler angles (MD10600 = 2) is not modelled: taken as RPY (Z, Y', X'')".into()),
                None => self.unknown(row, span, "a rotation about several axes, and MD10600 (RPY or Euler) not in the machine's data: taken as RPY (Z, Y', X'')".into()),
            }
        }
        rpy(angles)
    }

    fn frame_statement(&mut self, row: usize, span: Span, kind: FrameKind, words: &[Word]) {
        let axes = self.setup.axes.len();
        let mut values = vec![0.0; axes];
        let mut angles = [0.0; 3];
        let mut in_plane = None;
        for word in words {
            let Ok(value) = word.value else {
                self.unknown(
                    row,
                    span,
                    format!("the frame's `{}` is unknown offline: taken as 0", word.name),
                );
                continue;
            };
            if word.name == "RPL" {
                in_plane = Some(value);
                continue;
            }
            match self.setup.axis(&word.name) {
                Some(at) => {
                    values[at] = value;
                    if let Some(g) = self.setup.axes[at].geometry {
                        angles[g] = value;
                    }
                }
                None => self.unknown(
                    row,
                    span,
                    format!("`{}` is no axis of the channel", word.name),
                ),
            }
        }
        if let Some(angle) = in_plane {
            angles = [0.0; 3];
            angles[[2, 1, 0][self.plane]] = angle;
        }
        match kind {
            FrameKind::Trans => {
                self.programmable = Frame::identity(axes);
                self.programmable.translation = values.iter().map(|v| v * self.length_scale).collect();
            }
            FrameKind::ATrans => {
                let geometry = Vector3::new(values[0], values[1], values[2]) * self.length_scale;
                let turned = self.programmable.turn(geometry);
                for (k, v) in values.iter().enumerate() {
                    self.programmable.translation[k] += if k < 3 { turned[k] } else { *v };
                }
            }
            FrameKind::Rot => {
                self.programmable = Frame::identity(axes);
                self.programmable.rotation = self.rotation(row, span, angles);
            }
            FrameKind::ARot => {
                let rotation = self.rotation(row, span, angles);
                self.programmable.rotation *= rotation;
            }
            other => self.unknown(row, span, format!("{other:?} (a frame's scale, mirror or solid-angle rotation) is not modelled: the frame is left as it was")),
        }
    }

    /// The tool's length along the infeed axis of the plane, in the machine.
    fn tool_offset(&mut self, row: usize, span: Span) -> [f64; 3] {
        let mut offset = [0.0; 3];
        let (Some(t), Some(d)) = (self.tool, self.edge) else {
            return offset;
        };
        if d == 0 {
            return offset;
        }
        let Some(tool) = self.setup.tool(t, d) else {
            self.unknown(row, span, format!("T{t} D{d}: the machine's data hold no offsets for it (`$TC_DP`): its length taken as 0"));
            return offset;
        };
        let milling = tool.kind.is_none_or(|k| (100.0..300.0).contains(&k));
        if !milling {
            self.unknown(row, span, format!("T{t} D{d}: tool type {} (not a milling or drilling tool) is not modelled: its length taken as 0", tool.kind.unwrap_or(0.0)));
            return offset;
        }
        let length = tool.length[0].unwrap_or(0.0) + tool.length_wear[0].unwrap_or(0.0);
        offset[[2, 1, 0][self.plane]] = length;
        offset
    }

    /// The machine position of the programmed point `wcs`.
    fn to_machine(&self, wcs: &[Option<f64>], suppress: bool, tool: [f64; 3]) -> Vec<Option<f64>> {
        let mut at = if suppress {
            wcs.to_vec()
        } else {
            self.settable.apply(&self.programmable.apply(wcs))
        };
        for (k, length) in tool.iter().enumerate() {
            at[k] = at[k].map(|v| v + length);
        }
        at
    }

    /// The programmed point of the machine position `mcs`.
    fn to_program(&self, mcs: &[Option<f64>], suppress: bool, tool: [f64; 3]) -> Vec<Option<f64>> {
        let mut at = mcs.to_vec();
        for (k, length) in tool.iter().enumerate() {
            at[k] = at[k].map(|v| v - length);
        }
        if suppress {
            return at;
        }
        let back = |frame: &Frame, point: Vec<Option<f64>>| -> Vec<Option<f64>> {
            let mut out: Vec<Option<f64>> = point
                .iter()
                .zip(&frame.translation)
                .map(|(p, t)| p.map(|p| p - t))
                .collect();
            if frame.rotation != Rotation3::identity() {
                match (out[0], out[1], out[2]) {
                    (Some(x), Some(y), Some(z)) => {
                        let r = frame.rotation.inverse() * Vector3::new(x, y, z);
                        out[0] = Some(r.x);
                        out[1] = Some(r.y);
                        out[2] = Some(r.z);
                    }
                    _ => {
                        out[0] = None;
                        out[1] = None;
                        out[2] = None;
                    }
                }
            }
            out
        };
        back(&self.programmable, back(&self.settable, at))
    }

    #[allow(clippy::too_many_arguments)]
    fn motion_block(
        &mut self,
        row: usize,
        span: Span,
        targets: &[Option<(Result<f64, String>, Coordinate)>],
        centre: &[Option<(Result<f64, String>, Coordinate)>; 3],
        radius: Option<Result<f64, String>>,
        suppress: bool,
        exact_here: bool,
    ) {
        let tool = self.tool_offset(row, span);
        let start_mcs = self.mcs.clone();
        // Where the program left each axis; in machine coordinates less the
        // tool for a block that suppresses the frames (G53, G153, SUPA).
        let start = if suppress {
            self.to_program(&start_mcs, true, tool)
        } else {
            self.programmed.clone()
        };
        let mut end = start.clone();
        for (k, target) in targets.iter().enumerate() {
            let Some((value, coordinate)) = target else {
                continue;
            };
            let scale = if self.setup.axes[k].rotary() {
                1.0
            } else {
                self.length_scale
            };
            end[k] = match value {
                Ok(v) => {
                    let incremental = match coordinate {
                        Coordinate::Modal => self.incremental,
                        Coordinate::Absolute => false,
                        Coordinate::Incremental => true,
                    };
                    if incremental {
                        start[k].map(|s| s + v * scale)
                    } else {
                        Some(v * scale)
                    }
                }
                Err(why) => {
                    self.unknown(
                        row,
                        span,
                        format!("axis `{}`: its position is {why}", self.setup.axes[k].name),
                    );
                    None
                }
            };
        }
        // A changed frame or tool is traversed with the next move of the
        // axes it concerns (MD42440, MD42442 at their defaults): an axis not
        // programmed stays where it is; where the frames' rotation changed,
        // the geometry axes go together, as the rotation couples them.
        let reached = self.to_machine(&end, suppress, tool);
        let rotation = if suppress {
            Rotation3::identity()
        } else {
            self.settable.rotation * self.programmable.rotation
        };
        let coupled = rotation != self.last_rotation && targets.iter().take(3).any(Option::is_some);
        self.last_rotation = rotation;
        let end_mcs: Vec<Option<f64>> = (0..reached.len())
            .map(|k| {
                if targets[k].is_some() || (k < 3 && coupled) {
                    reached[k]
                } else {
                    start_mcs[k]
                }
            })
            .collect();
        self.programmed = if suppress {
            self.to_program(&end_mcs, false, tool)
        } else {
            end.clone()
        };
        // The arc, in the machine's coordinates.
        let arc = match self.motion {
            Motion::Clockwise | Motion::Counterclockwise => {
                self.arc(row, span, &start, &end, centre, radius, suppress, tool)
            }
            _ => None,
        };
        self.last_arc = arc;
        // Limits and travel: the ends, and the arc's turning points. Where
        // the block traverses a changed offset, the arc's start under the new
        // one too: the path lies between the arc under the old offset and
        // under the new, which holds its extremes.
        let mut points = vec![end_mcs.clone()];
        if let Some(arc) = &arc {
            for k in 0..3 {
                let start = std::iter::once(arc.point(0.0));
                for point in arc.turning_points(k).into_iter().chain(start) {
                    let mut at = end_mcs.clone();
                    at[0] = Some(point.x);
                    at[1] = Some(point.y);
                    at[2] = Some(point.z);
                    points.push(at);
                }
            }
        }
        let mut out = HashSet::new();
        for point in &points {
            self.check(row, span, point, &mut out);
        }
        // An axis back within its limits ends its excursion.
        self.beyond.retain(|key, _| out.contains(key));
        // Time.
        let moved: Vec<(usize, f64)> = start_mcs
            .iter()
            .zip(&end_mcs)
            .enumerate()
            .filter_map(|(k, (a, b))| match (a, b) {
                (Some(a), Some(b)) if (b - a).abs() > 1e-12 => Some((k, b - a)),
                _ => None,
            })
            .collect();
        // An axis whose start or end is unknown: how far it goes is unknown.
        let timed = start_mcs
            .iter()
            .zip(&end_mcs)
            .all(|(a, b)| a.is_some() == b.is_some());
        self.mcs = end_mcs;
        if !timed {
            self.report.blocks_without_time += 1;
            self.unknown(row, span, "where the axes were before this block is unknown (the program's start, or a value unknown offline): its time is not counted".into());
            return;
        }
        if moved.is_empty() && arc.is_none() {
            return;
        }
        self.time(row, span, &moved, arc.as_ref(), exact_here);
    }

    #[allow(clippy::too_many_arguments)]
    fn arc(
        &mut self,
        row: usize,
        span: Span,
        start: &[Option<f64>],
        end: &[Option<f64>],
        centre: &[Option<(Result<f64, String>, Coordinate)>; 3],
        radius: Option<Result<f64, String>>,
        suppress: bool,
        tool: [f64; 3],
    ) -> Option<Arc> {
        let point = |p: &[Option<f64>]| Some(Vector3::new(p[0]?, p[1]?, p[2]?));
        let (Some(s), Some(e)) = (point(start), point(end)) else {
            self.unknown(
                row,
                span,
                "an arc from or to a point unknown offline: its travel is not checked".into(),
            );
            return None;
        };
        let applicate = [2, 1, 0][self.plane];
        let mut normal = Vector3::zeros();
        normal[applicate] = if self.motion == Motion::Clockwise {
            -1.0
        } else {
            1.0
        };
        let c = match (centre.iter().any(Option::is_some), radius) {
            (true, _) => {
                let mut c = s;
                for (k, given) in centre.iter().enumerate() {
                    match given {
                        Some((Ok(v), Coordinate::Absolute)) => c[k] = v * self.length_scale,
                        Some((Ok(v), _)) => c[k] = s[k] + v * self.length_scale,
                        Some((Err(why), _)) => {
                            self.unknown(row, span, format!("the arc's centre is {why}"));
                            return None;
                        }
                        None => {}
                    }
                }
                c
            }
            (false, Some(Ok(r))) => {
                match Arc::centre_of_radius(s, e, r * self.length_scale, normal) {
                    Some(c) => c,
                    None => {
                        self.unknown(row, span, "the arc's radius is smaller than half the way from start to end: the control stops with an alarm (14045)".into());
                        return None;
                    }
                }
            }
            (false, Some(Err(why))) => {
                self.unknown(row, span, format!("the arc's radius is {why}"));
                return None;
            }
            (false, None) => {
                self.unknown(
                    row,
                    span,
                    "an arc without its centre (I, J, K) or radius (CR=)".into(),
                );
                return None;
            }
        };
        let arc = Arc::through(s, e, c, normal)?;
        // Into the machine: the frames turn and shift the arc, the tool shifts it.
        let to_machine = |p: Vector3<f64>| -> Vector3<f64> {
            let mut wcs: Vec<Option<f64>> = vec![Some(0.0); self.setup.axes.len()];
            wcs[0] = Some(p.x);
            wcs[1] = Some(p.y);
            wcs[2] = Some(p.z);
            let at = self.to_machine(&wcs, suppress, tool);
            Vector3::new(
                at[0].unwrap_or(0.0),
                at[1].unwrap_or(0.0),
                at[2].unwrap_or(0.0),
            )
        };
        let origin = to_machine(Vector3::zeros());
        let turn = |d: Vector3<f64>| to_machine(d) - origin;
        Some(Arc {
            centre: to_machine(arc.centre),
            u: turn(arc.u),
            v: turn(arc.v),
            normal: turn(arc.normal),
            sweep: arc.sweep,
            rise: arc.rise,
        })
    }

    /// Every position of `point` against its axis's software limits, and
    /// the travel's extent.
    fn check(
        &mut self,
        row: usize,
        span: Span,
        point: &[Option<f64>],
        out: &mut HashSet<(usize, bool)>,
    ) {
        for (k, value) in point.iter().enumerate() {
            let Some(value) = *value else { continue };
            self.minimum[k] = Some(self.minimum[k].map_or(value, |m| m.min(value)));
            self.maximum[k] = Some(self.maximum[k].map_or(value, |m| m.max(value)));
            let axis = &self.setup.axes[k];
            let limits = if self.options.second_limits {
                axis.machine.as_ref().map_or([None, None], |m| m.limits2)
            } else {
                axis.limits()
            };
            for (side, limit) in [(Side::Minus, limits[0]), (Side::Plus, limits[1])] {
                let Some(limit) = limit else { continue };
                let past = match side {
                    Side::Minus => value < limit,
                    Side::Plus => value > limit,
                };
                if !past {
                    continue;
                }
                let key = (k, side == Side::Plus);
                out.insert(key);
                let known = self
                    .beyond
                    .get(&key)
                    .or_else(|| {
                        self.began
                            .get(&(self.program.clone(), row, k, side == Side::Plus))
                    })
                    .copied();
                match known {
                    // Counted once an excursion, not listed.
                    Some(UNTOLD) => {
                        self.beyond.insert(key, UNTOLD);
                    }
                    Some(at) => {
                        let violation = &mut self.violations[at];
                        let worse = match side {
                            Side::Minus => value < violation.value,
                            Side::Plus => value > violation.value,
                        };
                        if worse {
                            violation.value = value;
                        }
                        violation.last_line = violation.last_line.max(row + 1);
                        self.beyond.insert(key, at);
                    }
                    None if self.violations.len() >= MOST_VIOLATIONS => {
                        self.report.violations_untold += 1;
                        self.beyond.insert(key, UNTOLD);
                    }
                    None => {
                        self.violations.push(Violation {
                            program: self.program.clone(),
                            line: row + 1,
                            last_line: row + 1,
                            span,
                            axis: axis.machine_name(),
                            value,
                            limit,
                            side,
                        });
                        let at = self.violations.len() - 1;
                        self.beyond.insert(key, at);
                        self.began
                            .insert((self.program.clone(), row, k, side == Side::Plus), at);
                    }
                }
            }
        }
    }

    /// The time of a move of `moved` (axis, distance in the machine), along
    /// `arc` where it is one.
    fn time(
        &mut self,
        row: usize,
        span: Span,
        moved: &[(usize, f64)],
        arc: Option<&Arc>,
        exact_here: bool,
    ) {
        let geometry: f64 = moved
            .iter()
            .filter(|(k, _)| *k < 3)
            .map(|(_, d)| d * d)
            .sum::<f64>()
            .sqrt();
        let others: f64 = moved
            .iter()
            .filter(|(k, _)| *k >= 3)
            .map(|(_, d)| d * d)
            .sum::<f64>()
            .sqrt();
        let length = match arc {
            Some(arc) => arc.length(),
            None if geometry > 0.0 => geometry,
            None => others,
        };
        if length <= 0.0 {
            return;
        }
        if self.motion == Motion::Rapid && !self.rapid_linear {
            return self.single_axis_rapid(moved, exact_here);
        }
        // The programmed path velocity.
        let mut velocity = match self.motion {
            Motion::Rapid => f64::INFINITY,
            _ => match (self.feed_mode, self.feed) {
                (_, None) => {
                    self.report.blocks_without_time += 1;
                    self.unknown(
                        row,
                        span,
                        "a feed motion without a feed (F): its time is not counted".into(),
                    );
                    return;
                }
                (FeedMode::PerMinute, Some(f)) => f * self.feed_scale / 60.0,
                (FeedMode::PerRevolution, Some(f)) => match self.spindle {
                    Some(s) if s > 0.0 => f * self.feed_scale * s / 60.0,
                    _ => {
                        self.report.blocks_without_time += 1;
                        self.unknown(row, span, "a feed per revolution (G95) without a known spindle speed (S): its time is not counted".into());
                        return;
                    }
                },
                (FeedMode::InverseTime, Some(f)) if f > 0.0 => length / (60.0 / f),
                (FeedMode::InverseTime, Some(_)) => f64::INFINITY,
            },
        };
        let group = self.options.dynamic_group;
        let mut acceleration = f64::INFINITY;
        let mut jerk = f64::INFINITY;
        let mut complete = true;
        for &(k, d) in moved {
            let axis = &self.setup.axes[k];
            // The axis's share of the path: all of it on an arc's plane.
            let share = match arc {
                Some(arc) if k < 3 => {
                    let plane =
                        (arc.u[k].hypot(arc.v[k]) * arc.sweep).hypot(arc.rise * arc.normal[k]);
                    (plane / length).clamp(0.0, 1.0).max(d.abs() / length)
                }
                _ => d.abs() / length,
            };
            if share <= 0.0 {
                continue;
            }
            let name = axis.machine_name();
            match axis.max_velocity() {
                Some(v) => velocity = velocity.min(v / share),
                None => {
                    self.note(format!("MD32000 $MA_MAX_AX_VELO of {name} is not in the machine's data: the blocks that move it are not capped by it (G0: not timed)"));
                    complete = false;
                }
            }
            match axis.max_acceleration(group) {
                Some(a) => acceleration = acceleration.min(a / share),
                None => {
                    self.note(format!("MD32300 $MA_MAX_AX_ACCEL of {name} is not in the machine's data: the upper bound leaves out the blocks that move it"));
                    complete = false;
                }
            }
            if self.soft {
                match axis.max_jerk(group) {
                    Some(j) => jerk = jerk.min(j / share),
                    None => self.note(format!("MD32431 $MA_MAX_AX_JERK of {name} is not in the machine's data: its SOFT blocks are timed as BRISK")),
                }
            }
        }
        if let (Some(arc), true) = (arc, acceleration.is_finite()) {
            // The centripetal acceleration v²/r stays within the axes'.
            velocity = velocity.min((acceleration * arc.radius()).sqrt());
        }
        if !velocity.is_finite() || velocity <= 0.0 {
            self.report.blocks_without_time += 1;
            return;
        }
        let mut lower = length / velocity;
        let upper = (complete && acceleration.is_finite()).then(|| {
            rest_to_rest(
                length,
                Limits {
                    velocity,
                    acceleration,
                    jerk: (self.soft && jerk.is_finite()).then_some(jerk),
                },
            )
        });
        if exact_here || self.exact_stop {
            if let Some(upper) = upper {
                lower = upper;
            }
        }
        if let Some(cycle) = self.setup.ipo_cycle_s {
            lower = lower.max(cycle);
        }
        self.add_time(lower, upper.map(|u| u.max(lower)));
    }

    /// The times the user gives for what the block's words and calls do
    /// (`[run] times`: `M6 = 7.5`), each added where it runs.
    fn given_times(&mut self, words: &[Word], called: &[(String, Vec<Option<Value>>)]) {
        if self.options.times.is_empty() {
            return;
        }
        let words = words.iter().filter_map(|word| match word.value {
            Ok(v) if v >= 0.0 && v.fract() == 0.0 && word.name.len() == 1 => {
                Some(format!("{}{}", word.name, v as u64))
            }
            _ => None,
        });
        let names: Vec<String> = words
            .chain(called.iter().map(|(name, _)| name.clone()))
            .collect();
        for name in names {
            if let Some(&seconds) = self.options.times.get(&name) {
                let said = format!(
                    "{name} takes {seconds} s each time it runs ([run] times in sinuprep.toml)"
                );
                if !self.report.assumptions.contains(&said) {
                    self.report.assumptions.push(said);
                }
                self.add_time(seconds, Some(seconds));
            }
        }
    }

    /// G0 under RTLIOF: each axis at its own velocity, acceleration and
    /// jerk, the block as long as its slowest axis.
    fn single_axis_rapid(&mut self, moved: &[(usize, f64)], exact_here: bool) {
        let group = self.options.dynamic_group;
        let (mut lower, mut upper) = (0.0f64, Some(0.0f64));
        for &(k, d) in moved {
            let axis = &self.setup.axes[k];
            let name = axis.machine_name();
            let Some(velocity) = axis.max_velocity() else {
                self.note(format!("MD32000 $MA_MAX_AX_VELO of {name} is not in the machine's data: the blocks that move it are not capped by it (G0: not timed)"));
                self.report.blocks_without_time += 1;
                return;
            };
            lower = lower.max(d.abs() / velocity);
            let jerk = if self.soft {
                axis.max_jerk(group)
            } else {
                None
            };
            upper = match (upper, axis.max_acceleration(group)) {
                (Some(upper), Some(acceleration)) => Some(upper.max(rest_to_rest(
                    d.abs(),
                    Limits {
                        velocity,
                        acceleration,
                        jerk,
                    },
                ))),
                _ => None,
            };
        }
        if exact_here || self.exact_stop {
            lower = upper.unwrap_or(lower);
        }
        if let Some(cycle) = self.setup.ipo_cycle_s {
            lower = lower.max(cycle);
        }
        self.add_time(lower, upper.map(|u| u.max(lower)));
    }

    fn add_time(&mut self, lower: f64, upper: Option<f64>) {
        self.report.time_s += lower;
        self.report.time_bounds_s[0] += lower;
        match upper {
            Some(upper) => self.report.time_bounds_s[1] += upper,
            None => self.upper_complete = false,
        }
        let tool = self
            .tool
            .map_or_else(|| "none".to_string(), |t| t.to_string());
        *self.tool_times.entry(tool).or_default() += lower;
    }

    fn finish(mut self) -> Report {
        let mut report = std::mem::take(&mut self.report);
        report.violations = std::mem::take(&mut self.violations);
        report.violations.sort_by_key(|v| v.line);
        report.axes = self
            .setup
            .axes
            .iter()
            .enumerate()
            .map(|(k, axis)| Travel {
                axis: axis.machine_name(),
                min: self.minimum[k],
                max: self.maximum[k],
                limits: if self.options.second_limits {
                    axis.machine.as_ref().map_or([None, None], |m| m.limits2)
                } else {
                    axis.limits()
                },
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

/// The variables every program level shares: the R parameters.
fn globals(variables: &HashMap<String, Value>) -> HashMap<String, Value> {
    variables
        .iter()
        .filter(|(key, _)| {
            key.strip_prefix('R')
                .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
        })
        .map(|(key, value)| (key.clone(), value.clone()))
        .collect()
}

/// `L105`: a subprogram called by its number (the digits as written:
/// `L0105` is another).
fn is_numbered_call(name: &str) -> bool {
    name.len() > 1 && name.starts_with('L') && name[1..].bytes().all(|b| b.is_ascii_digit())
}
