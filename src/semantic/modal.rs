//! The modal state a block leaves behind: the motion, plane, radius
//! compensation and dimensions (G90/G91) in force, whether a feed rate was
//! programmed and what the programmable frame holds, with the groups of the G
//! and M functions the control knows (Siemens, Programming Manual
//! Fundamentals, "List of G functions"; Function Manual Basic Functions,
//! "Auxiliary function outputs": the predefined groups).
//!
//! Read line by line from the [`Address`]es of each block, tree or plain, so
//! that a CAM program's plain lines need no tree; the frame statements, which
//! no plain line holds, from the tree.

use crate::semantic::addresses::Address;
use crate::span::Span;
use crate::syntax::tree::{Block, FrameKind, StatementKind};

/// The group of a G function written as a number (`G1`, `G641`), as the
/// Programming Manual numbers them; `None` for numbers it does not list.
pub fn g_group(number: u32) -> Option<u8> {
    Some(match number {
        0..=3 | 33..=35 | 331 | 332 => 1,
        4 | 5 | 7 | 63 | 74 | 75 | 147 | 148 | 247 | 248 | 347 | 348 => 2,
        25 | 26 | 58 | 59 | 110..=112 => 3,
        17..=19 => 6,
        40..=42 => 7,
        54..=57 | 500 | 505..=599 => 8,
        53 | 153 => 9,
        60 | 64 | 641..=645 => 10,
        9 => 11,
        601..=603 => 12,
        70 | 71 | 700 | 710 => 13,
        90 | 91 => 14,
        93..=97 | 931 | 942 | 952 | 961 | 962 | 971..=973 => 15,
        450 | 451 => 18,
        810..=819 => 31,
        820..=829 => 32,
        140..=143 => 43,
        340 | 341 => 44,
        290 | 291 => 47,
        460..=462 => 48,
        62 | 621 => 57,
        _ => return None,
    })
}

/// The G functions written as keywords, by group, as the Programming
/// Manual Fundamentals lists them ("List of G functions"; groups 19 to 25
/// as the 840D sl/840Di manual of 11/2006 gives them): a group's keywords
/// exclude each other and its numbered functions.
const KEYWORD_GROUPS: &[(u8, &[&str])] = &[
    (
        1,
        &[
            "CIP", "ASPLINE", "BSPLINE", "CSPLINE", "POLY", "CT", "INVCW", "INVCCW",
        ],
    ),
    (19, &["BNAT", "BTAN", "BAUTO"]),
    (20, &["ENAT", "ETAN", "EAUTO"]),
    (21, &["BRISK", "SOFT", "DRIVE"]),
    (
        22,
        &[
            "CUT2D", "CUT2DF", "CUT3DC", "CUT3DF", "CUT3DFS", "CUT3DFF", "CUT3DCC", "CUT3DCCD",
        ],
    ),
    (23, &["CDOF", "CDON", "CDOF2"]),
    (24, &["FFWOF", "FFWON"]),
    (25, &["ORIWKS", "ORIMKS"]),
];

/// Numbers the keywords take in [`keyword_g_group`]: above every G number.
const KEYWORD_NUMBERS: u32 = 10_000;

/// The group of a G function written as a keyword (any case: `CIP`,
/// `soft`), with a number that tells it from the group's other functions
/// (and from every G number); `None` for other names.
pub fn keyword_g_group(name: &[u8]) -> Option<(u8, u32)> {
    // Every keyword has two to eight letters: most names are not looked up.
    if !(2..=8).contains(&name.len()) {
        return None;
    }
    KEYWORD_GROUPS.iter().find_map(|&(group, names)| {
        let at = names
            .iter()
            .position(|n| n.as_bytes().eq_ignore_ascii_case(name))?;
        Some((group, KEYWORD_NUMBERS + at as u32))
    })
}

/// The groups whose G function shapes the block's syntax (motions, dwell and
/// the non-modal special motions, programmable frames): one of them rules how
/// the block's other addresses are read.
pub fn is_syntax_defining(group: u8) -> bool {
    (1..=3).contains(&group)
}

/// The predefined group of an M function: 1 for the program's stops and ends
/// (M0, M1, M2, M17, M30), 2 for a spindle's functions (M3, M4, M5, M19, M70).
/// Machine data can assign other functions to groups; those are unknown here.
pub fn m_group(number: u32) -> Option<u8> {
    match number {
        0 | 1 | 2 | 17 | 30 => Some(1),
        3 | 4 | 5 | 19 | 70 => Some(2),
        _ => None,
    }
}

/// G functions of group 1 that move at the programmed feed rate.
pub fn is_feed_motion(number: u32) -> bool {
    matches!(number, 1..=3)
}

/// The addresses that name an axis by its default name (Programming Manual
/// Fundamentals: geometry axes X, Y, Z; rotary axes A, B, C; further linear
/// axes U, V, W).
pub fn is_axis_letter(letter: u8) -> bool {
    matches!(
        letter,
        b'X' | b'Y' | b'Z' | b'A' | b'B' | b'C' | b'U' | b'V' | b'W'
    )
}

/// What the blocks so far have left in force.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Modal {
    /// The group 1 G function last programmed (`G1` is 1), `None` before the
    /// first: the machine's reset value then holds, which the program cannot
    /// see.
    pub motion: Option<u32>,
    /// A path feed rate (F) was programmed.
    pub feed: bool,
    /// The tool radius compensation in force (group 7): the `G41` or `G42`
    /// word that selected it, `None` under `G40` (the reset value as
    /// delivered) or before any.
    pub radius_compensation: Option<Span>,
    /// The working plane programmed (group 6: 17, 18 or 19), `None` before
    /// any: the reset value is machine data (G17 on a mill, G18 on a lathe).
    pub plane: Option<u32>,
    /// Incremental dimensions (group 14): the `G91` word that selected them,
    /// `None` under `G90` (the reset value as delivered) or before any.
    pub incremental: Option<Span>,
    /// The programmable frame holds something of the program's own: the
    /// frame statement that last set it (`ATRANS X10`); `None` while it is
    /// empty (`TRANS` without values clears it) or holds what the blocks do
    /// not show (an assignment to `$P_PFRAME` is not followed).
    pub programmable_frame: Option<Span>,
}

impl Modal {
    /// The state after a block with these addresses.
    pub fn apply(&mut self, source: &[u8], addresses: &[Address]) {
        for address in addresses {
            if address.is(source, "G") {
                match address.whole(source) {
                    Some(number) if g_group(number) == Some(1) => self.motion = Some(number),
                    Some(40) => self.radius_compensation = None,
                    Some(41 | 42) => self.radius_compensation = Some(address.span),
                    Some(number @ 17..=19) => self.plane = Some(number),
                    Some(90) => self.incremental = None,
                    Some(91) => self.incremental = Some(address.span),
                    _ => {}
                }
            } else if address.is(source, "F") && address.extension.is_none() {
                self.feed = true;
            }
        }
    }

    /// The state after a block of the tree: its addresses, and what its
    /// statements do to the programmable frame.
    pub fn apply_block(&mut self, source: &[u8], block: &Block, addresses: &[Address]) {
        self.apply(source, addresses);
        match programmable_frame(source, block) {
            Some(FrameChange::Set(span)) => self.programmable_frame = Some(span),
            Some(FrameChange::Clear) => self.programmable_frame = None,
            None => {}
        }
    }

    /// The state after a block the operator may skip (`/N10 G91`), given
    /// `ran`, the state had it run: what it would change is no longer known,
    /// since it may or may not run.
    pub fn may_have_run(&mut self, ran: Modal) {
        fn agree<T: PartialEq>(kept: &mut Option<T>, ran: Option<T>) {
            if *kept != ran {
                *kept = None;
            }
        }
        agree(&mut self.motion, ran.motion);
        agree(&mut self.radius_compensation, ran.radius_compensation);
        agree(&mut self.plane, ran.plane);
        agree(&mut self.incremental, ran.incremental);
        agree(&mut self.programmable_frame, ran.programmable_frame);
        self.feed &= ran.feed;
    }
}

/// What a block's statements do to the programmable frame.
enum FrameChange {
    /// A frame statement with values (`TRANS X10`, `AROT Z=30`): the span of
    /// the statement and its values.
    Set(Span),
    /// `TRANS`, `ROT`, `SCALE` or `MIRROR` without values, or an assignment
    /// to `$P_PFRAME` whose value is not followed: nothing the blocks show
    /// is left in the programmable frame.
    Clear,
}

/// The last change a block makes to the programmable frame (Programming
/// Manual Fundamentals, "Frame instructions": an absolute instruction
/// without values, such as `TRANS`, deletes the programmable frame).
fn programmable_frame(source: &[u8], block: &Block) -> Option<FrameChange> {
    let statements = &block.statements;
    let mut change = None;
    for (index, statement) in statements.iter().enumerate() {
        match &statement.kind {
            StatementKind::Frame(frame) => {
                // The values are the statements after the keyword, up to the next frame statement.
                let values = statements[index + 1..]
                    .iter()
                    .take_while(|s| !matches!(s.kind, StatementKind::Frame(_)))
                    .last();
                change = Some(match values {
                    Some(last) => FrameChange::Set(Span::new(statement.span.start, last.span.end)),
                    None if matches!(
                        frame.kind,
                        FrameKind::Trans | FrameKind::Rot | FrameKind::Scale | FrameKind::Mirror
                    ) =>
                    {
                        FrameChange::Clear
                    }
                    // `ATRANS` alone adds nothing.
                    None => continue,
                });
            }
            StatementKind::Assign(assign)
                if assign
                    .target
                    .name
                    .text(source)
                    .eq_ignore_ascii_case(b"$P_PFRAME") =>
            {
                change = Some(FrameChange::Clear);
            }
            _ => {}
        }
    }
    change
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::semantic::addresses::of_block;
    use crate::syntax::Lines;

    #[test]
    fn groups_as_the_manual_lists_them() {
        assert_eq!(g_group(0), g_group(1));
        assert_eq!(g_group(2), Some(1));
        assert_eq!(g_group(331), Some(1));
        assert_eq!(g_group(4), Some(2));
        assert_eq!(g_group(17), Some(6));
        assert_eq!(g_group(54), g_group(599));
        assert_eq!(g_group(641), g_group(64));
        assert_eq!(g_group(90), Some(14));
        assert_eq!(g_group(95), g_group(961));
        // One G function of every group the list holds.
        for (g, group) in [
            (3, 1),
            (332, 1),
            (4, 2),
            (348, 2),
            (26, 3),
            (112, 3),
            (19, 6),
            (42, 7),
            (57, 8),
            (500, 8),
            (599, 8),
            (153, 9),
            (64, 10),
            (645, 10),
            (9, 11),
            (602, 12),
            (71, 13),
            (710, 13),
            (91, 14),
            (94, 15),
            (973, 15),
            (451, 18),
            (815, 31),
            (825, 32),
            (142, 43),
            (341, 44),
            (291, 47),
            (461, 48),
            (621, 57),
        ] {
            assert_eq!(g_group(g), Some(group), "G{g}");
        }
        assert_eq!(g_group(8), None);
        assert_eq!(g_group(504), None);
        assert!(is_syntax_defining(3) && !is_syntax_defining(6));
        assert_eq!(m_group(30), m_group(0));
        assert_eq!(m_group(3), m_group(70));
        assert_eq!(m_group(6), None);
    }

    #[test]
    fn motion_and_feed_carry_over_blocks() {
        let source = b"G90 G0 X0\nG1 Z5\nX10 F=R1\nG641 Y5\nF2=100\n";
        let lines = Lines::new(source);
        let states: Vec<Modal> = (0..lines.len())
            .scan(Modal::default(), |modal, row| {
                let block = lines.block(row).expect("a block");
                modal.apply(source, &of_block(source, &block));
                Some(*modal)
            })
            .collect();
        assert!(states.iter().all(|m| m.radius_compensation.is_none()));
        let motions: Vec<_> = states.iter().map(|m| (m.motion, m.feed)).collect();
        assert_eq!(
            motions,
            [
                (Some(0), false),
                (Some(1), false),
                (Some(1), true),
                (Some(1), true),
                (Some(1), true)
            ]
        );
    }

    #[test]
    fn radius_compensation_is_the_word_that_selected_it_until_g40() {
        let source = b"G1 G41 X0 D1\nX10\nG42 Y5\nG40 X20\n";
        let lines = Lines::new(source);
        let mut modal = Modal::default();
        let mut seen = Vec::new();
        for row in 0..lines.len() {
            let block = lines.block(row).expect("a block");
            modal.apply(source, &of_block(source, &block));
            seen.push(
                modal
                    .radius_compensation
                    .map(|span| span.of(source).to_vec()),
            );
        }
        let g = |text: &str| Some(text.as_bytes().to_vec());
        assert_eq!(seen, [g("G41"), g("G41"), g("G42"), None]);
    }

    /// The state after each line, by the tree.
    fn states(source: &[u8]) -> Vec<Modal> {
        let lines = Lines::new(source);
        let mut modal = Modal::default();
        (0..lines.len())
            .map(|row| {
                let block = lines.block(row).expect("a block");
                let addresses = of_block(source, &block);
                let mut ran = modal;
                ran.apply_block(source, &block, &addresses);
                if block.skip.is_some() {
                    modal.may_have_run(ran);
                } else {
                    modal = ran;
                }
                modal
            })
            .collect()
    }

    #[test]
    fn plane_and_incremental_dimensions_carry_over_blocks() {
        let source = b"X1\nG18 G91 X1\nZ1\nG90 G19\n";
        let seen: Vec<_> = states(source)
            .iter()
            .map(|m| (m.plane, m.incremental.map(|s| s.of(source).to_vec())))
            .collect();
        let g91 = Some(b"G91".to_vec());
        assert_eq!(
            seen,
            [
                (None, None),
                (Some(18), g91.clone()),
                (Some(18), g91),
                (Some(19), None)
            ]
        );
    }

    #[test]
    fn the_programmable_frame_is_the_last_statement_that_set_it_until_cleared() {
        let source =
            b"ATRANS X10\nAROT Z=R1\nX5\nATRANS\nSCALE\nAMIRROR X0\nMIRROR\nTRANS X1\nROT\n\
            ATRANS Y2\nR1=5\n$P_PFRAME=CTRANS(X,5)\n";
        let frames: Vec<_> = states(source)
            .iter()
            .map(|m| m.programmable_frame.map(|s| s.of(source).to_vec()))
            .collect();
        let f = |text: &str| Some(text.as_bytes().to_vec());
        assert_eq!(
            frames,
            [
                f("ATRANS X10"),
                f("AROT Z=R1"),
                f("AROT Z=R1"),
                f("AROT Z=R1"), // ATRANS alone adds nothing
                None,
                f("AMIRROR X0"),
                None,
                f("TRANS X1"),
                None,
                f("ATRANS Y2"),
                f("ATRANS Y2"), // an assignment to another variable
                None            // what is assigned to $P_PFRAME is not followed
            ]
        );
    }

    #[test]
    fn a_skippable_block_makes_what_it_changes_unknown() {
        let source = b"G1 G17 G91 G41 X1 F100\n/G18 G90 X2\n/G41 F200\n";
        let after = states(source);
        assert_eq!(after[1].plane, None);
        assert_eq!(after[1].incremental, None);
        // What the skippable block leaves as it was stays known.
        assert!(after[1].radius_compensation.is_some());
        assert_eq!(after[1].motion, Some(1));
        assert!(after[1].feed);
        // The same word again is another span: no longer known as the first.
        assert_eq!(after[2].radius_compensation, None);

        // A feed rate a skippable block programs may not be programmed.
        let source = b"G1 X1\n/F100\n";
        assert!(!states(source)[1].feed);
    }
}
