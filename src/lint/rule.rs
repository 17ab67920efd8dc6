//! What a lint rule is: its metadata, and the checker that sees the program
//! one line at a time.

use std::cell::{OnceCell, RefCell};
use std::collections::HashSet;

use crate::diagnostic::{Diagnostic, RuleInfo};
use crate::lint::labels::Labels;
use crate::span::Span;
use crate::syntax::lines::RawLine;
use crate::syntax::plain::PlainFacts;
use crate::syntax::tree::{Block, Line, LineKind, StatementKind, Variable, Word, WordValue};
use crate::syntax::ProgramKind;

/// The file a rule is looking at.
pub struct FileContext<'a> {
    pub source: &'a [u8],
    /// The file's name as given (`<stdin>` or `--stdin-filename`).
    pub name: &'a str,
    pub kind: ProgramKind,
    /// Block numbers some jump names, announced during the line pass.
    wanted_numbers: RefCell<HashSet<u64>>,
    block_numbers: OnceCell<Vec<(u64, usize)>>,
    /// Labels as the line pass met them, then sorted for the rules.
    recorded_labels: RefCell<Labels>,
    labels: OnceCell<Labels>,
}

impl<'a> FileContext<'a> {
    pub fn new(source: &'a [u8], name: &'a str, kind: ProgramKind) -> Self {
        Self {
            source,
            name,
            kind,
            wanted_numbers: RefCell::default(),
            block_numbers: OnceCell::new(),
            recorded_labels: RefCell::default(),
            labels: OnceCell::new(),
        }
    }

    /// Records, during the line pass, the label at `span` on line `row`.
    pub fn record_label(&self, row: usize, span: Span) {
        self.recorded_labels
            .borrow_mut()
            .record(self.source, row, span);
    }

    /// Every label of the file (see [`Self::record_label`]); asked for once
    /// the line pass is over.
    pub fn labels(&self) -> &Labels {
        self.labels
            .get_or_init(|| self.recorded_labels.take().sorted())
    }

    /// Announces, during the line pass, a block number a jump names.
    pub fn want_block_number(&self, number: u64) {
        self.wanted_numbers.borrow_mut().insert(number);
    }

    /// Every block number some jump names (see [`Self::want_block_number`])
    /// with its row, sorted by number; asked for once the line pass is over,
    /// and read from the file then: most programs never jump to a number,
    /// and keeping every number as lines go by would cost more memory than
    /// the rest of `check`.
    pub fn block_numbers(&self) -> &[(u64, usize)] {
        self.block_numbers.get_or_init(|| {
            crate::syntax::plain::block_numbers(self.source, &self.wanted_numbers.borrow())
        })
    }
}

/// One line as the rules see it. What each statement reads is collected
/// once here: five rules need it, and walking every statement's expressions
/// once per rule cost a tenth of `check`'s time.
pub struct LineView<'l> {
    pub raw: RawLine,
    /// The block, when the line is one.
    pub block: Option<&'l Block>,
    /// Every statement is an address word with a number (`G1 X-12.5`): the
    /// line defines, reads, calls and jumps nowhere. Most blocks of a CAM
    /// program are such, and most rules have nothing to do there.
    pub plain: bool,
    /// (statement index, variable read), in statement order.
    reads: Vec<(usize, &'l Variable)>,
}

impl<'l> LineView<'l> {
    pub fn new(line: &'l Line) -> Self {
        let block = match &line.kind {
            LineKind::Block(block) => Some(block),
            _ => None,
        };
        let mut reads = Vec::new();
        let mut plain = true;
        for (index, statement) in block.iter().flat_map(|b| b.statements.iter().enumerate()) {
            if let StatementKind::Word(Word {
                value: WordValue::Number(_),
                ..
            }) = statement.kind
            {
                continue;
            }
            plain = false;
            reads.extend(
                crate::lint::rules::support::reads(statement)
                    .into_iter()
                    .map(|variable| (index, variable)),
            );
        }
        Self {
            raw: line.raw,
            block,
            plain,
            reads,
        }
    }

    /// The variables statement `index` of the block reads (DEF initialisers
    /// and indices included).
    pub fn reads(&self, index: usize) -> impl Iterator<Item = &'l Variable> + '_ {
        self.reads
            .iter()
            .filter(move |(i, _)| *i == index)
            .map(|(_, variable)| *variable)
    }
}

/// A line [`crate::syntax::plain::is_plain`] accepts (most lines of a CAM
/// program), as the rules see it without a tree: its words are address
/// letters with numbers, which define, read, call and jump nowhere.
pub struct PlainLine {
    /// 0-based.
    pub row: usize,
    pub raw: RawLine,
    pub facts: PlainFacts,
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

/// A rule with the checker that implements it; rules whose findings come
/// from the parser or the CYCLE600 walk have none.
pub struct Rule {
    pub info: &'static RuleInfo,
    pub checker: Option<fn() -> Box<dyn Check>>,
}
