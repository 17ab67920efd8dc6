//! The machine as the dry run needs it, from its own data: the axes a
//! program names (geometry axes through MD20050/MD20060, the others by their
//! channel names), each with its machine axis, limits and dynamics in the
//! units the run computes in (mm or degrees, per second), the settable
//! frames, the tool offsets and the clock. Nothing is assumed: a datum the
//! data lack stays `None`, and the run says what it could not do for it.

use std::collections::BTreeMap;

use crate::machine::data::{Index, MachineData};
use crate::machine::{axes, frames, tools, Axis, Components, Tool};
use crate::semantic::value::Value;
use crate::semantic::Supplied;

/// One axis a program moves.
#[derive(Clone, Debug, PartialEq)]
pub struct RunAxis {
    /// The name programs give it (`X`, `C`).
    pub name: String,
    /// Geometry axis 0, 1, 2 (`X`, `Y`, `Z` of the plane G17), if it is one.
    pub geometry: Option<usize>,
    /// The machine axis it drives, when the data say which.
    pub machine: Option<Axis>,
}

impl RunAxis {
    /// What reports call its machine axis: MD10000's name, else `AXn`,
    /// else the program's name.
    pub fn machine_name(&self) -> String {
        match &self.machine {
            Some(axis) => axis
                .machine_name
                .clone()
                .unwrap_or_else(|| format!("AX{}", axis.index)),
            None => self.name.clone(),
        }
    }

    pub fn rotary(&self) -> bool {
        self.machine
            .as_ref()
            .and_then(|a| a.rotary)
            .unwrap_or(self.geometry.is_none() && matches!(self.name.as_str(), "A" | "B" | "C"))
    }

    /// Its software limits (MD36100, MD36110; with `second`, MD36120,
    /// MD36130), none on a modulo axis.
    pub fn limits(&self, second: bool) -> [Option<f64>; 2] {
        match &self.machine {
            Some(axis) if axis.modulo == Some(true) => [None, None],
            Some(axis) if second => axis.limits2,
            Some(axis) => axis.limits,
            None => [None, None],
        }
    }

    /// MD32000 in mm/s (or degrees/s): the datum is mm/min (rev/min).
    pub fn max_velocity(&self) -> Option<f64> {
        let v = self.machine.as_ref()?.max_velocity?;
        Some(if self.rotary() {
            v * 360.0 / 60.0
        } else {
            v / 60.0
        })
    }

    /// MD32300 of dynamic response group `group` in mm/s² (degrees/s²):
    /// the datum is m/s² (rev/s²); one written without a group serves all.
    pub fn max_acceleration(&self, group: usize) -> Option<f64> {
        let values = &self.machine.as_ref()?.max_acceleration;
        let a = by_group(values, group)?;
        Some(if self.rotary() { a * 360.0 } else { a * 1000.0 })
    }

    /// MD32431 of `group` in mm/s³ (degrees/s³), as the acceleration.
    pub fn max_jerk(&self, group: usize) -> Option<f64> {
        let values = &self.machine.as_ref()?.max_jerk;
        let j = by_group(values, group)?;
        Some(if self.rotary() { j * 360.0 } else { j * 1000.0 })
    }
}

fn by_group(values: &[Option<f64>], group: usize) -> Option<f64> {
    match values {
        [one] => *one,
        _ => values.get(group).copied().flatten(),
    }
}

/// The machine of a run.
#[derive(Debug, Default)]
pub struct Setup {
    /// Geometry axes first (X, Y, Z as MD20060 names them), then the other
    /// channel axes.
    pub axes: Vec<RunAxis>,
    /// The settable frames by G function, their components by axis name.
    pub frames: BTreeMap<String, BTreeMap<String, Components>>,
    pub tools: Vec<Tool>,
    /// MD10240: `Some(true)` metric, `Some(false)` inch.
    pub metric: Option<bool>,
    /// The interpolation cycle in seconds (MD10050 × MD10070), the least
    /// time a block takes.
    pub ipo_cycle_s: Option<f64>,
    /// MD22550 `$MC_TOOL_CHANGE_MODE`: 1 where M6 changes the tool T selects.
    pub tool_change_with_m6: Option<bool>,
    /// MD20270 `$MC_CUTTING_EDGE_DEFAULT`: the D a tool change selects.
    pub default_edge: Option<u32>,
    /// MD20150 `$MC_GCODE_RESET_VALUES[9]` (G group 10): `Some(true)` for
    /// G60 at the start, `Some(false)` for a continuous-path mode.
    pub reset_exact_stop: Option<bool>,
    /// MD20150 `[20]` (G group 21): `Some(true)` for SOFT at the start.
    pub reset_soft: Option<bool>,
    /// The G functions MD20150 `$MC_GCODE_RESET_VALUES` makes active at the
    /// start in the groups the run follows (motion, plane, settable frame,
    /// units, G90/G91, feed type, corners), where the data hold them.
    pub reset_g_functions: Vec<u32>,
    /// The base frames in the data that move or turn anything (`CHBFR0`):
    /// not applied, since which are active is the control's state.
    pub base_frames: Vec<String>,
    /// MD10600 `$MN_FRAME_ANGLE_INPUT_MODE`: `Some(true)` for RPY angles
    /// (Z, Y', X''), `Some(false)` for Euler angles.
    pub angles_rpy: Option<bool>,
    /// The swivel data records CYCLE800 names (`$TC_CARR`), those the
    /// solver can use.
    pub records: Vec<crate::kinematics::Record>,
    /// The channel's orientation transformations, in the order `TRAORI(n)`
    /// numbers them.
    pub orientations: Vec<Orientation>,
    /// MD21104 `$MC_ORI_IPO_WITH_G_CODE`: `Some(true)` where G group 51
    /// (ORIAXES, ORIVECT, ...) chooses how the orientation turns, else
    /// ORIWKS/ORIMKS do.
    pub orientation_by_g_code: Option<bool>,
    /// MD20210 `$MC_CUTCOM_CORNER_LIMIT`: the contour's turn (degrees) from
    /// which an outside corner under G451 gets a circle after all.
    pub corner_limit: Option<f64>,
    /// MD20230 `$MC_CUTCOM_CURVE_INSERT_LIMIT`: the contour's turn (degrees)
    /// below which an outside corner under G450 gets the meeting point.
    pub curve_insert_limit: Option<f64>,
    /// Geometry axes the channel does not have (MD20050 0: a lathe's Y):
    /// kept in their place, left out of the report unless a program moves them.
    pub absent_geometry: [bool; 3],
}

/// An orientation transformation of the channel (TRAORI): one of MD24100
/// `$MC_TRAFO_TYPE_1..10` from 16 to 255 (a 3-, 4- or 5-axis
/// transformation: 16 the tool turns, 32 the workpiece, 48 both, 8 more
/// for a generic one, 72 the vectors of a swivel data record).
#[derive(Clone, Debug, PartialEq)]
pub struct Orientation {
    /// MD24100.
    pub trafo_type: u32,
    /// For type 72, the swivel data record whose vectors it takes: MD24582
    /// `$MC_TRAFO5_TCARR_NO_1` (`_2` for the channel's second).
    pub record: Option<u32>,
}

/// Transformations a channel holds, at most (MD24100 `_1` to `_10`).
const TRANSFORMATIONS: u32 = 10;

/// The channel's orientation transformations in order (see [`Orientation`]).
fn orientations(data: &MachineData) -> Vec<Orientation> {
    let number = |name: String| match data.get(&name, Some(1), &[]) {
        Some(Value::Number(n)) if *n >= 0.0 && n.fract() == 0.0 => Some(*n as u32),
        _ => None,
    };
    (1..=TRANSFORMATIONS)
        .filter_map(|x| number(format!("$MC_TRAFO_TYPE_{x}")))
        .filter(|t| (16..256).contains(t))
        .enumerate()
        .map(|(n, trafo_type)| Orientation {
            trafo_type,
            record: (trafo_type == 72)
                .then(|| number(format!("$MC_TRAFO5_TCARR_NO_{}", n + 1)))
                .flatten(),
        })
        .collect()
}

/// The G functions of the groups the run follows, by their place in MD20150
/// (the G group less one) and in the group (from 1), as the Programming
/// Manual's table of G functions orders them.
const RESET_GROUPS: [(u32, &[u32]); 7] = [
    (0, &[0, 1, 2, 3]),
    (5, &[17, 18, 19]),
    (12, &[70, 71, 700, 710]),
    (13, &[90, 91]),
    (14, &[93, 94, 95]),
    (17, &[450, 451]),
    // G500, G54..G57, G505..G599: the frame's number.
    (7, &[]),
];

/// The G functions MD20150 (read by `value` at a group's place) selects at
/// the start, in the groups the run follows.
fn reset_g_functions(value: impl Fn(u32) -> Option<f64>) -> Vec<u32> {
    RESET_GROUPS
        .iter()
        .filter_map(|&(group, members)| {
            let place = value(group)?;
            if place < 1.0 || place.fract() != 0.0 {
                return None;
            }
            let place = place as usize;
            if group == 7 {
                return crate::machine::frame_name(place as u32 - 1)?
                    .strip_prefix('G')?
                    .parse()
                    .ok();
            }
            members.get(place - 1).copied()
        })
        .collect()
}

impl Setup {
    pub fn of(data: &MachineData) -> Setup {
        let machine_axes = axes(data);
        let number = |name: &str, channel: Option<u32>, indices: &[Index]| match data
            .get(name, channel, indices)
        {
            Some(Value::Number(n)) => Some(*n),
            _ => None,
        };
        let text = |name: &str, index: u32| match data.get(name, Some(1), &[Index::Number(index)]) {
            Some(Value::Text(t)) => Some(t.to_ascii_uppercase()),
            _ => None,
        };
        // Channel axis k (1-based) by its name, MD20080.
        let channel_name = |k: u32| text("$MC_AXCONF_CHANAX_NAME_TAB", k - 1);
        let machine_of = |channel_name: &str| {
            machine_axes
                .iter()
                .find(|a| {
                    a.name
                        .as_deref()
                        .is_some_and(|n| n.eq_ignore_ascii_case(channel_name))
                })
                .cloned()
        };
        let mut run_axes = Vec::new();
        let mut absent_geometry = [false; 3];
        for g in 0..3u32 {
            let name = text("$MC_AXCONF_GEOAX_NAME_TAB", g)
                .unwrap_or_else(|| ["X", "Y", "Z"][g as usize].to_string());
            let assigned = number("$MC_AXCONF_GEOAX_ASSIGN_TAB", Some(1), &[Index::Number(g)]);
            let machine = match assigned {
                Some(k) if k >= 1.0 => channel_name(k as u32).and_then(|c| machine_of(&c)),
                Some(_) => {
                    absent_geometry[g as usize] = true;
                    None
                }
                None => machine_of(&name),
            };
            run_axes.push(RunAxis {
                name,
                geometry: Some(g as usize),
                machine,
            });
        }
        let geometry_machines: Vec<u32> = run_axes
            .iter()
            .filter_map(|a| a.machine.as_ref().map(|m| m.index))
            .collect();
        for axis in &machine_axes {
            let Some(name) = &axis.name else { continue };
            if geometry_machines.contains(&axis.index)
                || run_axes.iter().any(|a| a.name.eq_ignore_ascii_case(name))
            {
                continue;
            }
            run_axes.push(RunAxis {
                name: name.to_ascii_uppercase(),
                geometry: None,
                machine: Some(axis.clone()),
            });
        }
        // An NCK datum, wherever the files write it (after a CHANDATA too).
        let nck = |name: &str| match data.named(name).filter(|d| d.indices.is_empty()).last() {
            Some(crate::machine::Datum {
                value: Value::Number(n),
                ..
            }) => Some(*n),
            _ => None,
        };
        let sysclock = nck("$MN_SYSCLOCK_CYCLE_TIME");
        let ratio = nck("$MN_IPO_SYSCLOCK_TIME_RATIO");
        Setup {
            axes: run_axes,
            frames: frames(data),
            tools: tools(data),
            metric: nck("$MN_SCALING_SYSTEM_IS_METRIC").map(|n| n != 0.0),
            ipo_cycle_s: sysclock.zip(ratio).map(|(s, r)| s * r),
            tool_change_with_m6: number("$MC_TOOL_CHANGE_MODE", Some(1), &[]).map(|n| n == 1.0),
            reset_exact_stop: number("$MC_GCODE_RESET_VALUES", Some(1), &[Index::Number(9)])
                .map(|g| g == 1.0),
            reset_soft: number("$MC_GCODE_RESET_VALUES", Some(1), &[Index::Number(20)])
                .map(|g| g == 2.0),
            reset_g_functions: reset_g_functions(|group| {
                number("$MC_GCODE_RESET_VALUES", Some(1), &[Index::Number(group)])
            }),
            base_frames: crate::machine::base_frames(data)
                .into_iter()
                .filter(|(_, axes)| axes.values().any(|c| c.acts()))
                .map(|(name, _)| name)
                .collect(),
            angles_rpy: nck("$MN_FRAME_ANGLE_INPUT_MODE").map(|n| n == 1.0),
            default_edge: number("$MC_CUTTING_EDGE_DEFAULT", Some(1), &[])
                .and_then(|n| (n >= 0.0 && n.fract() == 0.0).then_some(n as u32)),
            records: Vec::new(),
            orientations: orientations(data),
            orientation_by_g_code: number("$MC_ORI_IPO_WITH_G_CODE", Some(1), &[])
                .map(|n| n != 0.0),
            corner_limit: number("$MC_CUTCOM_CORNER_LIMIT", Some(1), &[]),
            curve_insert_limit: number("$MC_CUTCOM_CURVE_INSERT_LIMIT", Some(1), &[]),
            absent_geometry,
        }
    }

    /// The setup with the swivel data records of `machine`, as read with
    /// the values the user gives.
    pub fn with_records(mut self, machine: &crate::semantic::machine::Machine) -> Setup {
        self.records = machine.usable().cloned().collect();
        self
    }

    /// The axis programs call `name` (upper case).
    pub fn axis(&self, name: &str) -> Option<usize> {
        self.axes.iter().position(|a| a.name == name)
    }

    /// Tool `t`'s cutting edge `d`.
    pub fn tool(&self, t: u32, d: u32) -> Option<&Tool> {
        self.tools.iter().find(|tool| tool.t == t && tool.d == d)
    }
}

/// The values a run reads: those the user gives (`--set`, `--values`,
/// sinuprep.toml), then those the machine's data hold for GUD variables and
/// R parameters (an archive's: the control's state when it was written),
/// the NC's and the first channel's; with how many the data gave.
pub fn values_with_data(given: &Supplied, data: &MachineData) -> (Supplied, usize) {
    let mut values = given.clone();
    let mut from_data = 0;
    for datum in &data.values {
        if datum.channel.is_some_and(|c| c != 1) {
            continue;
        }
        let indices: Vec<String> = datum
            .indices
            .iter()
            .map(|index| match index {
                Index::Number(n) => n.to_string(),
                Index::Axis(axis) => axis.clone(),
            })
            .collect();
        let key = crate::semantic::eval::key(&datum.name, &indices);
        if given.get(&key).is_none() {
            if values.get(&key).is_none() {
                from_data += 1;
            }
            values.insert(key, datum.value.clone(), "the machine's data".to_string());
        }
    }
    (values, from_data)
}
