//! The control's cycles a program calls, with their parameters in call
//! order: what each means and the values it takes, for the editor's
//! signature help, completion and hover.
//!
//! Only cycles whose parameter list a manual (or, where so marked, the CAM
//! post-processors that write them) confirms: the swivel cycle CYCLE800
//! (`../shared/reference/sinumerik.md` §1), the transformation cycle
//! CYCLE600 (`../shared/spec/cycle600.md`), the high-speed settings
//! CYCLE832 and the drilling cycles CYCLE81 to CYCLE89. The measuring
//! cycles CYCLE977, CYCLE978 and CYCLE998 are left out: several of their
//! positions have no confirmed name (`sinumerik.md` §4), and a parameter
//! list with gaps would put wrong names on the arguments after them.

/// One parameter of a cycle.
#[derive(Clone, Copy, Debug)]
pub struct Parameter {
    /// Its name in the cycle's definition (`_FR`, `RTP`).
    pub name: &'static str,
    /// What it means and the values it takes.
    pub meaning: &'static str,
}

/// One cycle.
#[derive(Clone, Copy, Debug)]
pub struct Cycle {
    pub name: &'static str,
    /// What it does, in a sentence.
    pub what: &'static str,
    pub parameters: &'static [Parameter],
    /// The manual it rests on.
    pub manual: &'static str,
}

const fn parameter(name: &'static str, meaning: &'static str) -> Parameter {
    Parameter { name, meaning }
}

/// The SINUMERIK 840D/840Di/810D Programming Manual Cycles (editions
/// 11.02 and 11/2006), whose parameter lists the CAM post-processors for
/// the 840D write in the same order.
const CYCLES_MANUAL: &str = "Programming Manual Cycles, drilling cycles";

/// The five parameters every drilling cycle begins with.
const RTP: Parameter = parameter("RTP", "retraction plane, absolute");
const RFP: Parameter = parameter("RFP", "reference plane, absolute");
const SDIS: Parameter = parameter(
    "SDIS",
    "safety clearance above the reference plane, without sign",
);
const DP: Parameter = parameter("DP", "final drilling depth, absolute");
const DPR: Parameter = parameter(
    "DPR",
    "final drilling depth relative to the reference plane, without sign (used when DP is not given)",
);
const DTB: Parameter = parameter("DTB", "dwell time at the final depth, in seconds");
const SDIR: Parameter = parameter("SDIR", "direction of spindle rotation: 3 for M3, 4 for M4");

/// The three parameters SINUMERIK Operate appends to several drilling
/// cycles, in the order the CAM post-processors for the 840D write them;
/// what their digits mean no manual at hand confirms.
const GMODE: Parameter = parameter(
    "_GMODE",
    "SINUMERIK Operate only: geometrical mode (its values not confirmed here)",
);
const DMODE: Parameter = parameter(
    "_DMODE",
    "SINUMERIK Operate only: display mode, 0 keeps the plane programmed (other values not confirmed here)",
);
const AMODE: Parameter = parameter(
    "_AMODE",
    "SINUMERIK Operate only: alternative mode, the units of the dwell and the depth (its digits not confirmed here)",
);

/// Every cycle described.
pub const CYCLES: &[Cycle] = &[
    Cycle {
        name: "CYCLE800",
        what: "Swivels the working plane (or aligns the tool) on a swivel data record.",
        parameters: &[
            parameter("_FR", "retraction before swivelling: 0 none, 1 in Z, 2 in Z then XY, 4 maximum in the tool direction, 5 incremental in the tool direction (by _FR_I)"),
            parameter("_TC", "the swivel data record's name (\"\" the channel's only one; \"0\" deselects)"),
            parameter("_ST", "swivel plane, ones digit: 0 new, 1 additive to the plane in force (higher digits not confirmed)"),
            parameter("_MODE", "swivel mode, bits 7-6: 0 axis by axis, 1 solid angle, 2 projection angle, 3 rotary axes direct; axis by axis, bits 1-0, 3-2, 5-4 the axes of _A, _B, _C (01 X, 10 Y, 11 Z)"),
            parameter("_X0", "centre of rotation, X, in the plane before the swivel"),
            parameter("_Y0", "centre of rotation, Y, in the plane before the swivel"),
            parameter("_Z0", "centre of rotation, Z, in the plane before the swivel"),
            parameter("_A", "first angle, read as _MODE says (axis by axis: the first turn; rotary axes direct: rotary axis 1), degrees"),
            parameter("_B", "second angle, read as _MODE says (axis by axis: the second turn, about the turned axis; rotary axes direct: rotary axis 2), degrees"),
            parameter("_C", "third angle, read as _MODE says (axis by axis: the third turn), degrees"),
            parameter("_X1", "zero point of the swivelled plane, X, after the turn"),
            parameter("_Y1", "zero point of the swivelled plane, Y, after the turn"),
            parameter("_Z1", "zero point of the swivelled plane, Z, after the turn"),
            parameter("_DIR", "which of the two solutions: -1 the lower, +1 the higher value of the reference rotary axis (0, no rotary axis motion, not confirmed)"),
            parameter("_FR_I", "retraction path in the tool direction for _FR 5 (mm)"),
            parameter("_DMODE", "how the screen form shows the plane, for the operator (its digits not confirmed)"),
        ],
        manual: "SINUMERIK Operate Milling, CYCLE800",
    },
    Cycle {
        name: "CYCLE600",
        what: "Converts rotation angles between intrinsic and extrinsic sequences and axis orders, stores the results in global user data and can swivel the head.",
        parameters: &[
            parameter("_INEXIN", "input rotation kind: 1 intrinsic, 0 extrinsic"),
            parameter("_MIHEAD", "accessory (milling head or rotary table) name, defined in HEAD_DEF"),
            parameter("_SW_REC", "1: recalculation only (results to the GUD, nothing moves); 0: rotate with the accessory"),
            parameter("_BIN_IN", "input axis sequence code, as CYCLE800's _MODE (57 X,Y,Z; 39 Z,X,Y; 27 Z,Y,X; ...)"),
            parameter("_POS_X", "translation of the reference point before the rotation, X"),
            parameter("_POS_Y", "translation of the reference point before the rotation, Y"),
            parameter("_POS_Z", "translation of the reference point before the rotation, Z"),
            parameter("_ANG_1", "angle of the first rotation of the input sequence, degrees"),
            parameter("_ANG_2", "angle of the second rotation of the input sequence, degrees"),
            parameter("_ANG_3", "angle of the third rotation of the input sequence, degrees"),
            parameter("_POS_X_R", "translation after the rotation, in the rotated system, X"),
            parameter("_POS_Y_R", "translation after the rotation, in the rotated system, Y"),
            parameter("_POS_Z_R", "translation after the rotation, in the rotated system, Z"),
            parameter("_INEXOUT", "output rotation kind: 1 intrinsic, 0 extrinsic (the published 19-value form has a reserved value before it)"),
            parameter("_BIN_OUT", "output axis sequence code"),
            parameter("_ROT_AD", "0: new rotation; 1: additive to the rotation in force"),
            parameter("_ROT_INV", "two-axis heads reach each orientation twice: 0 the computed position, 1 the inverse one"),
            parameter("_RETR_Z", "1: retract the tool before rotating; 0: no retraction"),
        ],
        manual: "Lehner, Valdman, Zidkova, \"Methodology of rotation of general surfaces\", MM Science Journal 2024",
    },
    Cycle {
        name: "CYCLE832",
        what: "High-speed settings: sets the contour tolerance, the machining type (the dynamic response of G group 59) and the orientation tolerance; CYCLE832() deselects them.",
        parameters: &[
            parameter("S_TOL", "contour tolerance, the axis tolerance of the geometry axes"),
            parameter("S_TOLM", "machining type, units digit: 0 deselection, 1 finishing, 2 rough finishing, 3 roughing, 4 smooth finishing; tens digit 1: the orientation tolerance is S_OTOL"),
            parameter("S_OTOL", "orientation tolerance, for machines with an orientation transformation (1 on a 3-axis program without tool orientation)"),
        ],
        manual: "SINUMERIK ONE Programming Manual NC Programming, \"Programming cycles externally\" (12/2019)",
    },
    Cycle {
        name: "CYCLE81",
        what: "Drilling, centring: drills at the feed to the final depth and retracts in rapid traverse.",
        parameters: &[RTP, RFP, SDIS, DP, DPR, GMODE, DMODE, AMODE],
        manual: CYCLES_MANUAL,
    },
    Cycle {
        name: "CYCLE82",
        what: "Drilling, counterboring: as CYCLE81 with a dwell at the final depth.",
        parameters: &[RTP, RFP, SDIS, DP, DPR, DTB, GMODE, DMODE, AMODE],
        manual: CYCLES_MANUAL,
    },
    Cycle {
        name: "CYCLE83",
        what: "Deep-hole drilling: drills in infeeds, retracting after each to remove swarf or to break the chip.",
        parameters: &[
            RTP,
            RFP,
            SDIS,
            DP,
            DPR,
            parameter("FDEP", "first drilling depth, absolute"),
            parameter("FDPR", "first drilling depth relative to the reference plane, without sign"),
            parameter("DAM", "amount by which each infeed is smaller than the one before (degression), without sign"),
            parameter("DTB", "dwell time at the drilling depth (chip breaking), in seconds"),
            parameter("DTS", "dwell time at the starting point and for swarf removal, in seconds"),
            parameter("FRF", "feed factor for the first drilling depth, without sign"),
            parameter("VARI", "machining type: 0 chip breaking, 1 swarf removal (retraction to the reference plane)"),
            parameter("_AXN", "tool axis: 1 the first, 2 the second, 3 the third geometry axis"),
            parameter("_MDEP", "minimum drilling depth"),
            parameter("_VRT", "retraction for chip breaking"),
            parameter("_DTD", "dwell time at the final depth, in seconds"),
            parameter("_DIS1", "limit distance before re-entering the hole"),
            GMODE,
            DMODE,
            AMODE,
        ],
        manual: CYCLES_MANUAL,
    },
    Cycle {
        name: "CYCLE84",
        what: "Tapping without compensating chuck (rigid tapping), the spindle in position control.",
        parameters: &[
            RTP,
            RFP,
            SDIS,
            DP,
            DPR,
            DTB,
            parameter("SDAC", "direction of rotation after the cycle: 3, 4 or 5 (for M3, M4, M5)"),
            parameter("MPIT", "thread lead as a metric thread size (3 for M3 to 48 for M48), the sign the direction of rotation"),
            parameter("PIT", "thread lead as a value, the sign the direction of rotation"),
            parameter("POSS", "spindle position for the oriented stop before tapping, in degrees"),
            parameter("SST", "spindle speed for tapping"),
            parameter("SST1", "spindle speed for retraction"),
            parameter("_AXN", "tool axis: 1 the first, 2 the second, 3 the third geometry axis"),
            parameter("_PTAB", "how the lead MPIT or PIT is read (0 as in the program's units)"),
            parameter("_TECHNO", "technology settings: exact stop, feedforward control, acceleration (digit-coded)"),
            parameter("_VARI", "machining type: 0 tapping in one cut, 1 deep-hole tapping with chip breaking, 2 deep-hole tapping with swarf removal"),
            parameter("_DAM", "incremental drilling depth for deep-hole tapping"),
            parameter("_VRT", "retraction for chip breaking in deep-hole tapping"),
        ],
        manual: CYCLES_MANUAL,
    },
    Cycle {
        name: "CYCLE85",
        what: "Boring 1 (reaming): drills and retracts at the feeds given.",
        parameters: &[
            RTP,
            RFP,
            SDIS,
            DP,
            DPR,
            DTB,
            parameter("FFR", "feed for drilling"),
            parameter("RFF", "feed for retraction"),
            GMODE,
            DMODE,
            AMODE,
        ],
        manual: CYCLES_MANUAL,
    },
    Cycle {
        name: "CYCLE86",
        what: "Boring 2: bores to the depth, stops the spindle oriented, lifts the cutting edge off the wall and retracts in rapid traverse.",
        parameters: &[
            RTP,
            RFP,
            SDIS,
            DP,
            DPR,
            DTB,
            SDIR,
            parameter("RPA", "retraction path along the abscissa of the plane, incremental with sign"),
            parameter("RPO", "retraction path along the ordinate of the plane, incremental with sign"),
            parameter("RPAP", "retraction path along the applicate, incremental with sign"),
            parameter("POSS", "spindle position for the oriented stop, in degrees"),
            GMODE,
            DMODE,
            AMODE,
        ],
        manual: CYCLES_MANUAL,
    },
    Cycle {
        name: "CYCLE87",
        what: "Boring 3: bores to the depth, stops the spindle and the program (M0); the operator's NC start retracts.",
        parameters: &[RTP, RFP, SDIS, DP, DPR, SDIR],
        manual: CYCLES_MANUAL,
    },
    Cycle {
        name: "CYCLE88",
        what: "Boring 4: as CYCLE87 with a dwell at the final depth.",
        parameters: &[RTP, RFP, SDIS, DP, DPR, DTB, SDIR],
        manual: CYCLES_MANUAL,
    },
    Cycle {
        name: "CYCLE89",
        what: "Boring 5: bores at the feed to the depth, dwells, and retracts at the same feed.",
        parameters: &[RTP, RFP, SDIS, DP, DPR, DTB],
        manual: CYCLES_MANUAL,
    },
];

/// The cycle `name` (any case) names, if it is described.
pub fn cycle(name: &[u8]) -> Option<&'static Cycle> {
    CYCLES
        .iter()
        .find(|cycle| cycle.name.as_bytes().eq_ignore_ascii_case(name))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::semantic::{cycle600, cycle800};

    fn names(name: &str) -> Vec<&'static str> {
        let cycle = cycle(name.as_bytes()).expect("described");
        cycle.parameters.iter().map(|p| p.name).collect()
    }

    #[test]
    fn cycle800_and_cycle600_take_the_parameters_their_models_read() {
        assert_eq!(names("CYCLE800"), cycle800::PARAMETERS);
        assert_eq!(names("cycle600"), cycle600::NAMES);
    }

    #[test]
    fn each_cycle_once_and_each_parameter_once_in_it() {
        let mut cycles: Vec<&str> = CYCLES.iter().map(|c| c.name).collect();
        cycles.sort_unstable();
        cycles.dedup();
        assert_eq!(cycles.len(), CYCLES.len(), "a cycle described twice");
        for cycle in CYCLES {
            let mut names: Vec<&str> = cycle.parameters.iter().map(|p| p.name).collect();
            names.sort_unstable();
            names.dedup();
            assert_eq!(names.len(), cycle.parameters.len(), "{}", cycle.name);
            assert!(cycle.what.ends_with('.'), "{}", cycle.name);
            assert!(
                cycle.parameters.iter().all(|p| !p.meaning.is_empty()),
                "{}",
                cycle.name
            );
        }
    }

    #[test]
    fn the_drilling_cycles_begin_alike() {
        for number in 81..=89 {
            let name = format!("CYCLE{number}");
            assert_eq!(
                names(&name)[..5],
                ["RTP", "RFP", "SDIS", "DP", "DPR"],
                "{name}"
            );
        }
        assert_eq!(names("CYCLE83").len(), 20);
        assert_eq!(names("CYCLE84").len(), 18);
        assert!(cycle(b"CYCLE998").is_none());
    }
}
