//! Expression evaluation with Sinumerik semantics: angles in degrees, `DIV`
//! integer division, `MOD` on reals, comparisons and logic giving 1 or 0,
//! `<<` concatenating text (Siemens PM, "Arithmetic functions", "Operators").
//!
//! Evaluation reads variables through [`Lookup`]; it never guesses: an
//! unknown variable makes the result unknown, naming the variable, and an
//! operation without a finite result (`ASIN(2)`, `0/0`) is an error.

use crate::semantic::value::{Unknown, Value};
use crate::syntax::tree::{BinaryOp, Expr, ExprKind, UnaryOp, Variable};

/// What the evaluator needs from the walk: the value of a variable, by key.
pub trait Lookup {
    fn variable(&self, key: &str) -> Result<Value, Unknown>;
}

/// The key of a variable: its name in upper case, `R01` as `R1`, with the
/// evaluated indices (`_OVR[16]`, `$AA_MW[X]`, `R[1]` as `R1`).
pub fn variable_key(
    source: &[u8],
    variable: &Variable,
    lookup: &dyn Lookup,
) -> Result<String, Unknown> {
    let name = variable.name.upper(source);
    if variable.indices.is_empty() {
        // The name is the key: not made a second time.
        return Ok(match r_parameter(&name) {
            Some(number) => format!("R{number}"),
            None => name,
        });
    }
    let mut indices = Vec::with_capacity(variable.indices.len());
    for index in &variable.indices {
        indices.push(index_text(source, index, lookup)?);
    }
    Ok(key(&name, &indices))
}

/// `R` with one numeric index is the R parameter of that number.
pub fn key(name: &str, indices: &[String]) -> String {
    if let Some(number) = r_parameter(name) {
        return format!("R{number}");
    }
    if name == "R" && indices.len() == 1 && indices[0].bytes().all(|b| b.is_ascii_digit()) {
        return format!(
            "R{}",
            indices[0]
                .trim_start_matches('0')
                .parse::<u64>()
                .unwrap_or(0)
        );
    }
    if indices.is_empty() {
        name.to_string()
    } else {
        format!("{name}[{}]", indices.join(","))
    }
}

fn r_parameter(name: &str) -> Option<u64> {
    let digits = name.strip_prefix('R')?;
    (!digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()))
        .then(|| digits.parse().ok())
        .flatten()
}

/// An index: an axis name stays a name (`X`), anything else is evaluated.
fn index_text(source: &[u8], index: &Expr, lookup: &dyn Lookup) -> Result<String, Unknown> {
    if let ExprKind::Variable(v) = &index.kind {
        if v.indices.is_empty() && is_axis_like(v.name.text(source)) {
            return Ok(v.name.upper(source));
        }
    }
    match evaluate(source, index, lookup)? {
        Value::Number(n) if n.fract() == 0.0 => Ok(format!("{}", n as i64)),
        Value::Number(n) => Err(Unknown::Invalid(format!("index {n} is not a whole number"))),
        Value::Text(t) => Ok(t),
    }
}

/// A geometry or rotary axis name, a machine axis by its number (`AX4`),
/// or a frame component (`TR`, `RT`).
fn is_axis_like(name: &[u8]) -> bool {
    if crate::semantic::words::is_machine_axis(name) {
        return true;
    }
    let upper = name.to_ascii_uppercase();
    matches!(
        upper.as_slice(),
        b"X" | b"Y"
            | b"Z"
            | b"A"
            | b"B"
            | b"C"
            | b"U"
            | b"V"
            | b"W"
            | b"TR"
            | b"RT"
            | b"SC"
            | b"MI"
            | b"FI"
    ) || (upper.len() <= 3
        && upper[0].is_ascii_alphabetic()
        && upper[1..].iter().all(u8::is_ascii_digit)
        && upper.len() > 1
        && upper[0] != b'R')
}

pub fn evaluate(source: &[u8], expr: &Expr, lookup: &dyn Lookup) -> Result<Value, Unknown> {
    match &expr.kind {
        ExprKind::Number(n) => Ok(Value::Number(n.value)),
        ExprKind::String => {
            let text = expr.span.of(source);
            Ok(Value::Text(
                String::from_utf8_lossy(&text[1..text.len() - 1]).into_owned(),
            ))
        }
        ExprKind::Paren(inner) => evaluate(source, inner, lookup),
        ExprKind::Tuple(_) => Err(Unknown::Invalid(
            "a list of values is not one value".to_string(),
        )),
        ExprKind::Variable(variable) => {
            let name = variable.name.text(source);
            if variable.indices.is_empty() {
                if name.eq_ignore_ascii_case(b"TRUE") {
                    return Ok(Value::Number(1.0));
                }
                if name.eq_ignore_ascii_case(b"FALSE") {
                    return Ok(Value::Number(0.0));
                }
                if name.eq_ignore_ascii_case(b"$PI") {
                    return Ok(Value::Number(std::f64::consts::PI));
                }
            }
            lookup.variable(&variable_key(source, variable, lookup)?)
        }
        ExprKind::Unary {
            op: UnaryOp::Concat,
            operand,
        } => Ok(Value::Text(as_text(evaluate(source, operand, lookup)?))),
        ExprKind::Unary { op, operand } => {
            let value = number(evaluate(source, operand, lookup)?)?;
            finite(match op {
                UnaryOp::Neg => -value,
                UnaryOp::Plus => value,
                UnaryOp::Not => truth(value == 0.0),
                UnaryOp::BitNot => !(integer(value)?) as f64,
                UnaryOp::Concat => unreachable!("handled above"),
            })
        }
        ExprKind::Binary { op, lhs, rhs } => binary(
            *op,
            evaluate(source, lhs, lookup),
            evaluate(source, rhs, lookup),
        ),
        ExprKind::Call(call) => {
            let name = call.name.upper(source);
            let mut args = Vec::with_capacity(call.arguments.items.len());
            let mut unknown: Option<Unknown> = None;
            for item in &call.arguments.items {
                match item.value.as_ref().map(|v| evaluate(source, v, lookup)) {
                    Some(Ok(value)) => args.push(value),
                    Some(Err(why)) => {
                        unknown = Some(match unknown {
                            Some(u) => u.merge(why),
                            None => why,
                        })
                    }
                    None => args.push(Value::Number(0.0)),
                }
            }
            if let Some(why) = unknown {
                return Err(why);
            }
            function(&name, &args)
        }
    }
}

/// A value as `<<` turns it into a string.
fn as_text(value: Value) -> String {
    match value {
        Value::Text(t) => t,
        Value::Number(n) => format!("{n}"),
    }
}

fn truth(value: bool) -> f64 {
    if value {
        1.0
    } else {
        0.0
    }
}

fn number(value: Value) -> Result<f64, Unknown> {
    value
        .number()
        .ok_or_else(|| Unknown::Invalid("a string where a number is needed".to_string()))
}

fn integer(value: f64) -> Result<i64, Unknown> {
    if value.fract() == 0.0 && value.abs() < 9.0e15 {
        Ok(value as i64)
    } else {
        Err(Unknown::Invalid(format!("{value} is not a whole number")))
    }
}

fn finite(value: f64) -> Result<Value, Unknown> {
    if value.is_finite() {
        Ok(Value::Number(value))
    } else {
        Err(Unknown::Invalid(
            "the result is not a finite number".to_string(),
        ))
    }
}

fn binary(
    op: BinaryOp,
    lhs: Result<Value, Unknown>,
    rhs: Result<Value, Unknown>,
) -> Result<Value, Unknown> {
    let (lhs, rhs) = match (lhs, rhs) {
        (Ok(l), Ok(r)) => (l, r),
        (Err(a), Err(b)) => return Err(a.merge(b)),
        (Err(e), _) | (_, Err(e)) => return Err(e),
    };
    if op == BinaryOp::Concat {
        return Ok(Value::Text(as_text(lhs) + &as_text(rhs)));
    }
    if let (Value::Text(a), Value::Text(b)) = (&lhs, &rhs) {
        return match op {
            BinaryOp::Eq => Ok(Value::Number(truth(a.eq_ignore_ascii_case(b)))),
            BinaryOp::Ne => Ok(Value::Number(truth(!a.eq_ignore_ascii_case(b)))),
            _ => Err(Unknown::Invalid(
                "strings only compare with == and <>, and join with <<".to_string(),
            )),
        };
    }
    let (a, b) = (number(lhs)?, number(rhs)?);
    let result = match op {
        BinaryOp::Add => a + b,
        BinaryOp::Sub => a - b,
        BinaryOp::Mul => a * b,
        BinaryOp::Div => {
            if b == 0.0 {
                return Err(Unknown::Invalid("division by zero".to_string()));
            }
            a / b
        }
        // DIV divides and drops the fraction, for reals too (7 DIV 4.1 = 1).
        BinaryOp::IntDiv => {
            if b == 0.0 {
                return Err(Unknown::Invalid("division by zero".to_string()));
            }
            (a / b).trunc()
        }
        BinaryOp::Mod => {
            if b == 0.0 {
                return Err(Unknown::Invalid("MOD by zero".to_string()));
            }
            a % b
        }
        BinaryOp::BitAnd => (integer(a)? & integer(b)?) as f64,
        BinaryOp::BitOr => (integer(a)? | integer(b)?) as f64,
        BinaryOp::BitXor => (integer(a)? ^ integer(b)?) as f64,
        BinaryOp::And => truth(a != 0.0 && b != 0.0),
        BinaryOp::Or => truth(a != 0.0 || b != 0.0),
        BinaryOp::Xor => truth((a != 0.0) != (b != 0.0)),
        BinaryOp::Eq => truth(a == b),
        BinaryOp::Ne => truth(a != b),
        BinaryOp::Lt => truth(a < b),
        BinaryOp::Gt => truth(a > b),
        BinaryOp::Le => truth(a <= b),
        BinaryOp::Ge => truth(a >= b),
        BinaryOp::Chain => {
            return Err(Unknown::Invalid(
                "frame expressions are not evaluated offline".to_string(),
            ))
        }
        BinaryOp::Concat => unreachable!("handled above"),
    };
    finite(result)
}

/// The built-in functions that matter for angles and positions.
fn function(name: &str, args: &[Value]) -> Result<Value, Unknown> {
    let numbers: Result<Vec<f64>, Unknown> = args.iter().cloned().map(number).collect();
    let arity = |n: usize| -> Result<(), Unknown> {
        if args.len() == n {
            Ok(())
        } else {
            Err(Unknown::Invalid(format!(
                "{name} takes {n} argument(s), not {}",
                args.len()
            )))
        }
    };
    let degrees = |x: f64| x.to_radians();
    let domain = |ok: bool, what: &str| {
        if ok {
            Ok(())
        } else {
            Err(Unknown::Invalid(format!("{name}({what}) is undefined")))
        }
    };
    let result = match name {
        "SIN" | "COS" | "TAN" | "ASIN" | "ACOS" | "SQRT" | "ABS" | "POT" | "TRUNC" | "ROUND"
        | "ROUNDUP" | "LN" | "EXP" => {
            arity(1)?;
            let x = numbers?[0];
            match name {
                "SIN" => crate::rotation::trig::sin_cos_degrees(x).0,
                "COS" => crate::rotation::trig::sin_cos_degrees(x).1,
                "TAN" => degrees(x).tan(),
                "ASIN" => {
                    domain((-1.0..=1.0).contains(&x), &x.to_string())?;
                    x.asin().to_degrees()
                }
                "ACOS" => {
                    domain((-1.0..=1.0).contains(&x), &x.to_string())?;
                    x.acos().to_degrees()
                }
                "SQRT" => {
                    domain(x >= 0.0, &x.to_string())?;
                    x.sqrt()
                }
                "ABS" => x.abs(),
                "POT" => x * x,
                "TRUNC" => x.trunc(),
                "ROUND" => x.round(),
                "ROUNDUP" => x.ceil(),
                "LN" => {
                    domain(x > 0.0, &x.to_string())?;
                    x.ln()
                }
                _ => x.exp(),
            }
        }
        "ATAN2" => {
            arity(2)?;
            let v = numbers?;
            domain(v[0] != 0.0 || v[1] != 0.0, "0, 0")?;
            v[0].atan2(v[1]).to_degrees()
        }
        "MINVAL" | "MAXVAL" => {
            arity(2)?;
            let v = numbers?;
            if name == "MINVAL" {
                v[0].min(v[1])
            } else {
                v[0].max(v[1])
            }
        }
        "BOUND" => {
            arity(3)?;
            let v = numbers?;
            v[2].clamp(v[0].min(v[1]), v[0].max(v[1]))
        }
        // Position modifiers carry their value through: X=IC(5) moves by 5.
        "AC" | "IC" | "DC" | "ACP" | "ACN" => {
            arity(1)?;
            numbers?[0]
        }
        _ => {
            return Err(Unknown::Invalid(format!(
                "{name}(...) is not evaluated offline"
            )))
        }
    };
    finite(result)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::expr::parse_expr;
    use crate::syntax::lexer::Input;

    struct Vars;

    impl Lookup for Vars {
        fn variable(&self, key: &str) -> Result<Value, Unknown> {
            match key {
                "R1" => Ok(Value::Number(10.0)),
                "_OVR[16]" => Ok(Value::Number(-0.5)),
                _ => Err(Unknown::Variables(vec![(
                    key.to_string(),
                    crate::semantic::value::Origin::NeverAssigned,
                )])),
            }
        }
    }

    fn eval(text: &str) -> Result<Value, Unknown> {
        let (_, expr) = parse_expr(Input::new(text.as_bytes(), 0)).expect("parses");
        evaluate(text.as_bytes(), &expr, &Vars)
    }

    fn num(text: &str) -> f64 {
        eval(text).ok().and_then(|v| v.number()).unwrap_or(f64::NAN)
    }

    #[test]
    fn unary_concatenation_makes_a_string() {
        assert_eq!(eval("<< R1"), Ok(Value::Text("10".into())));
        assert_eq!(eval("<< R1 << \"S\""), Ok(Value::Text("10S".into())));
        assert_eq!(eval("\"A\" << << 2"), Ok(Value::Text("A2".into())));
    }

    #[test]
    fn manual_examples() {
        assert_eq!(num("2+3*4"), 14.0);
        assert_eq!(num("7 DIV 3"), 2.0);
        assert!((num("7 MOD 4.1") - 2.9).abs() < 1e-12);
        assert_eq!(num("7 DIV 4.1"), 1.0);
        assert_eq!(num("7 DIV 0.4"), 17.0);
        assert!((num("SIN(30)") - 0.5).abs() < 1e-15);
        assert!((num("ATAN2(1,1)") - 45.0).abs() < 1e-12);
        assert_eq!(num("6 B_AND 3"), 2.0);
        assert_eq!(num("R1>=100"), 0.0);
        assert_eq!(num("r[1]*2"), 20.0);
        assert_eq!(num("_ovr[16]"), -0.5);
        assert_eq!(eval("\"R1=\" << R1"), Ok(Value::Text("R1=10".to_string())));
    }

    /// The manual gives no negative example: DIV drops the fraction toward
    /// zero (as an INT conversion does) and MOD keeps the dividend's sign,
    /// so that `a == (a DIV b) * b + a MOD b` holds for every sign.
    #[test]
    fn div_and_mod_of_negative_numbers() {
        assert_eq!(num("-7 DIV 2"), -3.0);
        assert_eq!(num("7 DIV -2"), -3.0);
        assert_eq!(num("-7 DIV -2"), 3.0);
        assert_eq!(num("-7 MOD 2"), -1.0);
        assert_eq!(num("7 MOD -2"), 1.0);
        for (a, b) in [(-7.0, 2.0), (7.0, -2.0), (-7.5, 2.0), (9.0, 4.0)] {
            let div = num(&format!("({a}) DIV ({b})"));
            let rem = num(&format!("({a}) MOD ({b})"));
            assert_eq!(div * b + rem, a, "{a} {b}");
        }
    }

    #[test]
    fn comparison_precedence_is_the_controls() {
        // Not (1==1) AND (2==2): the control computes (1 == (1 AND 2)) == 2.
        assert_eq!(num("1==1 AND 2==2"), 0.0);
        assert_eq!(num("(1==1) AND (2==2)"), 1.0);
    }

    #[test]
    fn no_result_is_an_error_not_nan() {
        for bad in ["ASIN(2)", "0/0", "SQRT(-1)", "1/0", "LN(0)", "ACOS(-1.5)"] {
            assert!(matches!(eval(bad), Err(Unknown::Invalid(_))), "{bad}");
        }
    }

    #[test]
    fn unknown_variables_are_named() {
        let Err(Unknown::Variables(vars)) = eval("R2+R3*R1") else {
            panic!("should be unknown")
        };
        let names: Vec<&str> = vars.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, ["R2", "R3"]);
    }
}
