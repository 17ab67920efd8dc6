//! The machine axes as the machine data describe them: their names, whether
//! they turn, their software limits and their dynamics. Each value is the
//! datum's as the control stores it, in its units (Siemens, SINUMERIK
//! 840D sl Machine data and parameters, List Manual, "Axis-specific machine
//! data"): positions in mm (inch on an inch machine, MD10240) or degrees,
//! MD32000 in mm/min or rev/min, MD32300 in m/s² or rev/s², MD32431 in m/s³
//! or rev/s³. A datum the files do not hold is `None`: never a default.

use crate::machine::data::{Index, MachineData};
use crate::semantic::value::Value;

/// One machine axis.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Axis {
    /// Its channel axis name (MD20080 `$MC_AXCONF_CHANAX_NAME_TAB` of the
    /// channel axis MD20070 `$MC_AXCONF_MACHAX_USED` makes it), in the
    /// first channel that uses it.
    pub name: Option<String>,
    /// MD10000 `$MN_AXCONF_MACHAX_NAME_TAB`.
    pub machine_name: Option<String>,
    /// Its number: `AX1` is 1.
    pub index: u32,
    /// MD30300 `$MA_IS_ROT_AX`.
    pub rotary: Option<bool>,
    /// MD30310 `$MA_ROT_IS_MODULO`: positions counted modulo 360°, no limits.
    pub modulo: Option<bool>,
    /// MD36100 `$MA_POS_LIMIT_MINUS`, MD36110 `$MA_POS_LIMIT_PLUS`.
    pub limits: [Option<f64>; 2],
    /// MD36120 `$MA_POS_LIMIT_MINUS2`, MD36130 `$MA_POS_LIMIT_PLUS2`, in force
    /// where the PLC selects them.
    pub limits2: [Option<f64>; 2],
    /// MD32000 `$MA_MAX_AX_VELO`.
    pub max_velocity: Option<f64>,
    /// MD32300 `$MA_MAX_AX_ACCEL`, by dynamic response group (DYNNORM,
    /// DYNPOS, DYNROUGH, DYNSEMIFIN, DYNFINISH) as the files index it; one
    /// value where a file writes it without the group.
    pub max_acceleration: Vec<Option<f64>>,
    /// MD32431 `$MA_MAX_AX_JERK`, by dynamic response group as above.
    pub max_jerk: Vec<Option<f64>>,
}

/// The machine axes the data name or describe, by number.
pub fn axes(data: &MachineData) -> Vec<Axis> {
    let names = machine_names(data);
    let mut axes: Vec<Axis> = Vec::new();
    for (at, name) in names.iter().enumerate() {
        if let Some(name) = name {
            axis(&mut axes, at as u32 + 1).machine_name = Some(name.clone());
        }
    }
    for datum in &data.data {
        let Some(field) = datum.name.strip_prefix("$MA_") else {
            continue;
        };
        // The axis is the last index; the group, where there is one, before it.
        let Some((Index::Axis(named), before)) = datum.indices.split_last() else {
            continue;
        };
        let Some(index) = axis_number(named, &names) else {
            continue;
        };
        let number = datum.value.number();
        let flag = number.map(|n| n != 0.0);
        let group = match before {
            [] => Some(0),
            [Index::Number(group)] => Some(*group as usize),
            _ => None,
        };
        let axis = axis(&mut axes, index);
        match (field, group) {
            ("IS_ROT_AX", _) => axis.rotary = flag,
            ("ROT_IS_MODULO", _) => axis.modulo = flag,
            ("POS_LIMIT_MINUS", _) => axis.limits[0] = number,
            ("POS_LIMIT_PLUS", _) => axis.limits[1] = number,
            ("POS_LIMIT_MINUS2", _) => axis.limits2[0] = number,
            ("POS_LIMIT_PLUS2", _) => axis.limits2[1] = number,
            ("MAX_AX_VELO", _) => axis.max_velocity = number,
            ("MAX_AX_ACCEL", Some(group)) => put(&mut axis.max_acceleration, group, number),
            ("MAX_AX_JERK", Some(group)) => put(&mut axis.max_jerk, group, number),
            _ => {}
        }
    }
    for (_, axis_number, name) in channel_names(data) {
        let axis = axis(&mut axes, axis_number);
        if axis.name.is_none() {
            axis.name = Some(name);
        }
    }
    axes
}

/// The axis numbered `index` among `axes` (sorted by number), added when
/// it is not yet.
fn axis(axes: &mut Vec<Axis>, index: u32) -> &mut Axis {
    let at = match axes.binary_search_by_key(&index, |a| a.index) {
        Ok(at) => at,
        Err(at) => {
            let new = Axis {
                index,
                ..Axis::default()
            };
            axes.insert(at, new);
            at
        }
    };
    &mut axes[at]
}

/// `value` as the `group`th of `values`, those before it unknown where no
/// line gave them.
fn put(values: &mut Vec<Option<f64>>, group: usize, value: Option<f64>) {
    // Five groups on the control; a larger index is a typo, not a reason to
    // hold millions of values.
    if group >= 16 {
        return;
    }
    if values.len() <= group {
        values.resize(group + 1, None);
    }
    values[group] = value;
}

/// MD10000: the machine axes' names, by position (`AX1` first).
fn machine_names(data: &MachineData) -> Vec<Option<String>> {
    let mut names: Vec<Option<String>> = Vec::new();
    for datum in data.named("$MN_AXCONF_MACHAX_NAME_TAB") {
        let ([Index::Number(at)], Value::Text(name)) = (&datum.indices[..], &datum.value) else {
            continue;
        };
        let at = *at as usize;
        if at >= 64 || name.is_empty() {
            continue;
        }
        if names.len() <= at {
            names.resize(at + 1, None);
        }
        names[at] = Some(name.to_ascii_uppercase());
    }
    names
}

/// The number of the axis `name` calls: `AX3` is 3, a machine axis's name
/// its place in MD10000.
fn axis_number(name: &str, names: &[Option<String>]) -> Option<u32> {
    if let Some(digits) = name.strip_prefix("AX") {
        if let Ok(n) = digits.parse::<u32>() {
            return (n >= 1).then_some(n);
        }
    }
    let at = names.iter().position(|n| n.as_deref() == Some(name))?;
    Some(at as u32 + 1)
}

/// (channel, machine axis, channel axis name) of every channel axis that
/// MD20070 maps to a machine axis and MD20080 names, channels in order.
/// Data before any `CHANDATA` are channel 1's, as the control loads them.
fn channel_names(data: &MachineData) -> Vec<(u32, u32, String)> {
    let channel_of = |channel: Option<u32>| channel.unwrap_or(1);
    let mut found = Vec::new();
    for used in data.named("$MC_AXCONF_MACHAX_USED") {
        let ([Index::Number(at)], Some(machine_axis)) = (&used.indices[..], used.value.number())
        else {
            continue;
        };
        if machine_axis < 1.0 || machine_axis.fract() != 0.0 || machine_axis > 64.0 {
            continue; // 0: no machine axis
        }
        let channel = channel_of(used.channel);
        let name = data
            .named("$MC_AXCONF_CHANAX_NAME_TAB")
            .filter(|d| channel_of(d.channel) == channel && d.indices == [Index::Number(*at)])
            .last()
            .and_then(|d| match &d.value {
                Value::Text(name) if !name.is_empty() => Some(name.to_ascii_uppercase()),
                _ => None,
            });
        if let Some(name) = name {
            found.push((channel, machine_axis as u32, name));
        }
    }
    found.sort_by_key(|&(channel, axis, _)| (channel, axis));
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    const DATA: &str = "\
N10000 $MN_AXCONF_MACHAX_NAME_TAB[0]=\"X1\"
N10000 $MN_AXCONF_MACHAX_NAME_TAB[1]=\"Y1\"
N10000 $MN_AXCONF_MACHAX_NAME_TAB[3]=\"C1\"
CHANDATA(1)
N20070 $MC_AXCONF_MACHAX_USED[0]=1
N20070 $MC_AXCONF_MACHAX_USED[1]=2
N20070 $MC_AXCONF_MACHAX_USED[2]=4
N20080 $MC_AXCONF_CHANAX_NAME_TAB[0]=\"X\"
N20080 $MC_AXCONF_CHANAX_NAME_TAB[1]=\"Y\"
N20080 $MC_AXCONF_CHANAX_NAME_TAB[2]=\"C\"
N30300 $MA_IS_ROT_AX[AX4]=1
N30310 $MA_ROT_IS_MODULO[AX4]=1
N30300 $MA_IS_ROT_AX[AX1]=0
N36100 $MA_POS_LIMIT_MINUS[AX1]=-0.6
N36110 $MA_POS_LIMIT_PLUS[AX1]=1500.6
N36120 $MA_POS_LIMIT_MINUS2[X1]=-10
N32000 $MA_MAX_AX_VELO[AX1]=30000
N32300 $MA_MAX_AX_ACCEL[0,AX1]=2.5
N32300 $MA_MAX_AX_ACCEL[2,AX1]=1.5
N32431 $MA_MAX_AX_JERK[0,AX1]=40
N32300 $MA_MAX_AX_ACCEL[AX2]=3
M17
";

    #[test]
    fn each_axis_gets_its_names_limits_and_dynamics() {
        let data = MachineData::read(DATA.as_bytes());
        assert!(data.diagnostics.is_empty());
        let axes = axes(&data);
        let indices: Vec<u32> = axes.iter().map(|a| a.index).collect();
        assert_eq!(indices, [1, 2, 4]);
        let x = &axes[0];
        assert_eq!(x.name.as_deref(), Some("X"));
        assert_eq!(x.machine_name.as_deref(), Some("X1"));
        assert_eq!(x.rotary, Some(false));
        assert_eq!(x.modulo, None);
        assert_eq!(x.limits, [Some(-0.6), Some(1500.6)]);
        assert_eq!(x.limits2, [Some(-10.0), None]);
        assert_eq!(x.max_velocity, Some(30000.0));
        assert_eq!(x.max_acceleration, [Some(2.5), None, Some(1.5)]);
        assert_eq!(x.max_jerk, [Some(40.0)]);
        let y = &axes[1];
        assert_eq!((y.name.as_deref(), y.rotary), (Some("Y"), None));
        assert_eq!(y.max_acceleration, [Some(3.0)]);
        let c = &axes[2];
        assert_eq!(c.name.as_deref(), Some("C"));
        assert_eq!((c.rotary, c.modulo), (Some(true), Some(true)));
        assert_eq!(c.limits, [None, None]);
    }
}
