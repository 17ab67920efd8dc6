//! What the control's G and M functions do, in a line each, for an editor's
//! hover: the functions of the Programming Manual Fundamentals' "List of G
//! functions" that programs use most, and the M functions the control
//! itself predefines (Function Manual Basic Functions, "Auxiliary function
//! outputs": M0, M1, M2, M3 to M5, M6, M17, M19, M30, M40 to M45, M70).
//! Others (M7 to M9, a machine builder's M functions) mean what the machine
//! builder made them mean, and are not described.

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
