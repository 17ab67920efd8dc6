//! What a lint rule is: its metadata, the kinds of things it reads
//! ([`Sees`]) and the checker that is handed them in line order ([`Check`]);
//! the checkers that read for a kind of rule are in [`crate::lint::readers`].

use std::cell::{OnceCell, RefCell};
use std::collections::BTreeSet;

use crate::diagnostic::{Diagnostic, RuleInfo};
pub use crate::lint::readers::{
    AtEnd, BlockWords, EachBlock, FromProgramStart, FromStart, InLineOrder, ModalCheck, ModalRule,
    ModalStep, Moves, OnModel, Words,
};
use crate::semantic::jumps::Target;
use crate::semantic::labels::Labels;
pub use crate::semantic::model::{LineView, PlainLine};
use crate::semantic::{Environment, Model};
use crate::span::Span;
use crate::syntax::tree::{Block, Call, Goto, Statement, Variable};
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
    /// The DEF, PROC and EXTERN statements ([`Check::declaration`]): what a
    /// rule of names reads, without being handed every other statement.
    pub const DECLARATIONS: Sees = Sees(64);
    /// The file's end only ([`Check::finish`]).
    pub const NOTHING: Sees = Sees(0);

    pub(crate) fn has(self, kind: Sees) -> bool {
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
    pub(crate) line: &'a LineView<'l>,
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
    /// Each DEF, PROC or EXTERN statement, after [`Check::statement`].
    fn declaration(&mut self, _file: &FileContext, _at: &StatementAt, _out: &mut Vec<Diagnostic>) {}
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

/// A rule and how its findings are made.
pub struct Rule {
    pub info: &'static RuleInfo,
    pub checking: Checking,
}

/// How a rule's findings are made.
pub enum Checking {
    /// Elsewhere: by the parser, the CYCLE600 walk, the suppressions.
    Elsewhere,
    /// By a checker of its own.
    Own(fn() -> Box<dyn Check>),
    /// By the one [`InLineOrder`] walk every selected modal rule shares.
    InLineOrder(fn() -> Box<dyn ModalCheck>),
}
