//! Which control blocks open and close where: IF ... ELSE ... ENDIF, WHILE,
//! FOR, LOOP and REPEAT ... UNTIL, matched line by line in the model's pass.
//! The CYCLE600 walk, the unclosed-block rule (N004), the formatter and an
//! editor's folding read this one matching, so a broken program is recovered from in one way: a closer closes the nearest
//! open block it belongs to, and the blocks opened inside that one stay
//! unclosed; a closer with no such block closes nothing.

use crate::span::Span;
use crate::syntax::tree::{Block, Statement, StatementKind};

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

/// The block a block's first control statement opens, and that statement.
/// `IF cond GOTOF L` is a jump, not a block; `REPEAT L1 L2` repeats a
/// section elsewhere.
pub fn opener(block: &Block) -> Option<(Opener, &Statement)> {
    let is_jump = block
        .statements
        .iter()
        .any(|s| matches!(s.kind, StatementKind::Goto(_)));
    block.statements.iter().find_map(|s| {
        let opener = match &s.kind {
            StatementKind::If { .. } if !is_jump => Opener::If,
            StatementKind::While { .. } => Opener::While,
            StatementKind::For { .. } => Opener::For,
            StatementKind::Loop => Opener::Loop,
            StatementKind::Repeat { targets, .. } if targets.is_empty() => Opener::Repeat,
            _ => return None,
        };
        Some((opener, s))
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

/// A block closed by its own closer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Closed {
    pub opener: Opener,
    /// The opener's row, 0-based.
    pub row: usize,
    /// The row of its ELSE (an IF's).
    pub else_row: Option<usize>,
    /// The closer's row.
    pub end: usize,
}

/// What is wrong with the program's blocks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fault {
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
    /// `open` is still open at the end of the file.
    NeverClosed(Open),
}

/// The program's control blocks, matched once in the model's line pass and
/// read by the walk, the unclosed-block rule (N004), the formatter and an
/// editor's folding.
#[derive(Debug, Default)]
pub struct Blocks {
    /// Sorted by the opener's row.
    closed: Vec<Closed>,
    /// (ELSE row, the ENDIF's row), sorted.
    elses: Vec<(usize, usize)>,
    /// In the order they are met, those never closed last (outermost first).
    pub faults: Vec<Fault>,
}

impl Blocks {
    /// The blocks closed by their own closer, in the order they open.
    pub fn closed(&self) -> &[Closed] {
        &self.closed
    }

    /// The closed block that opens on `row`.
    pub fn opened_on(&self, row: usize) -> Option<&Closed> {
        let at = self.closed.binary_search_by_key(&row, |c| c.row).ok()?;
        self.closed.get(at)
    }

    /// The row of the ENDIF of the closed IF whose ELSE is on `row`.
    pub fn else_end(&self, row: usize) -> Option<usize> {
        let at = self.elses.binary_search_by_key(&row, |&(e, _)| e).ok()?;
        Some(self.elses[at].1)
    }
}

/// The blocks open so far, fed each block in order.
#[derive(Default, Debug)]
pub struct BlockMatcher {
    open: Vec<Open>,
    closed: Vec<Closed>,
    faults: Vec<Fault>,
}

impl BlockMatcher {
    /// Line `row`'s block: what it opens is open after it, what it closes
    /// is closed.
    pub fn line(&mut self, row: usize, block: &Block) {
        if let Some((opener, statement)) = opener(block) {
            self.open.push(Open {
                opener,
                span: statement.span,
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
                        _ => self.faults.push(Fault::StrayElse {
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
                    self.faults
                        .extend(inner.into_iter().rev().map(|open| Fault::LeftOpen {
                            open,
                            closer: closer.closer(),
                            row,
                        }));
                    if let Some(open) = self.open.pop() {
                        self.closed.push(Closed {
                            opener: open.opener,
                            row: open.row,
                            else_row: open.else_row,
                            end: row,
                        });
                    }
                }
                None => self.faults.push(Fault::Stray {
                    closer: closer.closer(),
                    span: statement.span,
                }),
            }
        }
    }

    /// The blocks, those still open never closed.
    pub fn finish(self) -> Blocks {
        let mut closed = self.closed;
        // Closed innermost first: an outer block after the ones inside it.
        closed.sort_unstable_by_key(|c| c.row);
        let mut elses: Vec<(usize, usize)> = closed
            .iter()
            .filter_map(|c| Some((c.else_row?, c.end)))
            .collect();
        elses.sort_unstable();
        let mut faults = self.faults;
        faults.extend(self.open.into_iter().map(Fault::NeverClosed));
        Blocks {
            closed,
            elses,
            faults,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::parse;
    use crate::syntax::tree::LineKind;

    fn blocks_of(text: &str) -> Blocks {
        let program = parse(text.as_bytes());
        let mut matcher = BlockMatcher::default();
        for (row, line) in program.lines.iter().enumerate() {
            if let LineKind::Block(block) = &line.kind {
                matcher.line(row, block);
            }
        }
        matcher.finish()
    }

    /// The closed blocks (in the order they open) and the faults.
    fn matched(text: &str) -> (Vec<String>, Vec<String>) {
        let blocks = blocks_of(text);
        let closed = blocks
            .closed()
            .iter()
            .map(|c| {
                let keyword = c.opener.keyword();
                format!("{keyword} {}..{} else {:?}", c.row, c.end, c.else_row)
            })
            .collect();
        let faults = blocks
            .faults
            .iter()
            .map(|fault| match fault {
                Fault::LeftOpen { open, closer, row } => {
                    format!(
                        "{} {} left open by {closer} {row}",
                        open.opener.keyword(),
                        open.row
                    )
                }
                Fault::Stray { closer, .. } => format!("stray {closer}"),
                Fault::StrayElse { .. } => "stray ELSE".to_string(),
                Fault::NeverClosed(open) => {
                    format!("{} {} never closed", open.opener.keyword(), open.row)
                }
            })
            .collect();
        (closed, faults)
    }

    #[test]
    fn nested_blocks_close_innermost_first() {
        let text = "IF R1==1\nWHILE R2<3\nR2=R2+1\nENDWHILE\nELSE\nLOOP\nENDLOOP\nENDIF\nREPEAT\nUNTIL R3>1\n";
        let (closed, faults) = matched(text);
        assert_eq!(
            closed,
            [
                "IF 0..7 else Some(4)",
                "WHILE 1..3 else None",
                "LOOP 5..6 else None",
                "REPEAT 8..9 else None"
            ]
        );
        assert!(faults.is_empty(), "{faults:?}");
    }

    #[test]
    fn a_closer_closes_its_own_kind_and_leaves_the_inner_blocks_open() {
        let (closed, faults) =
            matched("IF R1==1\nWHILE R2<3\nENDIF\nENDFOR\nELSE\nFOR R3=1 TO 2\n");
        assert_eq!(closed, ["IF 0..2 else None"]);
        assert_eq!(
            faults,
            [
                "WHILE 1 left open by ENDIF 2",
                "stray ENDFOR",
                "stray ELSE",
                "FOR 5 never closed"
            ]
        );
    }

    #[test]
    fn a_conditional_jump_and_a_section_repetition_open_nothing() {
        let (closed, faults) = matched("IF R1==1 GOTOF LBL\nLBL:\nREPEAT LBL P=2\n");
        assert!(
            closed.is_empty() && faults.is_empty(),
            "{closed:?} {faults:?}"
        );
    }

    #[test]
    fn an_else_belongs_to_an_if_only() {
        let (closed, faults) = matched("WHILE R1<3\nELSE\nENDWHILE\n");
        assert_eq!(closed, ["WHILE 0..2 else None"]);
        assert_eq!(faults, ["stray ELSE"]);
    }

    /// An inner IF's ELSE comes before the outer one's: each ELSE finds
    /// its own ENDIF, and each opener its block.
    #[test]
    fn each_else_and_each_opener_finds_its_own_block() {
        let blocks = blocks_of("IF R1\nIF R2\nELSE\nENDIF\nELSE\nENDIF\n");
        assert_eq!((blocks.else_end(2), blocks.else_end(4)), (Some(3), Some(5)));
        assert_eq!(blocks.else_end(3), None);
        assert_eq!(blocks.opened_on(1).map(|c| c.end), Some(3));
        assert_eq!(blocks.opened_on(0).map(|c| c.end), Some(5));
        assert_eq!(blocks.opened_on(2), None);
    }
}
