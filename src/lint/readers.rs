//! The checkers that read a program for a kind of rule, so that the rule
//! holds its check alone: [`AtEnd`] for a rule on the finished model,
//! [`EachBlock`] for one on each block's address words, [`FromStart`] for
//! one that reads a main program from its start, [`InLineOrder`] for one
//! that follows the modal state while the lines run in their order.

use crate::diagnostic::Diagnostic;
use crate::lint::rule::{BlockAt, Check, FileContext, Sees};
use crate::semantic::addresses::{self, Address};
use crate::semantic::modal::Modal;
use crate::semantic::model::PlainLine;
use crate::span::Span;
use crate::syntax::plain::PlainFacts;
use crate::syntax::tree::Block;
use crate::syntax::ProgramKind;

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

/// A [`ModalRule`] behind a pointer, as [`InLineOrder`] holds every one
/// selected.
pub trait ModalCheck {
    fn reads(&self, file: &FileContext, main: bool) -> bool;
    fn may_matter(&self, facts: &PlainFacts) -> bool;
    fn block(&mut self, file: &FileContext, step: &ModalStep, out: &mut Vec<Diagnostic>);
    /// Another program of the file: what the rule remembers is forgotten.
    fn restart(&mut self);
}

impl<R: ModalRule> ModalCheck for R {
    fn reads(&self, file: &FileContext, main: bool) -> bool {
        <R as ModalRule>::reads(file, main)
    }

    fn may_matter(&self, facts: &PlainFacts) -> bool {
        <R as ModalRule>::may_matter(facts)
    }

    fn restart(&mut self) {
        *self = R::default();
    }

    fn block(&mut self, file: &FileContext, step: &ModalStep, out: &mut Vec<Diagnostic>) {
        ModalRule::block(self, file, step, out);
    }
}

/// The checker of the [`ModalRule`]s, one walk for all of them: the state
/// is the same whoever reads it, so each block is applied once. A jump, a
/// block structure (IF, ELSE, loops, CASE), a subprogram or cycle call or a
/// PROC ends what it knows (the state is then unknown, so nothing is
/// reported from it); a block the operator may skip (`/`) makes what it
/// changes unknown; a program header (`%_N_PART_MPF`) starts over. A plain
/// line is applied where it may matter to a rule that reads the program,
/// and handed to those alone. Every [`ModalRule`] keeps the promise that
/// makes this the state it would follow alone: a line that cannot matter
/// to it (`may_matter`) changes nothing of the state it reads.
pub struct InLineOrder {
    /// The program a header started is a main program; `None` before any
    /// header.
    header_main: Option<bool>,
    modal: Modal,
    /// The 0-based line of the compensation in force.
    compensated_since: usize,
    rules: Vec<Box<dyn ModalCheck>>,
    /// Which of `rules` read the program now: cleared at each header,
    /// found again at the next block or plain line.
    reading: Vec<bool>,
    /// A plain line's words, the buffer kept from line to line.
    words: Vec<Address>,
}

impl InLineOrder {
    pub fn new(rules: Vec<Box<dyn ModalCheck>>) -> Self {
        Self {
            header_main: None,
            modal: Modal::default(),
            compensated_since: 0,
            reading: Vec::new(),
            rules,
            words: Vec::new(),
        }
    }

    /// Whether any rule reads the program now; which do, kept.
    fn reads(&mut self, file: &FileContext) -> bool {
        if self.reading.len() != self.rules.len() {
            let main = self.header_main.unwrap_or(file.kind == ProgramKind::Main);
            self.reading = self.rules.iter().map(|r| r.reads(file, main)).collect();
        }
        self.reading.contains(&true)
    }

    /// One block that keeps the line order, handed to the rules `to` takes;
    /// `frames` is its tree when it may hold frame statements (more than
    /// address words).
    #[allow(clippy::too_many_arguments)]
    fn step(
        &mut self,
        file: &FileContext,
        row: usize,
        frames: Option<&Block>,
        addresses: &[Address],
        skippable: bool,
        to: impl Fn(&dyn ModalCheck) -> bool,
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
        for (rule, _) in self
            .rules
            .iter_mut()
            .zip(&self.reading)
            .filter(|(rule, &reading)| reading && to(rule.as_ref()))
        {
            rule.block(file, &step, out);
        }
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

impl Check for InLineOrder {
    fn sees(&self) -> Sees {
        Sees::HEADERS | Sees::BLOCKS | Sees::PLAIN_LINES
    }

    /// Another program of the file.
    fn header(&mut self, file: &FileContext, _row: usize, name: Span) {
        self.header_main = Some(starts_main_program(file.source, name));
        self.modal = Modal::default();
        self.compensated_since = 0;
        self.reading.clear();
        for rule in &mut self.rules {
            rule.restart();
        }
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
        let skippable = block.skip.is_some();
        self.step(file, at.row, frames, addresses, skippable, |_| true, out);
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
            let matters = |rule: &dyn ModalCheck| rule.may_matter(facts);
            let matters_to_one = self
                .rules
                .iter()
                .zip(&self.reading)
                .any(|(rule, &reading)| reading && matters(rule.as_ref()));
            if !matters_to_one {
                continue;
            }
            let mut words = std::mem::take(&mut self.words);
            addresses::of_plain_into(source, line.raw.content, &mut words);
            // A skippable block (`/N10 ...`) is never a plain line.
            self.step(file, line.row, None, &words, false, matters, out);
            self.words = words;
        }
    }
}
