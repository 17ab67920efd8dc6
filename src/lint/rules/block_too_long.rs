//! N008 `block-too-long`: Finds blocks longer than 512 characters (comment included).

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockAt, Check, FileContext, PlainLine, Sees};
use crate::span::Span;

pub static RULE: RuleInfo = RuleInfo {
    code: "N008",
    name: "block-too-long",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds blocks longer than 512 characters (comment included).

## Why it matters
512 characters is the block length commonly quoted for the control (not confirmed in a Siemens
manual available here); a longer block is refused when the program is loaded or run.

## Example
A CAM post that writes a whole point list into one MSG or one expression.

## Fix
Split the block: several assignments on separate blocks, shorter comments."#,
};

#[derive(Default)]
pub struct Checker;

const LIMIT: usize = crate::syntax::BLOCK_CHARACTERS;

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::BLOCKS | Sees::PLAIN_LINES
    }

    fn block(&mut self, file: &FileContext, at: &BlockAt, out: &mut Vec<Diagnostic>) {
        check_length(file, at.line.raw.content, out);
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], out: &mut Vec<Diagnostic>) {
        for line in lines {
            check_length(file, line.raw.content, out);
        }
    }
}

fn check_length(file: &FileContext, content: Span, out: &mut Vec<Diagnostic>) {
    if content.len() <= LIMIT {
        return;
    }
    let characters = crate::syntax::block_characters(content.of(file.source));
    if characters > LIMIT {
        out.push(
            RULE.at(Span::new(content.start, content.end))
                .message(format!(
                    "block of {characters} characters, longer than the control's {LIMIT}"
                ))
                .label("too long")
                .help("split it into several blocks"),
        );
    }
}
