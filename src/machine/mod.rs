//! The machine as its own data describe it: the machine data of the files
//! the control writes, read by name and index ([`data`]), and what they say
//! of each axis ([`axes`]), of its tools ([`tools`]) and its settable frames
//! ([`frames`]). The swivel data records are read by
//! [`crate::semantic::machine`], the names a program may use (GUD, macros,
//! axes) by [`crate::semantic::environment`].

pub mod axes;
pub mod data;
pub mod frames;
pub mod tools;

pub use axes::{axes, Axis};
pub use data::{Datum, Index, MachineData};
pub use frames::{base_frames, frame_name, frames, Components};
pub use tools::{tools, Tool};

use crate::semantic::value::Value;

/// Every datum by the key a program reads it with (`$MA_POS_LIMIT_PLUS[AX1]`,
/// see [`crate::semantic::eval::key`]): its indices as written, and where
/// one is an axis, by each of the axis's names as well (`[AX1]`, `[X1]`,
/// `[X]`). A channel's datum is channel 1's, where programs run unless the
/// machine has more; the last line that assigns a key wins, as on the
/// control.
pub fn keyed(data: &MachineData, axes: &[Axis]) -> Vec<(String, Value)> {
    let names_of = |index: &str| -> Vec<String> {
        let axis = axes.iter().find(|a| {
            format!("AX{}", a.index) == index
                || a.machine_name.as_deref() == Some(index)
                || a.name.as_deref() == Some(index)
        });
        match axis {
            Some(axis) => {
                let mut names = vec![format!("AX{}", axis.index)];
                names.extend(axis.machine_name.clone());
                names.extend(axis.name.clone());
                names.dedup();
                names
            }
            None => vec![index.to_string()],
        }
    };
    let mut keyed = Vec::new();
    for datum in &data.data {
        if datum.name.starts_with("$MC_") && datum.channel.is_some_and(|c| c != 1) {
            continue;
        }
        let mut keys: Vec<Vec<String>> = vec![Vec::new()];
        for index in &datum.indices {
            let texts = match index {
                Index::Number(n) => vec![n.to_string()],
                Index::Axis(name) => names_of(name),
            };
            keys = keys
                .iter()
                .flat_map(|key| {
                    texts.iter().map(move |text| {
                        let mut key = key.clone();
                        key.push(text.clone());
                        key
                    })
                })
                .collect();
        }
        for indices in keys {
            let key = crate::semantic::eval::key(&datum.name, &indices);
            keyed.push((key, datum.value.clone()));
        }
    }
    keyed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_datum_is_keyed_by_every_name_of_its_axis() {
        let source = b"N10000 $MN_AXCONF_MACHAX_NAME_TAB[2]=\"Z1\"\nCHANDATA(1)\n\
N20070 $MC_AXCONF_MACHAX_USED[2]=3\nN20080 $MC_AXCONF_CHANAX_NAME_TAB[2]=\"Z\"\n\
N32300 $MA_MAX_AX_ACCEL[1,AX3]=2.5\nCHANDATA(2)\nN20080 $MC_AXCONF_CHANAX_NAME_TAB[2]=\"ZZ\"\n\
$TC_DP3[1,1]=95.5\n";
        let data = MachineData::read(source);
        let keyed = keyed(&data, &axes(&data));
        let value = |key: &str| {
            keyed
                .iter()
                .rev()
                .find(|(k, _)| k == key)
                .map(|(_, v)| v.clone())
        };
        for key in [
            "$MA_MAX_AX_ACCEL[1,AX3]",
            "$MA_MAX_AX_ACCEL[1,Z1]",
            "$MA_MAX_AX_ACCEL[1,Z]",
        ] {
            assert_eq!(value(key), Some(Value::Number(2.5)), "{key}");
        }
        assert_eq!(value("$TC_DP3[1,1]"), Some(Value::Number(95.5)));
        assert_eq!(
            value("$MC_AXCONF_CHANAX_NAME_TAB[2]"),
            Some(Value::Text("Z".into()))
        );
    }
}
