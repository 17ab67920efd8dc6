//! Lines that the parser reads without an error, told without parsing them:
//! assignments and address words (`$TC_DP1[1,1]=120`, `CYCLES = 1`,
//! `M3 S=_RPM`, `X=R2 Y=-2.5 ; comment`), calls and commands
//! (`WARMUP_CYCLE(3600, 600)`, `G0 SUPA Z0`), lone keywords (`ENDIF`) and
//! one-line definitions (`DEF REAL START_CC=10`): what setup files and
//! hand-written cycles are mostly made of. A line without an error yields
//! nothing in the syntax pass ([`super::diagnostics`]), which steps over
//! these as over plain lines: telling one takes a fraction of parsing it (its
//! tree built and dropped).
//!
//! Strict and conservative, as [`super::plain::is_plain`] is: `false` means
//! "parse it to know". Each statement is one the parser reads the same way
//! wherever it stands in the block: an address word with a number; an
//! assignment whose value is operands (numbers, strings, variables, calls)
//! joined by `+ - * /` or `:`, with indices and arguments of single
//! operands; a call or command whose name the parser's own tests take for
//! one (`block::names_call_or_command`); each followed by a blank,
//! the comment or the line's end. Property-tested against the parser.

use crate::syntax::block::{
    block_number_digits, names_call_or_command, FLAG_ATTRIBUTES, VALUED_ATTRIBUTES,
};
use crate::syntax::lexer::{is_blank, is_one_of, Input, RESERVED};
use crate::syntax::MAX_PARSED_LINE;

/// Whether the parser reads `content` (a line without its terminator)
/// without an error; `false` when it might not.
pub fn reads_clean(content: &[u8]) -> bool {
    if content.len() > MAX_PARSED_LINE {
        return false;
    }
    let mut at = skip_blanks(content, 0);
    if let Some(digits) = block_number_digits(&content[at..]) {
        at = skip_blanks(content, at + 1 + digits);
    }
    // Statements that stand alone in their block: nothing but the comment
    // may follow.
    if let Some(end) = lone_keyword(content, at).or_else(|| definition(content, at)) {
        if matches!(content.get(skip_blanks(content, end)), None | Some(b';')) {
            return true;
        }
    }
    loop {
        if matches!(content.get(at), None | Some(b';')) {
            return true;
        }
        let Some(end) = statement(content, at) else {
            return false;
        };
        match content.get(end) {
            None | Some(b';') => return true,
            Some(&byte) if is(byte, BLANK) => at = skip_blanks(content, end),
            Some(_) => return false,
        }
    }
}

fn skip_blanks(bytes: &[u8], mut at: usize) -> usize {
    while bytes.get(at).is_some_and(|&b| is(b, BLANK)) {
        at += 1;
    }
    at
}

/// The classes of a byte, looked up rather than tested: each byte of a line
/// is asked about once or twice.
const BLANK: u8 = 1;
const NAME_START: u8 = 2;
const NAME_CHAR: u8 = 4;

static CLASSES: [u8; 256] = {
    let mut table = [0; 256];
    let mut byte = 0;
    while byte < 256 {
        let b = byte as u8;
        if is_blank(b) {
            table[byte] |= BLANK;
        }
        if b.is_ascii_alphabetic() || b == b'_' {
            table[byte] |= NAME_START | NAME_CHAR;
        }
        if b.is_ascii_digit() {
            table[byte] |= NAME_CHAR;
        }
        byte += 1;
    }
    table
};

#[inline(always)]
fn is(byte: u8, class: u8) -> bool {
    CLASSES[usize::from(byte)] & class != 0
}

/// The end of the keyword at `at` that makes a block of its own without
/// operands (`ENDIF`, `ELSE`, `ENDWHILE`, ...), if one is there.
fn lone_keyword(bytes: &[u8], at: usize) -> Option<usize> {
    const LONE: [&str; 6] = ["ELSE", "ENDIF", "ENDWHILE", "ENDFOR", "LOOP", "ENDLOOP"];
    if !matches!(bytes.get(at)?, b'E' | b'e' | b'L' | b'l') {
        return None;
    }
    let end = name(bytes, at)?;
    is_one_of(&bytes[at..end], &LONE).then_some(end)
}

/// `DEF type name ('=' value)? (',' name ('=' value)?)*` at `at`, with a
/// type other than STRING and names without dimensions, its end.
fn definition(bytes: &[u8], at: usize) -> Option<usize> {
    const TYPES: [&str; 6] = ["INT", "REAL", "BOOL", "CHAR", "AXIS", "FRAME"];
    let end = name(bytes, at)?;
    if !bytes[at..end].eq_ignore_ascii_case(b"DEF") || !is(*bytes.get(end)?, BLANK) {
        return None;
    }
    let type_start = skip_blanks(bytes, end);
    let type_end = name(bytes, type_start)?;
    if !is_one_of(&bytes[type_start..type_end], &TYPES) || !is(*bytes.get(type_end)?, BLANK) {
        return None;
    }
    let mut at = skip_blanks(bytes, type_end);
    loop {
        // A variable's name has two characters or more, is no reserved word,
        // and no attribute, which the type would take instead.
        let end = name(bytes, at)?;
        let text = &bytes[at..end];
        if text.len() < 2
            || text[0] == b'$'
            || is_one_of(text, RESERVED)
            || is_one_of(text, &VALUED_ATTRIBUTES)
            || is_one_of(text, &FLAG_ATTRIBUTES)
        {
            return None;
        }
        let mut end = end;
        let next = skip_blanks(bytes, end);
        if bytes.get(next) == Some(&b'=') {
            if matches!(bytes.get(next + 1), Some(b'=')) {
                return None;
            }
            let value_start = skip_blanks(bytes, next + 1);
            // `(1, 2)` initialises an array.
            if bytes.get(value_start) == Some(&b'(') {
                return None;
            }
            end = value(bytes, value_start)?;
        }
        let next = skip_blanks(bytes, end);
        if bytes.get(next) != Some(&b',') {
            return Some(end);
        }
        at = skip_blanks(bytes, next + 1);
    }
}

/// The end of the statement at `at` if it is one of those the module
/// accepts.
fn statement(bytes: &[u8], at: usize) -> Option<usize> {
    let first = bytes[at];
    // One letter not followed by a second name character is an address
    // (the parser's own test): `X10`, `R1=5`, `A[2]=1`.
    if first.is_ascii_alphabetic() && !bytes.get(at + 1).is_some_and(|&b| is(b, NAME_START)) {
        return address(bytes, at);
    }
    let name_end = name(bytes, at)?;
    let text = &bytes[at..name_end];
    if is_special(text) {
        return None;
    }
    let callable = || names_call_or_command(Input::new(text, at));
    match bytes.get(name_end) {
        Some(b'[') => {
            let after = indices(bytes, name_end)?;
            value_after_equals(bytes, after)
        }
        Some(b'(') if callable() => arguments(bytes, name_end),
        _ if bytes.get(skip_blanks(bytes, name_end)) == Some(&b'=') => {
            value_after_equals(bytes, name_end)
        }
        // `SETINT` names its interrupt in parentheses.
        _ if !text.eq_ignore_ascii_case(b"SETINT") && callable() => Some(name_end),
        _ => None,
    }
}

/// `ID=1 WHEN …` starts a synchronized action; an operator word after a
/// value continues the expression; `NOT`, `B_NOT` and `DO` read otherwise.
fn is_special(name: &[u8]) -> bool {
    const SPECIAL: [&str; 13] = [
        "ID", "IDS", "NOT", "B_NOT", "DO", "DIV", "MOD", "B_AND", "B_XOR", "B_OR", "AND", "XOR",
        "OR",
    ];
    // By length and first letter first: this runs on every name.
    matches!(name.len(), 2..=5)
        && matches!(
            name[0] | 0x20,
            b'i' | b'n' | b'b' | b'd' | b'm' | b'a' | b'x' | b'o'
        )
        && is_one_of(name, &SPECIAL)
}

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
    if !bytes.get(end).is_some_and(|&b| is(b, NAME_START)) {
        return None;
    }
    while bytes.get(end).is_some_and(|&b| is(b, NAME_CHAR)) {
        end += 1;
    }
    Some(end)
}

/// More terms than a value has here (frames: `CTRANS(…):CROT(…)`): a long
/// chain goes deeper than the parser follows.
const MOST_TERMS: usize = 16;

/// `'=' value` after blanks at `at` (not `==`), the end of the value.
fn value_after_equals(bytes: &[u8], at: usize) -> Option<usize> {
    let equals = skip_blanks(bytes, at);
    if bytes.get(equals) != Some(&b'=') || bytes.get(equals + 1) == Some(&b'=') {
        return None;
    }
    value(bytes, skip_blanks(bytes, equals + 1))
}

/// `term (operator term)*` at `at`, terms joined by `+ - * /` or chained by
/// `:`, its end. What follows must not continue it: a blank, the comment or
/// the line's end (the caller checks which; no statement it accepts starts
/// with an operator, and blanks before one are the parser's to skip too).
fn value(bytes: &[u8], at: usize) -> Option<usize> {
    let mut end = operand(bytes, at, true)?;
    for _ in 1..MOST_TERMS {
        let next = skip_blanks(bytes, end);
        if !matches!(bytes.get(next), Some(b'+' | b'-' | b'*' | b'/' | b':')) {
            return Some(end);
        }
        end = operand(bytes, skip_blanks(bytes, next + 1), true)?;
    }
    None
}

/// `'[' operand (',' operand)* ']'` at `at` (each operand a simple one),
/// its end.
fn indices(bytes: &[u8], at: usize) -> Option<usize> {
    let mut at = at + 1;
    loop {
        at = skip_blanks(bytes, at);
        at = skip_blanks(bytes, operand(bytes, at, false)?);
        match bytes.get(at) {
            Some(b',') => at += 1,
            Some(b']') => return Some(at + 1),
            _ => return None,
        }
    }
}

/// `'(' ')' | '(' operand? (',' operand?)* ')'` at `at` (each operand a
/// simple one), its end.
fn arguments(bytes: &[u8], at: usize) -> Option<usize> {
    let mut at = skip_blanks(bytes, at + 1);
    if bytes.get(at) == Some(&b')') {
        return Some(at + 1);
    }
    loop {
        at = skip_blanks(bytes, at);
        if !matches!(bytes.get(at), Some(b',' | b')')) {
            at = skip_blanks(bytes, operand(bytes, at, false)?);
        }
        match bytes.get(at) {
            Some(b',') => at += 1,
            Some(b')') => return Some(at + 1),
            _ => return None,
        }
    }
}

/// A signed number, a number, a string or a variable; when `compound`,
/// also a variable with indices or a call. Its end; the caller checks
/// what follows.
fn operand(bytes: &[u8], at: usize, compound: bool) -> Option<usize> {
    match *bytes.get(at)? {
        b'-' | b'+' => number(bytes, at + 1),
        b'0'..=b'9' | b'.' => number(bytes, at),
        b'"' => {
            let length = bytes.get(at + 1..)?.iter().position(|&b| b == b'"')?;
            Some(at + 2 + length)
        }
        _ => {
            let end = name(bytes, at)?;
            if is_special(&bytes[at..end]) {
                return None;
            }
            match bytes.get(end) {
                Some(b'[') if compound => indices(bytes, end),
                Some(b'(') if compound => arguments(bytes, end),
                _ => Some(end),
            }
        }
    }
}

/// A decimal number at `at`, `12`, `.5`, `30.`: at least one digit, one
/// point at most, no longer than the plain scan takes (so that it is never
/// too large for a REAL), followed by neither `E` (an exponent, or a
/// broken one) nor a name character.
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
    let ok = digits > 0 && points <= 1 && end - at <= 24;
    (ok && !bytes.get(end).is_some_and(|&b| is(b, NAME_CHAR))).then_some(end)
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
            "N10 ENDIF ; closes the IF",
            "else",
            "G0 SUPA Z0        ; retract Z",
            "WARMUP_CYCLE(3600, 600)   ; 30% for 10 min",
            "CMIRROR()",
            "SET(0,,,9,)",
            "$P_UIFR[1]=CTRANS(X,0.000,Y,0.000):CROT(X,0.000,Y,0.000,Z,0.000):CMIRROR()",
            "X=IC(10)",
            "TRAORI",
            "X=2+3*4",
            "X = 100 - 10*2 + 5",
            "X=2*-3",
            "DEF INT VAR1 = 4",
            "DEF REAL START_CC=10, START_CC_SPEED=0.5, EXTRUSION_MULTIPLIER=1, RETRACT_CC=1",
            "N10 def bool FLAG ; a flag",
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
            "ENDIF X1",
            "X1 ENDIF",
            "IF(1)",
            "TRANS X10",
            "CR25",
            "SETINT",
            "APR 7",
            "GOTOF END",
            "X=A(B(1))",
            "X=A (1)",
            "X=A(1):",
            "A(1):B(2)",
            "X=2+",
            "X=2 DIV 3",
            "DEF INT X",
            "DEF INT IF",
            "DEF INT APR 7",
            "DEF INT AB X1",
            "DEF INT AB=(1,2)",
            "DEF STRING[8] TAG",
            "DEF INT AB==1",
            "X1 DEF INT AB",
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
            "(N1 ?|:2 )?((ELSE|endif|LOOP|ENDLOOPX|IF|TRANS|ATRANS|APR|CR2|RND|CHF1|SETINT|GOTOF|WHEN|CALL|DEF|REPEAT|PROC|CASE|SUPA|\\$A|_B)(\\(( ?(-?[0-9.]{1,2}|X|\"A\"|A\\[1\\])? ?,?){0,3}\\)(:[A-Z]{1,2}\\([0-9]?\\))?)? ?(=|:)? ?){1,3}( ?;[A-Z ]*)?",
            "[A-Z$_]{1,3}=[A-Z]{1,2}\\(([0-9X, .\"-]|\\(|\\)){0,8}\\)(:[A-Z]{0,2}\\(?[0-9X,]{0,3}\\)?){0,3}",
            "[XN]1? ?= ?(-?[0-9.]{1,2}|A|\"B\"|F\\(1\\)|OR|\\() ?([-+*/:=<>]{1,2} ?(-?[0-9.]{1,2}|A|\"B\"|F\\(1\\)|OR|\\(|) ?){0,3}( X1| ;)?",
            "(N1 )?(DEF|def|REDEF|DEF ) ?(INT|REAL|STRING|NCK|APR|STRING\\[2\\]) ?(([A-Z$_]{1,3}|IF|APR|SYNR|TO)(\\[2\\])? ?(=|==)? ?(-?[0-9.]{0,2}|\\(1,2\\)|A\\+1|\"\")? ?,? ?){1,3}( X1| ;)?",
        ]) {
            if reads_clean(text.as_bytes()) {
                proptest::prop_assert!(parses_clean(&text), "{:?}", text);
            }
        }
    }
}
