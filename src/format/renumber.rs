//! `--renumber START,STEP`: the numbered blocks numbered again in order
//! (blocks without a number stay without), and every reference to a block
//! number rewritten to the new number of the block it lands on: GOTO,
//! GOTOF, GOTOB, GOTOC and CASE targets (where each lands is the
//! model's answer, the walk's) and `CALL BLOCK ... TO ...` ranges of
//! the program itself. (`REPEAT` names labels only, as the grammar reads
//! it: a label is never renumbered.)
//!
//! It refuses rather than guesses: a jump whose target is computed at run
//! time, or that names a number no block has, stops the renumbering of the
//! file (after it the number could land somewhere). A number another
//! program may name (a `CALL "PART" BLOCK N10 TO N20`, an ASUB, a block
//! search on the machine) is not visible here: the file's note says so.

use std::collections::HashMap;

use crate::format::layout::plain_prefix;
use crate::semantic::Model;
use crate::span::Span;
use crate::syntax::lexer::find_ignoring_case;
use crate::syntax::plain::digits_value;
use crate::syntax::tree::{GotoKind, GotoTarget, StatementKind};
use crate::syntax::visit::gotos;
use crate::syntax::MAX_PARSED_LINE;

/// The replacements a renumbering makes, sorted by where they stand.
pub struct Plan {
    pub replacements: Vec<(Span, Vec<u8>)>,
    /// How many block numbers changed.
    pub blocks: usize,
}

/// Why a file's blocks are not renumbered.
#[derive(Debug, Clone, PartialEq)]
pub struct Refusal {
    pub span: Span,
    pub message: String,
}

/// The renumbering of `model`'s program from `start` in steps of `step`.
pub fn plan(model: &Model, start: u64, step: u64) -> Result<Plan, Refusal> {
    let source = model.source;
    // Every numbered block, in order: (row, old number, its digits).
    let mut numbered: Vec<(usize, u64, Span)> = Vec::new();
    for row in 0..model.lines.len() {
        let content = model.lines.raw(row).content;
        let digits = if model.lines.is_plain(row) {
            plain_prefix(source, content).1
        } else if content.len() > MAX_PARSED_LINE {
            // Not read (S009), so left as it is: its number would stand out
            // of order among the new ones.
            if let Some(digits) = plain_prefix(source, content).1 {
                return Err(Refusal {
                    span: digits,
                    message: "this block is too long to read (S009): its number would keep its old value among the new ones; split the block first".to_string(),
                });
            }
            None
        } else {
            model
                .lines
                .block(row)
                .and_then(|block| block.number.map(|n| n.digits))
        };
        if let Some(digits) = digits {
            let Some(old) = digits_value(digits.of(source)) else {
                return Err(Refusal {
                    span: digits,
                    message: "this block number is too large to renumber".to_string(),
                });
            };
            numbered.push((row, old, digits));
        }
    }
    let mut new_of_row = HashMap::with_capacity(numbered.len());
    let mut replacements = Vec::with_capacity(numbered.len());
    let mut next = start;
    let mut blocks = 0;
    for &(row, _, digits) in &numbered {
        new_of_row.insert(row, next);
        let new = next.to_string().into_bytes();
        // A number that stays as it is (`N10` numbered 10 again) is no change.
        if digits.of(source) != new.as_slice() {
            replacements.push((digits, new));
            blocks += 1;
        }
        next = next.checked_add(step).ok_or_else(|| Refusal {
            span: digits,
            message: "the new block numbers would overflow".to_string(),
        })?;
    }
    // Old number -> rows, for the search CALL BLOCK makes.
    let mut rows_of: HashMap<u64, Vec<usize>> = HashMap::new();
    for &(row, old, _) in &numbered {
        rows_of.entry(old).or_default().push(row);
    }
    let new_text = |landing: Option<usize>, span: Span, what: &str| {
        landing
            .and_then(|row| new_of_row.get(&row))
            .map(|n| n.to_string().into_bytes())
            .ok_or_else(|| Refusal {
                span,
                message: format!("{what} names a block number no block has: after renumbering it could land on another block"),
            })
    };
    for (row, line) in model.lines.other_lines() {
        let crate::syntax::tree::LineKind::Block(block) = &line.kind else {
            continue;
        };
        for goto in gotos(block) {
            let Some(target) = &goto.target else {
                continue;
            };
            if let GotoTarget::Computed(expr) = target {
                return Err(Refusal {
                    span: expr.span,
                    message: "a jump to a computed target may name any block number".to_string(),
                });
            }
            if target.block_number(source).is_none() || goto.kind == GotoKind::Start {
                continue;
            }
            let landing = model.landing(target, goto.kind, row);
            let span = number_digits(target);
            let text = new_text(landing, span, "this jump")?;
            if span.of(source) != text.as_slice() {
                replacements.push((span, text));
            }
        }
        for statement in &block.statements {
            if let StatementKind::IndirectCall {
                keyword,
                target: Some(target),
            } = &statement.kind
            {
                if keyword.is(source, "CALL") {
                    for span in own_block_range(source, *target) {
                        let number =
                            n_number(&source[span.start - 1..span.end]).unwrap_or(u64::MAX);
                        // Searched as GOTO searches: forward, then back.
                        let landing = rows_of.get(&number).and_then(|rows| {
                            rows.iter()
                                .copied()
                                .find(|&r| r > row)
                                .or_else(|| rows.iter().copied().rev().find(|&r| r <= row))
                        });
                        let text = new_text(landing, span, "this CALL BLOCK")?;
                        if span.of(source) != text.as_slice() {
                            replacements.push((span, text));
                        }
                    }
                }
            }
        }
    }
    replacements.sort_unstable_by_key(|(span, _)| (span.start, span.end));
    Ok(Plan {
        replacements,
        blocks,
    })
}

/// The digits of a jump target that names a block number (`N0100`, `100`).
fn number_digits(target: &GotoTarget) -> Span {
    match target {
        GotoTarget::Label(name) => Span::new(name.span.start + 1, name.span.end),
        GotoTarget::Number(number) => number.span,
        GotoTarget::Computed(expr) => expr.span,
    }
}

/// `N100` (any case, any leading zeros) as its number.
fn n_number(text: &[u8]) -> Option<u64> {
    match text {
        [b'N' | b'n', digits @ ..] if !digits.is_empty() => digits_value(digits),
        _ => None,
    }
}

/// The digits of the block numbers in `CALL BLOCK N10 TO N20` when the
/// call names no program (the section is this program's own); nothing for
/// `CALL "PART" BLOCK ...`, whose numbers are another program's.
fn own_block_range(source: &[u8], target: Span) -> Vec<Span> {
    let text = target.of(source);
    let trimmed = text.trim_ascii_start();
    let lead = text.len() - trimmed.len();
    if trimmed.len() < 5 || !trimmed[..5].eq_ignore_ascii_case(b"BLOCK") {
        return Vec::new();
    }
    let mut found = Vec::new();
    let mut at = target.start + lead + 5;
    for keyword in [None, Some(b"TO".as_slice())] {
        if let Some(keyword) = keyword {
            match find_ignoring_case(&source[at..target.end], keyword) {
                Some(offset) => at += offset + keyword.len(),
                None => break,
            }
        }
        let rest = &source[at..target.end];
        let skip = rest.len() - rest.trim_ascii_start().len();
        let start = at + skip;
        let end = start
            + source[start..target.end]
                .iter()
                .take_while(|b| b.is_ascii_alphanumeric())
                .count();
        if n_number(&source[start..end]).is_some() {
            found.push(Span::new(start + 1, end));
        }
        at = end;
    }
    found
}
