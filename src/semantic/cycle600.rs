//! A CYCLE600 call bound to its named parameters, checked, and evaluated
//! (spec `cycle600.md` sections 1-3, 5).
//!
//! Binding keeps each argument's span, value and provenance, so that every
//! diagnostic points at the argument it is about. Evaluation turns the
//! parameters into the rotation the control would compute.

use nalgebra::{Rotation3, Vector3};

use crate::diagnostic::{Diagnostic, Severity};
use crate::registry;
use crate::rotation::{self, frame::compose_additive, Decomposition, Kind, Sequence};
use crate::semantic::env::{Active, Scope};
use crate::semantic::eval::{evaluate, variable_key};
use crate::semantic::head_def::Heads;
use crate::semantic::value::{Origin, Unknown, Value};
use crate::span::Span;
use crate::syntax::tree::{Call, ExprKind};

/// The 18 parameters of the canonical form, in order.
pub const NAMES: [&str; 18] = [
    "_INEXIN", "_MIHEAD", "_SW_REC", "_BIN_IN", "_POS_X", "_POS_Y", "_POS_Z", "_ANG_1", "_ANG_2",
    "_ANG_3", "_POS_X_R", "_POS_Y_R", "_POS_Z_R", "_INEXOUT", "_BIN_OUT", "_ROT_AD", "_ROT_INV",
    "_RETR_Z",
];

/// Where an argument's value comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum Provenance {
    /// `,,`: an omitted argument is 0.
    Empty,
    Literal,
    /// A variable, with the origin of its value.
    Variable {
        key: String,
        origin: Option<Origin>,
    },
    Expression,
}

#[derive(Clone, Debug)]
pub struct Argument {
    pub name: &'static str,
    pub span: Span,
    pub text: String,
    pub value: Result<Value, Unknown>,
    pub provenance: Provenance,
}

/// A call with its arguments named.
#[derive(Clone, Debug)]
pub struct Bound {
    pub arguments: Vec<Argument>,
    /// The extra value at position 14 of the paper's 19-value form.
    pub reserved: Option<Argument>,
}

/// The checked parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Parameters {
    pub head: String,
    pub recalculate_only: bool,
    pub input: Sequence,
    pub before: Vector3<f64>,
    pub angles: [f64; 3],
    pub after: Vector3<f64>,
    pub output: Sequence,
    pub additive: bool,
    pub inverse: bool,
    pub retract: bool,
}

/// What the control would compute.
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluation {
    pub parameters: Parameters,
    /// The call's own rotation.
    pub rotation: Rotation3<f64>,
    /// The rotation to swivel to: the call's own, or composed with the active one.
    pub target: Rotation3<f64>,
    /// `_ST` for CYCLE800: 0 new plane with `target`; 1 additive (the active
    /// rotation is unknown offline, `target` is the call's own rotation).
    pub additive_on_control: bool,
    /// `target` in the output sequence.
    pub output: Decomposition,
}

impl Evaluation {
    /// `_CYC600_1` .. `_CYC600_6` (spec section 5).
    pub fn gud(&self) -> [Value; 6] {
        let [a, b, c] = self.output.angles;
        [
            Value::Text(self.parameters.head.clone()),
            Value::Number(a),
            Value::Number(b),
            Value::Number(c),
            Value::Number(1.0),
            Value::Number(self.parameters.output.code() as f64),
        ]
    }
}

/// Names the arguments of `call`; a count other than 18 or 19 is an error.
pub fn bind(source: &[u8], call: &Call, scope: &Scope) -> Result<Bound, Diagnostic> {
    let items = &call.arguments.items;
    let count = items.len();
    if count != 18 && count != 19 {
        return Err(registry::cycle600_argument_count::RULE.at(call.arguments.span)
            .message(format!("CYCLE600 takes 18 arguments (or the paper's 19), this call has {count}"))
            .label(format!("{count} arguments"))
            .help("write the 18 parameters _INEXIN, _MIHEAD, _SW_REC, _BIN_IN, _POS_X.._POS_Z, _ANG_1.._ANG_3, _POS_X_R.._POS_Z_R, _INEXOUT, _BIN_OUT, _ROT_AD, _ROT_INV, _RETR_Z; empty positions (`,,`) count as 0"));
    }
    let mut named: Vec<(&'static str, usize)> = Vec::with_capacity(19);
    for (position, name) in NAMES.iter().enumerate() {
        let index = if count == 19 && position >= 13 {
            position + 1
        } else {
            position
        };
        named.push((name, index));
    }
    let argument = |name: &'static str, index: usize| {
        let item = &items[index];
        let text = String::from_utf8_lossy(item.span.of(source)).into_owned();
        let (value, provenance) = match &item.value {
            None => (Ok(Value::Number(0.0)), Provenance::Empty),
            Some(expr) => {
                let value = evaluate(source, expr, scope);
                let provenance = match &expr.kind {
                    ExprKind::Number(_) | ExprKind::String => Provenance::Literal,
                    ExprKind::Unary { operand, .. }
                        if matches!(operand.kind, ExprKind::Number(_)) =>
                    {
                        Provenance::Literal
                    }
                    ExprKind::Variable(variable) => match variable_key(source, variable, scope) {
                        Ok(key) => Provenance::Variable {
                            origin: scope.origin(&key),
                            key,
                        },
                        Err(_) => Provenance::Expression,
                    },
                    _ => Provenance::Expression,
                };
                (value, provenance)
            }
        };
        Argument {
            name,
            span: item.span,
            text,
            value,
            provenance,
        }
    };
    Ok(Bound {
        arguments: named
            .iter()
            .map(|&(name, index)| argument(name, index))
            .collect(),
        reserved: (count == 19).then(|| argument("reserved", 13)),
    })
}

/// Checks types and codes; returns every problem, each at its argument.
pub fn check(bound: &Bound, heads: Option<&Heads>) -> (Option<Parameters>, Vec<Diagnostic>) {
    let mut problems = Vec::new();
    let mut warnings = Vec::new();
    let args = &bound.arguments;
    let number = |i: usize, problems: &mut Vec<Diagnostic>| -> Option<f64> {
        let arg = &args[i];
        match &arg.value {
            Ok(Value::Number(n)) => Some(*n),
            Ok(Value::Text(_)) => {
                problems.push(
                    registry::cycle600_invalid_argument::RULE
                        .at(arg.span)
                        .message(format!("{} must be a number, not a string", arg.name))
                        .label("a string")
                        .help(format!("give {} as a number", arg.name)),
                );
                None
            }
            Err(why) => {
                problems.push(unknown_argument(arg, why));
                None
            }
        }
    };
    let flag = |i: usize, problems: &mut Vec<Diagnostic>| -> Option<bool> {
        let value = number(i, problems)?;
        if value == 0.0 || value == 1.0 {
            Some(value == 1.0)
        } else {
            let arg = &args[i];
            problems.push(
                registry::cycle600_flag_not_boolean::RULE
                    .at(arg.span)
                    .message(format!(
                        "{} is a BOOL and must be 0 or 1, not {value}",
                        arg.name
                    ))
                    .label("not 0 or 1")
                    .help(format!("write 0 or 1 for {}", arg.name)),
            );
            None
        }
    };
    let sequence =
        |i: usize, kind: Option<bool>, problems: &mut Vec<Diagnostic>| -> Option<Sequence> {
            let value = number(i, problems)?;
            let arg = &args[i];
            let code = if value.fract() == 0.0 {
                value as i64
            } else {
                -1
            };
            match Sequence::from_code(code, Kind::from_flag(kind.unwrap_or(true))) {
                Ok(sequence) => kind.map(|_| sequence),
                Err(error) => {
                    problems.push(
                        registry::cycle600_invalid_sequence_code::RULE
                            .at(arg.span)
                            .message(format!(
                                "{} = {value} is not an axis sequence code",
                                arg.name
                            ))
                            .label("invalid code")
                            .help(error.to_string()),
                    );
                    None
                }
            }
        };

    let inexin = flag(0, &mut problems);
    let head = match &args[1].value {
        Ok(Value::Text(text)) => Some(text.clone()),
        Ok(Value::Number(_)) => {
            problems.push(
                registry::cycle600_invalid_argument::RULE
                    .at(args[1].span)
                    .message("_MIHEAD must be the accessory's name as a string")
                    .label("not a string")
                    .help("write the name from HEAD_DEF in quotes, as \"UFK600\""),
            );
            None
        }
        Err(why) => {
            problems.push(unknown_argument(&args[1], why));
            None
        }
    };
    if let (Some(head), Some(heads)) = (&head, heads) {
        if let Some(problem) = heads.check(head, args[1].span) {
            problems.push(problem);
        }
    }
    let sw_rec = flag(2, &mut problems);
    let input = sequence(3, inexin, &mut problems);
    let coordinates: Vec<Option<f64>> = (4..13).map(|i| number(i, &mut problems)).collect();
    let inexout = flag(13, &mut problems);
    let output = sequence(14, inexout, &mut problems);
    let additive = flag(15, &mut problems);
    let inverse = flag(16, &mut problems);
    let retract = flag(17, &mut problems);
    if let Some(reserved) = &bound.reserved {
        match &reserved.value {
            Ok(Value::Number(n)) if *n == 0.0 => {}
            _ => warnings.push(
                registry::cycle600_reserved_not_zero::RULE
                    .at(reserved.span)
                    .message(format!(
                        "the reserved 14th value of the 19-value form is `{}`, not 0",
                        reserved.text
                    ))
                    .label("reserved, should be 0 or empty")
                    .help("write 0 here, or use the canonical 18-argument form"),
            ),
        }
    }
    if !problems.is_empty() {
        problems.extend(warnings);
        return (None, problems);
    }
    let c: Vec<f64> = coordinates.into_iter().map(|c| c.unwrap_or(0.0)).collect();
    let parameters = (|| {
        Some(Parameters {
            head: head?,
            recalculate_only: sw_rec?,
            input: input?,
            before: Vector3::new(c[0], c[1], c[2]),
            angles: [c[3], c[4], c[5]],
            after: Vector3::new(c[6], c[7], c[8]),
            output: output?,
            additive: additive?,
            inverse: inverse?,
            retract: retract?,
        })
    })();
    (parameters, warnings)
}

/// C608: `what` (an additive extrinsic rotation, an additive
/// recalculation) needs the active rotation, which is unknown offline.
pub fn additive_onto_unknown(span: Span, what: &str, why: &str) -> Diagnostic {
    let why = if why.is_empty() {
        String::new()
    } else {
        format!(": {why}")
    };
    registry::cycle600_additive_extrinsic_unknown_active::RULE
        .at(span)
        .message(format!(
            "{what} needs the active rotation, which is unknown offline{why}"
        ))
        .label("additive onto an unknown rotation")
        .help("make the earlier swivel known offline, or give the total rotation with _ROT_AD=0")
}

/// C611: a proper Euler output has no CYCLE800 `_MODE`.
pub fn no_cycle800_form(output: Sequence, span: Span) -> Diagnostic {
    registry::cycle600_no_cycle800_form::RULE.at(span)
        .message(format!("CYCLE800 swivels axis by axis in the six Tait-Bryan orders only; {output} is a proper Euler sequence"))
        .label("no CYCLE800 _MODE for this order")
        .help("rewrite with --emit frames, or choose a Tait-Bryan _BIN_OUT (57, 45, 54, 30, 39, 27)")
}

/// Statements after the call in its block (`CYCLE600(...) X5`): the rewrite
/// puts blocks where the call stood, and what followed it would run between
/// them or end up inside their comments.
pub fn shares_block(after: Span) -> Diagnostic {
    registry::cycle600_shares_block::RULE
        .at(after)
        .message("statements follow the CYCLE600 call in its block")
        .label("after the call")
        .help("move them to a block of their own: a cycle call stands alone in its block")
}

/// C618: a call inside blocks nested deeper than the walk follows.
pub fn nested_too_deep(call: Span, limit: usize) -> Diagnostic {
    registry::cycle600_nested_too_deep::RULE.at(call)
        .message(format!(
            "this CYCLE600 is inside {limit} or more nested blocks, deeper than the walk follows: it is not evaluated"
        ))
        .label("not evaluated")
        .help("take the call out of some of the nested IF/WHILE/FOR/LOOP/REPEAT blocks")
}

fn unknown_argument(arg: &Argument, why: &Unknown) -> Diagnostic {
    match why {
        Unknown::Invalid(reason) => registry::cycle600_invalid_argument::RULE
            .at(arg.span)
            .message(format!(
                "{} = `{}` has no value: {reason}",
                arg.name, arg.text
            ))
            .label("no finite value")
            .help(format!("correct the expression of {}", arg.name)),
        Unknown::Variables(vars) => {
            let measured: Vec<&String> = vars
                .iter()
                .filter(|(_, o)| matches!(o, Origin::Measured { .. }))
                .map(|(n, _)| n)
                .collect();
            let names: Vec<String> = vars
                .iter()
                .map(|(name, origin)| format!("`{name}` ({origin})"))
                .collect();
            let help = match measured.first() {
                Some(name) => format!(
                    "the value is measured on the machine: give it with `--set {name}=<value>` or in a `--values` file (one `{name}=<value>` per line), or let the control compute the conversion with `rewrite --emit-runtime`"
                ),
                None => {
                    let first = &vars[0].0;
                    format!("assign it before the call, or give it with `--set {first}=<value>`")
                }
            };
            registry::cycle600_unknown_argument::RULE
                .at(arg.span)
                .message(format!(
                    "{} = `{}` is not known offline: {}",
                    arg.name,
                    arg.text,
                    names.join(", ")
                ))
                .label("unknown offline")
                .help(help)
        }
    }
}

/// The rotation the control would swivel to, given the active one.
pub fn evaluate_parameters(
    parameters: Parameters,
    active: &Active,
    call_span: Span,
) -> Result<(Evaluation, Vec<Diagnostic>), Diagnostic> {
    let rotation = rotation::matrix(parameters.input, parameters.angles);
    let (target, additive_on_control) = if parameters.additive {
        match active.rotation() {
            Some(active) => (
                compose_additive(&active, &rotation, parameters.input.kind),
                false,
            ),
            None if parameters.input.kind == Kind::Intrinsic => (rotation, true),
            None => {
                let why = match active {
                    Active::Unknown { why } => why.clone(),
                    _ => String::new(),
                };
                return Err(additive_onto_unknown(
                    call_span,
                    "an additive extrinsic rotation",
                    &why,
                ));
            }
        }
    } else {
        (rotation, false)
    };
    let output = rotation::decompose(parameters.output, &target);
    let mut warnings = Vec::new();
    if output.gimbal_lock {
        let axes = parameters.output.axes;
        warnings.push(registry::cycle600_gimbal_lock::RULE.at(call_span)
            .message(format!(
                "gimbal lock in {}: the middle rotation aligns the first and third axes, so only their combination is defined; the {} and {} rotations were merged into the first ({:.6}°) and the third is 0",
                parameters.output,
                axes[0].letter(),
                axes[2].letter(),
                output.angles[0]
            ))
            .label("gimbal lock")
            .help("the rotation is still exact; check that the head may reach it this way"));
    }
    Ok((
        Evaluation {
            parameters,
            rotation,
            target,
            additive_on_control,
            output,
        },
        warnings,
    ))
}

/// A coordinate of a call: known offline, or an expression only the control
/// can evaluate (a measured angle, say).
#[derive(Clone, Debug, PartialEq)]
pub enum Operand {
    Known(f64),
    /// The argument as written.
    Runtime(String),
}

/// The parameters of a call whose angles or translations are known only at
/// run time; everything else (codes, flags, head) is known and checked.
#[derive(Clone, Debug, PartialEq)]
pub struct RuntimeParameters {
    pub head: String,
    pub recalculate_only: bool,
    pub input: Sequence,
    pub output: Sequence,
    pub additive: bool,
    pub inverse: bool,
    pub retract: bool,
    /// `_POS_X`.. `_POS_Z`, `_ANG_1`.. `_ANG_3`, `_POS_X_R`.. `_POS_Z_R`.
    pub coordinates: [Operand; 9],
}

impl RuntimeParameters {
    /// The parameters as far as the rotation goes, when only translations are
    /// known at run time (they stand in as 0): a rotation never depends on them.
    pub fn rotation_parameters(&self) -> Option<Parameters> {
        let known = |n: usize| match self.coordinates[n] {
            Operand::Known(value) => Some(value),
            Operand::Runtime(_) => None,
        };
        Some(Parameters {
            head: self.head.clone(),
            recalculate_only: self.recalculate_only,
            input: self.input,
            before: Vector3::zeros(),
            angles: [known(3)?, known(4)?, known(5)?],
            after: Vector3::zeros(),
            output: self.output,
            additive: self.additive,
            inverse: self.inverse,
            retract: self.retract,
        })
    }
}

/// `Some` when the only unknown arguments are coordinates whose expressions
/// read variables (not `ASIN(2)`-like errors): the call can be computed on
/// the control.
pub fn runtime_parameters(bound: &Bound, heads: Option<&Heads>) -> Option<RuntimeParameters> {
    let coordinates = 4..13;
    let runtime = |i: usize| matches!(bound.arguments[i].value, Err(Unknown::Variables(_)));
    if !coordinates.clone().any(runtime) {
        return None;
    }
    // Check the rest as usual, with the run-time coordinates standing in as 0.
    let mut standing_in = bound.clone();
    for i in coordinates.clone().filter(|&i| runtime(i)) {
        standing_in.arguments[i].value = Ok(Value::Number(0.0));
    }
    let (parameters, problems) = check(&standing_in, heads);
    if problems.iter().any(|d| d.severity == Severity::Error) {
        return None;
    }
    let p = parameters?;
    let known = [
        p.before.x,
        p.before.y,
        p.before.z,
        p.angles[0],
        p.angles[1],
        p.angles[2],
        p.after.x,
        p.after.y,
        p.after.z,
    ];
    let coordinates: [Operand; 9] = std::array::from_fn(|n| {
        let argument = &bound.arguments[4 + n];
        if runtime(4 + n) {
            Operand::Runtime(argument.text.clone())
        } else {
            Operand::Known(known[n])
        }
    });
    Some(RuntimeParameters {
        head: p.head,
        recalculate_only: p.recalculate_only,
        input: p.input,
        output: p.output,
        additive: p.additive,
        inverse: p.inverse,
        retract: p.retract,
        coordinates,
    })
}
