//! What the control's G and M functions do, in a line each, for an editor's
//! hover: the functions of the Programming Manual Fundamentals' "List of G
//! functions" that programs use most, and the M functions the control
//! itself predefines (Function Manual Basic Functions, "Auxiliary function
//! outputs": M0, M1, M2, M3 to M5, M6, M17, M19, M30, M40 to M45, M70).
//! Others (M7 to M9, a machine builder's M functions) mean what the machine
//! builder made them mean, and are not described. And the system variables
//! a program that swivels and probes reads: the swivel data record's
//! `$TC_CARR1..65` (`../shared/reference/kinematics.md` §1.1, each field
//! confirmed there), frames, positions and measured values.

use crate::semantic::modal::g_group;

/// What `G<number>` does, and its group; `None` for one not described.
pub fn g_function(number: u32) -> Option<(String, Option<u8>)> {
    let what = match number {
        0 => "rapid traverse",
        1 => "linear interpolation at the feed rate",
        2 => "circular interpolation, clockwise",
        3 => "circular interpolation, counter-clockwise",
        4 => "dwell time (F seconds or S spindle revolutions), for this block",
        9 => "exact stop, for this block",
        17 => "working plane X/Y, infeed along Z",
        18 => "working plane Z/X, infeed along Y",
        19 => "working plane Y/Z, infeed along X",
        25 => "lower working-area (or spindle speed) limit",
        26 => "upper working-area (or spindle speed) limit",
        33 => "thread cutting with constant lead",
        40 => "tool radius compensation off",
        41 => "tool radius compensation, tool left of the contour",
        42 => "tool radius compensation, tool right of the contour",
        53 => "the settable work offset and the programmable frame suppressed, for this block",
        54..=57 => {
            return Some((
                format!("settable work offset {}", number - 53),
                g_group(number),
            ))
        }
        500 => "settable work offsets off (the base frame only)",
        505..=599 => {
            return Some((
                format!("settable work offset {}", number - 500),
                g_group(number),
            ))
        }
        60 => "exact stop, modal",
        63 => "tapping with a compensating chuck",
        64 => "continuous-path mode",
        70 => "inch dimensions for geometry",
        71 => "metric dimensions for geometry",
        74 => "reference point approach",
        75 => "fixed point approach",
        90 => "absolute dimensions",
        91 => "incremental dimensions",
        93 => "inverse-time feed rate (1/min)",
        94 => "feed rate F per minute (mm/min, inch/min)",
        95 => "feed rate F per spindle revolution (mm/rev, inch/rev)",
        96 => "constant cutting speed on",
        97 => "constant cutting speed off",
        110 => "pole relative to the last programmed position",
        111 => "pole relative to the workpiece zero",
        112 => "pole relative to the last pole",
        153 => "every frame suppressed, the base frame included, for this block",
        331 => "rigid tapping",
        332 => "rigid tapping, retraction",
        450 => "transition circle at outside corners (radius compensation)",
        451 => "intersection of the equidistants at outside corners (radius compensation)",
        601 => "block change at exact stop fine",
        602 => "block change at exact stop coarse",
        603 => "block change at the end of interpolation",
        641 => "continuous-path mode with smoothing by distance (ADIS)",
        700 => "inch dimensions for geometry and feed rates",
        710 => "metric dimensions for geometry and feed rates",
        _ => return None,
    };
    Some((what.to_string(), g_group(number)))
}

/// What `M<number>` does where the control itself defines it.
pub fn m_function(number: u32) -> Option<&'static str> {
    Some(match number {
        0 => "programmed stop",
        1 => "optional stop (when the operator has selected it)",
        2 => "end of the main program",
        3 => "spindle clockwise",
        4 => "spindle counter-clockwise",
        5 => "spindle stop",
        6 => "tool change",
        17 => "end of the subprogram",
        19 => "spindle positioning",
        30 => "end of the program, as M2",
        40 => "automatic gear stage change",
        41..=45 => match number {
            41 => "gear stage 1",
            42 => "gear stage 2",
            43 => "gear stage 3",
            44 => "gear stage 4",
            _ => "gear stage 5",
        },
        70 => "spindle switched to axis mode",
        _ => return None,
    })
}

/// The field `$TC_CARR<field>` of a swivel data record.
fn swivel_data(field: u32) -> Option<String> {
    let xyz = |first: u32| ["x", "y", "z"][(field - first) as usize];
    Some(match field {
        1..=3 => format!("offset vector l1, {}", xyz(1)),
        4..=6 => format!("offset vector l2, {}", xyz(4)),
        7..=9 => format!("direction of rotary axis 1 (v1), {}", xyz(7)),
        10..=12 => format!("direction of rotary axis 2 (v2), {}", xyz(10)),
        13 | 14 => format!(
            "angle of rotary axis {} where no channel axis is named ($TC_CARR{})",
            field - 12,
            field + 8
        ),
        15..=17 => format!("offset vector l3, {}", xyz(15)),
        18..=20 => format!("offset vector l4, {}", xyz(18)),
        21 | 22 => format!(
            "channel axis of rotary axis {} (its position at block start is the angle)",
            field - 20
        ),
        23 => "kinematic type: T (head), P (table), M (mixed)".to_string(),
        24 | 25 => format!(
            "offset of rotary axis {} (degrees): its angle in the initial state",
            field - 23
        ),
        26 | 27 => format!("Hirth grid offset of rotary axis {} (degrees)", field - 25),
        28 | 29 => format!(
            "Hirth grid step of rotary axis {} (degrees; above 0, the axis is toothed)",
            field - 27
        ),
        30 | 31 => format!("lower limit of rotary axis {} (degrees)", field - 29),
        32 | 33 => format!("upper limit of rotary axis {} (degrees)", field - 31),
        34 => "the record's name, CYCLE800's `_TC`".to_string(),
        35 | 36 => format!("name of rotary axis {}", field - 34),
        37 => "CYCLE800 options, in decimal digits".to_string(),
        38..=40 => format!("CYCLE800 retraction position, {}", xyz(38)),
        41..=43 => format!("fine offset of l1, {}", xyz(41)),
        44..=46 => format!("fine offset of l2, {}", xyz(44)),
        55..=57 => format!("fine offset of l3, {}", xyz(55)),
        58..=60 => format!("fine offset of l4, {}", xyz(58)),
        64 | 65 => format!("fine offset of rotary axis {}'s offset", field - 63),
        _ => return None,
    })
}

/// What a system variable (`$TC_CARR7`, `$P_UIFR`, `$MC_...`) holds; `None`
/// for one not described.
pub fn system_variable(name: &[u8]) -> Option<String> {
    let name = String::from_utf8_lossy(name).to_ascii_uppercase();
    if let Some(field) = name.strip_prefix("$TC_CARR") {
        let what = swivel_data(field.parse().ok()?)?;
        return Some(format!("{name}[m]: swivel data record m, {what}"));
    }
    let what = match name.as_str() {
        "$P_UIFR" => "the settable frames (G54 to G57, G505 to G599), by number",
        "$P_PFRAME" => "the programmable frame (TRANS, ROT, ... in the program)",
        "$P_ACTFRAME" => "the whole frame in force",
        "$P_TOOLNO" => "the number of the active tool",
        "$P_TOOL" => "the active tool edge (D number)",
        "$AA_IM" => "an axis's current position (setpoint), machine coordinates",
        "$AA_IW" => "an axis's current position (setpoint), workpiece coordinates",
        "$AA_MM" => "an axis's measured position, machine coordinates",
        "$AA_MW" => "an axis's measured position, workpiece coordinates",
        "$AC_MEA" => "the probe has switched (1) or not (0)",
        _ => {
            let kind = match name.get(..4) {
                Some("$MN_") => "NC machine data",
                Some("$MC_") => "channel machine data",
                Some("$MA_") => "axis machine data",
                Some("$SN_") => "NC setting data",
                Some("$SC_") => "channel setting data",
                Some("$SA_") => "axis setting data",
                _ => return None,
            };
            return Some(format!("{name}: {kind}"));
        }
    };
    Some(format!("{name}: {what}"))
}

/// A G or M word (`G01`, `m30`) described: `None` for another word or one
/// not described.
pub fn describe(word: &[u8]) -> Option<String> {
    let (letter, digits) = word.split_first()?;
    if digits.is_empty() || !digits.iter().all(u8::is_ascii_digit) || digits.len() > 4 {
        return None;
    }
    let number: u32 = std::str::from_utf8(digits).ok()?.parse().ok()?;
    match letter | 0x20 {
        b'g' => {
            let (what, group) = g_function(number)?;
            Some(match group {
                Some(group) => format!("G{number}: {what} (G group {group})"),
                None => format!("G{number}: {what}"),
            })
        }
        b'm' => Some(format!("M{number}: {}", m_function(number)?)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn g_and_m_words_are_described_in_any_spelling() {
        assert_eq!(
            describe(b"G01").as_deref(),
            Some("G1: linear interpolation at the feed rate (G group 1)")
        );
        assert_eq!(
            describe(b"g54").as_deref(),
            Some("G54: settable work offset 1 (G group 8)")
        );
        assert_eq!(
            describe(b"G505").as_deref(),
            Some("G505: settable work offset 5 (G group 8)")
        );
        assert_eq!(
            describe(b"M30").as_deref(),
            Some("M30: end of the program, as M2")
        );
        // A machine builder's M function, a number the list does not hold,
        // an address that is no function: not described.
        assert_eq!(describe(b"M8"), None);
        assert_eq!(describe(b"G1234"), None);
        assert_eq!(describe(b"X10"), None);
        assert_eq!(describe(b"G"), None);
    }

    #[test]
    fn system_variables_are_described() {
        assert_eq!(
            system_variable(b"$tc_carr8").as_deref(),
            Some("$TC_CARR8[m]: swivel data record m, direction of rotary axis 1 (v1), y")
        );
        assert_eq!(
            system_variable(b"$TC_CARR33").as_deref(),
            Some("$TC_CARR33[m]: swivel data record m, upper limit of rotary axis 2 (degrees)")
        );
        assert_eq!(
            system_variable(b"$MC_AXCONF_GEOAX_NAME_TAB").as_deref(),
            Some("$MC_AXCONF_GEOAX_NAME_TAB: channel machine data")
        );
        // Fields the control does not define, names not described.
        assert_eq!(system_variable(b"$TC_CARR50"), None);
        assert_eq!(system_variable(b"$TC_CARR99"), None);
        assert_eq!(system_variable(b"$P_SOMETHING"), None);
    }

    /// Every G function described belongs to the group the modal state
    /// reads it in, where that knows it.
    #[test]
    fn every_described_g_function_has_its_group() {
        for number in 0..1000 {
            if let Some((_, group)) = g_function(number) {
                assert_eq!(group, g_group(number), "G{number}");
                assert!(group.is_some(), "G{number} has no group");
            }
        }
    }
}
