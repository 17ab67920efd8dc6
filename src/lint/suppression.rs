//! `; sinuprep: ignore CODE[,CODE...]` on a block and
//! `; sinuprep: ignore-file CODE[,CODE...]` anywhere, in any case (NC is
//! case-insensitive): findings they cover are dropped, and a suppression
//! that covers nothing is reported (N099), as is a misspelt directive
//! (`ignor`) or a code that names no rule.

use crate::diagnostic::Diagnostic;
use crate::lint::rules::unused_suppression;
use crate::span::Span;
use crate::syntax::lexer::find_ignoring_case;

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
                continue;
            }
            self.list.push(Suppression {
                row,
                code,
                span: Span::new(start, start + length),
                used: false,
            });
            position += length;
        }
    }

    /// Whether a suppression covers `diagnostic` on its 0-based `row` (and
    /// marks it used); the row is asked for only when a suppression names
    /// the code, since finding rows costs a pass over the file.
    pub fn covers(&mut self, diagnostic: &Diagnostic, row: impl FnOnce() -> usize) -> bool {
        if !self.list.iter().any(|s| s.code == diagnostic.code) {
            return false;
        }
        let row = row();
        let mut covered = false;
        for suppression in &mut self.list {
            if suppression.code == diagnostic.code && suppression.row.is_none_or(|r| r == row) {
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
        let unused = self
            .list
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
