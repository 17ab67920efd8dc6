//! Values of NC variables and where they come from.
//!
//! A value is known (with its origin) or unknown (with the reason), and the
//! reason travels with every expression that reads it, so a refusal can name
//! the measuring cycle or the loop behind a missing number.

use std::fmt;

/// A Sinumerik value: INT, REAL, BOOL and CHAR are all numbers here (BOOL is
/// 1/0, as the control computes with it); STRING is text; an axis name used as
/// an index or argument (`$AA_MW[X]`, `CTRANS(X,15)`) is a name.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Number(f64),
    Text(String),
}

impl Value {
    pub fn number(&self) -> Option<f64> {
        match self {
            Value::Number(n) => Some(*n),
            Value::Text(_) => None,
        }
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Number(n) => write!(f, "{n}"),
            Value::Text(t) => write!(f, "\"{t}\""),
        }
    }
}

/// Where a known value comes from, or why a value is unknown. `line` is 1-based.
#[derive(Clone, Debug, PartialEq)]
pub enum Origin {
    /// Written in the argument itself.
    Literal,
    /// Assigned (or DEF-initialised) on the way through the program.
    Assigned { line: usize },
    /// Measured on the machine: by a measuring cycle into `_OVR[...]`, read
    /// from `$AA_MW[...]`, or passed on from one of those.
    Measured { line: usize, source: String },
    /// Given by the user (`--set`, `--values`).
    Supplied { by: String },
    /// Results of a CYCLE600 evaluated offline.
    Cycle600 { line: usize },
    /// Written inside a loop or a jumped-over region whose path the walk cannot follow.
    ControlFlow { line: usize, what: &'static str },
    /// Assigned from an expression without a value offline.
    Unevaluable { line: usize, why: String },
    /// Read but never assigned in this program (a global, or an R parameter
    /// left from before).
    NeverAssigned,
}

impl fmt::Display for Origin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Origin::Literal => write!(f, "literal"),
            Origin::Assigned { line } => write!(f, "assigned on line {line}"),
            Origin::Measured { line, source } => write!(f, "measured on line {line}: {source}"),
            Origin::Supplied { by } => write!(f, "supplied by {by}"),
            Origin::Cycle600 { line } => write!(f, "result of the CYCLE600 on line {line}"),
            Origin::ControlFlow { line, what } => write!(
                f,
                "written in the {what} on line {line}, which the walk cannot follow"
            ),
            Origin::Unevaluable { line, why } => write!(
                f,
                "assigned on line {line} from an expression without a value offline: {why}"
            ),
            Origin::NeverAssigned => write!(f, "never assigned in this program"),
        }
    }
}

/// A variable's state at one point of the walk.
#[derive(Clone, Debug, PartialEq)]
pub enum Binding {
    Known { value: Value, origin: Origin },
    Unknown { origin: Origin },
}

/// Why an expression has no value offline: the variables it read that are
/// unknown, or an operation without a result.
#[derive(Clone, Debug, PartialEq)]
pub enum Unknown {
    Variables(Vec<(String, Origin)>),
    /// `ASIN(2)`, `0/0`, a string where a number is needed, ...
    Invalid(String),
}

impl Unknown {
    /// Both reasons, the variables of each collected.
    pub fn merge(self, other: Unknown) -> Unknown {
        match (self, other) {
            (Unknown::Variables(mut a), Unknown::Variables(b)) => {
                for item in b {
                    if !a.contains(&item) {
                        a.push(item);
                    }
                }
                Unknown::Variables(a)
            }
            (invalid @ Unknown::Invalid(_), _) | (_, invalid @ Unknown::Invalid(_)) => invalid,
        }
    }
}

impl fmt::Display for Unknown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Unknown::Invalid(why) => f.write_str(why),
            Unknown::Variables(vars) => {
                let parts: Vec<String> = vars
                    .iter()
                    .map(|(name, origin)| format!("`{name}` ({origin})"))
                    .collect();
                write!(f, "unknown offline: {}", parts.join(", "))
            }
        }
    }
}
