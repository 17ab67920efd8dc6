//! The lines the formatter leaves exactly as they are, and the files it
//! leaves whole.
//!
//! - The regions the control's HMI generates and reads back: ShopMill,
//!   ShopTurn and programGUIDE write their steps, cycle screens and contour
//!   definitions as NC blocks, and the HMI parses those blocks again to show
//!   the step's or cycle's form; a byte changed there can make the form
//!   unreadable or lose what it held. The HMI's regions ([`hmi_rows`]):
//!   - a line whose comment holds `*RO*` (read only in the HMI's editor),
//!     `*GP*` (generated), `*HD*` (hidden), `;#SM` (a step's header),
//!     `;NCG#` (a screen's generated code), `;CON,` (a contour's
//!     description) or "Don't change";
//!   - a contour section, from its `;#7__DlgK` line (`;#7__DlgK contour
//!     definition begin - Don't change!`, in the HMI's language) to its
//!     `;#End` line, with the `E_LAB_A_...:` label right before it and the
//!     `E_LAB_E_...:` label right after it, between which a cycle
//!     (CYCLE62) finds the contour: its lines need not carry a marker;
//!   - a screen's generated code, from its `;NCG#...` line to its
//!     `;#END#...` line: the code between is what the screen wrote, without
//!     markers, and recompiling reads it back into the screen.
//!
//!   A section whose end line is missing runs to the end of the file: what
//!   follows may be the HMI's, and leaving a line as it is is always safe.
//! - `; sinuprep:` lines and the blocks `rewrite` emitted under them (the
//!   frames and CYCLE800 the block structure knows, and the lines right
//!   after it that write `_CYC600_` results), and lines that use a DEFINE
//!   macro, whose text is not what the control reads there (the driver
//!   follows both).
//! - Definition files (`.DEF`, `.GUD`, `_DEF`, GUD): data, not a program.
//!
//! The lines after the program's end are the driver's to leave (it knows
//! where the end is as it goes).

use std::ops::Range;

use memchr::memmem;

use crate::syntax::lines::raw_lines;

/// Markers that make a line the HMI's (see the module's documentation).
const LINE_MARKERS: [&[u8]; 7] = [
    b"*RO*",
    b"*GP*",
    b"*HD*",
    b";#SM",
    b";NCG#",
    b";CON,",
    b"Don't change",
];

/// A contour section's first and last lines: the dialog's tag, which the
/// HMI writes whatever its language, or the English text after it.
const CONTOUR_BEGIN: [&[u8]; 2] = [b";#7__DlgK", b"contour definition begin"];
const CONTOUR_END: [&[u8]; 2] = [b";#End", b"contour definition end"];

/// A screen's generated code: its first line holds `;NCG#` (one of the
/// [`LINE_MARKERS`]), its last `;#END#`.
const GENERATED_BEGIN: &[u8] = b";NCG#";
const GENERATED_END: &[u8] = b";#END#";

/// The labels the HMI writes around a contour section.
const CONTOUR_START_LABEL: &[u8] = b"E_LAB_A_";
const CONTOUR_END_LABEL: &[u8] = b"E_LAB_E_";

/// Whether `source` holds any HMI marker at all: most programs hold none,
/// and then no line is searched.
pub fn mentions_hmi(source: &[u8]) -> bool {
    // Every marker but `;CON,` holds one of these, which CAM output rarely
    // does: one pass over the bytes instead of one a marker.
    if memchr::memchr3(b'*', b'#', b'\'', source).is_none() {
        return contains(source, b";CON,");
    }
    LINE_MARKERS
        .iter()
        .chain(&CONTOUR_BEGIN)
        .any(|marker| contains(source, marker))
}

/// Which section of the HMI's the lines are in.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Section {
    None,
    Contour,
    Generated,
}

/// The rows (line numbers from 0, as [`raw_lines`] counts them) the HMI
/// owns, as ranges in order, neighbours merged.
pub fn hmi_rows(source: &[u8]) -> Vec<Range<usize>> {
    let mut rows: Vec<Range<usize>> = Vec::new();
    let mut own = |row: usize| match rows.last_mut() {
        Some(last) if last.end >= row => last.end = last.end.max(row + 1),
        _ => rows.push(row..row + 1),
    };
    let mut section = Section::None;
    // The row of an `E_LAB_A_` label just read, and whether the row before
    // this one ended a contour section.
    let mut start_label = None;
    let mut contour_ended = false;
    for (row, line) in raw_lines(source).enumerate() {
        let content = line.content.of(source);
        let ended = std::mem::take(&mut contour_ended);
        let label = std::mem::take(&mut start_label);
        match section {
            Section::Contour => {
                own(row);
                if CONTOUR_END.iter().any(|end| contains(content, end)) {
                    section = Section::None;
                    contour_ended = true;
                }
                continue;
            }
            Section::Generated => {
                own(row);
                if contains(content, GENERATED_END) {
                    section = Section::None;
                }
                continue;
            }
            Section::None => {}
        }
        if ended && is_label(content, CONTOUR_END_LABEL) {
            own(row);
            continue;
        }
        if is_label(content, CONTOUR_START_LABEL) {
            start_label = Some(row);
        }
        if !may_hold_marker(content) {
            continue;
        }
        if CONTOUR_BEGIN.iter().any(|begin| contains(content, begin)) {
            if let Some(label) = label {
                own(label);
            }
            own(row);
            section = Section::Contour;
        } else if contains(content, GENERATED_BEGIN) {
            own(row);
            section = Section::Generated;
        } else if LINE_MARKERS.iter().any(|m| contains(content, m)) {
            own(row);
        }
    }
    rows
}

/// Whether the line `content` may hold a marker: a comment with one of
/// the bytes every marker holds. Most commented lines (CAM output's) have
/// none, and then no marker is searched for.
fn may_hold_marker(content: &[u8]) -> bool {
    memchr::memchr(b';', content).is_some()
        && (memchr::memchr3(b'*', b'#', b'\'', content).is_some()
            || (memchr::memchr(b',', content).is_some() && contains(content, b";CON,")))
}

/// Whether the line `content` starts (after blanks) with a label whose
/// name starts with `prefix`: `E_LAB_E_KONTUR:`.
fn is_label(content: &[u8], prefix: &[u8]) -> bool {
    let name = content.trim_ascii_start();
    if !name.starts_with(prefix) {
        return false;
    }
    let rest = &name[prefix.len()..];
    let length = rest
        .iter()
        .take_while(|b| b.is_ascii_alphanumeric() || **b == b'_')
        .count();
    rest.get(length) == Some(&b':')
}

/// As the HMI writes them: in this case only, so that whether a line is
/// the HMI's never depends on what formatting does to its case.
fn contains(haystack: &[u8], needle: &[u8]) -> bool {
    memmem::find(haystack, needle).is_some()
}

/// Whether the file named `name` holds definitions (GUD, macros, machine
/// data), which are left whole: `*.DEF`, `*.GUD`, `*_DEF` (an archive's
/// member), `*.INI`.
pub fn is_data_file(name: &str) -> bool {
    let upper = name.to_ascii_uppercase();
    [".DEF", ".GUD", "_DEF", ".INI"]
        .iter()
        .any(|suffix| upper.ends_with(suffix))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rows of `lines` (joined with LF) the HMI owns, one by one.
    fn owned(lines: &[&str]) -> Vec<usize> {
        let source = lines.join("\n");
        hmi_rows(source.as_bytes()).into_iter().flatten().collect()
    }

    #[test]
    fn a_contour_section_and_marked_lines_are_the_hmis() {
        let lines = [
            "G1 X10",
            "E_LAB_A_KONTUR: ;#SM Z:1",
            ";#7__DlgK contour definition begin - Don't change!;*GP*;*RO*;*HD*",
            "G17 G90 DIAMOF;*GP*",
            "G1 X0 Y0",
            ";#End contour definition end - Don't change!;*GP*;*RO*;*HD*",
            "E_LAB_E_KONTUR:",
            "g1 x5 ; mine",
            "CYCLE62(,2,\"E_LAB_A_X\",) ;*RO*",
        ];
        assert_eq!(owned(&lines), [1, 2, 3, 4, 5, 6, 8]);
        assert!(mentions_hmi(lines[8].as_bytes()));
        assert!(!mentions_hmi(b"G1 X10 ; GP\n"));
    }

    /// The HMI writes the section's text in its own language: the dialog's
    /// tag and `;#End` mark it, and its labels belong to it.
    #[test]
    fn a_contour_section_in_any_language_with_its_labels() {
        let lines = [
            "PROC SUB",
            "M17",
            "E_LAB_A_KONT:",
            ";#7__DlgK Konturdefinition Anfang - Nicht aendern!;*GP*;*RO*;*HD*",
            "g17  g90 diamof",
            "",
            ";#End Konturdefinition Ende - Nicht aendern!;*GP*;*RO*;*HD*",
            "E_LAB_E_KONT:",
            "E_LAB_E_OTHER:",
            "G1 X1",
        ];
        assert_eq!(owned(&lines), [2, 3, 4, 5, 6, 7]);
    }

    /// A screen's generated code is the HMI's from `;NCG#` to `;#END#`,
    /// marked or not; without its end it runs to the file's.
    #[test]
    fn a_screens_generated_code_is_the_hmis() {
        let lines = [
            "N10 G17",
            ";NCG#DRILL#\\cus.dir\\drill.com#DRILL1#1#*NCG;*RO*;*HD*",
            "if r1==1",
            "g0  z100",
            "endif",
            ";#END#*NCG;*RO*;*HD*",
            "if r2==1",
        ];
        assert_eq!(owned(&lines), [1, 2, 3, 4, 5]);
        assert_eq!(owned(&lines[..5]), [1, 2, 3, 4]);
        assert!(mentions_hmi(b";NCG#A#B\nG1\n"));
        assert!(mentions_hmi(b";CON,V64,2\n"));
    }

    #[test]
    fn a_label_is_the_name_before_a_colon() {
        assert!(is_label(b"  E_LAB_E_K1:", CONTOUR_END_LABEL));
        assert!(!is_label(b"E_LAB_E_K1 G1", CONTOUR_END_LABEL));
        assert!(!is_label(b"CYCLE62(\"E_LAB_E_K1\")", CONTOUR_END_LABEL));
    }

    #[test]
    fn definition_files_are_data() {
        assert!(is_data_file("UGUD.DEF"));
        assert!(is_data_file("a.arc:SGUD_DEF"));
        assert!(!is_data_file("PART.MPF"));
    }
}
