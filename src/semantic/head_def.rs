//! Accessories defined in a HEAD_DEF subprogram (spec section 6): each
//! section assigns `_HEAD_NAME="..."` and `_HEAD_ALLOWED=0|1`.
//!
//! The file is read by the project's own parser; only those two assignments
//! matter here.

use crate::diagnostic::Diagnostic;
use crate::registry;
use crate::span::Span;
use crate::suggest::closest;
use crate::syntax::parse;
use crate::syntax::tree::{ExprKind, StatementKind};

#[derive(Clone, Debug, PartialEq)]
pub struct Head {
    pub name: String,
    /// `None` when the section never sets `_HEAD_ALLOWED`.
    pub allowed: Option<bool>,
    /// 1-based line of `_HEAD_NAME`.
    pub line: usize,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Heads {
    /// Where they were read from, for messages.
    pub file: String,
    pub heads: Vec<Head>,
}

impl Heads {
    pub fn read(file: String, source: &[u8]) -> Heads {
        let program = parse(source);
        let mut heads: Vec<Head> = Vec::new();
        for (row, line) in program.lines.iter().enumerate() {
            let crate::syntax::tree::LineKind::Block(block) = &line.kind else {
                continue;
            };
            for statement in &block.statements {
                let StatementKind::Assign(assign) = &statement.kind else {
                    continue;
                };
                let target = assign.target.name.text(source);
                if target.eq_ignore_ascii_case(b"_HEAD_NAME") {
                    if let ExprKind::String = assign.value.kind {
                        let text = assign.value.span.of(source);
                        let name = String::from_utf8_lossy(&text[1..text.len() - 1]).into_owned();
                        heads.push(Head {
                            name,
                            allowed: None,
                            line: row + 1,
                        });
                    }
                } else if target.eq_ignore_ascii_case(b"_HEAD_ALLOWED") {
                    if let (Some(head), ExprKind::Number(n)) =
                        (heads.last_mut(), &assign.value.kind)
                    {
                        head.allowed = Some(n.value == 1.0);
                    }
                }
            }
        }
        Heads { file, heads }
    }

    /// The problem with `name`, if any: not defined, or not allowed.
    pub fn check(&self, name: &str, span: Span) -> Option<Diagnostic> {
        let found = self
            .heads
            .iter()
            .find(|h| h.name.eq_ignore_ascii_case(name));
        match found {
            Some(head) if head.allowed == Some(true) => None,
            Some(head) => Some(
                registry::cycle600_unknown_head::RULE.at(span)
                    .message(format!("accessory \"{name}\" is defined in {} (line {}) but not allowed (_HEAD_ALLOWED is not 1)", self.file, head.line))
                    .label("not allowed")
                    .help(format!("set _HEAD_ALLOWED=1 in its section of {}, or choose another accessory", self.file)),
            ),
            None => {
                let suggestion = closest(name, self.heads.iter().map(|h| h.name.as_str()), 3)
                    .map(|n| format!("did you mean \"{n}\"? "))
                    .unwrap_or_default();
                let known: Vec<&str> = self.heads.iter().map(|h| h.name.as_str()).collect();
                Some(
                    registry::cycle600_unknown_head::RULE.at(span)
                        .message(format!("accessory \"{name}\" is not defined in {}", self.file))
                        .label("unknown accessory")
                        .help(format!("{suggestion}defined accessories: {}", known.join(", "))),
                )
            }
        }
    }
}

/// C610: no HEAD_DEF was found, so head names were not checked.
pub fn not_found() -> Diagnostic {
    registry::head_def_missing::RULE
        .at(Span::new(0, 0))
        .message("head names were not checked: no HEAD_DEF.SPF next to the program")
        .label("accessories unchecked")
        .help(
            "give the accessory definitions with --heads HEAD_DEF.SPF, or `heads` in sinuprep.toml",
        )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_sample_head_def() {
        let source = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/samples/HEAD_DEF.SPF"))
            .expect("sample");
        let heads = Heads::read("HEAD_DEF.SPF".into(), &source);
        let names: Vec<(&str, Option<bool>)> = heads
            .heads
            .iter()
            .map(|h| (h.name.as_str(), h.allowed))
            .collect();
        assert_eq!(
            names,
            [
                ("IFVW207S", Some(true)),
                ("UFK600", Some(true)),
                ("RT2000", Some(true)),
                ("HEAD_OLD", Some(false))
            ]
        );
        assert!(heads.check("ufk600", Span::default()).is_none());
        let unknown = heads.check("UFK060", Span::default()).expect("unknown");
        assert!(unknown
            .help
            .as_deref()
            .unwrap_or("")
            .starts_with("did you mean \"UFK600\""));
        assert!(heads.check("HEAD_OLD", Span::default()).is_some());
    }
}
