//! The state of the walk at one point of the program: variables, the arrays
//! a measuring cycle has filled, and the active swivel rotation.

use std::collections::{HashMap, HashSet};

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

/// Bindings by key, with the keys of each array's elements and of the R
/// parameters at hand: forgetting an array or every R parameter costs what
/// they hold, not the whole table (a loop forgets all it writes, and loops
/// nest).
///
/// While a branch is walked, every key it changes is journalled with its
/// binding from before the branch, so that the branches of an IF are
/// compared and joined by what they changed, not by copying and comparing
/// the whole table at every IF.
#[derive(Clone, Debug, Default)]
struct Vars {
    bindings: HashMap<String, Binding>,
    /// Array name -> the keys of its elements that have a binding.
    elements: HashMap<String, HashSet<String>>,
    r_parameters: HashSet<String>,
    /// One level per branch being walked: key -> its binding before it.
    journal: Vec<Journal>,
}

type Journal = HashMap<String, Option<Binding>>;

impl Vars {
    fn get(&self, key: &str) -> Option<&Binding> {
        self.bindings.get(key)
    }

    /// Journals `key`'s binding, the first time the open branch changes it.
    fn record(&mut self, key: &str) {
        if let Some(level) = self.journal.last_mut() {
            if !level.contains_key(key) {
                level.insert(key.to_string(), self.bindings.get(key).cloned());
            }
        }
    }

    fn insert(&mut self, key: String, binding: Binding) {
        self.record(&key);
        self.insert_unrecorded(key, binding);
    }

    fn insert_unrecorded(&mut self, key: String, binding: Binding) {
        let name = base(&key);
        if name.len() != key.len() {
            self.elements
                .entry(name.to_string())
                .or_default()
                .insert(key.clone());
        } else if is_r_parameter(&key) {
            self.r_parameters.insert(key.clone());
        }
        self.bindings.insert(key, binding);
    }

    /// Removes `name` and every element of it.
    fn remove_all(&mut self, name: &str) {
        self.record(name);
        self.bindings.remove(name);
        self.r_parameters.remove(name);
        for key in self.elements.remove(name).into_iter().flatten() {
            self.record(&key);
            self.bindings.remove(&key);
        }
    }

    fn remove_r_parameters(&mut self) {
        for key in std::mem::take(&mut self.r_parameters) {
            self.record(&key);
            self.bindings.remove(&key);
        }
    }

    /// Puts the journalled keys back as they were; returns what they held.
    fn restore(&mut self, journal: Journal) -> Journal {
        journal
            .into_iter()
            .map(|(key, before)| {
                let now = match before {
                    Some(binding) => {
                        let now = self.bindings.get(&key).cloned();
                        self.insert_unrecorded(key.clone(), binding);
                        now
                    }
                    None => self.bindings.remove(&key),
                };
                (key, now)
            })
            .collect()
    }

    /// A branch's changes become the enclosing branch's, where it had not
    /// changed those keys itself.
    fn hand_up(&mut self, journal: Journal) {
        if let Some(level) = self.journal.last_mut() {
            for (key, before) in journal {
                level.entry(key).or_insert(before);
            }
        }
    }
}

#[derive(Clone, Debug)]
pub struct Env {
    vars: Vars,
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

/// What an [`Env`] holds beside its variables: small, copied at each fork.
#[derive(Clone, Debug)]
struct Rest {
    array_defaults: HashMap<String, Value>,
    measured_arrays: HashMap<String, (usize, String)>,
    r_clobbered: Option<Origin>,
    active: Active,
    frame_since_swivel: Option<FrameSeen>,
    user_frame: Option<FrameSeen>,
}

/// The state at the start of a branch ([`Env::fork`]).
pub struct Fork {
    rest: Rest,
}

/// What a branch left ([`Env::rewind`]): the keys it changed, with their
/// bindings at its end (`None`: removed), and the rest of its state.
pub struct Branch {
    values: Journal,
    rest: Rest,
}

impl Default for Env {
    fn default() -> Self {
        Self {
            vars: Vars::default(),
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
        self.vars.remove_all(&name);
        self.array_defaults.insert(name, default);
    }

    /// A measuring cycle wrote its result arrays.
    pub fn measure_arrays(&mut self, line: usize, cycle: &str) {
        for array in ["_OVR", "_OVI"] {
            self.vars.remove_all(array);
            self.measured_arrays
                .insert(array.to_string(), (line, cycle.to_string()));
        }
    }

    /// A subprogram call may have written any R parameter.
    pub fn clobber_r_parameters(&mut self, origin: Origin) {
        self.vars.remove_r_parameters();
        self.r_clobbered = Some(origin);
    }

    /// Whatever `name` (a variable or a whole array) held is unknown from here.
    pub fn forget(&mut self, name: &str, origin: Origin) {
        if name == "R" {
            return self.clobber_r_parameters(origin);
        }
        self.vars.remove_all(name);
        self.array_defaults.remove(name);
        self.vars
            .insert(name.to_string(), Binding::Unknown { origin });
    }

    fn rest(&self) -> Rest {
        Rest {
            array_defaults: self.array_defaults.clone(),
            measured_arrays: self.measured_arrays.clone(),
            r_clobbered: self.r_clobbered.clone(),
            active: self.active.clone(),
            frame_since_swivel: self.frame_since_swivel.clone(),
            user_frame: self.user_frame.clone(),
        }
    }

    fn take_rest(&mut self) -> Rest {
        Rest {
            array_defaults: std::mem::take(&mut self.array_defaults),
            measured_arrays: std::mem::take(&mut self.measured_arrays),
            r_clobbered: self.r_clobbered.take(),
            active: std::mem::replace(&mut self.active, Active::None),
            frame_since_swivel: self.frame_since_swivel.take(),
            user_frame: self.user_frame.take(),
        }
    }

    fn put_rest(&mut self, rest: Rest) {
        self.array_defaults = rest.array_defaults;
        self.measured_arrays = rest.measured_arrays;
        self.r_clobbered = rest.r_clobbered;
        self.active = rest.active;
        self.frame_since_swivel = rest.frame_since_swivel;
        self.user_frame = rest.user_frame;
    }

    /// Starts walking one branch of an IF.
    pub fn fork(&mut self) -> Fork {
        self.vars.journal.push(Journal::new());
        Fork { rest: self.rest() }
    }

    /// Ends the branch walked since `fork`: what it left, with the state put
    /// back as it was at the fork, and the other branch started from there.
    pub fn rewind(&mut self, fork: Fork) -> Branch {
        let journal = self.vars.journal.pop().unwrap_or_default();
        let rest = self.take_rest();
        self.put_rest(fork.rest);
        let values = self.vars.restore(journal);
        self.vars.journal.push(Journal::new());
        Branch { values, rest }
    }

    /// Ends the other branch (walked since [`Env::rewind`]) and joins it with
    /// the first one, `then`: what differs between them is unknown.
    pub fn join(&mut self, then: Branch, line: usize) {
        let journal = self.vars.journal.pop().unwrap_or_default();
        let mut differing = Vec::new();
        for key in journal.keys().chain(then.values.keys()) {
            let now = self.vars.get(key);
            let before = journal.get(key).map_or(now, Option::as_ref);
            let in_then = then.values.get(key).map_or(before, Option::as_ref);
            if in_then != now {
                differing.push(key.clone());
            }
        }
        // The enclosing branch journals the bindings from before the IF.
        self.vars.hand_up(journal);
        let differs = Origin::ControlFlow {
            line,
            what: "IF whose condition is unknown offline",
        };
        for key in differing {
            self.vars.insert(
                key,
                Binding::Unknown {
                    origin: differs.clone(),
                },
            );
        }
        let other = self.take_rest();
        self.put_rest(then.rest);
        self.merge_rest(other, line);
    }

    /// Joins the state beside the variables (`self` is the first branch's).
    fn merge_rest(&mut self, other: Rest, line: usize) {
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
