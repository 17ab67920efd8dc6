//! Machine data as the files the control writes hold them (`INITIAL.INI`,
//! `_N_NC_TEA_INI`, `_N_CH1_TEA_INI`, `_N_AX1_TEA_INI`, an archive's data
//! members): one assignment a line, optionally numbered by the datum
//! (`N36110 $MA_POS_LIMIT_PLUS[AX1]=1500.6`); an axis datum indexed by its
//! axis (`[AX1]`, or `[0,AX1]` for one of several values), a channel's data
//! after `CHANDATA(n)`. Every machine datum (`$MN_`, `$MC_`, `$MA_`),
//! setting datum (`$SN_`, `$SC_`, `$SA_`), tool offset (`$TC_DPn[t,d]`) and
//! settable frame component (`$P_UIFR[n,X,TR]`) is kept by name and index,
//! so that what a program reads of them can be answered offline. Read with the
//! project's own parser, and only the lines that name such a datum or
//! `CHANDATA`: a file of thousands of tool data lines passes at the speed
//! of a byte search.

use crate::diagnostic::Diagnostic;
use crate::registry::unreadable_machine_data::RULE;
use crate::semantic::env::Env;
use crate::semantic::eval::evaluate;
use crate::semantic::value::Value;
use crate::semantic::Supplied;
use crate::span::Span;
use crate::syntax::lines::RawLine;
use crate::syntax::tree::{BinaryOp, Expr, ExprKind, LineKind, StatementKind, Variable};
use crate::syntax::WordFinder;

/// The prefixes of the data kept: machine data of the NC, the channel and
/// the axes, setting data of the same three, the tool offsets, the settable
/// frames and the base frames (of the NC and of the channel).
const PREFIXES: [&str; 10] = [
    "$MN_", "$MC_", "$MA_", "$SN_", "$SC_", "$SA_", "$TC_DP", "$P_UIFR", "$P_NCBFR", "$P_CHBFR",
];

/// One index of a datum.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Index {
    Number(u32),
    /// An axis by name, upper case: `AX1`, or the machine axis's name (`X1`).
    Axis(String),
}

/// One datum as a line assigns it.
#[derive(Clone, Debug, PartialEq)]
pub struct Datum {
    /// Upper case, with its prefix: `$MA_POS_LIMIT_PLUS`.
    pub name: String,
    /// The channel of the `CHANDATA(n)` before it; `None` before any.
    pub channel: Option<u32>,
    pub indices: Vec<Index>,
    pub value: Value,
    /// The assignment.
    pub span: Span,
}

/// A frame a line assigns whole (`$P_UIFR[25]=CTRANS(X,1212,Y,1362)`, as
/// series start-up archives hold them): its components by axis.
#[derive(Clone, Debug, PartialEq)]
pub struct WholeFrame {
    /// Upper case: `$P_UIFR`, `$P_NCBFR`, `$P_CHBFR`.
    pub name: String,
    pub channel: Option<u32>,
    pub index: u32,
    pub components: Vec<Component>,
    pub span: Span,
}

/// One component of a frame: the axis (upper case), which (`TR`, `FI`,
/// `RT`, `SC`, `MI`) and its value.
pub type Component = (String, &'static str, f64);

/// The data of one file, and what in it could not be read.
#[derive(Debug, Default)]
pub struct MachineData {
    /// In the order of the lines.
    pub data: Vec<Datum>,
    /// The frames assigned whole, in the order of the lines.
    pub frames: Vec<WholeFrame>,
    /// The values the data give variables of programs: GUD variables
    /// (`_DM_GUD_INCH_MM=1`) and R parameters (`R[100]=1.2`), as an archive
    /// holds the control's state; constants only, in the order of the lines.
    pub values: Vec<Datum>,
    /// K006, and the syntax errors of the lines not read, in line order.
    pub diagnostics: Vec<Diagnostic>,
}

impl MachineData {
    pub fn read(source: &[u8]) -> MachineData {
        let mut read = MachineData::default();
        let finders = [
            WordFinder::new("$M"),
            WordFinder::new("$S"),
            WordFinder::new("$TC_DP"),
            WordFinder::new("$P_UIFR"),
            WordFinder::new("$P_NCBFR"),
            WordFinder::new("$P_CHBFR"),
            WordFinder::new("CHANDATA"),
        ];
        let env = Env::default();
        let supplied = Supplied::default();
        let scope = env.scope(&supplied, 0);
        let mut channel = None;
        let mut parser = crate::syntax::LineParser::default();
        for raw in crate::syntax::lines::raw_lines(source) {
            let raw = without_checksum(source, raw);
            let content = raw.content.of(source);
            let datum = finders.iter().any(|f| f.in_line(content));
            if !datum && !assigns_variable(content) {
                continue;
            }
            let (line, error) = parser.parse_line(source, raw);
            if let Some(error) = error {
                // The parser's own finding: nothing of the line is read.
                read.diagnostics.push(error);
                continue;
            }
            let LineKind::Block(block) = &line.kind else {
                continue;
            };
            for statement in &block.statements {
                match &statement.kind {
                    StatementKind::Call(call) if call.name.is(source, "CHANDATA") => {
                        let number = call.arguments.items.first().and_then(|a| a.value.as_ref());
                        match number.and_then(|n| whole(source, n, &scope)) {
                            Some(n) => channel = Some(n),
                            None => read.diagnostics.push(
                                RULE.at(call.arguments.span)
                                    .message("CHANDATA takes the channel's number, a whole number from 1")
                                    .label("no channel number"),
                            ),
                        }
                    }
                    StatementKind::Assign(assign) if !datum => {
                        // A variable's value: kept where it is a constant.
                        let name = assign.target.name.upper(source);
                        if name.starts_with('$') {
                            continue;
                        }
                        let indices = indices(source, &assign.target, &scope);
                        let value = evaluate(source, &assign.value, &scope);
                        if let (Some(indices), Ok(value)) = (indices, value) {
                            read.values.push(Datum {
                                name,
                                channel,
                                indices,
                                value,
                                span: statement.span,
                            });
                        }
                    }
                    StatementKind::Assign(assign) => {
                        let name = assign.target.name.upper(source);
                        if !PREFIXES.iter().any(|p| name.starts_with(p)) {
                            continue;
                        }
                        let indices = indices(source, &assign.target, &scope);
                        let Some(indices) = indices else {
                            read.diagnostics.push(
                                RULE.at(assign.target.span)
                                    .message(format!("`{name}` is indexed by something other than a whole number or an axis name"))
                                    .label("index not read")
                                    .help("an index is a number (`[0]`) or an axis (`[AX1]`, `[0,AX1]`), as the control writes them"),
                            );
                            continue;
                        };
                        if let (true, [Index::Number(index)]) =
                            (name.starts_with("$P_"), indices.as_slice())
                        {
                            match whole_frame(source, &assign.value, &scope) {
                                Some(components) => read.frames.push(WholeFrame {
                                    name,
                                    channel,
                                    index: *index,
                                    components,
                                    span: statement.span,
                                }),
                                None => read.diagnostics.push(
                                    RULE.at(assign.value.span)
                                        .message(format!("the frame `{name}[{index}]` is not read: it is neither a chain of CTRANS, CFINE, CROT, CSCALE and CMIRROR with constants nor written component by component"))
                                        .label("frame not read")
                                        .help("copy the frame as the control writes it: `$P_UIFR[1]=CTRANS(X,10,Y,20):CROT(Z,30)`, or `$P_UIFR[1,X,TR]=10`"),
                                ),
                            }
                            continue;
                        }
                        match evaluate(source, &assign.value, &scope) {
                            Ok(value) => read.data.push(Datum {
                                name,
                                channel,
                                indices,
                                value,
                                span: statement.span,
                            }),
                            Err(_) => read.diagnostics.push(
                                RULE.at(assign.value.span)
                                    .message(format!("the value of `{name}` is no constant"))
                                    .label("not a value sinuprep can read")
                                    .help("the files the control writes hold constants: copy the datum from the control as it is"),
                            ),
                        }
                    }
                    _ => {}
                }
            }
        }
        read
    }

    /// The value the last line that assigns `name` (upper case) with these
    /// indices gives it, in `channel` for a channel's datum.
    pub fn get(&self, name: &str, channel: Option<u32>, indices: &[Index]) -> Option<&Value> {
        self.data
            .iter()
            .rev()
            .find(|d| d.name == name && d.indices == indices && d.channel == channel)
            .map(|d| &d.value)
    }

    /// Every datum named `name` (upper case), in line order.
    pub fn named<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Datum> + 'a {
        self.data.iter().filter(move |d| d.name == name)
    }
}

/// Whether a line may assign a program's variable: a name first (a GUD
/// variable, `R[n]`), not a system variable, and an `=`.
fn assigns_variable(content: &[u8]) -> bool {
    let start = content.trim_ascii_start();
    start
        .first()
        .is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_')
        && !start.starts_with(b"DEF ")
        && !(start[0] == b'N' && start.get(1).is_some_and(u8::is_ascii_digit))
        && start.contains(&b'=')
}

/// A line as the files of a series start-up archive may hold it ends in a
/// checksum, a blank, an apostrophe and four hexadecimal digits
/// (`N10000 $MN_AXCONF_MACHAX_NAME_TAB[1]="C1" '5b7e`): read without it.
fn without_checksum(source: &[u8], raw: RawLine) -> RawLine {
    let content = raw.content.of(source).trim_ascii_end();
    let n = content.len();
    let checksum = n >= 6
        && content[n - 6].is_ascii_whitespace()
        && content[n - 5] == b'\''
        && content[n - 4..].iter().all(u8::is_ascii_hexdigit);
    if !checksum {
        return raw;
    }
    RawLine {
        content: Span::new(raw.content.start, raw.content.start + n - 6),
        ending: raw.ending,
    }
}

/// A frame written whole as a chain of the frame functions the control
/// writes, each with constants: `CTRANS(X,10,Y,20)` (coarse translation),
/// `CFINE(X,0.1)`, `CROT(Z,30)` (degrees), `CSCALE(X,2)`, `CMIRROR(X)`, joined
/// by `:` (Siemens, Job Planning, "Frames", "Predefined frame functions");
/// `CTRANS()` alone is the zero frame. `None` for anything else, one
/// function twice or out of that order (a chain of two shifts, or a turn
/// before a shift, is no longer their components).
fn whole_frame(
    source: &[u8],
    expr: &Expr,
    scope: &crate::semantic::env::Scope,
) -> Option<Vec<Component>> {
    let mut parts = Vec::new();
    let mut chain = vec![expr];
    while let Some(expr) = chain.pop() {
        match &expr.kind {
            ExprKind::Binary {
                op: BinaryOp::Chain,
                lhs,
                rhs,
            } => chain.extend([rhs.as_ref(), lhs.as_ref()]),
            ExprKind::Paren(inner) => chain.push(inner),
            ExprKind::Call(call) => parts.push(call),
            _ => return None,
        }
    }
    let mut components = Vec::new();
    // In the order the control writes them (a rotation before a shift
    // would turn it: no longer its components), each once.
    let mut last = None;
    for call in parts {
        let function = call.name.upper(source);
        let (order, component, valued) = match function.as_str() {
            "CTRANS" => (0, "TR", true),
            "CFINE" => (1, "FI", true),
            "CROT" => (2, "RT", true),
            "CSCALE" => (3, "SC", true),
            "CMIRROR" => (4, "MI", false),
            _ => return None,
        };
        if last.is_some_and(|last| order <= last) {
            return None;
        }
        last = Some(order);
        let mut items = call.arguments.items.iter();
        while let Some(axis) = items.next() {
            let Some(Expr {
                kind: ExprKind::Variable(variable),
                ..
            }) = &axis.value
            else {
                // `CTRANS()`: one empty argument.
                if axis.value.is_none() && call.arguments.items.len() == 1 {
                    break;
                }
                return None;
            };
            if !variable.indices.is_empty() {
                return None;
            }
            let value = if valued {
                let value = items.next()?.value.as_ref()?;
                evaluate(source, value, scope).ok()?.number()?
            } else {
                1.0
            };
            components.push((variable.name.upper(source), component, value));
        }
    }
    Some(components)
}

/// A target's indices, where each is a whole number or an axis's name.
fn indices(
    source: &[u8],
    target: &Variable,
    scope: &crate::semantic::env::Scope,
) -> Option<Vec<Index>> {
    (target.indices.iter())
        .map(|index| self::index(source, index, scope))
        .collect()
}

/// An index: a whole number, or an axis's name.
fn index(source: &[u8], expr: &Expr, scope: &crate::semantic::env::Scope) -> Option<Index> {
    if let ExprKind::Variable(variable) = &expr.kind {
        if variable.indices.is_empty() {
            return Some(Index::Axis(variable.name.upper(source)));
        }
    }
    whole(source, expr, scope).map(Index::Number)
}

fn whole(source: &[u8], expr: &Expr, scope: &crate::semantic::env::Scope) -> Option<u32> {
    match evaluate(source, expr, scope) {
        Ok(Value::Number(n)) if n >= 0.0 && n.fract() == 0.0 && n <= f64::from(u32::MAX) => {
            Some(n as u32)
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn axis(name: &str) -> Index {
        Index::Axis(name.to_string())
    }

    #[test]
    fn reads_every_datum_by_name_channel_and_index() {
        let source = b"; machine data\nN10000 $MN_AXCONF_MACHAX_NAME_TAB[0]=\"X1\"\nCHANDATA(2)\n\
N20080 $MC_AXCONF_CHANAX_NAME_TAB[0]=\"X\"\nN36110 $MA_POS_LIMIT_PLUS[AX1]=1500.6\n\
N32300 $MA_MAX_AX_ACCEL[1,AX1]=2.5 ; m/s2\n$TC_DP1[1,1]=120\n$SN_JOG_CONT_MODE_LEVELTRIGGRD=1\nM17\n";
        let read = MachineData::read(source);
        assert!(read.diagnostics.is_empty(), "{:?}", read.diagnostics);
        assert_eq!(read.data.len(), 6);
        let tool = [Index::Number(1), Index::Number(1)];
        assert_eq!(
            read.get("$TC_DP1", Some(2), &tool),
            Some(&Value::Number(120.0))
        );
        let number = |name, channel, indices: &[Index]| {
            read.get(name, channel, indices).and_then(Value::number)
        };
        assert_eq!(
            read.get("$MN_AXCONF_MACHAX_NAME_TAB", None, &[Index::Number(0)]),
            Some(&Value::Text("X1".to_string()))
        );
        assert_eq!(
            read.get("$MC_AXCONF_CHANAX_NAME_TAB", Some(2), &[Index::Number(0)]),
            Some(&Value::Text("X".to_string()))
        );
        assert_eq!(
            number("$MA_POS_LIMIT_PLUS", Some(2), &[axis("AX1")]),
            Some(1500.6)
        );
        assert_eq!(
            number(
                "$MA_MAX_AX_ACCEL",
                Some(2),
                &[Index::Number(1), axis("AX1")]
            ),
            Some(2.5)
        );
        assert_eq!(number("$MA_POS_LIMIT_PLUS", Some(1), &[axis("AX1")]), None);
    }

    #[test]
    fn what_cannot_be_read_is_named_on_its_line() {
        let source = b"$MA_POS_LIMIT_PLUS[AX1]=_LIMIT\n$MA_POS_LIMIT_MINUS[AX1]=(\nCHANDATA(X)\n\
$MA_MAX_AX_VELO[1.5]=1000\n$MA_MAX_AX_VELO[AX1]=10000\n";
        let read = MachineData::read(source);
        let lines: Vec<usize> = read
            .diagnostics
            .iter()
            .map(|d| {
                crate::span::LineIndex::new(source)
                    .position(d.span.start)
                    .row
            })
            .collect();
        assert_eq!(lines, [1, 2, 3, 4]);
        let codes: Vec<&str> = read.diagnostics.iter().map(|d| d.code()).collect();
        assert_eq!(codes, ["K006", "S005", "K006", "K006"]);
        assert_eq!(read.data.len(), 1);
    }

    /// The checksum an archive's line may end in is not part of the datum.
    #[test]
    fn a_line_checksum_is_read_past() {
        let source = b"CHANDATA(1) '1234\nN10000 $MN_AXCONF_MACHAX_NAME_TAB[1]=\"C1\" '5b7e\r\n\
N36110 $MA_POS_LIMIT_PLUS[AX1]=1500.6 'ABCD  \n$MA_POS_LIMIT_MINUS[AX1]=-1 'abcz\n";
        let read = MachineData::read(source);
        assert_eq!(
            read.get("$MN_AXCONF_MACHAX_NAME_TAB", Some(1), &[Index::Number(1)]),
            Some(&Value::Text("C1".to_string()))
        );
        assert_eq!(
            read.get("$MA_POS_LIMIT_PLUS", Some(1), &[axis("AX1")]),
            Some(&Value::Number(1500.6))
        );
        // Not four hexadecimal digits: no checksum, the line as written.
        let codes: Vec<&str> = read.diagnostics.iter().map(|d| d.code()).collect();
        assert_eq!(codes, ["S005"]);
    }
}
