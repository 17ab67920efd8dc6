//! Which words of a line are the language's own, whose case `[format] case`
//! decides: keywords and operators (`IF`, `AND`, `DEF`, `REAL`), address
//! letters (`G`, `M`, `X`, the block number's `N`, `CR`), R parameters,
//! system variables (`$P_UIFR`), the control's built-in functions and
//! commands (`SIN`, `TRAORI`, `STOPRE`) and its cycles (`CYCLE800`).
//!
//! A user's names (DEF variables, labels, PROC names and the subprograms
//! called) are never among them: the control ignores case, so changing it
//! changes nothing it does, but a name is written as its author chose.
//! Addresses come from the tree (`X10Y20` holds two); the other words are
//! recognised by spelling, outside strings.

use crate::semantic::addresses;
use crate::semantic::words::is_language_word;
use crate::span::Span;
use crate::syntax::lexer::is_name_char;
use crate::syntax::tree::{Block, GotoTarget, StatementKind};
use crate::syntax::visit::gotos;

/// The spans of the language's words in `block`'s code (before
/// `code_end`), sorted.
pub fn language_words(source: &[u8], content: Span, code_end: usize, block: &Block) -> Vec<Span> {
    let mut words = Vec::new();
    lexical_words(source, content.start, code_end, &mut words);
    if let Some(number) = block.number {
        words.push(Span::new(number.span.start, number.span.start + 1));
    }
    for address in addresses::of_block(source, block) {
        words.push(address.name);
    }
    for statement in &block.statements {
        if let StatementKind::SyncAction(sync) = &statement.kind {
            let otherwise = sync.otherwise.iter().flat_map(|(_, actions)| actions);
            for action in sync.actions.iter().chain(otherwise) {
                if let StatementKind::Word(word) = &action.kind {
                    words.push(word.address.span);
                }
            }
        }
    }
    // A block number a jump names: `GOTOF n100`.
    for goto in gotos(block) {
        if let Some(GotoTarget::Label(name)) = &goto.target {
            if goto
                .target
                .as_ref()
                .and_then(|t| t.block_number(source))
                .is_some()
            {
                words.push(Span::new(name.span.start, name.span.start + 1));
            }
        }
    }
    words.retain(|w| w.end <= code_end);
    words.sort_unstable_by_key(|w| (w.start, w.end));
    words
}

/// The names in `start..end` that are the language's by their spelling,
/// strings and numbers stepped over.
fn lexical_words(source: &[u8], start: usize, end: usize, out: &mut Vec<Span>) {
    let mut at = start;
    while at < end {
        let byte = source[at];
        if byte == b'"' || byte == b'\'' {
            at += 1;
            while at < end && source[at] != byte {
                at += 1;
            }
            at += 1;
        } else if byte == b'$' || byte.is_ascii_alphabetic() || byte == b'_' {
            let from = at;
            while at < end && source[at] == b'$' {
                at += 1;
            }
            while at < end && is_name_char(source[at]) {
                at += 1;
            }
            if is_language_word(&source[from..at]) {
                out.push(Span::new(from, at));
            }
        } else if byte.is_ascii_digit() || byte == b'.' {
            // A number, and letters glued to it (`1EX3`): never a word.
            while at < end && (is_name_char(source[at]) || source[at] == b'.') {
                at += 1;
            }
        } else {
            at += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::parse;
    use crate::syntax::tree::LineKind;

    fn words(text: &str) -> Vec<String> {
        let program = parse(text.as_bytes());
        let line = &program.lines[0];
        let LineKind::Block(block) = &line.kind else {
            panic!("a block");
        };
        let code_end = block.comment.map_or(line.raw.content.end, |c| c.start);
        language_words(text.as_bytes(), line.raw.content, code_end, block)
            .iter()
            .map(|s| String::from_utf8_lossy(s.of(text.as_bytes())).into_owned())
            .collect()
    }

    #[test]
    fn keywords_addresses_and_functions_are_the_languages() {
        assert_eq!(
            words("n10 if r1==sin(_angle) gotof n20 ; if"),
            ["n", "if", "r1", "sin", "gotof", "n"]
        );
        assert_eq!(words("g1 x10y20 f=_feed"), ["g", "x", "y", "f"]);
        assert_eq!(words("$p_uifr[1]=ctrans(x,1)"), ["$p_uifr", "ctrans"]);
    }

    #[test]
    fn user_names_and_strings_are_not() {
        assert_eq!(words("msg(\"if x\")"), ["msg"]);
        assert_eq!(words("my_sub"), Vec::<String>::new());
        assert_eq!(words("def real _ifx=1.5ex3"), ["def", "real"]);
        assert_eq!(words("cycle800(1) cycle_mine"), ["cycle800"]);
    }
}
