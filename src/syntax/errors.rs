//! A syntax error as the user reads it: the parser's stop turned into a
//! diagnostic at the offending bytes, with what was expected, what was found
//! and how to fix it.

use crate::diagnostic::{Applicability, Diagnostic, Fix};
use crate::registry;
use crate::span::Span;
use crate::syntax::expr;
use crate::syntax::lexer::{self, SyntaxError, SyntaxErrorKind};
use crate::syntax::lines::RawLine;

/// The UTF-8 byte-order mark, U+FEFF.
const BYTE_ORDER_MARK: &[u8] = b"\xEF\xBB\xBF";

/// Turns the parser's stop into a diagnostic at the offending bytes.
pub(crate) fn to_diagnostic(source: &[u8], raw: RawLine, error: &SyntaxError) -> Diagnostic {
    let diagnostic = describe(source, raw, error);
    match error.meant {
        Some((keyword, word)) => diagnostic
            .help(format!(
                "did you mean `{keyword}`? The block's first word is no keyword, so it reads as a subprogram call"
            ))
            .fix(Fix::replace(
                format!("write `{keyword}`"),
                Applicability::Unsafe,
                word,
                keyword,
            )),
        None => diagnostic,
    }
}

fn describe(source: &[u8], raw: RawLine, error: &SyntaxError) -> Diagnostic {
    let at = error.at.min(raw.content.end);
    let line_end = raw.content.end;
    let one = Span::new(at, (at + 1).min(line_end).max(at));
    let rest = Span::new(at, line_end);
    let show = |span: Span| String::from_utf8_lossy(span.of(source)).into_owned();
    match &error.kind {
        SyntaxErrorKind::UnclosedString => {
            registry::syntax::UNCLOSED_STRING.at(rest)
                .message("string is not closed on this line")
                .label("this string has no closing `\"`")
                .help("add the closing `\"`; strings cannot span lines")
        }
        SyntaxErrorKind::UnclosedBracket(open) => {
            let (open, close) = (*open as char, if *open == b'(' { ')' } else { ']' });
            let help = if is_call_paren(source, raw.content.start, at) {
                format!("add the missing `{close}`; a call broken over several lines (as the paper prints CYCLE600) must be joined into one line")
            } else {
                format!("add the missing `{close}`")
            };
            registry::syntax::UNBALANCED_BRACKET.at(one)
                .message(format!("`{open}` is not closed on this line"))
                .label(format!("this `{open}` has no matching `{close}`"))
                .help(help)
        }
        SyntaxErrorKind::UnmatchedClose(close) => {
            let close = *close as char;
            registry::syntax::UNBALANCED_BRACKET.at(one)
                .message(format!("`{close}` without a matching opening bracket"))
                .label("nothing to close here")
                .help(format!(
                    "remove this `{close}` or add the opening bracket it closes"
                ))
        }
        SyntaxErrorKind::InvalidNumber(why) => registry::syntax::INVALID_NUMBER.at(number_span(source, at, line_end),
        )
        .message(format!(
            "invalid number `{}`",
            show(number_span(source, at, line_end))
        ))
        .label("not a number")
        .help(why.to_string()),
        // Notepad and other Windows editors write it when saving as UTF-8;
        // the control reads it as three characters of its code page.
        SyntaxErrorKind::UnknownCharacter if at == 0 && source.starts_with(BYTE_ORDER_MARK) => {
            let mark = Span::new(0, BYTE_ORDER_MARK.len());
            registry::syntax::UNKNOWN_CHARACTER.at(mark)
                .message("byte-order mark U+FEFF at the start of the file, which the control does not read as part of a program")
                .label("byte-order mark")
                .help("save the file as UTF-8 without BOM (Notepad++: Encoding > UTF-8), or let --fix remove it")
                .fix(Fix::replace(
                    "remove the byte-order mark",
                    Applicability::Safe,
                    mark,
                    "",
                ))
        }
        SyntaxErrorKind::UnknownCharacter => {
            let help = match source.get(at) {
                Some(b'^') => {
                    "Sinumerik has no power operator: write POT(x) for x², or EXP(y*LN(x))"
                }
                Some(b'!') => "write `<>` for not equal and NOT for negation",
                _ => "remove it, or put it in a comment after `;` or inside a string",
            };
            registry::syntax::UNKNOWN_CHARACTER.at(char_span(source, at, line_end),
            )
            .message(format!(
                "character {} has no meaning here",
                describe_char(source, at, line_end)
            ))
            .label("unknown character")
            .help(help)
        }
        SyntaxErrorKind::MissingValue => registry::syntax::MISSING_VALUE.at(one,
        )
        .message(format!("address `{}` has no value", show(one)))
        .label("value missing")
        .help("write the value directly after the address (`X0`, not `X`) or as `X=expression`"),
        SyntaxErrorKind::ChainTooLong => {
            registry::syntax::NESTING_TOO_DEEP.at(one)
                .message(format!(
                    "more than {} operators in a row in one expression",
                    expr::MAX_DEPTH
                ))
                .label("too many operators")
                .help("split the expression over several assignments (a block takes 512 characters on the control)")
        }
        SyntaxErrorKind::TooDeep => {
            registry::syntax::NESTING_TOO_DEEP.at(one)
                .message(format!(
                    "expression nested deeper than {} levels",
                    expr::MAX_DEPTH
                ))
                .label("too deep")
                .help("split the expression over several assignments")
        }
        SyntaxErrorKind::TooLong => {
            registry::syntax::TOO_LONG_TO_READ.at(one)
                .message(format!(
                    "block of {} bytes: too long to read (the control takes at most 512 characters a block)",
                    raw.content.len()
                ))
                .label("too long")
                .help("split it into blocks of at most 512 characters")
        }
        SyntaxErrorKind::Trailing { after, help } => {
            registry::syntax::UNEXPECTED_TOKEN.at(word_span(source, at, line_end))
                .message(format!(
                    "unexpected `{}` after {after}",
                    show_token(source, at, line_end)
                ))
                .label(format!("nothing may follow {after} in its block"))
                .help(*help)
        }
        SyntaxErrorKind::NotAlone(what) => {
            registry::syntax::UNEXPECTED_TOKEN.at(word_span(source, at, line_end))
                .message(format!("{what} must stand alone in its block"))
                .label("after other statements")
                .help("move the statements before it into a block of their own")
        }
        SyntaxErrorKind::SignedString => registry::syntax::UNEXPECTED_TOKEN
            .at(one)
            .message(format!("`{}` before a string: a string has no sign", show(one)))
            .label("a sign needs a number")
            .help("remove the sign; NUMBER(\"...\") reads a number from a string"),
        SyntaxErrorKind::IndirectCallArguments(keyword) => registry::syntax::UNEXPECTED_TOKEN
            .at(Span::new(at, close_of(source, at, line_end)))
            .message(format!(
                "{keyword} names the program to run and takes no arguments"
            ))
            .label("arguments of an indirect call")
            .help("call the program by its name with the arguments (`NAME(10,20)`), or with PCALL and its path (`PCALL /_N_SPF_DIR/NAME(10,20)`)"),
        SyntaxErrorKind::NotInProgramName => registry::syntax::UNEXPECTED_TOKEN
            .at(char_span(source, at, line_end))
            .message(format!(
                "character {} cannot stand in a program's name",
                describe_char(source, at, line_end)
            ))
            .label("not a letter, digit or `_`")
            .help("a program's name holds letters, digits and `_` only, in the header as `%_N_<name>_<type>` (`%_N_CYCLE_SPF`)"),
        SyntaxErrorKind::Expected(what) => {
            let found = if at >= line_end {
                "the end of the line".to_string()
            } else {
                format!("`{}`", show_token(source, at, line_end))
            };
            registry::syntax::UNEXPECTED_TOKEN.at(if at >= line_end {
                    Span::new(at, at)
                } else {
                    one
                },
            )
            .message(format!("expected {what}, found {found}"))
            .label(format!("expected {what}"))
            .help("check the statement's spelling against the Sinumerik programming manual")
        }
    }
}

/// Whether the `(` at `at` follows a name, as in `CYCLE600 (`.
fn is_call_paren(source: &[u8], line_start: usize, at: usize) -> bool {
    source[line_start..at]
        .iter()
        .rev()
        .find(|&&b| !lexer::is_blank(b))
        .is_some_and(|&b| lexer::is_name_char(b))
}

/// The bytes of a malformed number, up to the next blank or separator.
fn number_span(source: &[u8], at: usize, end: usize) -> Span {
    let len = source[at..end]
        .iter()
        .take_while(|&&b| b.is_ascii_alphanumeric() || b == b'.' || b == b'\'')
        .count();
    Span::new(at, at + len.max(1).min(end - at))
}

/// One character: a whole UTF-8 sequence when it is one, else one byte.
fn char_span(source: &[u8], at: usize, end: usize) -> Span {
    let len = (1..=4)
        .filter(|&n| at + n <= end)
        .find(|&n| std::str::from_utf8(&source[at..at + n]).is_ok())
        .unwrap_or(1);
    Span::new(at, (at + len).min(end))
}

/// Where the brackets opened at `at` close (past the `)`), strings skipped;
/// the line's end when they do not.
fn close_of(source: &[u8], at: usize, end: usize) -> usize {
    let mut depth = 0usize;
    let mut in_string = false;
    for (i, &b) in source[at..end].iter().enumerate() {
        match b {
            b'"' => in_string = !in_string,
            b'(' if !in_string => depth += 1,
            b')' if !in_string => {
                depth = depth.saturating_sub(1);
                if depth == 0 {
                    return at + i + 1;
                }
            }
            _ => {}
        }
    }
    end
}

/// The name at `at` (`$` included), or its one character.
fn word_span(source: &[u8], at: usize, end: usize) -> Span {
    let len = source[at.min(end)..end]
        .iter()
        .take_while(|&&b| lexer::is_name_char(b) || b == b'$')
        .count();
    Span::new(at, (at + len.max(1)).min(end).max(at))
}

/// A whole name if one starts at `at`, else one character.
fn show_token(source: &[u8], at: usize, end: usize) -> String {
    let len = source[at..end]
        .iter()
        .take_while(|&&b| lexer::is_name_char(b))
        .count();
    if len > 1 {
        String::from_utf8_lossy(&source[at..at + len]).into_owned()
    } else {
        show_char(source, at, end)
    }
}

/// `` `#` ``, `` `ä` (Latin-1 byte 0xE4) `` or `byte 0x01`, for messages.
fn describe_char(source: &[u8], at: usize, end: usize) -> String {
    let span = char_span(source, at, end);
    let bytes = span.of(source);
    match (std::str::from_utf8(bytes), bytes) {
        (Ok(text), _) if !text.chars().any(char::is_control) => format!("`{text}`"),
        (Err(_), &[byte]) if byte >= 0xA0 => {
            format!("`{}` (Latin-1 byte 0x{byte:02X})", byte as char)
        }
        _ => bytes
            .iter()
            .map(|b| format!("byte 0x{b:02X}"))
            .collect::<Vec<_>>()
            .join(" "),
    }
}

fn show_char(source: &[u8], at: usize, end: usize) -> String {
    let span = char_span(source, at, end);
    match std::str::from_utf8(span.of(source)) {
        Ok(text) if !text.chars().any(char::is_control) => text.to_string(),
        _ => span
            .of(source)
            .iter()
            .map(|b| format!("\\x{b:02X}"))
            .collect(),
    }
}
