//! The state of the walk at one point of the program: variables, the arrays
//! a measuring cycle has filled, and the active swivel rotation.

use std::collections::HashMap;

use nalgebra::Rotation3;

use crate::semantic::eval::Lookup;
use crate::semantic::frames::FrameSeen;
use crate::semantic::value::{Binding, Origin, Unknown, Value};

/// Values the user supplies for measured variables (`--set`, `--values`).
#[derive(Clone, Debug, Default)]
pub struct Supplied {
    values: HashMap<String, (Value, String)>,
}

impl Supplied {
    /// `key` as built by [`crate::semantic::eval::key`]; `by` says where it came from.
    pub fn insert(&mut self, key: String, value: Value, by: String) {
        self.values.insert(key, (value, by));
    }

    pub fn get(&self, key: &str) -> Option<(&Value, &str)> {
        self.values.get(key).map(|(v, by)| (v, by.as_str()))
    }

    pub fn keys(&self) -> impl Iterator<Item = &String> {
        self.values.keys()
    }
}

/// The rotation left by the last CYCLE600 or CYCLE800 on the way here.
#[derive(Clone, Debug, PartialEq)]
pub enum Active {
    /// No swivel (program start, `CYCLE800()`).
    None,
    Known {
        rotation: Rotation3<f64>,
        line: usize,
    },
    Unknown {
        why: String,
    },
}

impl Active {
    pub fn rotation(&self) -> Option<Rotation3<f64>> {
        match self {
            Active::None => Some(Rotation3::identity()),
            Active::Known { rotation, .. } => Some(*rotation),
            Active::Unknown { .. } => None,
        }
    }
}

#[derive(Clone, Debug)]
pub struct Env {
    vars: HashMap<String, Binding>,
    /// Declared arrays without an initialiser: elements read as this default.
    array_defaults: HashMap<String, Value>,
    /// `_OVR` -> (line, cycle): results a measuring cycle wrote.
    measured_arrays: HashMap<String, (usize, String)>,
    /// Set after a subprogram call that may have written any R parameter.
    r_clobbered: Option<Origin>,
    pub active: Active,
    /// A frame statement of the program's own since the last swivel: the
    /// rotation an additive call adds to is unknown (spec section 8).
    pub frame_since_swivel: Option<FrameSeen>,
    /// A frame statement of the program's own active in the programmable
    /// frame, which the frames and TRAORI forms would replace.
    pub user_frame: Option<FrameSeen>,
}

impl Default for Env {
    fn default() -> Self {
        Self {
            vars: HashMap::new(),
            array_defaults: HashMap::new(),
            measured_arrays: HashMap::new(),
            r_clobbered: None,
            active: Active::None,
            frame_since_swivel: None,
            user_frame: None,
        }
    }
}

fn base(key: &str) -> &str {
    key.split('[').next().unwrap_or(key)
}

fn is_r_parameter(key: &str) -> bool {
    key.strip_prefix('R')
        .is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
}

/// Main-run values the probe measures (Siemens system variables list).
pub fn is_measured_system_variable(key: &str) -> bool {
    ["$AA_MW", "$AA_MM", "$AC_MEAS", "$AA_MEAACT", "$AC_MEA["]
        .iter()
        .any(|p| key.starts_with(p))
}

impl Env {
    pub fn set(&mut self, key: String, binding: Binding) {
        self.vars.insert(key, binding);
    }

    /// A known value of `key` (as built by [`crate::semantic::eval::key`]).
    pub fn value(&self, key: &str) -> Option<&Value> {
        match self.vars.get(key) {
            Some(Binding::Known { value, .. }) => Some(value),
            _ => None,
        }
    }

    pub fn binding(&self, key: &str) -> Option<&Binding> {
        self.vars.get(key)
    }

    pub fn declare_array(&mut self, name: String, default: Value) {
        self.vars.retain(|k, _| base(k) != name);
        self.array_defaults.insert(name, default);
    }

    /// A measuring cycle wrote its result arrays.
    pub fn measure_arrays(&mut self, line: usize, cycle: &str) {
        for array in ["_OVR", "_OVI"] {
            self.vars.retain(|k, _| base(k) != array);
            self.measured_arrays
                .insert(array.to_string(), (line, cycle.to_string()));
        }
    }

    /// A subprogram call may have written any R parameter.
    pub fn clobber_r_parameters(&mut self, origin: Origin) {
        self.vars.retain(|k, _| !is_r_parameter(k));
        self.r_clobbered = Some(origin);
    }

    /// Whatever `name` (a variable or a whole array) held is unknown from here.
    pub fn forget(&mut self, name: &str, origin: Origin) {
        if name == "R" {
            return self.clobber_r_parameters(origin);
        }
        self.vars.retain(|k, _| base(k) != name);
        self.array_defaults.remove(name);
        self.vars
            .insert(name.to_string(), Binding::Unknown { origin });
    }

    /// Both paths of a branch joined: what differs is unknown.
    pub fn merge(&mut self, other: Env, line: usize) {
        let differs = Origin::ControlFlow {
            line,
            what: "IF whose condition is unknown offline",
        };
        let keys: Vec<String> = self.vars.keys().chain(other.vars.keys()).cloned().collect();
        for key in keys {
            if self.vars.get(&key) != other.vars.get(&key) {
                self.vars.insert(
                    key,
                    Binding::Unknown {
                        origin: differs.clone(),
                    },
                );
            }
        }
        for (array, measured) in other.measured_arrays {
            self.measured_arrays.entry(array).or_insert(measured);
        }
        if self.r_clobbered.is_none() {
            self.r_clobbered = other.r_clobbered;
        }
        if self.frame_since_swivel.is_none() {
            self.frame_since_swivel = other.frame_since_swivel;
        }
        if self.user_frame.is_none() {
            self.user_frame = other.user_frame;
        }
        if self.active != other.active {
            self.active = Active::Unknown {
                why: format!("the IF on line {line} swivels differently in its branches"),
            };
        }
    }

    pub fn scope<'a>(&'a self, supplied: &'a Supplied, line: usize) -> Scope<'a> {
        Scope {
            env: self,
            supplied,
            line,
        }
    }
}

/// The environment as the evaluator sees it at one line.
pub struct Scope<'a> {
    env: &'a Env,
    supplied: &'a Supplied,
    line: usize,
}

impl Lookup for Scope<'_> {
    fn variable(&self, key: &str) -> Result<Value, Unknown> {
        let unknown = |origin: Origin| Err(Unknown::Variables(vec![(key.to_string(), origin)]));
        let name = base(key);
        match self
            .env
            .vars
            .get(key)
            .or_else(|| (name != key).then(|| self.env.vars.get(name)).flatten())
        {
            Some(Binding::Known { value, .. }) => return Ok(value.clone()),
            Some(Binding::Unknown { origin }) => return unknown(origin.clone()),
            None => {}
        }
        if let Some((line, cycle)) = self.env.measured_arrays.get(name) {
            return match self.supplied.get(key) {
                Some((value, _)) => Ok(value.clone()),
                None => unknown(Origin::Measured {
                    line: *line,
                    source: format!("{cycle} into {key}"),
                }),
            };
        }
        if is_measured_system_variable(key) {
            return match self.supplied.get(key) {
                Some((value, _)) => Ok(value.clone()),
                None => unknown(Origin::Measured {
                    line: self.line,
                    source: format!("{key} read from the probe"),
                }),
            };
        }
        if let Some(default) = self.env.array_defaults.get(name) {
            return Ok(default.clone());
        }
        if is_r_parameter(key) {
            if let Some(origin) = &self.env.r_clobbered {
                return unknown(origin.clone());
            }
        }
        match self.supplied.get(key) {
            Some((value, _)) => Ok(value.clone()),
            None => unknown(Origin::NeverAssigned),
        }
    }
}

impl Scope<'_> {
    /// Where a value read here comes from, for tables (`sinuprep eval`).
    pub fn origin(&self, key: &str) -> Option<Origin> {
        match self.env.vars.get(key) {
            Some(Binding::Known { origin, .. } | Binding::Unknown { origin }) => {
                Some(origin.clone())
            }
            None => self
                .supplied
                .get(key)
                .map(|(_, by)| Origin::Supplied { by: by.to_string() }),
        }
    }

    pub fn supplied(&self) -> &Supplied {
        self.supplied
    }
}
