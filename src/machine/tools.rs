//! The tool offsets the data hold (`$TC_DPn[t,d]`, a `TO_INI` or an
//! archive's `INITIAL_INI`): per tool and cutting edge its type, lengths and
//! radius with their wear (Siemens, SINUMERIK 840D sl Tool Management,
//! "Tool offset data": `$TC_DP1` type, `$TC_DP3..5` geometry lengths 1 to 3,
//! `$TC_DP6` radius, `$TC_DP12..14` their wear, `$TC_DP15` the radius's).
//! In the units of the machine (mm, or inch where MD10240 says so).

use crate::machine::data::{Index, MachineData};

/// One cutting edge of a tool.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Tool {
    /// The tool's number in the offset memory (`T`, or the internal number
    /// under tool management).
    pub t: u32,
    /// The cutting edge (`D`).
    pub d: u32,
    /// `$TC_DP1`: the tool type (120 end mill, 500 roughing tool, ...).
    #[serde(rename = "type")]
    pub kind: Option<f64>,
    /// `$TC_DP3..5`.
    pub length: [Option<f64>; 3],
    /// `$TC_DP6`.
    pub radius: Option<f64>,
    /// `$TC_DP12..14`.
    pub length_wear: [Option<f64>; 3],
    /// `$TC_DP15`.
    pub radius_wear: Option<f64>,
}

/// Every cutting edge a `$TC_DP` datum names, by tool and edge.
pub fn tools(data: &MachineData) -> Vec<Tool> {
    let mut tools: Vec<Tool> = Vec::new();
    for datum in &data.data {
        let Some(parameter) = datum.name.strip_prefix("$TC_DP") else {
            continue;
        };
        let Ok(parameter) = parameter.parse::<u32>() else {
            continue; // $TC_DPC, $TC_DPCE, $TC_DPH, ...: not offsets
        };
        let [Index::Number(t), Index::Number(d)] = datum.indices[..] else {
            continue;
        };
        let at = match tools.binary_search_by_key(&(t, d), |tool| (tool.t, tool.d)) {
            Ok(at) => at,
            Err(at) => {
                tools.insert(
                    at,
                    Tool {
                        t,
                        d,
                        ..Tool::default()
                    },
                );
                at
            }
        };
        let tool = &mut tools[at];
        let value = datum.value.number();
        match parameter {
            1 => tool.kind = value,
            3..=5 => tool.length[parameter as usize - 3] = value,
            6 => tool.radius = value,
            12..=14 => tool.length_wear[parameter as usize - 12] = value,
            15 => tool.radius_wear = value,
            _ => {}
        }
    }
    tools
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_edge_gets_its_lengths_and_radius() {
        let source = b"$TC_DP1[3,1]=120\n$TC_DP3[3,1]=95.5 $TC_DP6[3,1]=5\n$TC_DP12[3,1]=-0.02\n\
$TC_DP1[1,2]=500\n$TC_DP5[1,2]=10\n$TC_DPC1[1,2]=7\nM17\n";
        let tools = tools(&MachineData::read(source));
        let edges: Vec<(u32, u32)> = tools.iter().map(|t| (t.t, t.d)).collect();
        assert_eq!(edges, [(1, 2), (3, 1)]);
        assert_eq!(tools[0].kind, Some(500.0));
        assert_eq!(tools[0].length, [None, None, Some(10.0)]);
        assert_eq!(tools[1].length, [Some(95.5), None, None]);
        assert_eq!(tools[1].radius, Some(5.0));
        assert_eq!(tools[1].length_wear, [Some(-0.02), None, None]);
    }
}
