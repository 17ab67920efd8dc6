//! The lines the formatter leaves exactly as they are, and the files it
//! leaves whole.
//!
//! - The regions the control's HMI generates and reads back: ShopMill,
//!   ShopTurn and programGUIDE write their steps and contour definitions as
//!   NC blocks carrying a marker in their comment, and the HMI parses those
//!   blocks again to show the step's form: a line whose comment holds
//!   `*RO*` (read only), `*GP*` (generated), `*HD*` (hidden), `;#SM` (a
//!   step's header) or "Don't change!", and every line of a contour section
//!   (`;#7__DlgK contour definition begin - Don't change!` to
//!   `;#End contour definition end - Don't change!`) are left as they are.
//! - `; sinuprep:` lines and the blocks `rewrite` emitted under them (the
//!   frames and CYCLE800 the block structure knows, and the lines right
//!   after it that write `_CYC600_` results), and lines that use a DEFINE
//!   macro, whose text is not what the control reads there (the driver
//!   follows both).
//! - Definition files (`.DEF`, `_DEF`, GUD): data, not a program.
//!
//! The lines after the program's end are the driver's to leave (it knows
//! where the end is as it goes).

use memchr::memmem;

/// Markers that make a line the HMI's (see the module's documentation).
const LINE_MARKERS: [&[u8]; 5] = [b"*RO*", b"*GP*", b"*HD*", b";#SM", b"Don't change"];

/// The HMI writes these after `;#7__DlgK ` and `;#End `, with "Don't
/// change!" (which [`mentions_hmi`] looks for by its `#` and `'`).
const CONTOUR_BEGIN: &[u8] = b"contour definition begin";
const CONTOUR_END: &[u8] = b"contour definition end";

/// Whether `source` holds any HMI marker at all: most programs hold none,
/// and then no line is searched.
pub fn mentions_hmi(source: &[u8]) -> bool {
    // Every marker holds one of these, which CAM output rarely does: one
    // pass over the bytes instead of seven.
    if memchr::memchr3(b'*', b'#', b'\'', source).is_none() {
        return false;
    }
    LINE_MARKERS
        .iter()
        .chain([&CONTOUR_BEGIN, &CONTOUR_END])
        .any(|marker| memmem::find(source, marker).is_some())
}

/// Follows the HMI's regions line by line.
#[derive(Default)]
pub struct Hmi {
    in_contour: bool,
}

impl Hmi {
    /// Whether the line `content` (its bytes) is the HMI's, asked of every
    /// line in order.
    pub fn owns(&mut self, content: &[u8]) -> bool {
        if memchr::memchr(b';', content).is_none() {
            return self.in_contour;
        }
        if contains(content, CONTOUR_BEGIN) {
            self.in_contour = true;
            return true;
        }
        if contains(content, CONTOUR_END) {
            self.in_contour = false;
            return true;
        }
        self.in_contour || LINE_MARKERS.iter().any(|m| contains(content, m))
    }
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

    #[test]
    fn a_contour_section_and_marked_lines_are_the_hmis() {
        let lines: [&[u8]; 7] = [
            b"G1 X10",
            b";#7__DlgK contour definition begin - Don't change!;*GP*;*RO*;*HD*",
            b"G17 G90 DIAMOF;*GP*",
            b"G1 X0 Y0",
            b";#End contour definition end - Don't change!;*GP*;*RO*;*HD*",
            b"g1 x5 ; mine",
            b"CYCLE62(,2,\"E_LAB_A_X\",) ;*RO*",
        ];
        let mut hmi = Hmi::default();
        let owned: Vec<bool> = lines.iter().map(|l| hmi.owns(l)).collect();
        assert_eq!(owned, [false, true, true, true, true, false, true]);
        assert!(mentions_hmi(lines[6]));
        assert!(!mentions_hmi(b"G1 X10 ; GP\n"));
    }

    #[test]
    fn definition_files_are_data() {
        assert!(is_data_file("UGUD.DEF"));
        assert!(is_data_file("a.arc:SGUD_DEF"));
        assert!(!is_data_file("PART.MPF"));
    }
}
