//! The lossless syntax tree: what was written, with a span for every part.
//!
//! Nodes hold spans, never copies of the text: the bytes between and around
//! nodes (blanks, `&`, comments) are simply the source bytes between spans, so
//! printing a program is copying its lines. Names are compared
//! case-insensitively through [`Name::is`]. Nothing here evaluates anything.

use crate::span::Span;
use crate::syntax::lines::RawLine;

/// One physical line of the program.
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    pub raw: RawLine,
    pub kind: LineKind,
}

#[derive(Clone, Debug, PartialEq)]
pub enum LineKind {
    /// `%_N_NAME_MPF`: the archive header naming the program.
    Header { name: Span },
    /// `;$PATH=/_N_MPF_DIR`: the target directory of the archive.
    Path { directory: Span },
    /// Every other line, empty ones included.
    Block(Block),
}

/// `[/n] [Nnnn | :nnn] [LABEL:] statement* [; comment]`
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Block {
    pub skip: Option<Skip>,
    pub number: Option<BlockNumber>,
    pub label: Option<Name>,
    pub statements: Vec<Statement>,
    pub comment: Option<Span>,
    /// The rest of the line from the first byte the parser could not read
    /// (with a syntax diagnostic); kept as it is.
    pub unparsed: Option<Span>,
}

impl Block {
    pub fn is_empty(&self) -> bool {
        self.statements.is_empty() && self.unparsed.is_none()
    }
}

/// `/` or `/0`..`/9` at the start of a block.
#[derive(Clone, Debug, PartialEq)]
pub struct Skip {
    pub span: Span,
    pub level: Option<u8>,
}

/// `N10` or the main block number `:10`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlockNumber {
    pub span: Span,
    pub main: bool,
    /// The digits only.
    pub digits: Span,
}

/// An identifier as written; compare with [`Name::is`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Name {
    pub span: Span,
}

/// A name as the control compares it: in upper case, since the control
/// ignores case (bytes that are not UTF-8 become the replacement character).
pub fn upper(text: &[u8]) -> String {
    // Names are ASCII: one check and one copy, not the lossy decoder's walk.
    match std::str::from_utf8(text) {
        Ok(text) => text.to_ascii_uppercase(),
        Err(_) => String::from_utf8_lossy(text).to_ascii_uppercase(),
    }
}

/// `text` in upper case, written into `buffer` over what it held: a name
/// to look up without making a new string for it.
pub fn upper_in<'b>(text: &[u8], buffer: &'b mut String) -> &'b str {
    buffer.clear();
    match std::str::from_utf8(text) {
        Ok(text) => buffer.push_str(text),
        Err(_) => buffer.push_str(&String::from_utf8_lossy(text)),
    }
    buffer.make_ascii_uppercase();
    buffer
}

/// Whether `text` starts with the upper-case `prefix` in any case, as the
/// control compares names; without making the name's upper case.
pub fn starts_with_upper(text: &[u8], prefix: &str) -> bool {
    text.get(..prefix.len())
        .is_some_and(|start| start.eq_ignore_ascii_case(prefix.as_bytes()))
}

impl Name {
    pub fn text(self, source: &[u8]) -> &[u8] {
        self.span.of(source)
    }

    /// The name in upper case, as the control compares names.
    pub fn upper(self, source: &[u8]) -> String {
        upper(self.text(source))
    }

    /// Case-insensitive comparison with an upper-case keyword.
    pub fn is(self, source: &[u8], upper: &str) -> bool {
        self.text(source).eq_ignore_ascii_case(upper.as_bytes())
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Statement {
    pub span: Span,
    pub kind: StatementKind,
}

#[derive(Clone, Debug, PartialEq)]
pub enum StatementKind {
    /// An address word: `X12.5`, `G01`, `X=R1+2`, `A3=0.5`, `T="BALL_D6"`.
    Word(Word),
    /// `R1=1`, `_X=2`, `$P_UIFR[1]=CTRANS(X,15)`, `CR=20`.
    Assign(Assign),
    /// A cycle, subprogram or procedure call with arguments: `CYCLE800(...)`.
    Call(Call),
    /// A bare name: a G function (`TRAORI`, `SUPA`), a command (`STOPRE`) or a
    /// subprogram called without arguments (`CYCLE977`).
    Command(Name),
    /// `TRANS`, `AROT`, ... : the address words after it in the block are its values.
    Frame(FrameStatement),
    // Boxed, as are the other rare large statements, so that a statement
    // stays small: CAM blocks of address words are moved and stored by the
    // million.
    Def(Box<Def>),
    /// `REDEF NAME APR 7 APW 1`: new attributes for a variable (a GUD, a
    /// system variable, machine data) defined elsewhere.
    Redef {
        name: Name,
        attributes: Vec<Attribute>,
    },
    /// `APW 2 APR 7` alone in a block of a definition file: the access
    /// levels of the definitions after it.
    AccessLevels(Vec<Attribute>),
    Proc(Proc),
    /// `EXTERN NAME(REAL, VAR BOOL)`: the declaration is kept as written.
    Extern {
        name: Name,
        parameters: Option<Span>,
    },
    /// `DEFINE NAME AS text`: the macro text is kept as written.
    Define {
        name: Name,
        body: Span,
    },
    /// `IF cond`; a `GOTO…` after it in the same block makes it a one-line jump.
    If {
        condition: Expr,
    },
    Else,
    EndIf,
    While {
        condition: Expr,
    },
    EndWhile,
    For {
        variable: Name,
        start: Box<Expr>,
        end: Box<Expr>,
    },
    EndFor,
    Loop,
    EndLoop,
    /// `REPEAT` (opens a REPEAT/UNTIL loop), `REPEAT LBL1 [LBL2] [P=n]` or
    /// `REPEATB LBL [P=n]`.
    Repeat {
        targets: Vec<Name>,
        /// The `n` of `P=n`: how many times.
        count: Option<Box<Expr>>,
    },
    Until {
        condition: Expr,
    },
    Case(Box<Case>),
    Goto(Goto),
    /// `CALL`, `PCALL`, `MCALL`, `EXTCALL` with what follows kept as written.
    IndirectCall {
        keyword: Name,
        target: Option<Span>,
    },
    /// A synchronized action, the whole rest of its block: its actions run
    /// in the main run, not while the program is preprocessed.
    SyncAction(Box<SyncAction>),
}

/// `[ID=n | IDS=n] [WHEN | WHENEVER | FROM | EVERY [G..] condition] DO actions [ELSE actions]`
/// (Siemens, Function Manual Synchronized actions, "Definition of a
/// synchronized action").
#[derive(Clone, Debug, PartialEq)]
pub struct SyncAction {
    /// `ID=n` (modal) or `IDS=n` (static): the keyword and the number.
    pub id: Option<(Name, Expr)>,
    pub condition: Option<SyncCondition>,
    pub do_keyword: Name,
    /// Address words, assignments, calls and commands, in order.
    pub actions: Vec<Statement>,
    /// `ELSE` and its actions, run while the condition is not met.
    pub otherwise: Option<(Name, Vec<Statement>)>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct SyncCondition {
    /// `WHEN`, `WHENEVER`, `FROM` or `EVERY`: how often the condition is tested.
    pub frequency: Name,
    /// G functions that set the units the condition is tested in (`G710`).
    pub g_functions: Vec<Statement>,
    pub expr: Expr,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Word {
    /// The address letter.
    pub address: Name,
    /// The extension digits of `A3=`, `X1=`, `M1=`.
    pub extension: Option<Span>,
    pub value: WordValue,
}

#[derive(Clone, Debug, PartialEq)]
pub enum WordValue {
    /// `X12.5`, `X-.5`: the number directly after the address.
    Number(Number),
    /// `X=expr`.
    Expr(Expr),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Assign {
    pub target: Variable,
    pub value: Expr,
}

/// A variable reference: `R1`, `_OVR[16]`, `A[1,2]`, `$AA_MW[X]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Variable {
    pub span: Span,
    pub name: Name,
    pub indices: Vec<Expr>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Call {
    pub name: Name,
    pub arguments: Arguments,
}

/// `( arg, , arg )`: positional arguments, empty ones included.
#[derive(Clone, Debug, PartialEq)]
pub struct Arguments {
    /// From `(` to `)` inclusive.
    pub span: Span,
    pub items: Vec<Argument>,
}

/// One argument; an empty one (`,,`) has no value and an empty span where it stands.
#[derive(Clone, Debug, PartialEq)]
pub struct Argument {
    pub span: Span,
    pub value: Option<Expr>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameKind {
    Trans,
    ATrans,
    Rot,
    ARot,
    Rots,
    ARots,
    CRots,
    Scale,
    AScale,
    Mirror,
    AMirror,
}

impl FrameKind {
    pub const ALL: [(&'static str, FrameKind); 11] = [
        ("TRANS", FrameKind::Trans),
        ("ATRANS", FrameKind::ATrans),
        ("ROT", FrameKind::Rot),
        ("AROT", FrameKind::ARot),
        ("ROTS", FrameKind::Rots),
        ("AROTS", FrameKind::ARots),
        ("CROTS", FrameKind::CRots),
        ("SCALE", FrameKind::Scale),
        ("ASCALE", FrameKind::AScale),
        ("MIRROR", FrameKind::Mirror),
        ("AMIRROR", FrameKind::AMirror),
    ];
}

#[derive(Clone, Debug, PartialEq)]
pub struct FrameStatement {
    pub keyword: Name,
    pub kind: FrameKind,
}

/// `DEF [NCK|CHAN] [attributes] TYPE [attributes] name[dims] [= init], ...`
#[derive(Clone, Debug, PartialEq)]
pub struct Def {
    /// `NCK` or `CHAN` for global user data (GUD).
    pub scope: Option<Name>,
    pub attributes: Vec<Attribute>,
    pub data_type: DataType,
    pub variables: Vec<Declarator>,
}

/// `APW 5`, `LLI -100.0`, `SYNR`, `INIRE`, ...
#[derive(Clone, Debug, PartialEq)]
pub struct Attribute {
    pub keyword: Name,
    pub value: Option<Expr>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TypeKind {
    Int,
    Real,
    Bool,
    Char,
    String,
    Axis,
    Frame,
}

#[derive(Clone, Debug, PartialEq)]
pub struct DataType {
    pub span: Span,
    pub kind: TypeKind,
    /// `n` of `STRING[n]`.
    pub length: Option<Expr>,
}

/// `name[dims] [= init]` in a DEF or a PROC parameter list.
#[derive(Clone, Debug, PartialEq)]
pub struct Declarator {
    pub name: Name,
    /// Array dimensions; an open one (`[,5]`) has no value.
    pub dimensions: Vec<Argument>,
    pub init: Option<Initializer>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Initializer {
    Expr(Expr),
    /// `= (0.6, 0.7, 0.5)`
    List(Arguments),
}

/// `PROC NAME(params) attributes`
#[derive(Clone, Debug, PartialEq)]
pub struct Proc {
    pub name: Name,
    pub parameters: Vec<Parameter>,
    /// `SAVE`, `SBLOF`, `DISPLOF`, ...
    pub attributes: Vec<Name>,
}

/// `[VAR] TYPE name[dims] [= default]`
#[derive(Clone, Debug, PartialEq)]
pub struct Parameter {
    pub span: Span,
    pub by_reference: bool,
    pub data_type: DataType,
    pub declarator: Declarator,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GotoKind {
    /// `GOTOF`: search forward.
    Forward,
    /// `GOTOB`: search backward.
    Backward,
    /// `GOTO`: forward, then backward.
    Both,
    /// `GOTOC`: like GOTO, without an alarm when the target is missing.
    Conditional,
    /// `GOTOS`: back to the program start.
    Start,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Goto {
    pub keyword: Name,
    pub kind: GotoKind,
    pub target: Option<GotoTarget>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum GotoTarget {
    /// A label or a block number such as `N100`.
    Label(Name),
    /// A bare block number, `GOTOF 90`.
    Number(Number),
    /// A computed target, `GOTOF "LBL"<<IDX`.
    Computed(Expr),
}

impl GotoTarget {
    /// The block number the jump names: `GOTOF N100`, `GOTOF N0100` (the
    /// same block), `GOTOF 100`; `None` for a label or a computed target.
    pub fn block_number(&self, source: &[u8]) -> Option<u64> {
        match self {
            GotoTarget::Label(name) => match name.text(source) {
                [b'N' | b'n', digits @ ..] if !digits.is_empty() => {
                    crate::syntax::plain::digits_value(digits)
                }
                _ => None,
            },
            GotoTarget::Number(number) => Some(number.value as u64),
            GotoTarget::Computed(_) => None,
        }
    }
}

/// `CASE expr OF c1 GOTOF L1 c2 GOTOF L2 DEFAULT GOTOF LD`
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    pub selector: Expr,
    pub branches: Vec<(Expr, Goto)>,
    pub default: Option<Goto>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NumberKind {
    Decimal,
    Hex,
    Binary,
}

/// A numeric literal: its spelling is its span, its value is parsed once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Number {
    pub span: Span,
    pub value: f64,
    pub kind: NumberKind,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub span: Span,
    pub kind: ExprKind,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    Number(Number),
    /// A string literal; the span includes the quotes.
    String,
    Variable(Variable),
    /// `SIN(30)`, `IC(5)`, `CTRANS(X,15)`.
    Call(Call),
    Unary {
        op: UnaryOp,
        operand: Box<Expr>,
    },
    Binary {
        op: BinaryOp,
        lhs: Box<Expr>,
        rhs: Box<Expr>,
    },
    Paren(Box<Expr>),
    /// `(1+2, 16+32+64)`: the values of an indexed assignment that takes
    /// several (`OSCTRL[Z]=(...)`, `POSP[X]=(END, PART, MODE)`, `PO[X]=(...)`).
    Tuple(Arguments),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    Neg,
    Plus,
    Not,
    BitNot,
    /// `<<` with nothing before it: the operand as a string (Siemens, Job
    /// Planning, "String concatenation": `STRING_ERG = << any type`).
    Concat,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    Mul,
    Div,
    IntDiv,
    Mod,
    Add,
    Sub,
    BitAnd,
    BitXor,
    BitOr,
    And,
    Xor,
    Or,
    Concat,
    Eq,
    Ne,
    Lt,
    Gt,
    Le,
    Ge,
    /// `:`, frame chaining.
    Chain,
}
