//! The model of one program: what its lines define, name and jump to,
//! learned in the one pass that parses them and read by every later pass
//! (the linter's rules, the CYCLE600 walk, the rewrite).
//!
//! The pass is [`ModelBuilder`]'s: `check` drives it line by line, showing
//! each line to its rules on the way; [`Model::build`] drives it alone. Plain
//! lines (address words with numbers) are scanned, never parsed; the trees of
//! the others are kept in the line table (up to `syntax::line_table::KEPT_TREES`
//! bytes of source), so no pass parses a line twice.

use std::cell::OnceCell;
use std::sync::{Arc, OnceLock};

use crate::diagnostic::Diagnostic;
use crate::hash::HashSet;
use crate::semantic::addresses::{self, Address};
use crate::semantic::blocks::{BlockMatcher, Blocks};
use crate::semantic::jumps::{self, Target};
use crate::semantic::labels::Labels;
use crate::semantic::line_order;
use crate::semantic::structure::{LineFacts, Structure};
use crate::span::Span;
use crate::syntax::lines::RawLine;
use crate::syntax::macros::{Macros, Use};
use crate::syntax::plain::{scanned_lines, PlainFacts, Scanned};
use crate::syntax::tree::{
    upper, upper_in, Block, DataType, GotoKind, GotoTarget, Line, LineKind, Statement,
    StatementKind, Variable, Word, WordValue,
};
use crate::syntax::visit::{each_read, gotos, reads};
use crate::syntax::{LineParser, Lines, LinesRecorder, ProgramKind};

/// Plain lines passed to [`ModelBuilder::plain_lines`] at once, at most.
pub(crate) const PLAIN_RUN: usize = 256;

/// The trees kept take at most about this much memory, whatever the
/// program: past it, a pass that asks for a line parses it again. The line
/// table's own bound counts source bytes, and a file of short lines
/// (`IF R1>0`, `ENDIF`) takes some forty times its size as trees.
const KEPT_TREE_BYTES: usize = 8 << 20;

/// The expressions' nodes a byte of a line's source makes, about.
const TREE_BYTES_PER_BYTE: usize = 8;

/// A name a DEF or a PROC parameter list defines.
#[derive(Clone, Debug)]
pub struct Symbol {
    /// Upper case.
    pub name: String,
    /// The name as it is written where it is defined.
    pub span: Span,
    /// 0-based.
    pub row: usize,
    pub data_type: DataType,
    /// `NCK` or `CHAN` (a GUD variable); `None` for a local one.
    pub global: bool,
    pub parameter: bool,
}

/// The program, as every pass after the parse sees it.
pub struct Model<'src> {
    pub source: &'src [u8],
    pub kind: ProgramKind,
    /// Every line; the trees of those not plain.
    pub lines: Lines<'src>,
    /// Syntax errors, in line order.
    pub syntax: Vec<Diagnostic>,
    pub labels: Labels,
    /// The control blocks (IF, WHILE, FOR, LOOP, REPEAT) and what is wrong
    /// with them.
    pub blocks: Blocks,
    /// Defined names, in the order they are defined.
    pub symbols: Vec<Symbol>,
    /// Every name a statement reads (upper case), once.
    pub read_names: HashSet<String>,
    /// Lines with a STOPRE, in order.
    pub stopre: Vec<usize>,
    /// The first block that executes anything: (row, where its content starts).
    pub first_executable: Option<(usize, usize)>,
    /// Where the line of the last declaration before it ends.
    pub declarations_end: Option<usize>,
    /// The macros written in the program's lines and what each stood for,
    /// in source order (its trees are read from the expansions).
    pub macro_uses: Vec<Use>,
    /// Block numbers some jump names (`GOTOF N100`, `CASE ... GOTOF 20`).
    jump_numbers: HashSet<u64>,
    /// Those block numbers with their lines, sorted: read from the file
    /// when first asked for (most programs never jump to a number).
    block_numbers: OnceLock<Vec<(u64, usize)>>,
    /// Built when first asked for, by whichever thread asks.
    structure: OnceLock<Structure>,
}

impl<'src> Model<'src> {
    /// The model of `source`, its kind read from its first blocks.
    pub fn of(source: &'src [u8]) -> Self {
        Self::build(source, crate::syntax::program_kind(None, source))
    }

    /// The model of `source`, in a pass of its own.
    pub fn build(source: &'src [u8], kind: ProgramKind) -> Self {
        Self::build_with(source, kind, Arc::default())
    }

    /// [`Self::build`], the program's lines read with the macros of the
    /// machine's definition files (its own are learned on the way).
    pub fn build_with(source: &'src [u8], kind: ProgramKind, macros: Arc<Macros>) -> Self {
        let mut builder = ModelBuilder::new(source, true).with_macros(macros);
        let mut plain = Vec::with_capacity(PLAIN_RUN);
        for (row, line) in scanned_lines(source).enumerate() {
            match line {
                Scanned::Plain(line) if !builder.expands(line.raw) => {
                    plain.push(PlainLine {
                        row,
                        raw: line.raw,
                        facts: line.facts(),
                    });
                    // A run is passed on in pieces: a CAM program's run
                    // between two other lines may be millions of lines.
                    if plain.len() == PLAIN_RUN {
                        builder.plain_lines(&plain);
                        plain.clear();
                    }
                }
                other => {
                    let raw = other.raw();
                    builder.plain_lines(&plain);
                    plain.clear();
                    let tree = builder.parse(raw);
                    builder.learn(&LineView::new(&tree));
                    drop(builder.keep(tree));
                }
            }
        }
        builder.plain_lines(&plain);
        builder.finish(kind)
    }

    /// Where DEF lines added to the program go: after the last declaration
    /// before the first executable block, else before that block, else at
    /// the end.
    pub fn declarations_insertion(&self) -> usize {
        self.declarations_end
            .or(self.first_executable.map(|(_, start)| start))
            .unwrap_or(self.source.len())
    }

    /// The lines that hold `target`, in order.
    pub fn target_rows(&self, target: &Target) -> Vec<usize> {
        match target {
            Target::Label(name) => self.labels.rows(name).collect(),
            Target::Number(number) => self.numbered(*number).iter().map(|&(_, row)| row).collect(),
        }
    }

    /// The line a jump of `kind` from line `from` to `target` lands on,
    /// searching as the control does; `None` where the search finds none
    /// (or the target is computed).
    pub fn landing(&self, target: &GotoTarget, kind: GotoKind, from: usize) -> Option<usize> {
        self.target_landing(&Target::of(self.source, target)?, kind, from)
    }

    /// [`Self::landing`] of a jump to `target`.
    pub fn target_landing(&self, target: &Target, kind: GotoKind, from: usize) -> Option<usize> {
        match target {
            Target::Label(name) => self.labels.landing(name, kind, from),
            Target::Number(number) => {
                let numbers = self.numbered(*number);
                jumps::search_in(numbers, |&(_, row)| row, |_| true, kind, from)
            }
        }
    }

    /// Whether some line holds `target`.
    pub fn has_target(&self, target: &Target) -> bool {
        match target {
            Target::Label(name) => self.labels.contains(name),
            Target::Number(number) => !self.numbered(*number).is_empty(),
        }
    }

    /// The block numbers `number` with their lines, in order.
    fn numbered(&self, number: u64) -> &[(u64, usize)] {
        let numbers = self.block_numbers();
        let first = numbers.partition_point(|&(n, _)| n < number);
        let count = numbers[first..].partition_point(|&(n, _)| n == number);
        &numbers[first..first + count]
    }

    /// Every block number a jump names, with its line, sorted by number and
    /// then line; read from the file when first asked for.
    pub(crate) fn block_numbers(&self) -> &[(u64, usize)] {
        self.block_numbers
            .get_or_init(|| crate::syntax::plain::block_numbers(self.source, &self.jump_numbers))
    }

    /// The block structure the walk follows, built when first asked for.
    pub(crate) fn structure(&self) -> &Structure {
        self.structure.get_or_init(|| Structure::build(self))
    }

    /// The first variable whose name is `R<n>` for an `n` in `range`, read or
    /// written anywhere.
    pub fn first_r_parameter(&self, range: std::ops::Range<u32>) -> Option<(u32, Span)> {
        for (_, line) in self.lines.other_lines() {
            let LineKind::Block(block) = &line.kind else {
                continue;
            };
            for statement in &block.statements {
                let mut variables = reads(statement);
                if let StatementKind::Assign(assign) = &statement.kind {
                    variables.insert(0, &assign.target);
                }
                for variable in variables {
                    let number = std::str::from_utf8(variable.name.text(self.source))
                        .ok()
                        .and_then(|t| t.strip_prefix(['R', 'r']))
                        .and_then(|d| d.parse::<u32>().ok());
                    if let Some(n) = number.filter(|n| range.contains(n)) {
                        return Some((n, variable.span));
                    }
                }
            }
        }
        None
    }
}

/// Whether `statement` is STOPRE.
pub fn is_stopre(source: &[u8], statement: &Statement) -> bool {
    matches!(&statement.kind, StatementKind::Command(name) if name.is(source, "STOPRE"))
}

/// Whether `statement` only declares (it may stand before the first
/// executable block, where DEF must be): DEF, PROC, REDEF, access levels,
/// EXTERN, DEFINE.
pub fn is_declaration(statement: &Statement) -> bool {
    matches!(
        statement.kind,
        StatementKind::Def(_)
            | StatementKind::Proc(_)
            | StatementKind::Redef { .. }
            | StatementKind::AccessLevels(_)
            | StatementKind::Extern { .. }
            | StatementKind::Define { .. }
    )
}

/// A macro whose text names it (directly or through others): the control
/// cannot expand it.
fn recursive_macro(source: &[u8], used: Span) -> Diagnostic {
    let name = String::from_utf8_lossy(used.of(source));
    crate::registry::syntax::RECURSIVE_MACRO
        .at(used)
        .message(format!(
            "macro `{name}` names itself in its text, directly or through other macros"
        ))
        .label("expands to itself")
        .help("define the macro without its own name (a macro's text may name other macros)")
}

/// Whether `name` is a keyword or reserved word, which a macro may not
/// redefine (Siemens, Job Planning, "Macro technique (DEFINE ... AS)").
pub fn is_reserved(name: &[u8]) -> bool {
    crate::syntax::lexer::is_one_of(name, crate::syntax::lexer::RESERVED)
}

fn macro_redefines_keyword(source: &[u8], name: Span) -> Diagnostic {
    let text = crate::syntax::tree::upper(name.of(source));
    crate::registry::syntax::MACRO_REDEFINES_KEYWORD
        .at(name)
        .message(format!("`{text}` is a keyword: a macro may not redefine it"))
        .label("a keyword")
        .help("give the macro a name of its own; G, M and H functions and subprogram names may be macros")
}

/// One line as the rules and the model see it, with what each statement
/// reads collected once: five rules need it, and none walks every
/// statement's expressions again.
pub struct LineView<'l> {
    pub raw: RawLine,
    /// The block, when the line is one.
    pub block: Option<&'l Block>,
    /// The name after `%` when the line is a program header (`%_N_PART_MPF`).
    pub header: Option<Span>,
    /// Every statement is an address word with a number (`G1 X-12.5`): the
    /// line defines, reads, calls and jumps nowhere. Most blocks of a CAM
    /// program are such, and most rules have nothing to do there.
    pub plain: bool,
    /// (statement index, variable read), in statement order.
    reads: Vec<(usize, &'l Variable)>,
    /// The block's address words, read when a rule first asks.
    addresses: OnceCell<Vec<Address>>,
    /// Whether the block leaves the order of the lines, decided when a rule
    /// first asks.
    leaves_line_order: OnceCell<bool>,
}

impl<'l> LineView<'l> {
    pub fn new(line: &'l Line) -> Self {
        let (block, header) = match &line.kind {
            LineKind::Block(block) => (Some(block), None),
            LineKind::Header { name } => (None, Some(*name)),
            LineKind::Path { .. } => (None, None),
        };
        let mut all_reads = Vec::new();
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
            each_read(statement, &mut |variable| all_reads.push((index, variable)));
        }
        Self {
            raw: line.raw,
            block,
            header,
            plain,
            reads: all_reads,
            addresses: OnceCell::new(),
            leaves_line_order: OnceCell::new(),
        }
    }

    /// The block's address words (see `addresses::of_block`), read once
    /// for all the rules that ask; none for a line that is no block.
    pub fn addresses(&self, source: &[u8]) -> &[Address] {
        self.addresses.get_or_init(|| match self.block {
            Some(block) => addresses::of_block(source, block),
            None => Vec::new(),
        })
    }

    /// The block jumps, calls what may change the modal state or starts a
    /// PROC (see `line_order::leaves_line_order`), decided once for all the
    /// rules that follow the lines in order; `false` for a line that is no
    /// block.
    pub fn leaves_line_order(&self, source: &[u8]) -> bool {
        *self.leaves_line_order.get_or_init(|| match self.block {
            // Address words alone leave the order only by a subprogram call.
            Some(_) if self.plain => self.addresses(source).iter().any(|a| a.is(source, "L")),
            Some(block) => line_order::leaves_line_order(source, block, self.addresses(source)),
            None => false,
        })
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

/// Builds a [`Model`] from the lines in order: each run of plain lines passed
/// with [`Self::plain_lines`], each other line parsed by [`Self::parse`], learned from
/// with [`Self::learn`] and kept with [`Self::keep`].
pub struct ModelBuilder<'src> {
    source: &'src [u8],
    keep_trees: bool,
    /// What the trees kept take, about ([`KEPT_TREE_BYTES`]).
    kept: usize,
    table: LinesRecorder,
    parser: LineParser,
    row: usize,
    syntax: Vec<Diagnostic>,
    labels: Labels,
    blocks: BlockMatcher,
    symbols: Vec<Symbol>,
    /// Where a name is made upper case to be looked up.
    name_buffer: String,
    read_names: HashSet<String>,
    stopre: Vec<usize>,
    jump_numbers: HashSet<u64>,
    first_executable: Option<(usize, usize)>,
    declarations_end: Option<usize>,
    /// The macros the next line is read with: the machine's, and those the
    /// program has defined so far.
    macros: Arc<Macros>,
    macro_uses: Vec<Use>,
    /// What the walk's [`Structure`] reads of each line, taken while its
    /// tree is at hand (when the trees are kept for the walk).
    line_facts: Option<LineFacts>,
}

impl<'src> ModelBuilder<'src> {
    /// A builder that keeps the trees it is given ([`Self::keep`]) when
    /// `keep_trees`: `check` keeps them only for the CYCLE600 walk.
    pub fn new(source: &'src [u8], keep_trees: bool) -> Self {
        Self {
            source,
            keep_trees,
            kept: 0,
            table: LinesRecorder::default(),
            parser: LineParser::default(),
            row: 0,
            syntax: Vec::new(),
            labels: Labels::default(),
            blocks: BlockMatcher::default(),
            symbols: Vec::new(),
            read_names: HashSet::default(),
            name_buffer: String::new(),
            stopre: Vec::new(),
            jump_numbers: HashSet::default(),
            first_executable: None,
            declarations_end: None,
            macros: Arc::default(),
            macro_uses: Vec::new(),
            line_facts: keep_trees.then(LineFacts::default),
        }
    }

    /// The lines read with `macros` expanded (the machine's definition
    /// files'); the program's own DEFINEs add to them from their line on.
    pub fn with_macros(mut self, macros: Arc<Macros>) -> Self {
        if !macros.is_empty() {
            // Their lines are read again with the macros (see `finish`).
            self.line_facts = None;
        }
        self.macros = macros;
        self
    }

    /// Whether the plain line `raw` names a macro (one named as an address
    /// word, `M6`): it is then parsed as the control reads it, not scanned.
    pub fn expands(&self, raw: RawLine) -> bool {
        self.macros.reach_plain_lines() && self.macros.named_in(raw.content.of(self.source))
    }

    /// Whether a plain line may name a macro now (see [`Macros::reach_plain_lines`]).
    pub fn macros_reach_plain_lines(&self) -> bool {
        self.macros.reach_plain_lines()
    }

    /// The next lines, plain ones: only their words matter. Taken a run at
    /// a time, since a CAM program is millions of them.
    pub fn plain_lines(&mut self, lines: &[PlainLine]) {
        debug_assert!(lines.first().is_none_or(|line| line.row == self.row));
        self.table
            .record_plain_run(lines.len(), |n| lines[n].raw.content.start);
        self.parser.pass_plain_lines(lines.len());
        if self.first_executable.is_none() {
            if let Some(line) = lines.iter().find(|line| line.facts.has_words()) {
                self.first_executable = Some((line.row, line.raw.content.start));
            }
        }
        self.row += lines.len();
    }

    /// The next line, one that is not plain: its tree, its syntax error kept.
    pub fn parse(&mut self, raw: RawLine) -> Line {
        self.table.record_other(raw.content.start);
        self.row += 1;
        if self.macros.is_empty() {
            let (tree, error) = self.parser.parse_line(self.source, raw);
            self.syntax.extend(error);
            return tree;
        }
        let (tree, error, expansion) =
            self.parser
                .parse_line_expanding(self.source, raw, &self.macros);
        self.syntax.extend(error);
        if let Some(expansion) = expansion {
            for used in expansion.uses.iter().filter(|u| u.recursive) {
                self.syntax.push(recursive_macro(self.source, used.span));
            }
            self.macro_uses.extend(expansion.uses);
        }
        tree
    }

    /// The next line, one that is not plain, parsed ahead of the model
    /// (see [`crate::syntax::ahead`]): its syntax error kept.
    pub fn parsed(&mut self, tree: Line, error: Option<Diagnostic>) -> Line {
        debug_assert!(self.macros.is_empty(), "lines with macros are parsed here");
        self.table.record_other(tree.raw.content.start);
        self.row += 1;
        self.syntax.extend(error);
        tree
    }

    /// The parser the lines read ahead leave (see [`crate::syntax::ahead`]):
    /// the model parses the next lines with it.
    pub fn parse_on_with(&mut self, parser: LineParser) {
        self.parser = parser;
    }

    /// What the line just parsed defines, reads and marks.
    pub fn learn(&mut self, view: &LineView) {
        let row = self.row - 1;
        let source = self.source;
        let Some(block) = view.block else {
            return;
        };
        if let Some(label) = block.label {
            self.labels.record(source, row, label.span);
        }
        if block.statements.is_empty() {
            return;
        }
        if self.first_executable.is_none() {
            if block.statements.iter().all(is_declaration) {
                self.declarations_end = Some(view.raw.full().end);
            } else {
                self.first_executable = Some((row, view.raw.content.start));
            }
        }
        if let Some(facts) = &mut self.line_facts {
            facts.line(source, row, block);
        }
        if view.plain {
            return;
        }
        self.blocks.line(row, block);
        for goto in gotos(block) {
            jumps::named_number(source, goto.target.as_ref(), &mut self.jump_numbers);
        }
        for (index, statement) in block.statements.iter().enumerate() {
            // ENDFOR reads the counter: it counts it up and compares it with
            // the end value.
            let counter = match &statement.kind {
                StatementKind::For { variable, .. } => Some(variable.text(source)),
                _ => None,
            };
            let names = view.reads(index).map(|v| v.name.text(source));
            for name in names.chain(counter) {
                let name = upper_in(name, &mut self.name_buffer);
                if !self.read_names.contains(name) {
                    self.read_names.insert(name.to_string());
                }
            }
            let symbol = |declarator: &crate::syntax::tree::Declarator,
                          data_type: &DataType,
                          global: bool,
                          parameter: bool| Symbol {
                name: upper(declarator.name.text(source)),
                span: declarator.name.span,
                row,
                data_type: data_type.clone(),
                global,
                parameter,
            };
            match &statement.kind {
                StatementKind::Def(def) => self.symbols.extend(
                    def.variables
                        .iter()
                        .map(|d| symbol(d, &def.data_type, def.scope.is_some(), false)),
                ),
                StatementKind::Proc(proc) => self.symbols.extend(
                    proc.parameters
                        .iter()
                        .map(|p| symbol(&p.declarator, &p.data_type, false, true)),
                ),
                StatementKind::Define { name, body } => {
                    if is_reserved(name.text(source)) {
                        self.syntax.push(macro_redefines_keyword(source, name.span));
                    } else {
                        Arc::make_mut(&mut self.macros).define(name.text(source), body.of(source));
                        self.line_facts = None;
                    }
                }
                _ if is_stopre(source, statement) => self.stopre.push(row),
                _ => {}
            }
        }
    }

    /// Keeps the tree of the line just parsed for the passes after this one
    /// (if the builder keeps trees; passes asking for a line not kept parse it).
    /// A tree not kept is given back, to be dropped where the caller says
    /// (the thread that made it: see [`crate::syntax::ahead`]).
    /// Inlined: a tree is a few hundred bytes, copied on every call.
    #[inline]
    pub fn keep(&mut self, line: Line) -> Option<Line> {
        if !self.keep_trees {
            return Some(line);
        }
        let statements = match &line.kind {
            LineKind::Block(block) => block.statements.len(),
            _ => 0,
        };
        self.kept += std::mem::size_of::<(usize, Line)>()
            + statements * std::mem::size_of::<Statement>()
            + TREE_BYTES_PER_BYTE * line.raw.content.len();
        if self.kept > KEPT_TREE_BYTES {
            return Some(line);
        }
        self.table.keep(line);
        None
    }

    pub fn finish(self, kind: ProgramKind) -> Model<'src> {
        let mut lines = self.table.finish(self.source);
        // A line parsed again is read with the macros defined at the
        // program's end, not those of its own line: the facts taken on the
        // way stand for the lines only where there are none.
        let line_facts = self.line_facts.filter(|_| self.macros.is_empty());
        if !self.macros.is_empty() {
            lines.read_with(self.macros);
        }
        let model = Model {
            source: self.source,
            kind,
            lines,
            syntax: self.syntax,
            labels: self.labels.sorted(),
            blocks: self.blocks.finish(),
            symbols: self.symbols,
            read_names: self.read_names,
            stopre: self.stopre,
            first_executable: self.first_executable,
            declarations_end: self.declarations_end,
            macro_uses: self.macro_uses,
            jump_numbers: self.jump_numbers,
            block_numbers: OnceLock::new(),
            structure: OnceLock::new(),
        };
        if let Some(facts) = line_facts {
            let _ = model.structure.set(Structure::of(facts, &model));
        }
        model
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::tree::TypeKind;

    /// Where a jump lands, for every reader: a label or a block number
    /// (`N20`, `N020`, `GOTOF 20` the same block), searched in the jump's
    /// direction; numbers no jump names are not read.
    #[test]
    fn the_model_says_where_each_jump_lands() {
        let program = "N10 GOTOF N020\nN20 LBL:\nN30 GOTOB LBL\nN40 GOTOF LBL\nN20 M30\n";
        let model = Model::of(program.as_bytes());
        assert_eq!(model.block_numbers(), [(20, 1), (20, 4)]);
        assert_eq!(model.target_rows(&Target::Number(20)), [1, 4]);
        assert_eq!(model.target_rows(&Target::Number(30)), [] as [usize; 0]);
        let label = Target::Label("LBL".to_string());
        assert_eq!(model.target_landing(&label, GotoKind::Backward, 2), Some(1));
        assert_eq!(model.target_landing(&label, GotoKind::Forward, 3), None);
        let number = Target::Number(20);
        assert_eq!(model.target_landing(&number, GotoKind::Forward, 0), Some(1));
        assert_eq!(model.target_landing(&number, GotoKind::Forward, 1), Some(4));
        assert_eq!(model.target_landing(&number, GotoKind::Backward, 0), None);
    }

    const PROGRAM: &str = "PROC PART(REAL DEPTH)\nDEF REAL _X, COUNT\nEXTERN SUB(INT)\nDEF NCK INT LIMIT\nSTART:\nG0 X10\nSTOPRE\nR1=DEPTH+_X\nIF R1>0 GOTOB START\nM17\n";

    #[test]
    fn the_model_knows_symbols_labels_stopre_and_where_declarations_end() {
        let model = Model::of(PROGRAM.as_bytes());
        assert_eq!(model.kind, ProgramKind::Subprogram);
        let symbols: Vec<(&str, usize, TypeKind, bool, bool)> = model
            .symbols
            .iter()
            .map(|s| {
                (
                    s.name.as_str(),
                    s.row,
                    s.data_type.kind,
                    s.global,
                    s.parameter,
                )
            })
            .collect();
        assert_eq!(
            symbols,
            [
                ("DEPTH", 0, TypeKind::Real, false, true),
                ("_X", 1, TypeKind::Real, false, false),
                ("COUNT", 1, TypeKind::Real, false, false),
                ("LIMIT", 3, TypeKind::Int, true, false),
            ]
        );
        assert_eq!(model.labels.rows("START").collect::<Vec<_>>(), [4]);
        assert_eq!(model.stopre, [6]);
        assert!(model.read_names.contains("DEPTH") && model.read_names.contains("_X"));
        assert!(!model.read_names.contains("COUNT"));
        // EXTERN declares, and a label alone executes nothing: added DEF lines go
        // after the last DEF, and the first executable block is `G0 X10`.
        let after_limit = PROGRAM.find("START:").expect("in the program");
        assert_eq!(model.declarations_insertion(), after_limit);
        assert_eq!(model.first_executable.map(|(row, _)| row), Some(5));
        assert_eq!(model.first_r_parameter(1..2).map(|(n, _)| n), Some(1));
        assert_eq!(model.first_r_parameter(2..10), None);
        assert!(model.syntax.is_empty());
    }

    /// The blocks are matched in the model's own pass, plain lines between
    /// them and a macro's expansion read as the control reads them.
    #[test]
    fn the_model_matches_the_control_blocks_once() {
        let text = "DEFINE CLOSE AS ENDIF\nIF R1>0\nG1 X1\nN20 ELSE\nCLOSE\nWHILE R2<1\n";
        let model = Model::of(text.as_bytes());
        let closed: Vec<(usize, Option<usize>, usize)> = model
            .blocks
            .closed()
            .iter()
            .map(|c| (c.row, c.else_row, c.end))
            .collect();
        assert_eq!(closed, [(1, Some(3), 4)]);
        assert_eq!(model.blocks.else_end(3), Some(4));
        assert!(matches!(
            model.blocks.faults[..],
            [crate::semantic::blocks::Fault::NeverClosed(open)] if open.row == 5
        ));
    }

    #[test]
    fn without_declarations_they_go_before_the_first_executable_block_or_at_the_end() {
        let model = Model::of(b"; a comment\nG1 X1 F100\nM30\n");
        assert_eq!(model.declarations_insertion(), 12);
        let model = Model::of(b"; only a comment\n");
        assert_eq!(model.declarations_insertion(), 17);
        // An assignment executes: a DEF after it is no declaration of the head.
        let model = Model::of(b"DEF REAL A\nR1=5\nDEF REAL B\nG0 X1\n");
        assert_eq!(model.first_executable, Some((1, 11)));
        assert_eq!(model.declarations_insertion(), 11);
    }

    #[test]
    fn the_trees_of_lines_not_plain_are_kept_and_plain_ones_parsed_when_asked() {
        let model = Model::of(b"R1=5\nG1 X1\n");
        assert!(matches!(model.lines.line(0), std::borrow::Cow::Borrowed(_)));
        assert!(matches!(model.lines.line(1), std::borrow::Cow::Owned(_)));
        assert!(!model.lines.is_empty() && Model::of(b"").lines.is_empty());
    }

    proptest::proptest! {
        /// Every tree the model gives back, kept or parsed again, is the one
        /// a fresh parse of the whole program builds.
        #[test]
        fn the_kept_trees_are_the_parsed_ones(
            lines in proptest::collection::vec(
                "(N[0-9]{1,3} )?(G1 X[0-9]|R1=R2\\+1|DEF REAL A[0-9]|L[A-Z]: X1|IF R1==1 GOTOF LA|IF R1|ENDIF|; c|X=\\(|)",
                0..40,
            ),
        ) {
            let text = lines.join("\n");
            let model = Model::of(text.as_bytes());
            let program = crate::syntax::parse(text.as_bytes());
            proptest::prop_assert_eq!(model.lines.len(), program.lines.len());
            for (index, expected) in program.lines.iter().enumerate() {
                proptest::prop_assert_eq!(&*model.lines.line(index), expected);
            }
            proptest::prop_assert_eq!(&model.syntax, &program.diagnostics);
        }
    }

    /// A file of short lines keeps no more trees than the bound allows (a
    /// bound on source bytes alone would let 1 MiB of `IF R1>0` keep 130,000
    /// trees, a kilobyte each); the lines past it are parsed again when asked.
    #[test]
    fn short_lines_keep_trees_within_the_bound() {
        let text = "IF R1>0\n".repeat(150_000);
        let model = Model::of(text.as_bytes());
        let kept = model
            .lines
            .other_lines()
            .filter(|(_, line)| matches!(line, std::borrow::Cow::Borrowed(_)))
            .count();
        let each = std::mem::size_of::<(usize, Line)>() + std::mem::size_of::<Statement>();
        assert!(kept > 0);
        assert!(kept * each <= KEPT_TREE_BYTES, "{kept} trees kept");
        let program = crate::syntax::parse(text.as_bytes());
        assert_eq!(*model.lines.line(149_999), program.lines[149_999]);
    }
}
