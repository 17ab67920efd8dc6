//! Lines of assignments and address words that the parser reads without an
//! error, told without parsing them: `$TC_DP1[1,1]=120`, `CYCLES = 1`,
//! `M3 S=_RPM`, `X=R2 Y=-2.5 ; comment`, the lines that setup files and
//! hand-written cycles are mostly made of. A line without an error yields
//! nothing in the syntax pass ([`super::diagnostics`]), which steps over
//! these as over plain lines: parsing one cost about 2,000 instructions
//! (its tree built and dropped), telling it about 100.
//!
//! Strict and conservative, as [`super::plain::is_plain`] is: `false` means
//! "parse it to know". Each statement is one the parser reads the same way
//! wherever it stands in the block (an address word with a number, or an
//! assignment whose value and indices are single operands), followed by a
//! blank, the comment or the line's end. Property-tested against the parser.

use crate::syntax::lexer::{is_blank, is_name_char, is_name_start, is_one_of};
use crate::syntax::MAX_PARSED_LINE;

/// Whether the parser reads `content` (a line without its terminator)
/// without an error; `false` when it might not.
pub fn reads_clean(content: &[u8]) -> bool {
    if content.len() > MAX_PARSED_LINE {
        return false;
    }
    let mut at = skip_blanks(content, 0);
    loop {
        if matches!(content.get(at), None | Some(b';')) {
            return true;
        }
        let Some(end) = statement(content, at) else {
            return false;
        };
        match content.get(end) {
            None | Some(b';') => return true,
            Some(&byte) if is_blank(byte) => at = skip_blanks(content, end),
            Some(_) => return false,
        }
    }
}

fn skip_blanks(bytes: &[u8], mut at: usize) -> usize {
    while bytes.get(at).is_some_and(|&b| is_blank(b)) {
        at += 1;
    }
    at
}

/// The end of the statement at `at` if it is one of those the module
/// accepts.
fn statement(bytes: &[u8], at: usize) -> Option<usize> {
    let first = bytes[at];
    // One letter not followed by a second name character is an address
    // (the parser's own test): `X10`, `R1=5`, `A[2]=1`.
    if first.is_ascii_alphabetic() && !bytes.get(at + 1).is_some_and(|&b| is_name_start(b)) {
        return address(bytes, at);
    }
    let name_end = name(bytes, at)?;
    // `ID=1 WHEN …` starts a synchronized action; an operator word after a
    // value continues the expression; `NOT`, `B_NOT` and `DO` read otherwise.
    if is_one_of(&bytes[at..name_end], SPECIAL_NAMES) {
        return None;
    }
    let after = match bytes.get(name_end) {
        Some(b'[') => indices(bytes, name_end)?,
        _ => name_end,
    };
    value_after_equals(bytes, after)
}

/// Names the parser does not read as a plain assignment's target or a
/// variable operand.
const SPECIAL_NAMES: &[&str] = &[
    "ID", "IDS", "NOT", "B_NOT", "DO", "DIV", "MOD", "B_AND", "B_XOR", "B_OR", "AND", "XOR", "OR",
];

/// An address word: `X-12.5`, `X1=R2` (not `G1=…`), `X=5`, `R[1]=5`.
fn address(bytes: &[u8], at: usize) -> Option<usize> {
    let after_letter = at + 1;
    let digits = bytes[after_letter..]
        .iter()
        .take_while(|b| b.is_ascii_digit())
        .count();
    let after_digits = after_letter + digits;
    if bytes.get(skip_blanks(bytes, after_digits)) == Some(&b'=') {
        // `G1=5` is an error; `N10 =5` starts with a block number.
        let g = bytes[at].eq_ignore_ascii_case(&b'G');
        let n = bytes[at].eq_ignore_ascii_case(&b'N');
        if digits > 0 && (g || n && bytes.get(after_digits) != Some(&b'=')) {
            return None;
        }
        return value_after_equals(bytes, after_digits);
    }
    if digits == 0 && bytes.get(after_letter) == Some(&b'[') {
        let after = indices(bytes, after_letter)?;
        return value_after_equals(bytes, after);
    }
    // A number word, as the parser's shortcut for them reads it.
    let mut number_start = after_letter;
    if matches!(bytes.get(number_start), Some(b'-' | b'+')) {
        number_start += 1;
    }
    number(bytes, number_start)
}

/// `'$'* (letter | '_') (letter | digit | '_')*`, its end.
fn name(bytes: &[u8], at: usize) -> Option<usize> {
    let mut end = at;
    while bytes.get(end) == Some(&b'$') {
        end += 1;
    }
    if !bytes.get(end).is_some_and(|&b| is_name_start(b)) {
        return None;
    }
    while bytes.get(end).is_some_and(|&b| is_name_char(b)) {
        end += 1;
    }
    Some(end)
}

/// `'=' blank operand` after blanks at `at` (not `==`), the operand's end.
fn value_after_equals(bytes: &[u8], at: usize) -> Option<usize> {
    let equals = skip_blanks(bytes, at);
    if bytes.get(equals) != Some(&b'=') || bytes.get(equals + 1) == Some(&b'=') {
        return None;
    }
    // What follows the value must not continue it: a blank, the comment or
    // the line's end (the caller checks which; no statement it accepts
    // starts with an operator).
    operand(bytes, skip_blanks(bytes, equals + 1), true)
}

/// `'[' operand (',' operand)* ']'` at `at` (each operand without indices),
/// its end.
fn indices(bytes: &[u8], at: usize) -> Option<usize> {
    let mut at = at + 1;
    loop {
        at = skip_blanks(bytes, at);
        let end = operand(bytes, at, false)?;
        at = skip_blanks(bytes, end);
        match bytes.get(at) {
            Some(b',') => at += 1,
            Some(b']') => return Some(at + 1),
            _ => return None,
        }
    }
}

/// A signed number, a number, a string or a variable (with indices if
/// `indexed`), followed by a blank, `,`, `]`, `;` or the line's end; its
/// end.
fn operand(bytes: &[u8], at: usize, indexed: bool) -> Option<usize> {
    let end = match *bytes.get(at)? {
        b'-' | b'+' => number(bytes, at + 1)?,
        b'0'..=b'9' | b'.' => number(bytes, at)?,
        b'"' => at + 2 + memchr::memchr(b'"', bytes.get(at + 1..)?)?,
        _ => {
            let end = name(bytes, at)?;
            if is_one_of(&bytes[at..end], SPECIAL_NAMES) {
                return None;
            }
            match bytes.get(end) {
                Some(b'[') if indexed => indices(bytes, end)?,
                _ => end,
            }
        }
    };
    match bytes.get(end) {
        None => Some(end),
        Some(&byte) if is_blank(byte) || matches!(byte, b',' | b']' | b';') => Some(end),
        Some(_) => None,
    }
}

/// A decimal number at `at`, `12`, `.5`, `30.`: at least one digit, one
/// point at most, no longer than the plain scan takes (so that it is never
/// too large for a REAL); followed by anything but a digit or a point.
fn number(bytes: &[u8], at: usize) -> Option<usize> {
    let (mut end, mut digits, mut points) = (at, 0, 0);
    loop {
        match bytes.get(end) {
            Some(b'0'..=b'9') => digits += 1,
            Some(b'.') => points += 1,
            _ => break,
        }
        end += 1;
    }
    (digits > 0 && points <= 1 && end - at <= 24).then_some(end)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::lines::raw_lines;
    use crate::syntax::LineParser;

    /// Whether the parser reads `text` (one line) without a diagnostic.
    fn parses_clean(text: &str) -> bool {
        let source = text.as_bytes();
        let mut parser = LineParser::default();
        raw_lines(source).all(|raw| parser.parse_line(source, raw).1.is_none())
    }

    #[test]
    fn assignments_and_words_read_clean() {
        for clean in [
            "$TC_DP1[1,1]=120",
            "$TC_TP2[1]=\"CUTTER 4\"",
            "  CYCLES = 1 ; at least one",
            "M3 S=_RPM",
            "X=R2 Y=-2.5 Z=.5",
            "R1 = $AA_IW[Z]",
            "N40 R3=30 R4=3",
            "R[1]=5",
            "X1=100",
            "N10 G1 X-12.5",
            "X=1600 Y=900 Z=0 E=0; edge cases",
            "$P_UIFR[1,X,TR]=0",
            "ENDIF=5",
        ] {
            assert!(reads_clean(clean.as_bytes()), "{clean}");
            assert!(parses_clean(clean), "{clean}");
        }
        for not in [
            "G1=5",
            "N10 =5",
            "X=1 N10 =5",
            "X=5 OR=1",
            "ID=1 WHEN $A_IN[1]==1 DO M3",
            "R1==5",
            "X=-\"A\"",
            "X=1.2.3",
            "X=1EX3",
            "$TC_DP1[]=1",
            "$TC_DP1[1,]=1",
            "R1[2]=5",
            "X=A[B[1]]",
            "R1=SIN(30)",
            "ENDIF",
            "TRAORI",
            "X=5 DIV 2",
            "/X1",
            "%_N_A_MPF",
            "LBL: X=1",
        ] {
            assert!(!reads_clean(not.as_bytes()), "{not}");
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(4000))]

        /// What `reads_clean` accepts, the parser reads without an error.
        #[test]
        fn a_clean_line_parses_without_error(text in proptest::prop_oneof![
            "[ NnGgXxRr$_A-Z0-9.=\\[\\],;\"+-]{0,30}",
            "( ?(N[0-9]{1,2}|[GXRNAOD][0-9]?|\\$?(TC|ID|IDS|OR|AND|DO|NOT|X_A)[0-9]?)(\\[([-+]?[0-9.]{1,3}|[XA]|\"[a;]?\"|AND|)( ?, ?([0-9.]{1,2}|X))?\\])? ?(=|==)? ?([-+]?[0-9.E]{0,4}|\"[A ;]{0,2}\"?|\\$?[A-Z_]{1,5}(\\[[0-9X]\\])?)){0,4}( ?;[A-Z ]*)?",
            "([XN]=[0-9] ){1,2}(OR|AND|XOR|MOD|DIV|B_OR|NOT|DO|ID|XA|N1)( ?= ?[0-9])?",
        ]) {
            if reads_clean(text.as_bytes()) {
                proptest::prop_assert!(parses_clean(&text), "{:?}", text);
            }
        }
    }
}
