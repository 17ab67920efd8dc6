//! Token recognizers written with nom: blanks, names, numbers, strings.
//!
//! They work on bytes (files are often Latin-1) through [`Input`], which
//! carries the file offset, so every token gets a file span without
//! allocating. They do not decide what a token means.

use nom::bytes::complete::{take_while, take_while1};
use nom::error::{ErrorKind, ParseError};
use nom::{Err, IResult, Input as _, Parser};

use crate::span::Span;
use crate::syntax::tree::{Name, Number, NumberKind};

pub use crate::syntax::input::Input;

pub type PResult<'a, T> = IResult<Input<'a>, T, SyntaxError>;

/// Why the parser stopped, and where.
#[derive(Clone, Debug, PartialEq)]
pub struct SyntaxError {
    pub at: usize,
    pub kind: SyntaxErrorKind,
    /// A keyword the block's first word looks like, and that word's span:
    /// `IFF R1==1` was meant as `IF`.
    pub meant: Option<(&'static str, Span)>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum SyntaxErrorKind {
    /// Something else was expected here; the text says what.
    Expected(&'static str),
    UnclosedString,
    /// The `(` or `[` at `at` has no partner on this line.
    UnclosedBracket(u8),
    /// A `)` or `]` without an opening partner.
    UnmatchedClose(u8),
    InvalidNumber(&'static str),
    UnknownCharacter,
    /// An address letter without a value, `X` alone.
    MissingValue,
    /// Parentheses or operators nested deeper than the parser follows.
    TooDeep,
    /// More operators in a row than the parser follows (`1+1+...+1`).
    ChainTooLong,
    /// A line longer than the parser reads into a tree ([`crate::syntax::MAX_PARSED_LINE`]).
    TooLong,
    /// A statement after one that ends its block: `ELSE invalid`.
    Trailing {
        /// What ends the block: `ELSE`, `a jump`, ...
        after: &'static str,
        help: &'static str,
    },
    /// A statement that stands alone in its block, after others: `X10 ENDIF`.
    NotAlone(&'static str),
    /// A sign before a string: `-"String 1"`.
    SignedString,
    /// Arguments after the program an indirect call names: `CALL _PNAME(10,20)`;
    /// the keyword (`CALL`, `ISOCALL`).
    IndirectCallArguments(&'static str),
    /// A character a program's name cannot hold, in a header `%_N_..._SPF`.
    NotInProgramName,
}

impl SyntaxError {
    pub fn new(at: usize, kind: SyntaxErrorKind) -> Self {
        Self {
            at,
            kind,
            meant: None,
        }
    }

    /// A recoverable error at `input` (another alternative may still match).
    pub fn at<T>(input: &Input, kind: SyntaxErrorKind) -> Result<T, Err<SyntaxError>> {
        Err(Err::Error(SyntaxError::new(offset(input), kind)))
    }

    /// A committed error at `at`: the construct is known, and it is broken.
    pub fn fail<T>(at: usize, kind: SyntaxErrorKind) -> Result<T, Err<SyntaxError>> {
        Err(Err::Failure(SyntaxError::new(at, kind)))
    }
}

impl<'a> ParseError<Input<'a>> for SyntaxError {
    fn from_error_kind(input: Input<'a>, _kind: ErrorKind) -> Self {
        SyntaxError::new(offset(&input), SyntaxErrorKind::Expected("something else"))
    }

    fn append(_input: Input<'a>, _kind: ErrorKind, other: Self) -> Self {
        other
    }

    /// Of two failed alternatives, report the one that got further.
    fn or(self, other: Self) -> Self {
        if other.at >= self.at {
            other
        } else {
            self
        }
    }
}

/// The absolute file offset of `input`.
pub fn offset(input: &Input) -> usize {
    input.offset()
}

/// The span from `start` up to (not including) where `end` begins.
pub fn span_between(start: &Input, end: &Input) -> Span {
    Span::new(offset(start), offset(end))
}

pub fn peek(input: &Input) -> Option<u8> {
    input.fragment().first().copied()
}

pub fn peek_at(input: &Input, n: usize) -> Option<u8> {
    input.fragment().get(n).copied()
}

/// Blanks separate words: space, tab, `&` and other non-printing bytes, which
/// the control treats like a blank (Siemens PM, "Character set").
pub const fn is_blank(byte: u8) -> bool {
    matches!(byte, b' ' | b'\t' | b'&' | 0x7f) || (byte < 0x20 && byte != b'\n' && byte != b'\r')
}

pub fn is_name_start(byte: u8) -> bool {
    byte.is_ascii_alphabetic() || byte == b'_'
}

pub fn is_name_char(byte: u8) -> bool {
    byte.is_ascii_alphanumeric() || byte == b'_'
}

/// `blank := (' ' | TAB | '&' | control)*`
pub fn parse_blank(input: Input) -> Input {
    let len = input
        .fragment()
        .iter()
        .take_while(|&&b| is_blank(b))
        .count();
    input.take_from(len)
}

/// Consumes one expected byte after optional blanks.
pub fn symbol(byte: u8) -> impl Fn(Input) -> PResult<Input> {
    move |input| {
        let rest = parse_blank(input);
        if peek(&rest) == Some(byte) {
            Ok(rest.take_split(1))
        } else {
            SyntaxError::at(&rest, SyntaxErrorKind::Expected("another character"))
        }
    }
}

/// Words of the language that name nothing else: the control keywords,
/// the operators, the data types and the frame statements (Siemens,
/// Fundamentals, "Reserved words"). A variable cannot take one as its name.
pub const RESERVED: &[&str] = &[
    "IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR", "TO", "ENDFOR", "LOOP", "ENDLOOP", "REPEAT",
    "REPEATB", "UNTIL", "CASE", "OF", "DEFAULT", "GOTO", "GOTOF", "GOTOB", "GOTOC", "GOTOS", "DEF",
    "REDEF", "PROC", "EXTERN", "DEFINE", "AS", "RET", "DO", "WHEN", "WHENEVER", "FROM", "EVERY",
    "AND", "OR", "XOR", "NOT", "B_AND", "B_OR", "B_XOR", "B_NOT", "DIV", "MOD", "INT", "REAL",
    "BOOL", "CHAR", "STRING", "AXIS", "FRAME", "TRANS", "ATRANS", "ROT", "AROT", "ROTS", "AROTS",
    "CROTS", "SCALE", "ASCALE", "MIRROR", "AMIRROR", "CALL", "PCALL", "MCALL", "EXTCALL",
    "ISOCALL",
];

/// Whether `text` is one of `words` (any case).
pub fn is_one_of(text: &[u8], words: &[&str]) -> bool {
    words
        .iter()
        .any(|w| w.as_bytes().eq_ignore_ascii_case(text))
}

// Inlined: every keyword test calls it as well.
/// `name := '$'* (letter | '_') (letter | digit | '_')*`
#[inline]
pub fn parse_name(input: Input) -> PResult<Name> {
    let start = input;
    let (input, _) = take_while(|b| b == b'$').parse(input)?;
    if !peek(&input).is_some_and(is_name_start) {
        return SyntaxError::at(&input, SyntaxErrorKind::Expected("a name"));
    }
    let (input, _) = take_while1(is_name_char).parse(input)?;
    Ok((
        input,
        Name {
            span: span_between(&start, &input),
        },
    ))
}

/// Where `needle` first occurs in `haystack`, in any case (NC ignores case; without an
/// upper-case copy of the text).
pub fn find_ignoring_case(haystack: &[u8], needle: &[u8]) -> Option<usize> {
    let first = *needle.first()?;
    memchr::memchr2_iter(
        first.to_ascii_uppercase(),
        first.to_ascii_lowercase(),
        haystack,
    )
    .find(|&at| {
        haystack
            .get(at..at + needle.len())
            .is_some_and(|found| found.eq_ignore_ascii_case(needle))
    })
}

/// A whole word that equals `keyword`, case-insensitively.
pub fn keyword<'a>(word: &'static str) -> impl Fn(Input<'a>) -> PResult<'a, Name> {
    move |input| {
        let (rest, name) = parse_name(input)?;
        if input.fragment()[..name.span.len()].eq_ignore_ascii_case(word.as_bytes()) {
            Ok((rest, name))
        } else {
            SyntaxError::at(&input, SyntaxErrorKind::Expected(word))
        }
    }
}

/// `number := decimal | "'H" hex+ "'" | "'B" ('0'|'1')+ "'"`
/// `decimal := (digit+ ('.' digit*)? | '.' digit+) ('EX' ('+'|'-')? digit+)?`
#[inline]
pub fn parse_number(input: Input) -> PResult<Number> {
    match peek(&input) {
        Some(b'\'') => parse_radix_number(input),
        Some(b'0'..=b'9' | b'.') => parse_decimal(input),
        _ => SyntaxError::at(&input, SyntaxErrorKind::Expected("a number")),
    }
}

fn parse_decimal(input: Input) -> PResult<Number> {
    let start = input;
    let bytes = input.fragment();
    // The digits before and after the point, keeping the value while it is
    // exact (at most 19 digits; more wrap, and take the general parser).
    let mut mantissa: u64 = 0;
    let mut len = 0;
    let mut digits = |len: &mut usize| {
        while let Some(&byte @ b'0'..=b'9') = bytes.get(*len) {
            mantissa = mantissa
                .wrapping_mul(10)
                .wrapping_add(u64::from(byte - b'0'));
            *len += 1;
        }
    };
    digits(&mut len);
    let point = (bytes.get(len) == Some(&b'.')).then_some(len);
    if point.is_some() {
        len += 1;
        digits(&mut len);
    }
    let digit_count = len - usize::from(point.is_some());
    if digit_count == 0 {
        return SyntaxError::at(&input, SyntaxErrorKind::Expected("a number"));
    }
    let mantissa_len = len;
    let mut exponent = None;
    // Most numbers end at a blank, a comma or a bracket: one byte tells.
    let e_follows = matches!(bytes.get(len), Some(b'E' | b'e'));
    if e_follows && matches!(bytes.get(len + 1), Some(b'X' | b'x')) {
        let mut at = len + 2;
        if matches!(bytes.get(at), Some(b'+' | b'-')) {
            at += 1;
        }
        let digits = bytes[at..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count();
        if digits == 0 {
            return SyntaxError::fail(
                offset(&start),
                SyntaxErrorKind::InvalidNumber(
                    "`EX` must be followed by the exponent's digits, as in `1.5EX3`",
                ),
            );
        }
        exponent = Some(&bytes[len + 2..at + digits]);
        len = at + digits;
    }
    if bytes.get(len) == Some(&b'.') {
        return SyntaxError::fail(
            offset(&start),
            SyntaxErrorKind::InvalidNumber("a number has at most one decimal point"),
        );
    }
    let decimals = point.map_or(0, |p| mantissa_len - p - 1);
    let value = match exact_decimal(mantissa, digit_count, decimals) {
        Some(value) if exponent.is_none() => value,
        _ => decimal_value(&bytes[..mantissa_len], exponent),
    };
    let (rest, _) = input.take_split(len);
    let span = span_between(&start, &rest);
    if !value.is_finite() {
        return SyntaxError::fail(
            span.start,
            SyntaxErrorKind::InvalidNumber(
                "the number is too large for a REAL (at most about 1.8EX308)",
            ),
        );
    }
    Ok((
        rest,
        Number {
            span,
            value,
            kind: NumberKind::Decimal,
        },
    ))
}

/// The value of digits (one `.` allowed) and an optional `EX` exponent, by
/// the standard library's correctly rounded parser.
fn decimal_value(mantissa: &[u8], exponent: Option<&[u8]>) -> f64 {
    let mut text = String::with_capacity(mantissa.len() + 8);
    text.extend(mantissa.iter().map(|&b| b as char));
    if text.ends_with('.') {
        text.push('0');
    }
    if let Some(exponent) = exponent {
        text.push('e');
        text.extend(exponent.iter().map(|&b| b as char));
    }
    // Only digits, one '.', and 'e' with an optional sign reach here, so the
    // parse cannot fail; an exponent beyond i32 parses to inf or 0.
    text.parse().unwrap_or(f64::NAN)
}

/// Powers of ten that f64 holds exactly.
const EXACT_POWERS_OF_TEN: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// `mantissa / 10^decimals` when it can be computed exactly: a mantissa of at
/// most 15 digits is an exact integer, 10^k for k <= 22 is exact, and one
/// IEEE division is correctly rounded (Clinger's fast path). CNC numbers
/// nearly always qualify; others (leading zeros counted) take the general
/// parser, which rounds the same.
fn exact_decimal(mantissa: u64, digits: usize, decimals: usize) -> Option<f64> {
    if digits > 15 {
        return None;
    }
    Some(mantissa as f64 / *EXACT_POWERS_OF_TEN.get(decimals)?)
}

fn parse_radix_number(input: Input) -> PResult<Number> {
    let start = input;
    let bytes = input.fragment();
    let (kind, radix) = match bytes.get(1).map(u8::to_ascii_uppercase) {
        Some(b'H') => (NumberKind::Hex, 16),
        Some(b'B') => (NumberKind::Binary, 2),
        _ => {
            return SyntaxError::fail(
                offset(&input),
                SyntaxErrorKind::InvalidNumber(
                    "a quoted number is hexadecimal `'H1F'` or binary `'B101'`",
                ),
            )
        }
    };
    let digits = bytes[2..]
        .iter()
        .take_while(|b| b.is_ascii_alphanumeric())
        .count();
    let text = &bytes[2..2 + digits];
    if bytes.get(2 + digits) != Some(&b'\'') {
        return SyntaxError::fail(
            offset(&input),
            SyntaxErrorKind::InvalidNumber("a quoted number ends with `'`"),
        );
    }
    let value = std::str::from_utf8(text)
        .ok()
        .filter(|t| !t.is_empty())
        .and_then(|t| u64::from_str_radix(t, radix).ok());
    let Some(value) = value else {
        return SyntaxError::fail(
            offset(&input),
            SyntaxErrorKind::InvalidNumber(if radix == 16 {
                "`'H` takes hexadecimal digits 0-9 and A-F"
            } else {
                "`'B` takes binary digits 0 and 1"
            }),
        );
    };
    let (rest, _) = input.take_split(3 + digits);
    Ok((
        rest,
        Number {
            span: span_between(&start, &rest),
            value: value as f64,
            kind,
        },
    ))
}

/// `string := '"' (any byte but '"')* '"'`: strings may not span lines.
pub fn parse_string(input: Input) -> PResult<Span> {
    if peek(&input) != Some(b'"') {
        return SyntaxError::at(&input, SyntaxErrorKind::Expected("a string"));
    }
    match memchr::memchr(b'"', &input.fragment()[1..]) {
        Some(end) => {
            let (rest, _) = input.take_split(end + 2);
            Ok((rest, span_between(&input, &rest)))
        }
        None => SyntaxError::fail(offset(&input), SyntaxErrorKind::UnclosedString),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(text: &str) -> Input<'_> {
        Input::new(text.as_bytes(), 0)
    }

    fn number(text: &str) -> f64 {
        parse_number(input(text))
            .map(|(_, n)| n.value)
            .unwrap_or(f64::NAN)
    }

    #[test]
    fn numbers_in_every_spelling() {
        assert_eq!(number("1"), 1.0);
        assert_eq!(number("1."), 1.0);
        assert_eq!(number(".5"), 0.5);
        assert_eq!(number("1.5EX3"), 1500.0);
        assert_eq!(number("10ex-5"), 1e-4);
        assert_eq!(number("'H1F'"), 31.0);
        assert_eq!(number("'b101'"), 5.0);
    }

    #[test]
    fn the_exact_fast_path_agrees_with_the_general_parser() {
        for text in [
            "0",
            "1.",
            ".5",
            "12.25",
            "498.375",
            "-0.009",
            "0.1",
            "0.000000000000000000001",
            "123456789012345",
            "1234567890123456",
            "3.141592653589793",
            "0.30000000000000004",
            "00012.5000",
        ] {
            let digits = text.trim_start_matches('-');
            let expected: f64 = format!(
                "{}{}",
                if digits.starts_with('.') { "0" } else { "" },
                digits
            )
            .trim_end_matches('.')
            .parse()
            .expect("valid");
            assert_eq!(number(digits), expected, "{text}");
            assert_eq!(decimal_value(digits.as_bytes(), None), expected, "{text}");
        }
    }

    proptest::proptest! {
        /// Every digit string, with or without a point, reads as the
        /// standard library reads it.
        #[test]
        fn numbers_read_as_the_standard_library_reads_them(
            integer in "[0-9]{0,20}",
            fraction in proptest::option::of("[0-9]{0,25}"),
        ) {
            let text = match &fraction {
                Some(fraction) => format!("{integer}.{fraction}"),
                None => integer.clone(),
            };
            proptest::prop_assume!(text != "." && !text.is_empty());
            // Leading and (after a point) trailing zeros change nothing.
            let padding = if fraction.is_some() { "0" } else { "" };
            let expected: f64 = format!("0{text}{padding}").parse().expect("valid");
            proptest::prop_assert_eq!(number(&text), expected);
        }
    }

    #[test]
    fn bad_numbers_are_committed_errors() {
        for bad in ["1.2.3", "1EX", "'H1G'", "'B102'", "'X1'", "1EX99999"] {
            assert!(
                matches!(parse_number(input(bad)), Err(Err::Failure(_))),
                "{bad}"
            );
        }
    }

    #[test]
    fn text_is_found_in_any_case() {
        assert_eq!(find_ignoring_case(b"R1=2 sNp_A=1", b"SNP_"), Some(5));
        assert_eq!(find_ignoring_case(b"S100 SNP", b"SNP_"), None);
        assert_eq!(find_ignoring_case(b"SNP_", b"SNP_"), Some(0));
        assert_eq!(find_ignoring_case(b"", b"SNP_"), None);
    }

    #[test]
    fn names_and_keywords() {
        let (rest, name) = parse_name(input("$AA_IW[Z]")).expect("name");
        assert_eq!(name.span, Span::new(0, 6));
        assert_eq!(rest.fragment(), b"[Z]");
        assert!(keyword("GOTOF")(input("gotof x")).is_ok());
        assert!(keyword("GOTO")(input("GOTOF x")).is_err());
    }

    #[test]
    fn strings_do_not_span_lines() {
        assert!(parse_string(input("\"abc\" x")).is_ok());
        assert!(matches!(parse_string(input("\"abc")), Err(Err::Failure(_))));
    }
}
