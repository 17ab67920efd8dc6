//! What each word of a program is, for an editor to colour: comments,
//! strings, numbers, keywords, G and M functions, addresses, variables,
//! system variables, calls, labels and block numbers, macros. A scan of the
//! line's bytes, told by the table of uses what a name is (a jump's label,
//! a subprogram) and by the model where a macro stands; no line is parsed
//! again. A line that does not parse is coloured all the same.

use std::ops::Range;

use crate::semantic::uses::{Namespace, Uses};
use crate::semantic::words::is_language_word;
use crate::semantic::Model;
use crate::span::Span;
use crate::syntax::lexer::{is_name_char, is_name_start, is_one_of, RESERVED};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    Comment,
    String,
    Number,
    /// Control words (`IF`, `DEF`, `GOTOF`, `AND`) and G and M functions.
    Keyword,
    /// An address letter (`X`, `F`, `CR`) before its value.
    Address,
    Variable,
    /// A `$` variable of the control, and an R parameter.
    SystemVariable,
    /// A subprogram, cycle or function called.
    Function,
    /// A label or a block number, defined or jumped to.
    Label,
    Macro,
    /// A `%_N_..._MPF` header or a `;$PATH=` line.
    Header,
}

/// A word of class `class` at `span`, within one line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token {
    pub span: Span,
    pub class: Class,
}

/// The tokens of lines `rows` (0-based), in order.
pub fn tokens(model: &Model, uses: &Uses, rows: Range<usize>) -> Vec<Token> {
    let source = model.source;
    let mut out = Vec::new();
    for row in rows.start..rows.end.min(model.lines.len()) {
        let content = model.lines.raw(row).content;
        let line = &source[content.start..content.end];
        let header = line.first() == Some(&b'%') || line.starts_with(b";$PATH=");
        if header {
            out.push(Token {
                span: content,
                class: Class::Header,
            });
            continue;
        }
        Line {
            source,
            uses,
            model,
            at: content.start,
            end: content.end,
            first_word: true,
            out: &mut out,
        }
        .scan();
    }
    out
}

struct Line<'a> {
    source: &'a [u8],
    uses: &'a Uses,
    model: &'a Model<'a>,
    at: usize,
    end: usize,
    /// Nothing but a skip level or a block number came before: a name here
    /// followed by `:` is a label.
    first_word: bool,
    out: &'a mut Vec<Token>,
}

impl Line<'_> {
    fn byte(&self, at: usize) -> Option<u8> {
        (at < self.end).then(|| self.source[at])
    }

    fn push(&mut self, start: usize, end: usize, class: Class) {
        self.out.push(Token {
            span: Span::new(start, end),
            class,
        });
    }

    fn scan(mut self) {
        while let Some(byte) = self.byte(self.at) {
            let start = self.at;
            match byte {
                b';' => {
                    self.push(start, self.end, Class::Comment);
                    return;
                }
                b'"' => {
                    let close = self.source[start + 1..self.end]
                        .iter()
                        .position(|&b| b == b'"');
                    self.at = close.map_or(self.end, |at| start + 1 + at + 1);
                    self.push(start, self.at, Class::String);
                }
                b'0'..=b'9' | b'.' if self.number_at(start) => self.number(),
                b'/' if self.first_word => {
                    // A skip level: `/` or `/1` before the block.
                    self.at += 1;
                    while self.byte(self.at).is_some_and(|b| b.is_ascii_digit()) {
                        self.at += 1;
                    }
                }
                b':' if self.first_word
                    && self.byte(start + 1).is_some_and(|b| b.is_ascii_digit()) =>
                {
                    // A main block number, `:100`.
                    self.at += 1;
                    while self.byte(self.at).is_some_and(|b| b.is_ascii_digit()) {
                        self.at += 1;
                    }
                    self.push(start, self.at, Class::Label);
                }
                b'$' => self.name(),
                byte if is_name_start(byte) => self.name(),
                _ => self.at += 1,
            }
        }
    }

    fn number_at(&self, at: usize) -> bool {
        let byte = self.source[at];
        byte.is_ascii_digit() || self.byte(at + 1).is_some_and(|b| b.is_ascii_digit())
    }

    /// `12`, `1.5`, `.5`, `1EX-3`, `'H1F'` is not read here.
    fn number(&mut self) {
        let start = self.at;
        while self
            .byte(self.at)
            .is_some_and(|b| b.is_ascii_digit() || b == b'.')
        {
            self.at += 1;
        }
        let exponent = self.byte(self.at).is_some_and(|b| b | 0x20 == b'e')
            && self.byte(self.at + 1).is_some_and(|b| b | 0x20 == b'x');
        if exponent {
            let mut at = self.at + 2;
            if self.byte(at).is_some_and(|b| b == b'+' || b == b'-') {
                at += 1;
            }
            if self.byte(at).is_some_and(|b| b.is_ascii_digit()) {
                self.at = at;
                while self.byte(self.at).is_some_and(|b| b.is_ascii_digit()) {
                    self.at += 1;
                }
            }
        }
        self.push(start, self.at, Class::Number);
        self.first_word = false;
    }

    fn name(&mut self) {
        let start = self.at;
        while self.byte(self.at) == Some(b'$') {
            self.at += 1;
        }
        let letters = self.at;
        while self.byte(self.at).is_some_and(is_name_char) {
            self.at += 1;
        }
        let end = self.at;
        let word = &self.source[letters..end];
        let first_word = std::mem::replace(&mut self.first_word, false);
        if start == letters && (word.len() == 1 || !is_name_start(word[1])) {
            return self.address(start, first_word);
        }
        let found = self.uses.at(start).filter(|u| u.span.start == start);
        let class = if self.is_macro(start) {
            Class::Macro
        } else if start < letters {
            Class::SystemVariable
        } else if !is_one_of(word, RESERVED)
            && is_language_word(word)
            && found.is_none_or(|u| u.namespace == Namespace::Variable)
        {
            // The control's own: a command (STOPRE, SUPA) or a function;
            // never a user's variable, whatever the walk makes of it (a
            // user's PROC named CYCLE123 stays a call).
            match self.next_non_blank(end) == Some(b'(') {
                true => Class::Function,
                false => Class::Keyword,
            }
        } else if let Some(found) = found {
            match found.namespace {
                Namespace::Label => Class::Label,
                Namespace::Subprogram => Class::Function,
                Namespace::Variable => Class::Variable,
            }
        } else if first_word && self.byte(end) == Some(b':') && self.byte(end + 1) != Some(b'=') {
            Class::Label
        } else if is_one_of(word, RESERVED) {
            Class::Keyword
        } else if self.next_non_blank(end) == Some(b'(') {
            Class::Function
        } else {
            Class::Variable
        };
        self.push(start, end, class);
    }

    /// An address word: its letter (and the value's digits where they are
    /// its extension, `G01`, `M30`, `N10`, `R5`).
    fn address(&mut self, start: usize, first_word: bool) {
        let letter = self.source[start] | 0x20;
        // The letter and the digits straight after it.
        let mut digits = start + 1;
        while self.byte(digits).is_some_and(|b| b.is_ascii_digit()) {
            digits += 1;
        }
        let has_digits = digits > start + 1;
        match letter {
            b'g' | b'm' if has_digits => self.push(start, digits, Class::Keyword),
            b'n' if has_digits && first_word => {
                self.first_word = true;
                self.push(start, digits, Class::Label)
            }
            b'r' if has_digits => self.push(start, digits, Class::SystemVariable),
            _ => {
                self.push(start, start + 1, Class::Address);
                self.at = start + 1;
                return;
            }
        }
        self.at = digits;
    }

    fn is_macro(&self, start: usize) -> bool {
        let uses = &self.model.macro_uses;
        let after = uses.partition_point(|u| u.span.start < start);
        uses.get(after).is_some_and(|u| u.span.start == start)
    }

    fn next_non_blank(&self, mut at: usize) -> Option<u8> {
        while self.byte(at).is_some_and(|b| b == b' ' || b == b'\t') {
            at += 1;
        }
        self.byte(at)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn classes(source: &str) -> Vec<(&str, Class)> {
        let model = Model::of(source.as_bytes());
        let uses = Uses::of(&model);
        tokens(&model, &uses, 0..model.lines.len())
            .into_iter()
            .map(|t| (&source[t.span.start..t.span.end], t.class))
            .collect()
    }

    #[test]
    fn each_word_has_its_class() {
        use Class::*;
        let found = classes(
            "%_N_PART_MPF\nN10 G01 X10.5 Y=R1+2 F500 ; feed\nSTART: DEF REAL _DEPTH=1EX-3\n\
             IF $P_TOOL>0 GOTOF START\nMSG(\"X = 1\")\nCYCLE800(1,\"TC1\")\n:100 M30\n",
        );
        assert_eq!(
            found,
            [
                ("%_N_PART_MPF", Header),
                ("N10", Label),
                ("G01", Keyword),
                ("X", Address),
                ("10.5", Number),
                ("Y", Address),
                ("R1", SystemVariable),
                ("2", Number),
                ("F", Address),
                ("500", Number),
                ("; feed", Comment),
                ("START", Label),
                ("DEF", Keyword),
                ("REAL", Keyword),
                ("_DEPTH", Variable),
                ("1EX-3", Number),
                ("IF", Keyword),
                ("$P_TOOL", SystemVariable),
                ("0", Number),
                ("GOTOF", Keyword),
                ("START", Label),
                ("MSG", Function),
                ("\"X = 1\"", String),
                ("CYCLE800", Function),
                ("1", Number),
                ("\"TC1\"", String),
                (":100", Label),
                ("M30", Keyword),
            ]
        );
    }

    /// The control's commands are keywords, whether or not the walk reads
    /// them as names; its functions are functions.
    #[test]
    fn commands_are_keywords_not_variables() {
        use Class::*;
        let found = classes("STOPRE\nSUPA G0 Z0\nTRAFOOF\nR1=TRUNC(2.5)\nM30\n");
        for (word, class) in [
            ("STOPRE", Keyword),
            ("SUPA", Keyword),
            ("TRAFOOF", Keyword),
            ("TRUNC", Function),
        ] {
            assert!(found.contains(&(word, class)), "{word}: {found:?}");
        }
    }

    #[test]
    fn a_macro_is_a_macro_and_a_broken_line_is_still_coloured() {
        let found = classes("DEFINE M_ON AS M3\nM_ON\nIF (\"open\n");
        assert!(found.contains(&("M_ON", Class::Macro)), "{found:?}");
        assert!(found.contains(&("\"open", Class::String)), "{found:?}");
    }
}
