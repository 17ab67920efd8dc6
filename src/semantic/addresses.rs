//! The address words of a block (`G1`, `X10`, `M2=3`, `F=R1`, `CR=5`), read
//! alike from its tree and from a plain line's bytes: what the rules on a
//! block's addresses and the modal state read, without a tree for the
//! millions of plain lines of a CAM program.

use crate::span::Span;
use crate::syntax::tree::{Block, Expr, ExprKind, StatementKind, WordValue};

/// One address word of a block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Address {
    /// The whole word.
    pub span: Span,
    /// The address: one letter (`X`), or a name the tree reads as an
    /// assignment (`CR`, `AP`, `TURN`).
    pub name: Span,
    /// The extension digits of `M2=3`, `S1=1000`.
    pub extension: Option<Span>,
    /// The value when it is a number written out (`12.5`, `-.5`); `None` for
    /// an expression (`F=R1`, `X=IC(5)`).
    pub number: Option<Span>,
}

/// Addresses of more than one letter, which the tree reads as assignments:
/// the circle's radius and aperture, polar end points, turns of a helix,
/// chamfers and roundings (Siemens, Programming Manual Fundamentals, "List of
/// addresses").
const NAMED: [&str; 9] = ["CR", "AR", "AP", "RP", "TURN", "RND", "RNDM", "CHF", "CHR"];

impl Address {
    /// The address in upper case is `name`.
    pub fn is(&self, source: &[u8], name: &str) -> bool {
        self.name.of(source).eq_ignore_ascii_case(name.as_bytes())
    }

    /// The address's letter in upper case (the first of a name).
    pub fn letter(&self, source: &[u8]) -> u8 {
        source[self.name.start].to_ascii_uppercase()
    }

    /// The value as a whole number written with digits alone (`G01` is 1);
    /// `None` for a sign, a point, an expression or more than nine digits.
    pub fn whole(&self, source: &[u8]) -> Option<u32> {
        digits(self.number?.of(source))
    }

    /// The extension as a number (`M2=3` is 2).
    pub fn extension_value(&self, source: &[u8]) -> Option<u32> {
        digits(self.extension?.of(source))
    }
}

fn digits(text: &[u8]) -> Option<u32> {
    if text.is_empty() || text.len() > 9 || !text.iter().all(u8::is_ascii_digit) {
        return None;
    }
    Some(
        text.iter()
            .fold(0, |value, &digit| value * 10 + u32::from(digit - b'0')),
    )
}

/// The block's address words in order: its words, and its assignments to the
/// named addresses. Words inside a synchronized action are the action's and
/// not among them, and so are the words of a macro's text (`LINE` with
/// `DEFINE LINE AS G1 F300`): their spans are the macro's name, whose
/// spelling is not theirs.
pub fn of_block(source: &[u8], block: &Block) -> Vec<Address> {
    block
        .statements
        .iter()
        .filter_map(|statement| match &statement.kind {
            StatementKind::Word(word) if word.address.span == statement.span => None,
            StatementKind::Word(word) => Some(Address {
                span: statement.span,
                name: word.address.span,
                extension: word.extension,
                number: match &word.value {
                    WordValue::Number(number) => Some(number.span),
                    WordValue::Expr(expr) => literal(expr),
                },
            }),
            StatementKind::Assign(assign)
                if assign.target.indices.is_empty()
                    && assign.target.name.span != statement.span
                    && NAMED.iter().any(|name| assign.target.name.is(source, name)) =>
            {
                Some(Address {
                    span: statement.span,
                    name: assign.target.name.span,
                    extension: None,
                    number: literal(&assign.value),
                })
            }
            _ => None,
        })
        .collect()
}

/// The number an expression is, when it is one written out (`CR=5`).
fn literal(expr: &Expr) -> Option<Span> {
    matches!(expr.kind, ExprKind::Number(_)).then_some(expr.span)
}

/// The address words of a plain line's content (see
/// [`crate::syntax::plain::is_plain`]), the block number left out: a plain
/// line is words of a letter and a number only, so they are read without a
/// parser.
pub fn of_plain(source: &[u8], content: Span) -> Vec<Address> {
    let mut addresses = Vec::with_capacity(8);
    of_plain_into(source, content, &mut addresses);
    addresses
}

/// [`of_plain`] into `addresses`, emptied first: a reader of millions of
/// lines keeps one buffer rather than one a line.
pub fn of_plain_into(source: &[u8], content: Span, addresses: &mut Vec<Address>) {
    addresses.clear();
    crate::syntax::plain::words(source, content.start, |letter, end| {
        addresses.push(Address {
            span: Span::new(letter, end),
            name: Span::new(letter, letter + 1),
            extension: None,
            number: Some(Span::new(letter + 1, end)),
        });
    });
}

/// Where the program ends in this block: its M2, M17 or M30 word (M02 and
/// M030 alike), or its RET.
pub fn program_end(source: &[u8], block: &Block, addresses: &[Address]) -> Option<Span> {
    let word = addresses.iter().find(|a| is_end_word(source, a));
    word.map(|a| a.span).or_else(|| {
        block.statements.iter().find_map(|s| match &s.kind {
            StatementKind::Command(name) if name.is(source, "RET") => Some(s.span),
            StatementKind::Call(call) if call.name.is(source, "RET") => Some(s.span),
            _ => None,
        })
    })
}

/// M2, M17 or M30 without an extension.
pub fn is_end_word(source: &[u8], address: &Address) -> bool {
    address.is(source, "M")
        && address.extension.is_none()
        && matches!(address.whole(source), Some(2 | 17 | 30))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::Lines;

    fn words(text: &str) -> Vec<String> {
        let source = text.as_bytes();
        let lines = Lines::new(source);
        let block = lines.block(0).expect("a block");
        of_block(source, &block)
            .iter()
            .map(|a| String::from_utf8_lossy(a.span.of(source)).into_owned())
            .collect()
    }

    #[test]
    fn reads_words_and_named_addresses() {
        assert_eq!(
            words("N10 G2 X10 Y=R1 CR=5 M2=3 R1=4 _X=2 AP[1]=3 ; c"),
            ["G2", "X10", "Y=R1", "CR=5", "M2=3"]
        );
        let source = b"G01 M2=3 F=R1 CR=5";
        let lines = Lines::new(source);
        let block = lines.block(0).expect("a block");
        let found = of_block(source, &block);
        assert_eq!(found[0].whole(source), Some(1));
        assert_eq!(found[1].extension_value(source), Some(2));
        assert_eq!(found[1].whole(source), Some(3));
        assert_eq!(found[2].number, None);
        assert_eq!(found[3].whole(source), Some(5));
    }

    proptest::proptest! {
        /// A plain line's words read from its bytes are the tree's.
        #[test]
        fn plain_words_are_the_trees(text in "(N[0-9]{1,3} )?([GXMFnx][-+]?[0-9]{0,3}\\.?[0-9]{1,2} ?){0,6}(;[A-Z ]{0,4})?") {
            let source = text.as_bytes();
            let lines = Lines::new(source);
            if crate::syntax::plain::is_plain(source) && !lines.is_empty() {
                if let Some(block) = lines.block(0) {
                    let raw = lines.raw(0);
                    proptest::prop_assert_eq!(of_plain(source, raw.content), of_block(source, &block));
                }
            }
        }
    }
}
