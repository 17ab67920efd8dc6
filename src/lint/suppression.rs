//! `; sinuprep: ignore CODE[,CODE...]` on a block and
//! `; sinuprep: ignore-file CODE[,CODE...]` anywhere: findings they cover
//! are dropped, and a suppression that covers nothing is reported (N099).

use crate::diagnostic::Diagnostic;
use crate::lint::rules::unused_suppression;
use crate::span::Span;

struct Suppression {
    /// The line it applies to; `None` for the whole file.
    row: Option<usize>,
    code: String,
    span: Span,
    used: bool,
}

#[derive(Default)]
pub struct Suppressions {
    list: Vec<Suppression>,
}

impl Suppressions {
    /// Reads the suppressions of a comment on line `row` at `comment`.
    pub fn read(&mut self, source: &[u8], row: usize, comment: Span) {
        let text = String::from_utf8_lossy(comment.of(source));
        let Some(at) = text.find("sinuprep:") else {
            return;
        };
        let rest = text[at + "sinuprep:".len()..].trim_start();
        let (row, codes) = if let Some(codes) = rest.strip_prefix("ignore-file") {
            (None, codes)
        } else if let Some(codes) = rest.strip_prefix("ignore") {
            (Some(row), codes)
        } else {
            return;
        };
        for code in codes
            .split([',', ' ', '\t'])
            .map(str::trim)
            .filter(|c| !c.is_empty())
        {
            let offset = comment.start + at + text[at..].find(code).unwrap_or(0);
            self.list.push(Suppression {
                row,
                code: code.to_ascii_uppercase(),
                span: Span::new(offset, offset + code.len()),
                used: false,
            });
        }
    }

    /// Whether `diagnostic` on line `row` is suppressed (and marks the suppression used).
    pub fn covers(&mut self, diagnostic: &Diagnostic, row: usize) -> bool {
        let mut covered = false;
        for suppression in &mut self.list {
            if suppression.code == diagnostic.code && suppression.row.map_or(true, |r| r == row) {
                suppression.used = true;
                covered = true;
            }
        }
        covered
    }

    /// N099 for every suppression of an enabled rule that covered nothing
    /// (one for a rule not checked now may well be needed).
    pub fn unused<'a>(
        &'a self,
        enabled: impl Fn(&str) -> bool + 'a,
    ) -> impl Iterator<Item = Diagnostic> + 'a {
        self.list
            .iter()
            .filter(move |s| !s.used && enabled(&s.code))
            .map(|s| {
                unused_suppression::RULE
                    .at(s.span)
                    .message(format!(
                        "`; sinuprep: ignore {}` suppresses nothing here",
                        s.code
                    ))
                    .label("nothing to suppress")
                    .help("remove it")
            })
    }
}
