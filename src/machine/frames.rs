//! The settable frames the data hold, component by component as the control
//! writes them (`$P_UIFR[1,X,TR]=10`, a `_N_UFR_INI` or an archive's
//! `INITIAL_INI`): per frame and axis its coarse translation `TR`, fine
//! translation `FI`, rotation `RT` (degrees), scale `SC` and mirror `MI`
//! (Siemens, SINUMERIK 840D sl Job Planning, "Frames": `$P_UIFR[0]` is the
//! frame of G500, `[1]` to `[4]` those of G54 to G57, `[5]` to `[99]` those of
//! G505 to G599).

use std::collections::BTreeMap;

use crate::machine::data::{Index, MachineData};

/// One axis's components of a frame; `None` where the data hold none.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Components {
    pub tr: Option<f64>,
    pub fi: Option<f64>,
    pub rt: Option<f64>,
    pub sc: Option<f64>,
    pub mi: Option<f64>,
}

/// The G function that selects settable frame `index`.
pub fn frame_name(index: u32) -> Option<String> {
    match index {
        0 => Some("G500".to_string()),
        1..=4 => Some(format!("G{}", 53 + index)),
        5..=99 => Some(format!("G{}", 500 + index)),
        _ => None,
    }
}

/// The settable frames by their G function, each with its axes' components
/// by axis name (upper case).
pub fn frames(data: &MachineData) -> BTreeMap<String, BTreeMap<String, Components>> {
    named_frames(data, "$P_UIFR", frame_name)
}

/// The base frames the data hold, the NC's (`$P_NCBFR[n]`, named `NCBFRn`)
/// and the first channel's (`$P_CHBFR[n]`, `CHBFRn`), each with its axes'
/// components. Which of them are active is the control's state
/// (`$P_NCBFRMASK`, `$P_CHBFRMASK` and MD20110's reset behaviour).
pub fn base_frames(data: &MachineData) -> BTreeMap<String, BTreeMap<String, Components>> {
    let mut frames = named_frames(data, "$P_NCBFR", |n| Some(format!("NCBFR{n}")));
    frames.extend(named_frames(data, "$P_CHBFR", |n| {
        Some(format!("CHBFR{n}"))
    }));
    frames
}

/// The frames of the system variable `variable`, named by `name` from their
/// index, component by component.
fn named_frames(
    data: &MachineData,
    variable: &str,
    name: impl Fn(u32) -> Option<String>,
) -> BTreeMap<String, BTreeMap<String, Components>> {
    // The first channel's, or the NC's: what a frame's line assigns, a
    // component or the whole frame, in the order of the lines.
    let ours = |channel: Option<u32>| variable != "$P_CHBFR" || channel.is_none_or(|c| c == 1);
    let mut assignments: Vec<Assignment> = data
        .named(variable)
        .filter(|datum| ours(datum.channel))
        .filter_map(|datum| match &datum.indices[..] {
            [Index::Number(index), Index::Axis(axis), Index::Axis(component)] => Some(Assignment {
                at: datum.span.start,
                index: *index,
                components: vec![(axis.clone(), component.as_str(), datum.value.number())],
                whole: false,
            }),
            _ => None,
        })
        .collect();
    assignments.extend(
        data.frames
            .iter()
            .filter(|frame| frame.name == variable && ours(frame.channel))
            .map(|frame| {
                let components = frame
                    .components
                    .iter()
                    .map(|(axis, component, value)| (axis.clone(), *component, Some(*value)))
                    .collect();
                Assignment {
                    at: frame.span.start,
                    index: frame.index,
                    components,
                    whole: true,
                }
            }),
    );
    assignments.sort_by_key(|a| a.at);
    let mut frames: BTreeMap<String, BTreeMap<String, Components>> = BTreeMap::new();
    for assignment in assignments {
        let Some(name) = name(assignment.index) else {
            continue;
        };
        let frame = frames.entry(name).or_default();
        if assignment.whole {
            frame.clear();
        }
        for (axis, component, value) in assignment.components {
            let components = frame.entry(axis).or_default();
            match component {
                "TR" => components.tr = value,
                "FI" => components.fi = value,
                "RT" => components.rt = value,
                "SC" => components.sc = value,
                "MI" => components.mi = value,
                _ => {}
            }
        }
    }
    frames
}

/// A line's assignment to a frame: one component, or the whole frame.
struct Assignment<'a> {
    /// Where the line starts: the order they are taken in.
    at: usize,
    index: u32,
    components: Vec<(String, &'a str, Option<f64>)>,
    whole: bool,
}

impl Components {
    /// Whether the frame moves or turns anything: a translation or rotation
    /// other than 0, a scale other than 1, a mirror.
    pub fn acts(&self) -> bool {
        [self.tr, self.fi, self.rt, self.mi]
            .iter()
            .flatten()
            .any(|v| *v != 0.0)
            || self.sc.is_some_and(|s| s != 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_are_named_by_the_g_function_that_selects_them() {
        let names: Vec<Option<String>> = [0, 1, 4, 5, 99, 100].map(frame_name).to_vec();
        let expected = ["G500", "G54", "G57", "G505", "G599"];
        assert_eq!(names[..5], expected.map(|n| Some(n.to_string())));
        assert_eq!(names[5], None);
        let source = b"$P_UIFR[1,X,TR]=100.5\n$P_UIFR[1,X,FI]=0.01\n$P_UIFR[1,Z,RT]=30\n\
$P_UIFR[6,Y,TR]=-5\n";
        let frames = frames(&MachineData::read(source));
        assert_eq!(frames.keys().collect::<Vec<_>>(), ["G506", "G54"]);
        let x = &frames["G54"]["X"];
        assert_eq!((x.tr, x.fi, x.rt), (Some(100.5), Some(0.01), None));
        assert_eq!(frames["G54"]["Z"].rt, Some(30.0));
        assert_eq!(frames["G506"]["Y"].tr, Some(-5.0));
        let base = base_frames(&MachineData::read(
            b"$P_NCBFR[0,X,TR]=1\nCHANDATA(1)\n$P_CHBFR[0,Z,RT]=2\nCHANDATA(2)\n$P_CHBFR[1,Z,TR]=3\n",
        ));
        assert_eq!(base.keys().collect::<Vec<_>>(), ["CHBFR0", "NCBFR0"]);
        assert!(base["CHBFR0"]["Z"].acts());
    }

    /// As series start-up archives write them: whole, by the frame
    /// functions, replacing what lines before gave; `CTRANS()` the zero frame.
    #[test]
    fn frames_written_whole_are_read_by_their_components() {
        let source =
            b"$P_UIFR[1,X,TR]=100.5\n$P_UIFR[1]=CTRANS(X,1,Y,-2.5):CFINE(X,0.01):CROT(Z,30)\n\
$P_UIFR[2]=CTRANS()\n$P_UIFR[3]=CTRANS(Z,5):CSCALE(X,2):CMIRROR(Y)\n$P_UIFR[3,Z,TR]=6\n\
$P_CHBFR[0]=CTRANS(Z,137.3)\n";
        let data = MachineData::read(source);
        assert!(data.diagnostics.is_empty(), "{:?}", data.diagnostics);
        let frames = frames(&data);
        assert_eq!(frames.keys().collect::<Vec<_>>(), ["G54", "G55", "G56"]);
        let x = &frames["G54"]["X"];
        assert_eq!((x.tr, x.fi), (Some(1.0), Some(0.01)));
        assert_eq!(frames["G54"]["Y"].tr, Some(-2.5));
        assert_eq!(frames["G54"]["Z"].rt, Some(30.0));
        assert!(frames["G55"].is_empty());
        assert_eq!(frames["G56"]["Z"].tr, Some(6.0));
        assert_eq!(frames["G56"]["X"].sc, Some(2.0));
        assert_eq!(frames["G56"]["Y"].mi, Some(1.0));
        assert_eq!(base_frames(&data)["CHBFR0"]["Z"].tr, Some(137.3));
        // Two shifts in one chain, or a turn before a shift, are no longer
        // components: named, not read.
        let chained = MachineData::read(
            b"$P_UIFR[1]=CTRANS(X,1):CTRANS(X,2)\n$P_UIFR[2]=R1\n$P_UIFR[3]=CROT(Z,30):CTRANS(X,1)\n",
        );
        let codes: Vec<&str> = chained.diagnostics.iter().map(|d| d.code()).collect();
        assert_eq!(codes, ["K006", "K006", "K006"]);
    }
}
