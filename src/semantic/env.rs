//! The state of the walk at one point of the program: variables, the arrays
//! a measuring cycle has filled, and the active swivel rotation.

use std::cell::Cell;
use std::sync::Arc;

use nalgebra::Rotation3;

use crate::hash::{HashMap, HashSet};
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

/// Where each name is written: what a region of lines makes unknown when a
/// loop or a jump forgets it. A site is one name one statement writes; its
/// position orders the sites of one line as the statements stand.
#[derive(Debug, Default, PartialEq)]
pub(crate) struct Writers {
    /// Every site, in program order: its line.
    lines: Vec<usize>,
    /// The name of each site (an index into `names`), by position.
    written: Vec<usize>,
    /// Each name written, and the positions of its sites, ascending.
    names: Vec<(String, Vec<usize>)>,
    /// Name -> its index in `names`.
    index: HashMap<String, usize>,
}

impl Writers {
    /// Records that `line` writes `name` (lines in order).
    pub(crate) fn push(&mut self, line: usize, name: String) {
        let position = self.lines.len();
        self.lines.push(line);
        let id = match self.index.get(&name) {
            Some(&id) => id,
            None => {
                let id = self.names.len();
                self.index.insert(name.clone(), id);
                self.names.push((name, Vec::new()));
                id
            }
        };
        self.names[id].1.push(position);
        self.written.push(id);
    }

    fn sites_of(&self, name: &str) -> Option<&[usize]> {
        let id = *self.index.get(name)?;
        Some(&self.names[id].1)
    }

    /// The position of the last site of `sites` on a line of `start..end`.
    fn last_in(&self, sites: &[usize], start: usize, end: usize) -> Option<usize> {
        let after = sites.partition_point(|&p| self.lines[p] < end);
        let last = *sites.get(after.checked_sub(1)?)?;
        (self.lines[last] >= start).then_some(last)
    }

    /// Whether a line of `start..end` writes `name`.
    pub(crate) fn writes(&self, name: &str, start: usize, end: usize) -> bool {
        self.sites_of(name)
            .is_some_and(|sites| self.last_in(sites, start, end).is_some())
    }

    /// The positions of the sites on lines of `start..end`.
    fn range(&self, start: usize, end: usize) -> std::ops::Range<usize> {
        self.lines.partition_point(|&l| l < start)..self.lines.partition_point(|&l| l < end)
    }
}

/// A region whose written names a loop or a jump made unknown, not yet
/// applied to the bindings: a name reads as `unknown` when a line of the
/// region writes it and nothing bound it since. Nested loops forget nested
/// regions again and again; applying each in full cost lines × depth.
#[derive(Clone, Debug)]
struct Mark {
    start: usize,
    end: usize,
    /// Later than every binding made before the region was forgotten.
    stamp: u64,
    /// `Binding::Unknown` with the region's origin.
    unknown: Binding,
}

/// Marks held before they are applied all at once: a read looks through at
/// most this many.
const MAX_MARKS: usize = 64;

/// A binding and when it was made (`None`: removed), against the marks.
#[derive(Clone, Debug)]
struct Slot {
    binding: Option<Binding>,
    stamp: u64,
}

/// Bindings by key, with the keys of each array's elements and of the R
/// parameters at hand: forgetting an array or every R parameter costs what
/// they hold, not the whole table.
///
/// A region a loop or a jump forgets is a [`Mark`], read lazily; the marks
/// are applied (in one sweep over the sites they cover, each site once) when
/// an IF forks or joins, before every R parameter is forgotten at once, and
/// when more than [`MAX_MARKS`] are held.
///
/// While a branch is walked, every key it changes is journalled with its
/// binding from before the branch, so that the branches of an IF are
/// compared and joined by what they changed, not by copying and comparing
/// the whole table at every IF.
#[derive(Clone, Debug, Default)]
struct Vars {
    slots: HashMap<String, Slot>,
    /// Array name -> the keys of its elements that have a binding.
    elements: HashMap<String, HashSet<String>>,
    r_parameters: HashSet<String>,
    /// One level per branch being walked: key -> its slot before it.
    journal: Vec<Journal>,
    writers: Arc<Writers>,
    marks: Vec<Mark>,
    clock: u64,
    /// Units of work spent on forgetting: marks looked at, sites swept,
    /// keys changed. Bounded by the program's size times a constant.
    work: Cell<u64>,
}

type Journal = HashMap<String, Option<Slot>>;

/// What the newest mark later than a binding says of its key.
enum Hit<'a> {
    Unknown(&'a Binding),
    Removed,
}

impl Vars {
    fn get(&self, key: &str) -> Option<&Binding> {
        let slot = self.slots.get(key);
        let since = slot.map_or(0, |s| s.stamp);
        if self.marks.last().is_some_and(|m| m.stamp > since) {
            match self.marked(key, since) {
                Some(Hit::Unknown(binding)) => return Some(binding),
                Some(Hit::Removed) => return None,
                None => {}
            }
        }
        slot.and_then(|s| s.binding.as_ref())
    }

    /// The newest mark later than `since` that changes `key`: a region that
    /// writes it makes it unknown; one that writes its array removes an
    /// element; one with a subprogram call (name `R`) removes an R
    /// parameter, unless the parameter is written after the call there.
    fn marked(&self, key: &str, since: u64) -> Option<Hit<'_>> {
        let name = base(key);
        let element = name.len() != key.len();
        let own = self.writers.sites_of(name);
        let calls = (!element && is_r_parameter(key))
            .then(|| self.writers.sites_of("R"))
            .flatten();
        if own.is_none() && calls.is_none() {
            return None;
        }
        for mark in self.marks.iter().rev() {
            if mark.stamp <= since {
                break;
            }
            self.work.set(self.work.get() + 1);
            let last = |sites: Option<&[usize]>| {
                sites.and_then(|s| self.writers.last_in(s, mark.start, mark.end))
            };
            match (last(own), last(calls)) {
                (None, None) => continue,
                (Some(written), call) if !element && call.is_none_or(|c| written > c) => {
                    return Some(Hit::Unknown(&mark.unknown))
                }
                _ => return Some(Hit::Removed),
            }
        }
        None
    }

    /// Forgets what lines `start..end` write, lazily (at most
    /// [`MAX_MARKS`] held: settle first).
    fn mark(&mut self, start: usize, end: usize, origin: Origin) {
        self.work.set(self.work.get() + self.marks.len() as u64 + 1);
        // A region inside this one says nothing this one does not override.
        self.marks.retain(|m| !(m.start >= start && m.end <= end));
        self.clock += 1;
        self.marks.push(Mark {
            start,
            end,
            stamp: self.clock,
            unknown: Binding::Unknown { origin },
        });
    }

    /// Applies the marks held to the bindings, as forgetting each region in
    /// turn would: each key takes the newest mark that changes it, and the
    /// sites each mark covers are swept once, whatever the nesting.
    /// Returns the names made unknown (their arrays lose their defaults).
    fn settle(&mut self) -> Vec<String> {
        if self.marks.is_empty() {
            return Vec::new();
        }
        let marks = std::mem::take(&mut self.marks);
        let writers = Arc::clone(&self.writers);
        // Name -> (stamp, position, mark) of the newest mark covering one of
        // its sites, the last such site among that mark's.
        let mut newest: HashMap<&str, (u64, usize, usize)> = HashMap::default();
        let mut by_start: Vec<usize> = (0..marks.len()).collect();
        by_start.sort_by_key(|&i| marks[i].start);
        let mut covering = std::collections::BinaryHeap::new();
        let mut next = 0;
        let mut position = 0;
        let mut swept = 0u64;
        while next < by_start.len() || !covering.is_empty() {
            // Skip to the next region when no mark covers the sites here.
            if covering.is_empty() {
                let mark = &marks[by_start[next]];
                position = position.max(writers.range(mark.start, mark.end).start);
            }
            let Some(&line) = writers.lines.get(position) else {
                break;
            };
            while let Some(&i) = by_start.get(next) {
                if marks[i].start > line {
                    break;
                }
                covering.push((marks[i].stamp, marks[i].end, i));
                next += 1;
            }
            while covering.peek().is_some_and(|&(_, end, _)| end <= line) {
                covering.pop();
            }
            let Some(&(stamp, _, i)) = covering.peek() else {
                continue;
            };
            swept += 1;
            let entry = newest
                .entry(writers.names[writers.written[position]].0.as_str())
                .or_insert((stamp, position, i));
            *entry = (*entry).max((stamp, position, i));
            position += 1;
        }
        let mut changes: Vec<(u64, usize, usize, &str)> = newest
            .into_iter()
            .map(|(name, (stamp, position, i))| (stamp, position, i, name))
            .collect();
        changes.sort_unstable();
        let mut forgotten = Vec::new();
        self.work
            .set(self.work.get() + swept + changes.len() as u64);
        for (stamp, _, i, name) in changes {
            let Binding::Unknown { origin } = &marks[i].unknown else {
                continue;
            };
            if name == "R" {
                let older: Vec<String> = self
                    .r_parameters
                    .iter()
                    .filter(|key| self.older(key, stamp))
                    .cloned()
                    .collect();
                for key in older {
                    self.r_parameters.remove(&key);
                    self.tombstone(key);
                }
            } else if self.older(name, stamp) {
                let elements = self.elements.remove(name).unwrap_or_default();
                for key in elements {
                    if self.older(&key, stamp) {
                        self.tombstone(key);
                    } else {
                        self.elements
                            .entry(name.to_string())
                            .or_default()
                            .insert(key);
                    }
                }
                self.insert(
                    name.to_string(),
                    Binding::Unknown {
                        origin: origin.clone(),
                    },
                );
                forgotten.push(name.to_string());
            }
        }
        forgotten
    }

    /// Whether `key` was bound before `stamp` (or never).
    fn older(&self, key: &str, stamp: u64) -> bool {
        self.slots.get(key).is_none_or(|s| s.stamp < stamp)
    }

    #[cfg(test)]
    fn work(&self) -> u64 {
        self.work.get()
    }

    /// Journals `key`'s slot, the first time the open branch changes it.
    fn record(&mut self, key: &str) {
        if let Some(level) = self.journal.last_mut() {
            if !level.contains_key(key) {
                level.insert(key.to_string(), self.slots.get(key).cloned());
            }
        }
    }

    fn insert(&mut self, key: String, binding: Binding) {
        self.record(&key);
        self.insert_unrecorded(
            key,
            Slot {
                binding: Some(binding),
                stamp: self.clock,
            },
        );
    }

    fn tombstone(&mut self, key: String) {
        self.record(&key);
        let stamp = self.clock;
        self.slots.insert(
            key,
            Slot {
                binding: None,
                stamp,
            },
        );
    }

    fn insert_unrecorded(&mut self, key: String, slot: Slot) {
        let name = base(&key);
        if name.len() != key.len() {
            self.elements
                .entry(name.to_string())
                .or_default()
                .insert(key.clone());
        } else if is_r_parameter(&key) {
            self.r_parameters.insert(key.clone());
        }
        self.slots.insert(key, slot);
    }

    /// Removes `name` and every element of it.
    fn remove_all(&mut self, name: &str) {
        self.tombstone(name.to_string());
        self.r_parameters.remove(name);
        for key in self.elements.remove(name).into_iter().flatten() {
            self.tombstone(key);
        }
    }

    /// Every R parameter (settled first: one a mark made unknown is in no
    /// index until then).
    fn remove_r_parameters(&mut self) {
        for key in std::mem::take(&mut self.r_parameters) {
            self.tombstone(key);
        }
    }

    /// Puts the journalled keys back as they were; returns what they held.
    fn restore(&mut self, journal: Journal) -> Journal {
        journal
            .into_iter()
            .map(|(key, before)| {
                let now = match before {
                    Some(slot) => {
                        let now = self.slots.get(&key).cloned();
                        self.insert_unrecorded(key.clone(), slot);
                        now
                    }
                    None => self.slots.remove(&key),
                };
                (key, now)
            })
            .collect()
    }

    /// A branch's changes become the enclosing branch's, where it had not
    /// changed those keys itself. The larger journal is kept and the smaller
    /// poured into it, so a chain of nested IFs costs what they change, not
    /// that times their depth.
    fn hand_up(&mut self, mut journal: Journal) {
        if let Some(level) = self.journal.last_mut() {
            if level.len() < journal.len() {
                std::mem::swap(level, &mut journal);
                // `journal` now holds the enclosing level's own, older entries.
                for (key, before) in journal {
                    level.insert(key, before);
                }
            } else {
                for (key, before) in journal {
                    level.entry(key).or_insert(before);
                }
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
            array_defaults: HashMap::default(),
            measured_arrays: HashMap::default(),
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
    /// The state at the start of a program whose names are written where
    /// `writers` says.
    pub(crate) fn of_program(writers: Arc<Writers>) -> Self {
        let mut env = Self::default();
        env.vars.writers = writers;
        env
    }

    /// Whatever lines `start..end` write is unknown from here, with
    /// `origin`: their names (read lazily, see [`Mark`]), an array's
    /// elements, and the R parameters where a subprogram is called there.
    pub(crate) fn forget_region(&mut self, start: usize, end: usize, origin: Origin) {
        if self.vars.marks.len() >= MAX_MARKS {
            self.settle();
        }
        if self.vars.writers.writes("R", start, end) {
            self.r_clobbered = Some(origin.clone());
        }
        self.vars.mark(start, end, origin);
    }

    /// Applies the regions forgotten lazily.
    fn settle(&mut self) {
        for name in self.vars.settle() {
            self.array_defaults.remove(&name);
        }
    }

    /// Units of work forgetting has cost so far (regions marked, marks read,
    /// sites swept): a measure of the walk's cost that no machine's speed
    /// changes.
    #[cfg(test)]
    pub(crate) fn work(&self) -> u64 {
        self.vars.work()
    }

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
        self.settle();
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
        self.settle();
        self.vars.journal.push(Journal::default());
        Fork { rest: self.rest() }
    }

    /// Ends the branch walked since `fork`: what it left, with the state put
    /// back as it was at the fork, and the other branch started from there.
    pub fn rewind(&mut self, fork: Fork) -> Branch {
        self.settle();
        let journal = self.vars.journal.pop().unwrap_or_default();
        let rest = self.take_rest();
        self.put_rest(fork.rest);
        let values = self.vars.restore(journal);
        self.vars.journal.push(Journal::default());
        Branch { values, rest }
    }

    /// Ends the other branch (walked since [`Env::rewind`]) and joins it with
    /// the first one, `then`: what differs between them is unknown.
    pub fn join(&mut self, then: Branch, line: usize) {
        self.settle();
        let journal = self.vars.journal.pop().unwrap_or_default();
        let mut differing = Vec::new();
        fn binding(slot: &Option<Slot>) -> Option<&Binding> {
            slot.as_ref().and_then(|s| s.binding.as_ref())
        }
        for key in journal.keys().chain(then.values.keys()) {
            let now = self.vars.get(key);
            let before = journal.get(key).map_or(now, binding);
            let in_then = then.values.get(key).map_or(before, binding);
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
