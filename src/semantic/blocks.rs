//! Which control blocks open and close where: IF ... ELSE ... ENDIF, WHILE,
//! FOR, LOOP and REPEAT ... UNTIL, matched line by line. The CYCLE600 walk's
//! structure and the unclosed-block rule (N004) read the same matching, so a
//! broken program is recovered from in one way: a closer closes the nearest
//! open block it belongs to, and the blocks opened inside that one stay
//! unclosed; a closer with no such block closes nothing.

use crate::span::Span;
use crate::syntax::tree::{Block, StatementKind};

/// A statement that opens a control block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Opener {
    If,
    While,
    For,
    Loop,
    Repeat,
}

impl Opener {
    pub fn keyword(self) -> &'static str {
        match self {
            Opener::If => "IF",
            Opener::While => "WHILE",
            Opener::For => "FOR",
            Opener::Loop => "LOOP",
            Opener::Repeat => "REPEAT",
        }
    }

    /// The statement that closes it.
    pub fn closer(self) -> &'static str {
        match self {
            Opener::If => "ENDIF",
            Opener::While => "ENDWHILE",
            Opener::For => "ENDFOR",
            Opener::Loop => "ENDLOOP",
            Opener::Repeat => "UNTIL",
        }
    }
}

/// The block a block's first control statement opens, and that statement's
/// span. `IF cond GOTOF L` is a jump, not a block; `REPEAT L1 L2` repeats a
/// section elsewhere.
pub fn opener(block: &Block) -> Option<(Opener, Span)> {
    let is_jump = block
        .statements
        .iter()
        .any(|s| matches!(s.kind, StatementKind::Goto(_)));
    block.statements.iter().find_map(|s| match &s.kind {
        StatementKind::If { .. } if !is_jump => Some((Opener::If, s.span)),
        StatementKind::While { .. } => Some((Opener::While, s.span)),
        StatementKind::For { .. } => Some((Opener::For, s.span)),
        StatementKind::Loop => Some((Opener::Loop, s.span)),
        StatementKind::Repeat { targets, .. } if targets.is_empty() => {
            Some((Opener::Repeat, s.span))
        }
        _ => None,
    })
}

/// A block opened and not yet closed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Open {
    pub opener: Opener,
    /// The opening statement.
    pub span: Span,
    /// 0-based.
    pub row: usize,
    /// The row of its ELSE (an IF's).
    pub else_row: Option<usize>,
}

/// What one line did to the open blocks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Event {
    /// `open` is closed on `row`.
    Closed { open: Open, row: usize },
    /// `open` was still open inside a block `closer` closed on `row`.
    LeftOpen {
        open: Open,
        closer: &'static str,
        row: usize,
    },
    /// A closer (ENDIF, ENDWHILE, ...) with no open block of its kind.
    Stray { closer: &'static str, span: Span },
    /// An ELSE where the innermost open block is not an IF.
    StrayElse { span: Span },
}

/// The blocks open so far, fed each block in order.
#[derive(Default, Debug)]
pub struct BlockMatcher {
    open: Vec<Open>,
}

impl BlockMatcher {
    /// Line `row`'s block; what it opens is open after it, what it closes
    /// is reported to `events`.
    pub fn line(&mut self, row: usize, block: &Block, events: &mut impl FnMut(Event)) {
        if let Some((opener, span)) = opener(block) {
            self.open.push(Open {
                opener,
                span,
                row,
                else_row: None,
            });
            return;
        }
        for statement in &block.statements {
            let closer = match statement.kind {
                StatementKind::EndIf => Opener::If,
                StatementKind::EndWhile => Opener::While,
                StatementKind::EndFor => Opener::For,
                StatementKind::EndLoop => Opener::Loop,
                StatementKind::Until { .. } => Opener::Repeat,
                StatementKind::Else => {
                    match self.open.last_mut() {
                        // A second ELSE is the parser's to refuse; the first one counts.
                        Some(open) if open.opener == Opener::If => {
                            open.else_row.get_or_insert(row);
                        }
                        _ => events(Event::StrayElse {
                            span: statement.span,
                        }),
                    }
                    continue;
                }
                _ => continue,
            };
            match self.open.iter().rposition(|o| o.opener == closer) {
                Some(index) => {
                    let inner = self.open.split_off(index + 1);
                    for open in inner.into_iter().rev() {
                        events(Event::LeftOpen {
                            open,
                            closer: closer.closer(),
                            row,
                        });
                    }
                    if let Some(open) = self.open.pop() {
                        events(Event::Closed { open, row });
                    }
                }
                None => events(Event::Stray {
                    closer: closer.closer(),
                    span: statement.span,
                }),
            }
        }
    }

    /// The blocks never closed, outermost first.
    pub fn finish(self) -> Vec<Open> {
        self.open
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::parse;
    use crate::syntax::tree::LineKind;

    fn events(text: &str) -> (Vec<String>, Vec<Open>) {
        let program = parse(text.as_bytes());
        let mut matcher = BlockMatcher::default();
        let mut out = Vec::new();
        for (row, line) in program.lines.iter().enumerate() {
            if let LineKind::Block(block) = &line.kind {
                matcher.line(row, block, &mut |event| {
                    out.push(match event {
                        Event::Closed { open, row } => format!(
                            "{} {}..{} else {:?}",
                            open.opener.keyword(),
                            open.row,
                            row,
                            open.else_row
                        ),
                        Event::LeftOpen { open, closer, row } => {
                            format!(
                                "{} {} left open by {closer} {row}",
                                open.opener.keyword(),
                                open.row
                            )
                        }
                        Event::Stray { closer, .. } => format!("stray {closer}"),
                        Event::StrayElse { .. } => "stray ELSE".to_string(),
                    })
                });
            }
        }
        (out, matcher.finish())
    }

    #[test]
    fn nested_blocks_close_innermost_first() {
        let (found, open) = events(
            "IF R1==1\nWHILE R2<3\nR2=R2+1\nENDWHILE\nELSE\nLOOP\nENDLOOP\nENDIF\nREPEAT\nUNTIL R3>1\n",
        );
        assert_eq!(
            found,
            [
                "WHILE 1..3 else None",
                "LOOP 5..6 else None",
                "IF 0..7 else Some(4)",
                "REPEAT 8..9 else None"
            ]
        );
        assert!(open.is_empty());
    }

    #[test]
    fn a_closer_closes_its_own_kind_and_leaves_the_inner_blocks_open() {
        let (found, open) = events("IF R1==1\nWHILE R2<3\nENDIF\nENDFOR\nELSE\nFOR R3=1 TO 2\n");
        assert_eq!(
            found,
            [
                "WHILE 1 left open by ENDIF 2",
                "IF 0..2 else None",
                "stray ENDFOR",
                "stray ELSE"
            ]
        );
        assert_eq!(open.len(), 1);
        assert_eq!((open[0].opener, open[0].row), (Opener::For, 5));
    }

    #[test]
    fn a_conditional_jump_and_a_section_repetition_open_nothing() {
        let (found, open) = events("IF R1==1 GOTOF LBL\nLBL:\nREPEAT LBL P=2\n");
        assert!(found.is_empty() && open.is_empty(), "{found:?} {open:?}");
    }

    #[test]
    fn an_else_belongs_to_an_if_only() {
        let (found, open) = events("WHILE R1<3\nELSE\nENDWHILE\n");
        assert_eq!(found, ["stray ELSE", "WHILE 0..2 else None"]);
        assert!(open.is_empty());
    }
}
