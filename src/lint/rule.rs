//! What a lint rule is: its metadata, and the checker that sees the program
//! one line at a time.

use std::cell::{OnceCell, RefCell};
use std::collections::BTreeSet;

use crate::diagnostic::{Diagnostic, RuleInfo};
use crate::semantic::addresses::{self, Address};
use crate::semantic::labels::Labels;
use crate::semantic::modal::Modal;
pub use crate::semantic::model::{LineView, PlainLine};
use crate::semantic::{Environment, Model};
use crate::span::Span;
use crate::syntax::plain::PlainFacts;
use crate::syntax::tree::Block;
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

/// A checker: fed every line in order, then told the file is over. Rules
/// keep only what they must remember (labels, names, one state flag).
pub trait Check {
    fn line(
        &mut self,
        _file: &FileContext,
        _row: usize,
        _line: &LineView,
        _out: &mut Vec<Diagnostic>,
    ) {
    }
    /// Whether the rule learns anything from plain lines. Most do not, and
    /// `check` then gives them neither [`Check::plain_lines`] nor
    /// [`Check::line`] for those lines: the parser never builds their tree.
    fn sees_plain_lines(&self) -> bool {
        false
    }
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

/// A rule that looks at each block's address words alone, whatever came
/// before it (N022-N025): [`EachBlock`] is its checker.
pub trait BlockWords {
    /// Whether a plain line with these scanned facts can hold a finding: the
    /// facts decide for most lines of a CAM program without reading a word.
    fn may_find(facts: &PlainFacts) -> bool;
    /// The findings of one block; `block` is its tree, `None` for a plain line.
    fn check(
        file: &FileContext,
        block: Option<&Block>,
        addresses: &[Address],
        out: &mut Vec<Diagnostic>,
    );
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
    fn line(
        &mut self,
        file: &FileContext,
        _row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        if let Some(block) = line.block {
            R::check(file, Some(block), line.addresses(file.source), out);
        }
    }

    fn sees_plain_lines(&self) -> bool {
        true
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], out: &mut Vec<Diagnostic>) {
        for line in lines.iter().filter(|line| R::may_find(&line.facts)) {
            addresses::of_plain_into(file.source, line.raw.content, &mut self.words);
            R::check(file, None, &self.words, out);
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
    /// One more block; `named` says that it moves an axis the machine
    /// names. Gives `true` once the rule has its answer.
    fn block(
        &mut self,
        file: &FileContext,
        addresses: &[Address],
        named: bool,
        out: &mut Vec<Diagnostic>,
    ) -> bool;
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
    fn line(
        &mut self,
        file: &FileContext,
        _row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        use crate::lint::rules::support::moves_a_named_axis;
        if let Some(name) = line.header {
            *self = Self {
                rule: R::default(),
                done: !starts_main_program(file.source, name),
                words: std::mem::take(&mut self.words),
            };
            return;
        }
        let Some(block) = line.block.filter(|_| self.reads(file)) else {
            return;
        };
        let addresses = line.addresses(file.source);
        self.done = line.leaves_line_order(file.source)
            || self
                .rule
                .block(file, addresses, moves_a_named_axis(file, block), out);
    }

    fn sees_plain_lines(&self) -> bool {
        true
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
            self.done = self.rule.block(file, &self.words, false, out);
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
    fn line(&mut self, file: &FileContext, row: usize, line: &LineView, out: &mut Vec<Diagnostic>) {
        use crate::semantic::line_order::is_block_structure;
        let Some(block) = line.block else {
            if let Some(name) = line.header {
                // Another program of the file.
                *self = Self {
                    header_main: Some(starts_main_program(file.source, name)),
                    words: std::mem::take(&mut self.words),
                    ..Self::default()
                };
            }
            return;
        };
        if !self.reads(file) {
            return;
        }
        let addresses = line.addresses(file.source);
        if is_block_structure(block) || line.leaves_line_order(file.source) {
            self.modal = Modal::default();
            return;
        }
        let frames = (!line.plain).then_some(block);
        self.step(file, row, frames, addresses, block.skip.is_some(), out);
    }

    fn sees_plain_lines(&self) -> bool {
        true
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
