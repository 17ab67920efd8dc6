//! The protocol's types from the library's and back: positions in the unit
//! the client and server agreed on, `file:` URIs and paths, diagnostics,
//! semantic tokens.

use std::path::{Path, PathBuf};

use lsp_types as lsp;

use crate::diagnostic::{Diagnostic, Severity};
use crate::document::text::Text;
use crate::semantic::highlight::{Class, Token};
use crate::span::{ColumnUnit, Position, Span};

/// How the client counts a line's characters: UTF-8 bytes when it offers
/// them (no conversion at all), else the protocol's default, UTF-16 units.
pub fn encoding(client: &lsp::ClientCapabilities) -> (lsp::PositionEncodingKind, ColumnUnit) {
    let offered = client
        .general
        .as_ref()
        .and_then(|general| general.position_encodings.as_deref())
        .unwrap_or_default();
    if offered.contains(&lsp::PositionEncodingKind::UTF8) {
        (lsp::PositionEncodingKind::UTF8, ColumnUnit::Bytes)
    } else {
        (lsp::PositionEncodingKind::UTF16, ColumnUnit::Utf16)
    }
}

/// The byte offset of a client's position (clamped to the text).
pub fn offset(text: &Text, position: lsp::Position, unit: ColumnUnit) -> usize {
    let position = Position {
        row: position.line as usize + 1,
        column: position.character as usize + 1,
    };
    text.offset(position, unit)
}

pub fn position(text: &Text, offset: usize, unit: ColumnUnit) -> lsp::Position {
    let Position { row, column } = text.position(offset, unit);
    lsp::Position::new(saturate(row - 1), saturate(column - 1))
}

pub fn range(text: &Text, span: Span, unit: ColumnUnit) -> lsp::Range {
    lsp::Range::new(
        position(text, span.start, unit),
        position(text, span.end, unit),
    )
}

/// The byte range of a client's range, its ends in order.
pub fn span(text: &Text, range: lsp::Range, unit: ColumnUnit) -> Span {
    let (a, b) = (
        offset(text, range.start, unit),
        offset(text, range.end, unit),
    );
    Span::new(a.min(b), a.max(b))
}

fn saturate(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// A finding of the document at `uri`, its related place in the same one.
pub fn diagnostic(
    text: &Text,
    uri: &lsp::Uri,
    found: &Diagnostic,
    unit: ColumnUnit,
) -> lsp::Diagnostic {
    let severity = match found.severity {
        Severity::Error => lsp::DiagnosticSeverity::ERROR,
        Severity::Warning => lsp::DiagnosticSeverity::WARNING,
        Severity::Info => lsp::DiagnosticSeverity::INFORMATION,
    };
    let mut message = found.message.clone();
    if let Some(help) = &found.help {
        message.push_str("\nhelp: ");
        message.push_str(help);
    }
    lsp::Diagnostic {
        range: range(text, found.span, unit),
        severity: Some(severity),
        code: Some(lsp::NumberOrString::String(found.code().to_string())),
        code_description: super::rule_pages::link(found.code())
            .map(|href| lsp::CodeDescription { href }),
        source: Some("sinuprep".to_string()),
        message,
        related_information: found.related.as_ref().map(|related| {
            vec![lsp::DiagnosticRelatedInformation {
                location: lsp::Location::new(uri.clone(), range(text, related.span, unit)),
                message: related.message.clone(),
            }]
        }),
        ..lsp::Diagnostic::default()
    }
}

/// The token types and modifiers the server colours with, in the order
/// [`token_type`] numbers them.
pub fn legend() -> lsp::SemanticTokensLegend {
    use lsp::SemanticTokenType as T;
    lsp::SemanticTokensLegend {
        token_types: vec![
            T::COMMENT,
            T::STRING,
            T::NUMBER,
            T::KEYWORD,
            T::PROPERTY,
            T::VARIABLE,
            T::FUNCTION,
            // VS Code's own type for labels; other clients take it as a name.
            T::new("label"),
            T::MACRO,
            T::NAMESPACE,
        ],
        token_modifiers: vec![lsp::SemanticTokenModifier::DEFAULT_LIBRARY],
    }
}

/// A class's type in [`legend`], and its modifier bits.
pub fn token_type(class: Class) -> (u32, u32) {
    match class {
        Class::Comment => (0, 0),
        Class::String => (1, 0),
        Class::Number => (2, 0),
        Class::Keyword => (3, 0),
        Class::Address => (4, 0),
        Class::Variable => (5, 0),
        // The control's own: `defaultLibrary`.
        Class::SystemVariable => (5, 1),
        Class::Function => (6, 0),
        Class::Label => (7, 0),
        Class::Macro => (8, 0),
        Class::Header => (9, 0),
    }
}

/// Tokens as the protocol sends them: each from the one before, in lines
/// and in columns of `unit` (a token lies within one line).
pub fn semantic_tokens(text: &Text, tokens: &[Token], unit: ColumnUnit) -> Vec<lsp::SemanticToken> {
    let mut out = Vec::with_capacity(tokens.len());
    let (mut line, mut character) = (0, 0);
    for token in tokens {
        let start = position(text, token.span.start, unit);
        let end = position(text, token.span.end, unit);
        if end.line != start.line || end.character <= start.character {
            continue;
        }
        let (token_type, token_modifiers_bitset) = token_type(token.class);
        out.push(lsp::SemanticToken {
            delta_line: start.line - line,
            delta_start: match start.line == line {
                true => start.character - character,
                false => start.character,
            },
            length: end.character - start.character,
            token_type,
            token_modifiers_bitset,
        });
        (line, character) = (start.line, start.character);
    }
    out
}

/// The `file:` URI of an absolute path (`None` for a relative one), as
/// the client is told of another file of the workspace.
pub fn uri(path: &Path) -> Option<lsp::Uri> {
    crate::uri::file_uri(path)?.parse().ok()
}

/// The file a `file:` URI names; `None` for another scheme (an unsaved
/// buffer), which is checked with the default settings.
pub fn path(uri: &lsp::Uri) -> Option<PathBuf> {
    let rest = uri.as_str().strip_prefix("file://")?;
    // `file:///C:/...` on Windows; `file://server/share/...` is a UNC path.
    let rest = match rest.strip_prefix('/') {
        Some(path) if cfg!(windows) && path.as_bytes().get(1) == Some(&b':') => path.to_string(),
        Some(path) => format!("/{path}"),
        None if cfg!(windows) => format!("//{rest}"),
        None => return None,
    };
    let decoded = percent_decode(rest.as_bytes())?;
    #[cfg(unix)]
    {
        use std::os::unix::ffi::OsStringExt;
        Some(PathBuf::from(std::ffi::OsString::from_vec(decoded)))
    }
    #[cfg(not(unix))]
    {
        String::from_utf8(decoded).ok().map(PathBuf::from)
    }
}

fn percent_decode(bytes: &[u8]) -> Option<Vec<u8>> {
    let mut out = Vec::with_capacity(bytes.len());
    let mut at = 0;
    while at < bytes.len() {
        if bytes[at] == b'%' {
            let hex = std::str::from_utf8(bytes.get(at + 1..at + 3)?).ok()?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            at += 3;
        } else {
            out.push(bytes[at]);
            at += 1;
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::str::FromStr;

    #[test]
    fn a_file_uri_names_its_path() {
        let uri = lsp::Uri::from_str("file:///home/cam/K%C3%BChl%20PART.MPF").expect("uri");
        if cfg!(unix) {
            assert_eq!(path(&uri), Some(PathBuf::from("/home/cam/Kühl PART.MPF")));
        }
        let untitled = lsp::Uri::from_str("untitled:Untitled-1").expect("uri");
        assert_eq!(path(&untitled), None);
    }

    #[test]
    fn positions_go_both_ways_in_the_agreed_unit() {
        let text = Text::new("; ü😀\nG1 X1\n".as_bytes().to_vec());
        let x = "; ü😀\nG1 ".len();
        for unit in [ColumnUnit::Utf16, ColumnUnit::Bytes] {
            let at = position(&text, x, unit);
            assert_eq!(at.line, 1);
            assert_eq!(offset(&text, at, unit), x);
        }
        let end = position(&text, "; ü😀".len(), ColumnUnit::Utf16);
        assert_eq!(end, lsp::Position::new(0, 5));
        // A position past the end is the end.
        assert_eq!(
            offset(&text, lsp::Position::new(99, 0), ColumnUnit::Utf16),
            text.bytes().len()
        );
    }
}
