//! N004 `unclosed-block`: Finds IF, WHILE, FOR, LOOP and REPEAT blocks that are not closed, closed by the wrong keyword, or

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView};
use crate::span::Span;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N004",
    name: "unclosed-block",
    severity: Severity::Error,
    docs: r#"## What it does
Finds IF, WHILE, FOR, LOOP and REPEAT blocks that are not closed, closed by the wrong keyword, or
closers (ENDIF, ENDWHILE, ENDFOR, ENDLOOP, UNTIL, ELSE) without their opener. Reported at the opener.

## Why it matters
The control refuses the program (alarm 12640 and its kin) or runs a different structure than the
indentation suggests.

## Example
```
N10 WHILE R1<10
N20   R1=R1+1
N30 ENDIF          ; closes nothing: the WHILE stays open
```

## Fix
Add or correct the closing keyword."#,
};

#[derive(Default)]
pub struct Checker {
    open: Vec<(&'static str, &'static str, Span, usize)>,
}

/// (opener, its closer) of a block's first control statement.
fn opener(block: &crate::syntax::tree::Block) -> Option<(&'static str, &'static str, Span)> {
    let is_jump = block
        .statements
        .iter()
        .any(|s| matches!(s.kind, StatementKind::Goto(_)));
    block.statements.iter().find_map(|s| match &s.kind {
        StatementKind::If { .. } if !is_jump => Some(("IF", "ENDIF", s.span)),
        StatementKind::While { .. } => Some(("WHILE", "ENDWHILE", s.span)),
        StatementKind::For { .. } => Some(("FOR", "ENDFOR", s.span)),
        StatementKind::Loop => Some(("LOOP", "ENDLOOP", s.span)),
        StatementKind::Repeat { targets, .. } if targets.is_empty() => {
            Some(("REPEAT", "UNTIL", s.span))
        }
        _ => None,
    })
}

impl Check for Checker {
    fn line(
        &mut self,
        _file: &FileContext,
        row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        let Some(block) = line.block.filter(|_| !line.plain) else {
            return;
        };
        if let Some((keyword, closer, span)) = opener(block) {
            self.open.push((keyword, closer, span, row));
            return;
        }
        for statement in &block.statements {
            let closer = match statement.kind {
                StatementKind::EndIf => "ENDIF",
                StatementKind::EndWhile => "ENDWHILE",
                StatementKind::EndFor => "ENDFOR",
                StatementKind::EndLoop => "ENDLOOP",
                StatementKind::Until { .. } => "UNTIL",
                StatementKind::Else => {
                    if self.open.last().is_none_or(|(k, ..)| *k != "IF") {
                        out.push(
                            RULE.at(statement.span)
                                .message("ELSE without an open IF")
                                .label("no IF to belong to")
                                .help("add the IF, or remove the ELSE"),
                        );
                    }
                    continue;
                }
                _ => continue,
            };
            match self.open.iter().rposition(|(_, c, ..)| *c == closer) {
                Some(index) => {
                    for (keyword, expected, span, _) in self
                        .open
                        .drain(index..)
                        .skip(1)
                        .collect::<Vec<_>>()
                        .into_iter()
                        .rev()
                    {
                        out.push(
                            RULE.at(span)
                                .message(format!(
                                    "{keyword} is not closed before {closer} on line {}",
                                    row + 1
                                ))
                                .label(format!("{keyword} opened here"))
                                .help(format!("add {expected} before line {}", row + 1)),
                        );
                    }
                }
                None => out.push(
                    RULE.at(statement.span)
                        .message(format!("{closer} without its opening block"))
                        .label("closes nothing")
                        .help(format!("remove {closer}, or add the block it should close")),
                ),
            }
        }
    }

    fn finish(&mut self, _file: &FileContext, out: &mut Vec<Diagnostic>) {
        for (keyword, closer, span, _) in self.open.drain(..) {
            out.push(
                RULE.at(span)
                    .message(format!("{keyword} is never closed"))
                    .label(format!("{keyword} opened here"))
                    .help(format!("add {closer} where the block ends")),
            );
        }
    }
}
