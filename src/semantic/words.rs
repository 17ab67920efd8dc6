//! The words the language owns by their spelling: keywords and operators,
//! R parameters, system variables, the control's functions, commands and
//! cycles, and the machine axes `AX1`, `AX2`, ... A user's name is none of
//! them: the formatter writes them in the case asked for, and a rename
//! refuses them.

use crate::semantic::calls::BUILTINS;
use crate::syntax::lexer::{is_one_of, RESERVED};

/// The control's functions (Siemens, Programming Manual Job Planning,
/// "Arithmetic functions", "Frame calculation", "String functions") and the
/// modifiers of a coordinate (`AC`, `IC`, ...).
pub(crate) const FUNCTIONS: &[&str] = &[
    "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN2", "SQRT", "ABS", "POT", "TRUNC", "ROUND", "LN",
    "EXP", "MINVAL", "MAXVAL", "BOUND", "CTRANS", "CROT", "CSCALE", "CMIRROR", "CFINE", "AC", "IC",
    "DC", "ACP", "ACN", "CAC", "CIC", "CACP", "CACN", "AXSTRING", "SPRINT", "SUBSTR", "TOLOWER",
    "TOUPPER", "STRLEN", "INDEX", "RINDEX", "MATCH", "NUMBER", "ISNUMBER", "AXNAME", "ISAXIS",
    "ISVAR", "ISFILE", "TRUE", "FALSE", "GOTOS", "M17", "MSG", "SETAL",
];

/// Whether `name` is one of the language's words by its spelling.
pub fn is_language_word(name: &[u8]) -> bool {
    if name.first() == Some(&b'$') {
        return name.len() > 1;
    }
    let numbered = |prefix: &[u8]| {
        name.len() > prefix.len()
            && name[..prefix.len()].eq_ignore_ascii_case(prefix)
            && name[prefix.len()..].iter().all(u8::is_ascii_digit)
    };
    numbered(b"R")
        || numbered(b"CYCLE")
        || is_one_of(name, RESERVED)
        || is_one_of(name, FUNCTIONS)
        || is_one_of(name, BUILTINS)
}

/// Whether `name` is a machine axis's generic name (`AX1`, `ax12`), which
/// every control knows whatever its axes are called.
pub fn is_machine_axis(name: &[u8]) -> bool {
    name.len() > 2
        && name[..2].eq_ignore_ascii_case(b"AX")
        && name[2..].iter().all(u8::is_ascii_digit)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_languages_words_and_no_user_name() {
        for word in [
            "IF", "gotof", "REAL", "SIN", "TRUE", "CYCLE800", "R5", "STOPRE", "$P_UIFR",
        ] {
            assert!(is_language_word(word.as_bytes()), "{word}");
        }
        for name in ["_DEPTH", "MY_SUB", "CYCLE_MINE", "RX", "SINUS"] {
            assert!(!is_language_word(name.as_bytes()), "{name}");
        }
        assert!(is_machine_axis(b"AX1") && is_machine_axis(b"ax12"));
        assert!(!is_machine_axis(b"AX") && !is_machine_axis(b"AXE"));
    }
}
