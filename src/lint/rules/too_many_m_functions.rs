//! N021 `too-many-m-functions`: Finds a block with more than five M functions.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockAt, Check, FileContext, PlainLine, Sees};
use crate::span::Span;
use crate::syntax::lexer::is_blank;
use crate::syntax::tree::{Statement, StatementKind, Word};

pub static RULE: RuleInfo = RuleInfo {
    code: "N021",
    name: "too-many-m-functions",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a block with more than five M functions (`M3 M8 M7 M10 M11 M12`), extended ones (`M2=3`)
included. M functions inside a synchronized action are the action's, not the block's.

## Why it matters
The control takes at most five M functions in one block (Siemens, Programming Manual
Fundamentals, "M functions") and refuses the block otherwise.

## Example
```
N10 M3 M8 M7 M10 M11 M12 S2000
```

## Fix
Spread the M functions over several blocks."#,
};

/// Most M functions a block may hold.
const MOST: usize = 5;

#[derive(Default)]
pub struct Checker;

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::BLOCKS | Sees::PLAIN_LINES
    }

    fn block(&mut self, file: &FileContext, at: &BlockAt, out: &mut Vec<Diagnostic>) {
        let block = at.block;
        let is_m = |s: &&Statement| matches!(&s.kind, StatementKind::Word(Word { address, .. }) if address.is(file.source, "M"));
        // Counted first: most blocks have none, and then nothing is collected.
        if block.statements.iter().filter(is_m).count() > MOST {
            let m_words: Vec<Span> = block
                .statements
                .iter()
                .filter(is_m)
                .map(|s| s.span)
                .collect();
            report(&m_words, out);
        }
    }

    /// A run of plain lines is one stretch of the file: one search for `M`
    /// over all of it, the letters found counted by line, and only a line
    /// with more than five looked at word by word (a plain line holds address
    /// words only: every letter before its comment starts a word).
    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], out: &mut Vec<Diagnostic>) {
        let (Some(first), Some(last)) = (lines.first(), lines.last()) else {
            return;
        };
        let stretch = Span::new(first.raw.content.start, last.raw.content.end);
        // (index of the line, its M letters so far)
        let mut current: Option<(usize, usize)> = None;
        for found in memchr::memchr2_iter(b'M', b'm', stretch.of(file.source)) {
            let at = stretch.start + found;
            match &mut current {
                Some((line, count)) if at < lines[*line].raw.content.end => *count += 1,
                _ => {
                    if let Some((line, count)) = current {
                        check_plain_line(file, &lines[line], count, out);
                    }
                    let line = lines.partition_point(|l| l.raw.content.end <= at);
                    current = Some((line.min(lines.len() - 1), 1));
                }
            }
        }
        if let Some((line, count)) = current {
            check_plain_line(file, &lines[line], count, out);
        }
    }
}

/// A plain line with `letters` M letters (its comment's included): its M
/// words, when there may be too many.
fn check_plain_line(
    file: &FileContext,
    line: &PlainLine,
    letters: usize,
    out: &mut Vec<Diagnostic>,
) {
    if letters <= MOST {
        return;
    }
    let content = line.raw.content.of(file.source);
    let words = content.split(|&b| b == b';').next().unwrap_or_default();
    let m_words: Vec<Span> = words
        .iter()
        .enumerate()
        .filter(|(_, b)| b.eq_ignore_ascii_case(&b'M'))
        .map(|(at, _)| {
            let start = line.raw.content.start + at;
            // The word ends at a letter or a blank (control bytes too, as
            // the parser reads them).
            let length = words[at + 1..]
                .iter()
                .take_while(|&&b| !b.is_ascii_alphabetic() && !is_blank(b))
                .count();
            Span::new(start, start + 1 + length)
        })
        .collect();
    report(&m_words, out);
}

/// The finding for a block whose M words are `m_words`, when they are too many.
fn report(m_words: &[Span], out: &mut Vec<Diagnostic>) {
    if m_words.len() <= MOST {
        return;
    }
    let (Some(first), Some(last)) = (m_words.first(), m_words.last()) else {
        return;
    };
    out.push(
        RULE.at(first.to(*last))
            .message(format!(
                "{} M functions in one block: the control takes at most {MOST}",
                m_words.len()
            ))
            .label("too many M functions")
            .help("spread the M functions over several blocks"),
    );
}
