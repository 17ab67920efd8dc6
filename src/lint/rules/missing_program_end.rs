//! N010 `missing-program-end`: Finds a program whose last block neither ends it (M30, M2, M17, RET, a REPOS command) nor jumps unconditionally (GOTO, ENDLOOP).

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockAt, Check, FileContext, PlainLine, Sees};
use crate::lint::rules::support::{command_name, is_definition_file, program_end};
use crate::span::Span;
use crate::syntax::tree::{StatementKind, WordValue};
use crate::syntax::ProgramKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N010",
    name: "missing-program-end",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a program whose last block neither ends it (M30, M2, M17, RET) nor jumps unconditionally.
`ENDLOOP` jumps back to its `LOOP` (an endless loop never falls off the end), and an ASUB
(interrupt routine) returns to the program it interrupted through `REPOSA` (or another REPOS
command: REPOSL, REPOSQ, REPOSQA, REPOSH, REPOSHA): either may be the last block. A macro of the definition files given that stands for one of them (`DEFINE ENDE AS M30`) ends the
program where it is written, as the control expands it. Blocks after the end that jumps reach often end with a jump back (`GOTOB LOOP`). A main program may end with M17 or RET as a subprogram does (it can be called as one; the
Programming Manual allows M2, M17 or M30 as the last block), and a subprogram with M30 or M2.
Files that are not programs (`.DEF` definition files, `.INI` setup data) are not checked. When
the last block has a syntax error, the finding stands at that block, unless an end command is
written in it. Blocks after an end that run on to the file's end are N027's finding, reported
once there, not again here.

## Why it matters
Without an end, a main program stops with an alarm at its last block instead of ending, and a
subprogram does not return to its caller as intended.

## Example
```
N10 G0 X0
N20 G1 X100 F500 M5
```

## Fix
End a main program with `M30` (or `M2`), a subprogram with `M17` or `RET`."#,
};

/// The commands through which an ASUB returns to the interrupted program
/// (Job Planning, "Repositioning at the contour (REPOS)").
const REPOS: [&str; 6] = ["REPOSA", "REPOSL", "REPOSQ", "REPOSQA", "REPOSH", "REPOSHA"];

/// Remembers only which line the last block is; `finish` takes its tree
/// from the model, so that the millions of blocks before it cost nothing.
#[derive(Default)]
pub struct Checker {
    last: Option<usize>,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::BLOCKS | Sees::PLAIN_LINES
    }

    fn block(&mut self, _file: &FileContext, at: &BlockAt, _out: &mut Vec<Diagnostic>) {
        if !at.block.statements.is_empty() || at.block.unparsed.is_some() {
            self.last = Some(at.row);
        }
    }

    fn plain_lines(
        &mut self,
        _file: &FileContext,
        lines: &[PlainLine],
        _out: &mut Vec<Diagnostic>,
    ) {
        if let Some(line) = lines.iter().rev().find(|line| line.facts.has_words()) {
            self.last = Some(line.row);
        }
    }

    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        let Some(row) = self.last else {
            return;
        };
        // A program with nothing to execute is N020's, once.
        if is_definition_file(file.name) || file.model().first_executable.is_none() {
            return;
        }
        let model = file.model();
        let Some(block) = model.lines.block(row) else {
            return;
        };
        let raw = model.lines.raw(row);
        let m_words: Vec<f64> = block
            .statements
            .iter()
            .filter_map(|s| match &s.kind {
                StatementKind::Word(word) if word.address.is(file.source, "M") => match &word.value
                {
                    WordValue::Number(n) => Some(n.value),
                    WordValue::Expr(_) => None,
                },
                _ => None,
            })
            .collect();
        // An unconditional jump never lets the program run past the file's
        // end: blocks after M30 reached by jumps often end with `GOTOB`.
        let conditional = block
            .statements
            .iter()
            .any(|s| matches!(s.kind, StatementKind::If { .. }));
        let jumps = !conditional
            && block
                .statements
                .iter()
                .any(|s| matches!(s.kind, StatementKind::Goto(_) | StatementKind::EndLoop));
        // An ASUB returns to the program it interrupted through a REPOS
        // command, repositioning on the way.
        let returns = block.statements.iter().any(|s| {
            command_name(s)
                .is_some_and(|name| REPOS.iter().any(|repos| name.is(file.source, repos)))
        });
        let addresses = crate::semantic::addresses::of_block(file.source, &block);
        // A macro of the program's own written in the block (`M99` after
        // `DEFINE M99 AS M30`): its text is what the control reads.
        let own_macro_ends = model.macro_uses.iter().any(|used| {
            !used.recursive
                && raw.content.start <= used.span.start
                && used.span.end <= raw.content.end
                && crate::semantic::environment::Macro::of(used.text.as_bytes()).ends_program
        });
        let ends = jumps
            || returns
            || own_macro_ends
            || m_words.iter().any(|m| [2.0, 17.0, 30.0].contains(m))
            || program_end(file, &block, &addresses).is_some();
        // A broken last block may still hold its end where the parser stopped.
        let ends_in_unparsed = block.unparsed.is_some_and(|rest| {
            rest.of(file.source)
                .split(|b| !b.is_ascii_alphanumeric())
                .any(|word| {
                    ["M30", "M2", "M02", "M17", "RET"]
                        .iter()
                        .any(|e| word.eq_ignore_ascii_case(e.as_bytes()))
                })
        });
        if ends || ends_in_unparsed {
            return;
        }
        let (what, fix) = match file.kind {
            ProgramKind::Main => (
                "main program",
                "end it with M30 (or M2; M17 or RET if it is called as a subprogram)",
            ),
            ProgramKind::Subprogram => ("subprogram", "end it with M17 or RET (or M30)"),
        };
        let message = match m_words.as_slice() {
            [] => format!("the {what} does not end: no M30, M2, M17 or RET in its last block"),
            words => format!(
                "the {what} does not end: its last block has {}, not M30, M2, M17 or RET",
                words
                    .iter()
                    .map(|m| format!("M{m}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        out.push(
            RULE.at(Span::new(raw.content.start, raw.content.end))
                .message(message)
                .label("last block")
                .help(fix),
        );
    }
}
