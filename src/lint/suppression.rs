//! `; sinuprep: ignore CODE[,CODE...]` on a block and
//! `; sinuprep: ignore-file CODE[,CODE...]` anywhere, in any case (NC is
//! case-insensitive): findings they cover are dropped, and a suppression
//! that covers nothing is reported (N099), as is a misspelt directive
//! (`ignor`) or a code that names no rule.

use crate::diagnostic::{Applicability, Diagnostic, Fix};
use crate::lint::rules::unused_suppression;
use crate::span::Span;
use crate::syntax::lexer::find_ignoring_case;

struct Suppression {
    /// The line it applies to; `None` for the whole file.
    row: Option<usize>,
    code: String,
    span: Span,
    used: bool,
    /// Index of its directive in [`Suppressions::directives`].
    directive: usize,
}

/// One `sinuprep: ignore ...` text, for the fix that drops codes from it.
struct Directive {
    comment: Span,
    /// From `sinuprep:` to the end of its last code.
    span: Span,
    /// `ignore` or `ignore-file`.
    word: String,
    /// It names a code no rule has: no fix is offered to rewrite it.
    broken: bool,
}

#[derive(Default)]
pub struct Suppressions {
    list: Vec<Suppression>,
    directives: Vec<Directive>,
    /// Suppressions that cannot work: what is wrong, where, and the fix.
    broken: Vec<(Span, String, String)>,
}

const DIRECTIVES: [&str; 2] = ["ignore", "ignore-file"];

impl Suppressions {
    /// Reads the suppressions of a comment on line `row` at `comment`.
    /// Works on the bytes: a comment may hold any bytes (Latin-1, garbage),
    /// and the spans must be the source's own offsets.
    pub fn read(&mut self, source: &[u8], row: usize, comment: Span) {
        let text = comment.of(source);
        let Some(at) = find_ignoring_case(text, b"sinuprep:") else {
            return;
        };
        let mut position = at + b"sinuprep:".len();
        let skip_blanks = |position: &mut usize| {
            while text
                .get(*position)
                .is_some_and(|b| *b == b' ' || *b == b'\t')
            {
                *position += 1;
            }
        };
        skip_blanks(&mut position);
        let word_length = text[position..]
            .iter()
            .take_while(|b| b.is_ascii_alphabetic() || **b == b'-')
            .count();
        let word =
            String::from_utf8_lossy(&text[position..position + word_length]).to_ascii_lowercase();
        let row = match word.as_str() {
            "ignore-file" => None,
            "ignore" => Some(row),
            // Other text after `sinuprep:` (the rewrite's `; sinuprep: CYCLE600(...)`
            // marker, a remark) is no directive; one near a directive is a typo.
            _ => {
                if let Some(meant) = crate::suggest::closest(&word, &DIRECTIVES, 2) {
                    let start = comment.start + position;
                    self.broken.push((
                        Span::new(start, start + word_length),
                        format!("`{word}` is no sinuprep directive, so nothing is suppressed"),
                        format!("did you mean `{meant}`?"),
                    ));
                }
                return;
            }
        };
        position += word_length;
        let directive = self.directives.len();
        self.directives.push(Directive {
            comment,
            span: Span::new(comment.start + at, comment.start + position),
            word: word.clone(),
            broken: false,
        });
        // Codes: ASCII letters and digits, separated by commas and blanks.
        loop {
            while text
                .get(position)
                .is_some_and(|b| matches!(b, b' ' | b'\t' | b','))
            {
                position += 1;
            }
            let length = text[position..]
                .iter()
                .take_while(|b| b.is_ascii_alphanumeric())
                .count();
            if length == 0 {
                return;
            }
            let code =
                String::from_utf8_lossy(&text[position..position + length]).to_ascii_uppercase();
            let start = comment.start + position;
            if let Err(unknown) = crate::lint::codes::check(&code) {
                let help = match unknown.did_you_mean {
                    Some(code) => format!("did you mean `{code}`?"),
                    None => "`sinuprep rule --all` lists every code".to_string(),
                };
                self.broken.push((
                    Span::new(start, start + length),
                    format!("no rule has the code `{code}`, so nothing is suppressed"),
                    help,
                ));
                position += length;
                self.directives[directive].broken = true;
                self.directives[directive].span.end = start + length;
                continue;
            }
            self.list.push(Suppression {
                row,
                code,
                span: Span::new(start, start + length),
                used: false,
                directive,
            });
            position += length;
            self.directives[directive].span.end = start + length;
        }
    }

    /// Whether a suppression covers `diagnostic` on its 0-based `row` (and
    /// marks it used); the row is asked for only when a suppression names
    /// the code, since finding rows costs a pass over the file.
    pub fn covers(&mut self, diagnostic: &Diagnostic, row: impl FnOnce() -> usize) -> bool {
        if !self.list.iter().any(|s| s.code == diagnostic.code()) {
            return false;
        }
        let row = row();
        let mut covered = false;
        for suppression in &mut self.list {
            if suppression.code == diagnostic.code() && suppression.row.is_none_or(|r| r == row) {
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
        source: &'a [u8],
        enabled: impl Fn(&str) -> bool + Copy + 'a,
    ) -> impl Iterator<Item = Diagnostic> + 'a {
        let unused = self
            .list
            .iter()
            .filter(move |s| !s.used && enabled(&s.code))
            .map(move |s| {
                let diagnostic = unused_suppression::RULE
                    .at(s.span)
                    .message(format!(
                        "`; sinuprep: ignore {}` suppresses nothing here",
                        s.code
                    ))
                    .label("nothing to suppress")
                    .help("remove it");
                match self.without_unused(source, s.directive, enabled) {
                    Some(fix) => diagnostic.fix(fix),
                    None => diagnostic,
                }
            });
        let broken = self.broken.iter().map(|(span, message, help)| {
            unused_suppression::RULE
                .at(*span)
                .message(message.clone())
                .label("suppresses nothing")
                .help(help.clone())
        });
        unused.chain(broken)
    }
}

impl Suppressions {
    /// The fix that rewrites directive `index` without the codes that
    /// suppress nothing (kept: those used, and those of rules not checked
    /// now), or removes it when none is left. Every unused code of one
    /// directive gets the same fix, applied once.
    fn without_unused(
        &self,
        source: &[u8],
        index: usize,
        enabled: impl Fn(&str) -> bool,
    ) -> Option<Fix> {
        let directive = &self.directives[index];
        if directive.broken {
            return None;
        }
        let kept: Vec<&str> = self
            .list
            .iter()
            .filter(|s| s.directive == index && (s.used || !enabled(&s.code)))
            .map(|s| s.code.as_str())
            .collect();
        if !kept.is_empty() {
            let text = format!("sinuprep: {} {}", directive.word, kept.join(", "));
            return Some(Fix::replace(
                "remove the codes that suppress nothing",
                Applicability::Safe,
                directive.span,
                text,
            ));
        }
        // A comment that is only the directive goes, with the blanks before it.
        let comment = directive.comment;
        let before = &source[comment.start..directive.span.start];
        let after = &source[directive.span.end..comment.end];
        let alone = before.first() == Some(&b';')
            && before[1..].iter().all(|b| matches!(b, b' ' | b'\t'))
            && after.iter().all(|b| matches!(b, b' ' | b'\t'));
        let span = if alone {
            let blanks = source[..comment.start]
                .iter()
                .rev()
                .take_while(|b| matches!(b, b' ' | b'\t'))
                .count();
            Span::new(comment.start - blanks, comment.end)
        } else {
            directive.span
        };
        Some(Fix::replace(
            "remove the suppression",
            Applicability::Safe,
            span,
            "",
        ))
    }
}
