//! What a lint rule is: its metadata, and the checker that sees the program
//! one line at a time.

use std::cell::{OnceCell, RefCell};
use std::collections::BTreeSet;

use crate::diagnostic::{Diagnostic, RuleInfo};
use crate::semantic::addresses::{self, Address};
use crate::semantic::jumps::Target;
use crate::semantic::labels::Labels;
use crate::semantic::modal::Modal;
pub use crate::semantic::model::{LineView, PlainLine};
use crate::semantic::{Environment, Model};
use crate::span::Span;
use crate::syntax::plain::PlainFacts;
use crate::syntax::tree::{Block, Call, Goto, Statement, StatementKind, Variable};
use crate::syntax::ProgramKind;

/// The file a rule is looking at: its source lives for `'src`, what the
/// caller gives with it (its name, the machine's names) for `'a`.
pub struct FileContext<'a, 'src> {
    pub source: &'src [u8],
    /// The file's name as given (`<stdin>` or `--stdin-filename`).
    pub name: &'a str,
    pub kind: ProgramKind,
    /// Names the machine defines.
    pub environment: &'a Environment,
    /// The file holds declarations only (`.DEF`, `.INI`, `.GUD`, `.COM`),
    /// as its name says: decided once, asked on every line.
    pub definition_file: bool,
    /// The program's model, complete once the line pass is over.
    model: OnceCell<Model<'src>>,
    /// Subprograms called whose declaration was found nowhere, so that
    /// their calls could not be checked.
    unresolved: RefCell<BTreeSet<String>>,
}

impl<'a, 'src> FileContext<'a, 'src> {
    pub fn new(
        source: &'src [u8],
        name: &'a str,
        kind: ProgramKind,
        environment: &'a Environment,
    ) -> Self {
        Self {
            source,
            name,
            kind,
            environment,
            definition_file: crate::lint::rules::support::is_definition_file(name),
            model: OnceCell::new(),
            unresolved: RefCell::default(),
        }
    }

    /// Notes a called subprogram whose declaration was found nowhere.
    pub fn unresolved_call(&self, name: &str) {
        let mut unresolved = self.unresolved.borrow_mut();
        // A subprogram called thousands of times is kept once.
        if !unresolved.contains(name) {
            unresolved.insert(name.to_string());
        }
    }

    /// The subprograms noted by [`Self::unresolved_call`], in order.
    pub(crate) fn take_unresolved(&self) -> BTreeSet<String> {
        self.unresolved.take()
    }

    /// Gives the model the line pass built, before the rules finish.
    pub(crate) fn complete(&self, model: Model<'src>) {
        let _ = self.model.set(model);
    }

    /// The model, once the rules are done with it.
    pub(crate) fn into_model(self) -> Model<'src> {
        self.model
            .into_inner()
            .expect("the model is complete once the line pass is over")
    }

    /// The program's model; asked for once the line pass is over (in
    /// [`Check::finish`]).
    pub fn model(&self) -> &Model<'src> {
        self.model
            .get()
            .expect("the model is complete before the rules finish")
    }

    /// Every label of the file; asked for once the line pass is over.
    pub fn labels(&self) -> &Labels {
        &self.model().labels
    }
}

/// What a checker is handed, beside the end of the file: each rule
/// declares the kinds it reads, and the line pass gives it those alone,
/// already unpacked.
#[derive(Clone, Copy, Default, PartialEq, Eq)]
pub struct Sees(u8);

impl Sees {
    /// Program headers ([`Check::header`]).
    pub const HEADERS: Sees = Sees(1);
    /// Blocks read into a tree ([`Check::block`]).
    pub const BLOCKS: Sees = Sees(2);
    /// The statements of blocks read into a tree ([`Check::statement`]).
    pub const STATEMENTS: Sees = Sees(4);
    /// Jumps, their targets read ([`Check::jump`]).
    pub const JUMPS: Sees = Sees(8);
    /// Plain lines, read by the scan alone ([`Check::plain_lines`]).
    pub const PLAIN_LINES: Sees = Sees(16);
    /// Calls with arguments (`CYCLE800(...)`, [`Check::call`]).
    pub const CALLS: Sees = Sees(32);
    /// The file's end only ([`Check::finish`]).
    pub const NOTHING: Sees = Sees(0);

    fn has(self, kind: Sees) -> bool {
        self.0 & kind.0 != 0
    }
}

impl std::ops::BitOr for Sees {
    type Output = Sees;
    fn bitor(self, other: Sees) -> Sees {
        Sees(self.0 | other.0)
    }
}

/// A block read into a tree, as a rule sees it.
pub struct BlockAt<'a, 'l> {
    /// Its 0-based line.
    pub row: usize,
    pub block: &'l Block,
    /// Its line, with what the line pass read of it once for every rule.
    pub line: &'a LineView<'l>,
}

/// One statement of a block read into a tree.
pub struct StatementAt<'a, 'l> {
    /// Its 0-based line.
    pub row: usize,
    pub block: &'l Block,
    /// Its place among the block's statements.
    pub index: usize,
    pub statement: &'l Statement,
    line: &'a LineView<'l>,
}

impl<'l> StatementAt<'_, 'l> {
    /// The variables it reads (DEF initialisers and indices included).
    pub fn reads(&self) -> impl Iterator<Item = &'l Variable> + '_ {
        self.line.reads(self.index)
    }
}

/// One call with arguments (`CYCLE800(...)`).
pub struct CallAt<'l> {
    /// Its 0-based line.
    pub row: usize,
    pub call: &'l Call,
}

/// One jump: a GOTO, GOTOF, GOTOB or GOTOC statement, or a CASE's branch.
pub struct JumpAt<'l> {
    /// Its 0-based line.
    pub row: usize,
    pub goto: &'l Goto,
    /// Where it goes, and the span that names it; `None` for a computed
    /// target.
    pub target: Option<(Target, Span)>,
}

/// A checker: handed in line order what it [`Check::sees`], then told the
/// file is over. Rules keep only what they must remember (labels, names,
/// one state flag).
pub trait Check {
    /// The kinds of things the rule reads.
    fn sees(&self) -> Sees;
    /// A program header (`%_N_PART_MPF`): another program of the file starts.
    fn header(&mut self, _file: &FileContext, _row: usize, _name: Span) {}
    /// A block read into a tree, after its statements and jumps: every block
    /// that is not a plain line, and plain lines where a macro may stand.
    fn block(&mut self, _file: &FileContext, _at: &BlockAt, _out: &mut Vec<Diagnostic>) {}
    /// Each statement of a block read into a tree, in order.
    fn statement(&mut self, _file: &FileContext, _at: &StatementAt, _out: &mut Vec<Diagnostic>) {}
    /// Each call with arguments, after its statement.
    fn call(&mut self, _file: &FileContext, _at: &CallAt, _out: &mut Vec<Diagnostic>) {}
    /// Each jump, after the statement that holds it.
    fn jump(&mut self, _file: &FileContext, _at: &JumpAt, _out: &mut Vec<Diagnostic>) {}
    /// Plain lines in order, each run of them between other lines in
    /// slices: a call per slice rather than per line, because a CAM program
    /// is millions of them.
    fn plain_lines(
        &mut self,
        _file: &FileContext,
        _lines: &[PlainLine],
        _out: &mut Vec<Diagnostic>,
    ) {
    }
    fn finish(&mut self, _file: &FileContext, _out: &mut Vec<Diagnostic>) {}
}

/// The selected rules' checkers, and which of them read each kind of thing:
/// a kind no rule reads costs nothing.
pub(crate) struct Checkers {
    all: Vec<Box<dyn Check>>,
    headers: Vec<usize>,
    blocks: Vec<usize>,
    statements: Vec<usize>,
    calls: Vec<usize>,
    jumps: Vec<usize>,
    plain_lines: Vec<usize>,
}

impl Checkers {
    pub(crate) fn new(all: Vec<Box<dyn Check>>) -> Self {
        let seeing = |kind: Sees| -> Vec<usize> {
            (0..all.len())
                .filter(|&n| all[n].sees().has(kind))
                .collect()
        };
        Self {
            headers: seeing(Sees::HEADERS),
            blocks: seeing(Sees::BLOCKS),
            statements: seeing(Sees::STATEMENTS),
            calls: seeing(Sees::CALLS),
            jumps: seeing(Sees::JUMPS),
            plain_lines: seeing(Sees::PLAIN_LINES),
            all,
        }
    }

    /// One line read into a tree, handed out by kind.
    pub(crate) fn line(
        &mut self,
        file: &FileContext,
        row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        if let Some(name) = line.header {
            for &n in &self.headers {
                self.all[n].header(file, row, name);
            }
        }
        let Some(block) = line.block else {
            return;
        };
        self.statements(file, row, block, line, out);
        let at = BlockAt { row, block, line };
        for &n in &self.blocks {
            self.all[n].block(file, &at, out);
        }
    }

    fn statements(
        &mut self,
        file: &FileContext,
        row: usize,
        block: &Block,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        for (index, statement) in block.statements.iter().enumerate() {
            let at = StatementAt {
                row,
                block,
                index,
                statement,
                line,
            };
            for &n in &self.statements {
                self.all[n].statement(file, &at, out);
            }
            if let StatementKind::Call(call) = &statement.kind {
                let at = CallAt { row, call };
                for &n in &self.calls {
                    self.all[n].call(file, &at, out);
                }
            }
            if self.jumps.is_empty() {
                continue;
            }
            let mut hand = |goto: &Goto| {
                let at = JumpAt {
                    row,
                    goto,
                    target: crate::lint::rules::support::target(file, goto),
                };
                for &n in &self.jumps {
                    self.all[n].jump(file, &at, out);
                }
            };
            match &statement.kind {
                StatementKind::Goto(goto) => hand(goto),
                StatementKind::Case(case) => {
                    let branches = case.branches.iter().map(|(_, goto)| goto);
                    branches.chain(&case.default).for_each(hand);
                }
                _ => {}
            }
        }
    }

    /// A run of plain lines, to the rules that read them.
    pub(crate) fn plain_lines(
        &mut self,
        file: &FileContext,
        lines: &[PlainLine],
        out: &mut Vec<Diagnostic>,
    ) {
        for &n in &self.plain_lines {
            self.all[n].plain_lines(file, lines, out);
        }
    }

    /// Every rule's last step, once the file is over; `false` when `stopped`
    /// said so before one of them.
    pub(crate) fn finish(
        &mut self,
        file: &FileContext,
        out: &mut Vec<Diagnostic>,
        stopped: impl Fn() -> bool,
    ) -> bool {
        for checker in &mut self.all {
            if stopped() {
                return false;
            }
            checker.finish(file, out);
        }
        true
    }
}

/// A rule that reads the finished model alone (N004, N007, N020):
/// [`AtEnd`] is its checker.
pub trait OnModel {
    fn check(file: &FileContext, out: &mut Vec<Diagnostic>);
}

/// The checker of an [`OnModel`] rule.
pub struct AtEnd<R>(std::marker::PhantomData<R>);

impl<R> Default for AtEnd<R> {
    fn default() -> Self {
        Self(std::marker::PhantomData)
    }
}

impl<R: OnModel> Check for AtEnd<R> {
    fn sees(&self) -> Sees {
        Sees::NOTHING
    }

    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        R::check(file, out);
    }
}

/// A rule that looks at each block's address words alone, whatever came
/// before it (N022-N025): [`EachBlock`] is its checker.
pub trait BlockWords {
    /// Whether a plain line with these scanned facts can hold a finding: the
    /// facts decide for most lines of a CAM program without reading a word.
    fn may_find(facts: &PlainFacts) -> bool;
    /// The findings of one block.
    fn check(file: &FileContext, words: &Words, out: &mut Vec<Diagnostic>);
}

/// A block's address words, as a [`BlockWords`] rule sees them.
pub struct Words<'a> {
    /// Its tree; `None` for a plain line.
    pub block: Option<&'a Block>,
    pub addresses: &'a [Address],
}

/// The checker of a [`BlockWords`] rule: a tree line's words as the line
/// view read them once for every rule, a plain line's from its bytes when
/// its facts allow a finding.
pub struct EachBlock<R> {
    /// A plain line's words, the buffer kept from line to line.
    words: Vec<Address>,
    rule: std::marker::PhantomData<R>,
}

impl<R> Default for EachBlock<R> {
    fn default() -> Self {
        Self {
            words: Vec::new(),
            rule: std::marker::PhantomData,
        }
    }
}

impl<R: BlockWords> Check for EachBlock<R> {
    fn sees(&self) -> Sees {
        Sees::BLOCKS | Sees::PLAIN_LINES
    }

    fn block(&mut self, file: &FileContext, at: &BlockAt, out: &mut Vec<Diagnostic>) {
        let addresses = at.line.addresses(file.source);
        let block = Some(at.block);
        R::check(file, &Words { block, addresses }, out);
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], out: &mut Vec<Diagnostic>) {
        for line in lines.iter().filter(|line| R::may_find(&line.facts)) {
            addresses::of_plain_into(file.source, line.raw.content, &mut self.words);
            let addresses = &self.words;
            R::check(
                file,
                &Words {
                    block: None,
                    addresses,
                },
                out,
            );
        }
    }
}

/// A rule with the checker that implements it; rules whose findings come
/// from the parser or the CYCLE600 walk have none.
pub struct Rule {
    pub info: &'static RuleInfo,
    pub checker: Option<fn() -> Box<dyn Check>>,
}

/// A rule that reads a main program from its start in the order the
/// control runs it, until it has its answer (N026, N029): [`FromStart`] is
/// its checker. Subprograms are not read (their caller's state holds in
/// them), nor definition files.
pub trait FromProgramStart: Default {
    /// One more block. Gives `true` once the rule has its answer.
    fn block(&mut self, file: &FileContext, at: &Moves, out: &mut Vec<Diagnostic>) -> bool;
}

/// A block as a [`FromProgramStart`] rule sees it.
pub struct Moves<'a> {
    pub addresses: &'a [Address],
    /// It moves an axis the machine names (`XC=10`).
    pub named: bool,
}

/// The checker of a [`FromProgramStart`] rule: it stops at the first jump,
/// subprogram or cycle call, `PROC` or modal call, after which the order of
/// the lines is no longer the order they run in, and begins again at a
/// program header (`%_N_PART_MPF`).
#[derive(Default)]
pub struct FromStart<R> {
    rule: R,
    done: bool,
    /// A plain line's words, the buffer kept from line to line.
    words: Vec<Address>,
}

impl<R: FromProgramStart> FromStart<R> {
    fn reads(&self, file: &FileContext) -> bool {
        !self.done && file.kind == ProgramKind::Main && !file.definition_file
    }
}

impl<R: FromProgramStart> Check for FromStart<R> {
    fn sees(&self) -> Sees {
        Sees::HEADERS | Sees::BLOCKS | Sees::PLAIN_LINES
    }

    fn header(&mut self, file: &FileContext, _row: usize, name: Span) {
        *self = Self {
            rule: R::default(),
            done: !starts_main_program(file.source, name),
            words: std::mem::take(&mut self.words),
        };
    }

    fn block(&mut self, file: &FileContext, at: &BlockAt, out: &mut Vec<Diagnostic>) {
        use crate::lint::rules::support::moves_a_named_axis;
        if !self.reads(file) {
            return;
        }
        let (line, source) = (at.line, file.source);
        if line.leaves_line_order(source) {
            self.done = true;
            return;
        }
        let addresses = line.addresses(source);
        let named = moves_a_named_axis(file, at.block);
        self.done = self.rule.block(file, &Moves { addresses, named }, out);
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], out: &mut Vec<Diagnostic>) {
        if !self.reads(file) {
            return;
        }
        for line in lines {
            if self.done {
                return;
            }
            // `L10`: a subprogram call.
            if line.facts.letters.contains(b'L') {
                self.done = true;
                return;
            }
            addresses::of_plain_into(file.source, line.raw.content, &mut self.words);
            let addresses = &self.words;
            self.done = self.rule.block(
                file,
                &Moves {
                    addresses,
                    named: false,
                },
                out,
            );
        }
    }
}

/// The program header named `name` (`%_N_PART_MPF`) starts a main program.
fn starts_main_program(source: &[u8], name: Span) -> bool {
    crate::lint::rules::support::upper(source, name).ends_with("_MPF")
}

/// A rule about the modal state block by block (N028, N030, N031):
/// [`InLineOrder`] is its checker, which follows the state the blocks leave
/// in force while the order of the lines is the order the control runs them.
pub trait ModalRule: Default {
    /// Whether the rule reads this file, or the program of it that a header
    /// started: `main` says whether that program is a main program (by the
    /// header's `_MPF`, else by the file's kind).
    fn reads(_file: &FileContext, _main: bool) -> bool {
        true
    }
    /// Whether a plain line with these scanned facts can change what the
    /// rule follows or hold a finding: the others are not read.
    fn may_matter(facts: &PlainFacts) -> bool;
    /// One block read in line order.
    fn block(&mut self, file: &FileContext, step: &ModalStep, out: &mut Vec<Diagnostic>);
}

/// One block as a [`ModalRule`] sees it.
pub struct ModalStep<'a> {
    /// Its 0-based line.
    pub row: usize,
    /// Its tree when it holds more than address words (a command, a frame
    /// statement); `None` for a line of address words alone.
    pub block: Option<&'a Block>,
    pub addresses: &'a [Address],
    /// The state it starts from.
    pub before: Modal,
    /// The state it leaves when it runs.
    pub after: Modal,
    /// The 0-based line where the tool radius compensation in force before
    /// it was selected.
    pub compensated_since: usize,
}

/// The checker of a [`ModalRule`]. A jump, a block structure (IF, ELSE,
/// loops, CASE), a subprogram or cycle call or a PROC ends what it knows
/// (the state is then unknown, so nothing is reported from it); a block
/// the operator may skip (`/`) makes what it changes unknown; a program
/// header (`%_N_PART_MPF`) starts over.
#[derive(Default)]
pub struct InLineOrder<R> {
    /// The program a header started is a main program; `None` before any
    /// header.
    header_main: Option<bool>,
    modal: Modal,
    /// The 0-based line of the compensation in force.
    compensated_since: usize,
    rule: R,
    /// A plain line's words, the buffer kept from line to line.
    words: Vec<Address>,
}

impl<R: ModalRule> InLineOrder<R> {
    fn reads(&self, file: &FileContext) -> bool {
        let main = self.header_main.unwrap_or(file.kind == ProgramKind::Main);
        R::reads(file, main)
    }

    /// One block that keeps the line order; `frames` is its tree when it
    /// may hold frame statements (more than address words).
    fn step(
        &mut self,
        file: &FileContext,
        row: usize,
        frames: Option<&Block>,
        addresses: &[Address],
        skippable: bool,
        out: &mut Vec<Diagnostic>,
    ) {
        let source = file.source;
        let before = self.modal;
        let mut after = before;
        match frames {
            Some(block) => after.apply_block(source, block, addresses),
            None => after.apply(source, addresses),
        }
        let step = ModalStep {
            row,
            block: frames,
            addresses,
            before,
            after,
            compensated_since: self.compensated_since,
        };
        self.rule.block(file, &step, out);
        if skippable {
            self.modal.may_have_run(after);
        } else {
            self.modal = after;
        }
        if self.modal.radius_compensation != before.radius_compensation {
            self.compensated_since = row;
        }
    }
}

impl<R: ModalRule> Check for InLineOrder<R> {
    fn sees(&self) -> Sees {
        Sees::HEADERS | Sees::BLOCKS | Sees::PLAIN_LINES
    }

    /// Another program of the file.
    fn header(&mut self, file: &FileContext, _row: usize, name: Span) {
        *self = Self {
            header_main: Some(starts_main_program(file.source, name)),
            words: std::mem::take(&mut self.words),
            ..Self::default()
        };
    }

    fn block(&mut self, file: &FileContext, at: &BlockAt, out: &mut Vec<Diagnostic>) {
        use crate::semantic::line_order::is_block_structure;
        if !self.reads(file) {
            return;
        }
        let (line, block) = (at.line, at.block);
        let addresses = line.addresses(file.source);
        if is_block_structure(block) || line.leaves_line_order(file.source) {
            self.modal = Modal::default();
            return;
        }
        let frames = (!line.plain).then_some(block);
        self.step(file, at.row, frames, addresses, block.skip.is_some(), out);
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], out: &mut Vec<Diagnostic>) {
        if !self.reads(file) {
            return;
        }
        let source = file.source;
        for line in lines {
            let facts = &line.facts;
            if facts.letters.contains(b'L') {
                self.modal = Modal::default(); // a subprogram call
                continue;
            }
            if !R::may_matter(facts) {
                continue;
            }
            let mut words = std::mem::take(&mut self.words);
            addresses::of_plain_into(source, line.raw.content, &mut words);
            // A skippable block (`/N10 ...`) is never a plain line.
            self.step(file, line.row, None, &words, false, out);
            self.words = words;
        }
    }
}
