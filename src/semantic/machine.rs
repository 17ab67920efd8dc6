//! A machine's swivel data records, read from the NC assignments the control
//! holds them in (`$TC_CARRn[m]=value`: a setup program, `TO_INI.INI`, an
//! archive's `INITIAL.INI`) with the project's own parser. Only the lines
//! that name `$TC_CARR` are parsed, so a file of thousands of tool data
//! lines is read at the speed of a byte search.

use std::collections::BTreeMap;

use nalgebra::Vector3;

use crate::diagnostic::Diagnostic;
use crate::kinematics::{Hirth, Kinematics, Record, RecordError, RotaryAxis};
use crate::registry::invalid_swivel_data::RULE;
use crate::semantic::env::Env;
use crate::semantic::eval::{evaluate, Lookup};
use crate::semantic::value::{Unknown, Value};
use crate::semantic::Supplied;
use crate::span::Span;
use crate::syntax::tree::{Expr, LineKind, StatementKind};

/// The records of a machine file, and what is wrong in it.
#[derive(Debug, Default)]
pub struct Machine {
    /// By record number.
    pub records: Vec<Record>,
    pub diagnostics: Vec<Diagnostic>,
}

/// The highest record number read: a control holds as many swivel data
/// records as a machine datum sets (a handful on most machines), so a number
/// past it is a typo; a `u32`, exact in a double.
pub const MAX_RECORD: u32 = 999_999;

/// Options of reading.
#[derive(Clone, Copy, Debug, Default)]
pub struct Reading {
    /// Add the fine offsets (`$TC_CARR41..46`, `55..60`, `64/65`) as the
    /// control does with SD42974 `$SC_TOCARR_FINE_CORRECTION = 1`, which
    /// the file does not hold.
    pub fine_offsets: bool,
}

/// One parameter's value.
#[derive(Clone, Debug)]
enum Field {
    Number(f64),
    Text(String),
}

impl Machine {
    pub fn read(source: &[u8], reading: Reading) -> Machine {
        Machine::read_knowing(source, reading, &Supplied::default())
    }

    /// The records of `source`, a value that names a variable (a GUD
    /// variable, an R parameter: `$TC_CARR5[1]=_RT_HOEHE_Y`) read from
    /// `supplied` (the values the user gives).
    pub fn read_knowing(source: &[u8], reading: Reading, supplied: &Supplied) -> Machine {
        let mut fields: BTreeMap<u32, BTreeMap<u32, (Field, Span)>> = BTreeMap::new();
        let mut diagnostics = Vec::new();
        let env = Env::default();
        for (line, error) in crate::syntax::lines_naming(source, "TC_CARR") {
            diagnostics.extend(error);
            let LineKind::Block(block) = &line.kind else {
                continue;
            };
            for statement in &block.statements {
                let StatementKind::Assign(assign) = &statement.kind else {
                    continue;
                };
                let name = assign.target.name.upper(source);
                let Some(digits) = name.strip_prefix("$TC_CARR") else {
                    continue;
                };
                // `$TC_CARR_KIN_...`: kinematic chains, not read.
                let Ok(parameter) = digits.parse::<u32>() else {
                    continue;
                };
                let span = statement.span;
                if !is_parameter(parameter) {
                    diagnostics.push(
                        RULE.at(assign.target.name.span)
                            .message(format!("`$TC_CARR{parameter}` is no swivel data parameter: the control raises an alarm for it"))
                            .label("no such parameter")
                            .help("the parameters are $TC_CARR1 to $TC_CARR65 less 47-54 and 61-63"),
                    );
                    continue;
                }
                let scope = env.scope(supplied, 0);
                let record = match assign.target.indices.as_slice() {
                    [index] => {
                        match evaluate(source, index, &scope) {
                            Ok(Value::Number(n))
                                if n >= 1.0 && n.fract() == 0.0 && n <= f64::from(MAX_RECORD) =>
                            {
                                n as u32
                            }
                            _ => {
                                diagnostics.push(
                                RULE.at(index.span)
                                    .message(format!("a record number is a whole number from 1 to {MAX_RECORD}"))
                                    .label("not a record number"),
                            );
                                continue;
                            }
                        }
                    }
                    _ => {
                        diagnostics.push(
                            RULE.at(assign.target.span)
                                .message(format!(
                                    "`$TC_CARR{parameter}` takes one index, the record's number"
                                ))
                                .label("one index expected"),
                        );
                        continue;
                    }
                };
                if let Some(written) = c_exponent_after(source, assign.value.span) {
                    let text = String::from_utf8_lossy(written.of(source));
                    diagnostics.push(
                        RULE.at(written)
                            .message(format!("`$TC_CARR{parameter}[{record}]` is written `{text}`: the control reads the number before the `E` and the rest as another word"))
                            .label("no power of ten in this language")
                            .help("write a power of ten with EX, as 1EX-7, or the number in full, as 0.0000001"),
                    );
                    continue;
                }
                match value(source, parameter, &assign.value, &scope) {
                    Ok(field) => {
                        fields
                            .entry(record)
                            .or_default()
                            .insert(parameter, (field, span));
                    }
                    Err(Unread::Variables(names)) => {
                        let listed = names
                            .iter()
                            .map(|n| format!("`{n}`"))
                            .collect::<Vec<_>>()
                            .join(", ");
                        let first = &names[0];
                        diagnostics.push(
                            RULE.at(assign.value.span)
                                .message(format!("`$TC_CARR{parameter}[{record}]` reads {listed}, which neither the machine's files nor the values given hold: a GUD variable or R parameter set on the control"))
                                .label("its value is needed")
                                .help(format!("give its value as the control holds it: --set {first}=VALUE, or a `values` file (sinuprep.toml); until then it counts as 0 and what is solved on record {record} is in doubt")),
                        );
                    }
                    Err(Unread::Why(why)) => diagnostics.push(
                        RULE.at(assign.value.span)
                            .message(format!("`$TC_CARR{parameter}[{record}]`: {why}"))
                            .label("not a value sinuprep can read"),
                    ),
                }
            }
        }
        let mut records = Vec::new();
        for (number, fields) in fields {
            let (record, problem) = build(number, &fields, reading);
            if let Some(diagnostic) = problem {
                diagnostics.push(diagnostic);
            }
            records.push(record);
        }
        diagnostics.sort_by_key(|d| d.span.start);
        Machine {
            records,
            diagnostics,
        }
    }

    /// The record `_TC` names: by its name (`$TC_CARR34`, any case), or by
    /// its number.
    pub fn record(&self, name: &str) -> Option<&Record> {
        let name = name.trim();
        self.records
            .iter()
            .find(|r| !r.name.is_empty() && r.name.eq_ignore_ascii_case(name))
            .or_else(|| {
                let number: u32 = name.parse().ok()?;
                self.records.iter().find(|r| r.number == number)
            })
    }

    /// Whether a finding makes the file fail (K001 and syntax errors are
    /// errors): the same for every command that reads it.
    pub fn has_errors(&self) -> bool {
        self.diagnostics
            .iter()
            .any(|d| d.severity == crate::diagnostic::Severity::Error)
    }

    /// The records that describe a rotary axis, for messages.
    pub fn usable(&self) -> impl Iterator<Item = &Record> {
        self.records.iter().filter(|r| r.axis_count() > 0)
    }
}

/// The span of a value whose last number is written as C writes a power of
/// ten (`1e-7`, `-2.5E3`, `2*1e3`), the value's text to the exponent's end:
/// the language writes `1EX-7`, and reads `1e-7` as 1 and a word `E-7`.
fn c_exponent_after(source: &[u8], value: Span) -> Option<Span> {
    let text = value.of(source);
    let literal = text
        .iter()
        .rev()
        .take_while(|b| b.is_ascii_digit() || **b == b'.')
        .count();
    // A number ends the value, not a name's digits (`R1` then `E3`).
    let before = text.len().checked_sub(literal + 1).map(|at| text[at]);
    if literal == 0 || before.is_some_and(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'$') {
        return None;
    }
    let rest = &source[value.end..];
    let mut at = match rest.first() {
        Some(b'e' | b'E') => 1,
        _ => return None,
    };
    if matches!(rest.get(at), Some(b'+' | b'-')) {
        at += 1;
    }
    let digits = rest[at..].iter().take_while(|b| b.is_ascii_digit()).count();
    (digits > 0).then(|| Span::new(value.start, value.end + at + digits))
}

/// Parameters 1 to 65 but the undefined 47-54 and 61-63.
fn is_parameter(n: u32) -> bool {
    matches!(n, 1..=46 | 55..=60 | 64 | 65)
}

/// Whether parameter `n` holds text: the type (23), names (34-36) and the
/// axis identifiers (21, 22).
fn is_text(n: u32) -> bool {
    matches!(n, 21 | 22 | 23 | 34..=36)
}

/// Why a parameter's value was not read.
enum Unread {
    /// It reads variables without a value (their names).
    Variables(Vec<String>),
    Why(String),
}

fn value(source: &[u8], parameter: u32, expr: &Expr, scope: &dyn Lookup) -> Result<Field, Unread> {
    // The axis identifiers are of type AXIS: a bare axis name (`C1`).
    if matches!(parameter, 21 | 22) {
        let text = String::from_utf8_lossy(expr.span.of(source));
        return Ok(Field::Text(text.trim_matches('"').to_string()));
    }
    match evaluate(source, expr, scope) {
        Ok(Value::Number(n)) if !is_text(parameter) => Ok(Field::Number(n)),
        Ok(Value::Text(t)) if is_text(parameter) => Ok(Field::Text(t)),
        Ok(Value::Number(_)) => Err(Unread::Why("text expected (in quotes)".into())),
        Ok(Value::Text(_)) => Err(Unread::Why("a number expected".into())),
        Err(Unknown::Variables(read)) if !read.is_empty() => Err(Unread::Variables(
            read.into_iter().map(|(name, _)| name).collect(),
        )),
        Err(_) => Err(Unread::Why("the value must be a constant".into())),
    }
}

/// A record from its fields, and the first problem that makes it unusable
/// (for a record with a name or an axis: an empty record of a file that
/// lists every record is no problem).
fn build(
    number: u32,
    fields: &BTreeMap<u32, (Field, Span)>,
    reading: Reading,
) -> (Record, Option<Diagnostic>) {
    let number_of = |n: u32| match fields.get(&n) {
        Some((Field::Number(value), _)) => *value,
        _ => 0.0,
    };
    let text_of = |n: u32| match fields.get(&n) {
        Some((Field::Text(text), _)) => text.clone(),
        _ => String::new(),
    };
    let fine = |n: u32| {
        if reading.fine_offsets {
            number_of(n)
        } else {
            0.0
        }
    };
    let vector = |first: u32, fine_first: Option<u32>| {
        let base = Vector3::new(number_of(first), number_of(first + 1), number_of(first + 2));
        match fine_first {
            Some(f) => base + Vector3::new(fine(f), fine(f + 1), fine(f + 2)),
            None => base,
        }
    };
    let span_of = |n: u32| fields.get(&n).map(|(_, span)| *span);
    let first_span = fields
        .values()
        .map(|(_, span)| *span)
        .min_by_key(|s| s.start);
    let type_letter = text_of(23);
    let kinematics = if fields.contains_key(&23) {
        Kinematics::from_letter(&type_letter)
    } else {
        Some(Kinematics::Head) // the control's default
    };
    let axis = |i: u32| {
        let limits = (number_of(30 + i), number_of(32 + i));
        RotaryAxis {
            name: text_of(35 + i),
            vector: vector(7 + 3 * i, None),
            offset: number_of(24 + i) + fine(64 + i),
            hirth: (number_of(28 + i) != 0.0).then(|| Hirth {
                offset: number_of(26 + i),
                increment: number_of(28 + i),
            }),
            limits: (limits != (0.0, 0.0)).then_some(limits),
            angle: number_of(13 + i),
        }
    };
    let record = Record {
        number,
        name: text_of(34),
        kinematics: kinematics.unwrap_or(Kinematics::Head),
        offsets: [
            vector(1, Some(41)),
            vector(4, Some(44)),
            vector(15, Some(55)),
            vector(18, Some(58)),
        ],
        axes: [axis(0), axis(1)],
        options: number_of(37).max(0.0) as u64,
        direction_axis: None,
    };
    let at = |n: u32| span_of(n).or(first_span).unwrap_or_default();
    if kinematics.is_none() {
        let diagnostic = RULE
            .at(at(23))
            .message(format!(
                "record {number}: kinematic type `{type_letter}` is none of T (head), P (table), M (mixed): alarm 14153"
            ))
            .label("not T, P or M");
        return (record, Some(diagnostic));
    }
    let defined = !record.name.is_empty() || record.axis_count() > 0;
    let problem = match record.check() {
        Err(error) if defined => Some(error),
        _ => None,
    };
    let diagnostic = problem.map(|error| {
        let parameter = match &error {
            RecordError::NoFirstAxis => 7,
            RecordError::MixedWithOneAxis => 23,
            RecordError::ParallelAxes => 10,
            RecordError::LimitBeyondBound { index, which, .. } => {
                30 + 2 * u32::from(*which == "maximum") + u32::from(*index == 1)
            }
            RecordError::LimitsReversed { axis, .. } => {
                30 + u32::from(axis == &record.axes[1].label(1))
            }
            RecordError::NegativeHirth { axis, .. } => {
                28 + u32::from(axis == &record.axes[1].label(1))
            }
        };
        let name = if record.name.is_empty() {
            format!("record {number}")
        } else {
            format!("record {number} ({})", record.name)
        };
        RULE.at(at(parameter))
            .message(format!("{name}: {error}"))
            .label("cannot describe a machine")
    });
    (record, diagnostic)
}

#[cfg(test)]
mod tests {
    use super::*;

    const HEAD: &str = "; a C-A head\n\
        $TC_CARR23[1]=\"T\" $TC_CARR34[1]=\"HEAD_CA\"\n\
        $TC_CARR7[1]=0 $TC_CARR8[1]=0 $TC_CARR9[1]=1\n\
        $TC_CARR10[1]=1 $TC_CARR11[1]=0 $TC_CARR12[1]=0\n\
        $TC_CARR30[1]=0 $TC_CARR32[1]=360\n\
        $TC_CARR31[1]=-10 $TC_CARR33[1]=90\n\
        $TC_CARR35[1]=\"C\" $TC_CARR36[1]=\"A\"\n\
        $TC_CARR2[1]=100.5 $TC_CARR42[1]=0.25\n\
        $TC_DP1[1,1]=120 ; tool data, not read\n";

    #[test]
    fn a_record_is_read_with_its_fields() {
        let machine = Machine::read(HEAD.as_bytes(), Reading::default());
        assert!(machine.diagnostics.is_empty(), "{:?}", machine.diagnostics);
        let record = machine.record("head_ca").expect("by name");
        assert_eq!(machine.record("1"), Some(record), "by number");
        assert_eq!(record.kinematics, Kinematics::Head);
        assert_eq!(record.axes[0].vector, Vector3::z());
        assert_eq!(record.axes[1].limits, Some((-10.0, 90.0)));
        assert_eq!(record.axes[1].name, "A");
        assert_eq!(record.offsets[0].y, 100.5, "fine offsets not asked for");
        let fine = Machine::read(HEAD.as_bytes(), Reading { fine_offsets: true });
        assert_eq!(fine.records[0].offsets[0].y, 100.75);
    }

    #[test]
    fn a_limit_no_axis_has_is_told_at_its_assignment_with_its_value() {
        for (value, told) in [
            ("1EX11", "maximum position 1e11"),
            ("-1EX300", "maximum position -1e300"),
        ] {
            let source = format!("{HEAD}$TC_CARR32[1]={value}\n");
            let machine = Machine::read(source.as_bytes(), Reading::default());
            let index = crate::span::LineIndex::new(source.as_bytes());
            let [finding] = machine.diagnostics.as_slice() else {
                panic!("{:?}", machine.diagnostics);
            };
            assert_eq!(index.position(finding.span.start).row, 10);
            assert!(finding.message.contains(told), "{}", finding.message);
            assert!(machine.records[0].check().is_err());
        }
        let source = format!("{HEAD}$TC_CARR30[1]=-1EX8 $TC_CARR32[1]=1EX8\n");
        let machine = Machine::read(source.as_bytes(), Reading::default());
        assert!(
            machine.diagnostics.is_empty(),
            "the bound itself is allowed"
        );
    }

    /// `1e-7` is no number of the language: told, not read as 1.
    #[test]
    fn a_power_of_ten_written_as_in_c_is_told() {
        let source = b"$TC_CARR23[1]=\"T\" $TC_CARR34[1]=\"H\"\n$TC_CARR7[1]=0 $TC_CARR8[1]=0 $TC_CARR9[1]=1\n$TC_CARR13[1]=1e-7\n$TC_CARR14[1]=1EX-7\n";
        let machine = Machine::read(source, Reading::default());
        let told: Vec<_> = machine
            .diagnostics
            .iter()
            .filter(|d| d.message.contains("`1e-7`"))
            .collect();
        assert_eq!(told.len(), 1, "{:?}", machine.diagnostics);
        assert_eq!(told[0].span.of(source), b"1e-7");
        assert_eq!(machine.records[0].axes[0].angle, 0.0);
        // Signed, in an expression, any case: told; a name's digits and
        // the language's EX are not.
        for (value, told) in [
            ("-1e-7", Some("-1e-7")),
            ("-2.5E+3", Some("-2.5E+3")),
            ("2*1e3", Some("2*1e3")),
            (".5e2", Some(".5e2")),
            ("-1EX-7", None),
            ("R1 E3=1", None),
        ] {
            let source = format!("$TC_CARR23[1]=\"P\" $TC_CARR9[1]=1 $TC_CARR13[1]={value}\n");
            let machine = Machine::read(source.as_bytes(), Reading::default());
            let said = machine.diagnostics.iter().find(|d| {
                d.message.contains("no power of ten") || d.message.contains("is written")
            });
            assert_eq!(
                said.map(|d| String::from_utf8_lossy(d.span.of(source.as_bytes())).into_owned()),
                told.map(str::to_string),
                "{value}: {:?}",
                machine.diagnostics
            );
        }
    }

    #[test]
    fn bad_data_is_told_at_its_line() {
        let source = "$TC_CARR50[1]=1\n$TC_CARR7[0]=1\n$TC_CARR23[2]=\"X\" $TC_CARR9[2]=1\n\
            $TC_CARR34[3]=\"PAR\" $TC_CARR9[3]=1 $TC_CARR12[3]=2\n$TC_CARR1[4]=R1\n";
        let machine = Machine::read(source.as_bytes(), Reading::default());
        let index = crate::span::LineIndex::new(source.as_bytes());
        let found: Vec<(usize, String)> = machine
            .diagnostics
            .iter()
            .map(|d| (index.position(d.span.start).row, d.message.clone()))
            .collect();
        assert_eq!(found.len(), 5, "{found:#?}");
        assert!(found[0]
            .1
            .contains("`$TC_CARR50` is no swivel data parameter"));
        assert_eq!(
            (found[1].0, found[1].1.as_str()),
            (2, "a record number is a whole number from 1 to 999999")
        );
        assert!(found[2].1.contains("kinematic type `X`"), "{found:?}");
        assert!(
            found[3]
                .1
                .contains("record 3 (PAR): the two rotary axes are parallel"),
            "{found:?}"
        );
        assert!(
            found[4]
                .1
                .contains("`$TC_CARR1[4]` reads `R1`, which neither"),
            "{found:?}"
        );
    }

    /// A record's value that names a variable is read from the values the
    /// user gives; without one it is named, with what would give it.
    #[test]
    fn a_variable_in_a_record_is_read_from_the_values_given() {
        let source = b"$TC_CARR23[1]=\"T\" $TC_CARR8[1]=1 $TC_CARR5[1]=_RT_HOEHE_Y*2\n";
        let without = Machine::read(source, Reading::default());
        let told = &without.diagnostics[0];
        assert!(
            told.message.contains("reads `_RT_HOEHE_Y`"),
            "{}",
            told.message
        );
        assert!(
            told.help
                .as_deref()
                .is_some_and(|h| h.contains("--set _RT_HOEHE_Y=VALUE")),
            "{:?}",
            told.help
        );
        let mut known = Supplied::default();
        known.insert("_RT_HOEHE_Y".into(), Value::Number(12.5), "--set".into());
        let with = Machine::read_knowing(source, Reading::default(), &known);
        assert!(with.diagnostics.is_empty(), "{:?}", with.diagnostics);
        let record = with.record("1").expect("record 1");
        assert_eq!(record.offsets[1].y, 25.0, "$TC_CARR5 is l2 along y");
    }
}
