//! `textDocument/completion`: what may be written where the cursor is.
//! After a jump, the labels it can reach (GOTOF forward, GOTOB backward);
//! after `$`, the control's system variables; elsewhere the language's
//! words ([`crate::semantic::vocabulary`]), the G and M functions, the
//! cycles with their parameters as a snippet, the program's variables, the
//! definition files' GUD variables and macros, the subprograms the control
//! finds and the machine's axes. Nothing in a comment or a string.

use lsp_types as lsp;

use crate::semantic::cycles;
use crate::semantic::functions::{g_function, m_function, system_variable};
use crate::semantic::uses::{Namespace, Role};
use crate::semantic::vocabulary::{self, Kind};
use crate::span::{ColumnUnit, Span};
use crate::syntax::tree::GotoKind;

use super::answers::Snapshot;
use super::cursor;

/// How the items sort before the client's own ranking by the typed word:
/// the program's own names first, the control's last.
const OWN: &str = "0";
const LANGUAGE: &str = "1";
const FUNCTIONS: &str = "2";
const SYSTEM: &str = "3";

/// The highest `$TC_CARRn` field.
const SWIVEL_DATA_FIELDS: u32 = 65;

impl Snapshot<'_, '_> {
    /// The completions at `position`; `snippets`: the client inserts
    /// snippets (a cycle's parameters as placeholders).
    pub fn completion(&self, position: lsp::Position, snippets: bool) -> Vec<lsp::CompletionItem> {
        let at = self.offset(position);
        let row = self.text.position(at, ColumnUnit::Bytes).row - 1;
        let line_start = self.model.lines.raw(row).content.start;
        let source = self.text.bytes();
        let before = cursor::read(&source[line_start..at.max(line_start)]);
        if before.in_text {
            return Vec::new();
        }
        let typed = Span::new(line_start + before.word_start, at);
        let mut items = Items {
            typed: before.word,
            range: self.range(typed),
            lower: before.word.iter().any(u8::is_ascii_alphabetic)
                && !before.word.iter().any(u8::is_ascii_uppercase),
            out: Vec::new(),
        };
        if let Some(jump) = before.previous.and_then(jump_kind) {
            self.labels(&mut items, row, jump);
        } else if before.word.first() == Some(&b'$') {
            system_variables(&mut items);
        } else {
            self.names(&mut items);
            language(&mut items, snippets);
        }
        items.out
    }

    /// The labels a jump of `kind` on line `row` can reach.
    fn labels(&self, items: &mut Items, row: usize, kind: GotoKind) {
        let reaches = |label_row: usize| match kind {
            GotoKind::Forward => label_row > row,
            GotoKind::Backward => label_row < row,
            _ => true,
        };
        let labels = self.uses().all().iter().filter(|u| {
            u.namespace == Namespace::Label && u.role == Role::Defines && reaches(u.row)
        });
        for label in labels {
            let written = label.span.of(self.text.bytes());
            let detail = format!("label, line {}", label.row + 1);
            items.own(written, lsp::CompletionItemKind::REFERENCE, detail);
        }
    }

    /// The program's variables and PROC parameters, and what the control
    /// holds outside it: GUD variables, macros, subprograms, axes.
    fn names(&self, items: &mut Items) {
        let source = self.text.bytes();
        let mut seen = std::collections::HashSet::new();
        for symbol in self.model.symbols.iter() {
            if seen.insert(&symbol.name) {
                let what = if symbol.parameter { "parameter" } else { "DEF" };
                let written = String::from_utf8_lossy(symbol.data_type.span.of(source));
                let detail = format!("{what} {written}, line {}", symbol.row + 1);
                let kind = lsp::CompletionItemKind::VARIABLE;
                items.own(symbol.span.of(source), kind, detail);
            }
        }
        let environment = &self.settings.environment;
        for name in &environment.variables {
            let kind = lsp::CompletionItemKind::VARIABLE;
            items.own(name.as_bytes(), kind, "GUD variable".to_string());
        }
        for (name, expansion) in &environment.macros {
            let detail = format!("macro: {}", expansion.text);
            items.own(name.as_bytes(), lsp::CompletionItemKind::CONSTANT, detail);
        }
        for (name, procedure) in environment.procedures.iter() {
            let detail = format!("subprogram ({})", procedure.parameters.join(", "));
            items.own(name.as_bytes(), lsp::CompletionItemKind::FUNCTION, detail);
        }
        for axis in &environment.axes {
            let detail = "axis of the machine data".to_string();
            items.own(axis.as_bytes(), lsp::CompletionItemKind::FIELD, detail);
        }
    }
}

/// What a jump word searches.
fn jump_kind(word: &[u8]) -> Option<GotoKind> {
    let kinds = [
        ("GOTOF", GotoKind::Forward),
        ("GOTOB", GotoKind::Backward),
        ("GOTO", GotoKind::Both),
        ("GOTOC", GotoKind::Conditional),
    ];
    kinds
        .into_iter()
        .find(|(name, _)| name.as_bytes().eq_ignore_ascii_case(word))
        .map(|(_, kind)| kind)
}

/// The language's words, G and M functions and cycles.
fn language(items: &mut Items, snippets: bool) {
    for word in vocabulary::WORDS {
        let kind = match word.kind {
            Kind::Keyword | Kind::Command => lsp::CompletionItemKind::KEYWORD,
            Kind::Function | Kind::Procedure => lsp::CompletionItemKind::FUNCTION,
            Kind::SystemVariable => continue,
        };
        items.word(
            word.name,
            kind,
            None,
            Some(documented(word.meaning, word.manual)),
        );
    }
    for number in 0..1000 {
        if let Some((what, _)) = g_function(number) {
            items.word(
                &format!("G{number}"),
                lsp::CompletionItemKind::KEYWORD,
                Some(what),
                None,
            );
        }
    }
    for number in 0..100 {
        if let Some(what) = m_function(number) {
            let kind = lsp::CompletionItemKind::KEYWORD;
            items.word(&format!("M{number}"), kind, Some(what.to_string()), None);
        }
    }
    for cycle in cycles::CYCLES {
        items.cycle(cycle, snippets);
    }
}

/// The system variables described, `$TC_CARR1..65` among them.
fn system_variables(items: &mut Items) {
    for word in vocabulary::WORDS {
        if word.kind == Kind::SystemVariable {
            let kind = lsp::CompletionItemKind::VARIABLE;
            items.word(
                word.name,
                kind,
                None,
                Some(documented(word.meaning, word.manual)),
            );
        }
    }
    for field in 1..=SWIVEL_DATA_FIELDS {
        let name = format!("$TC_CARR{field}");
        if let Some(what) = system_variable(name.as_bytes()) {
            items.word(&name, lsp::CompletionItemKind::VARIABLE, Some(what), None);
        }
    }
}

fn documented(meaning: &str, manual: &str) -> lsp::Documentation {
    lsp::Documentation::MarkupContent(lsp::MarkupContent {
        kind: lsp::MarkupKind::Markdown,
        value: format!("{meaning}\n\n*{manual}*"),
    })
}

/// The items so far, each replacing the word typed.
struct Items<'l> {
    typed: &'l [u8],
    range: lsp::Range,
    /// The word is typed in lower case: the language's words are offered so.
    lower: bool,
    out: Vec<lsp::CompletionItem>,
}

impl Items<'_> {
    /// Whether `name` goes on from the word typed (any case).
    fn continues(&self, name: &[u8]) -> bool {
        name.len() >= self.typed.len() && name[..self.typed.len()].eq_ignore_ascii_case(self.typed)
    }

    /// One of the program's or the machine's names, as written.
    fn own(&mut self, name: &[u8], kind: lsp::CompletionItemKind, detail: String) {
        if self.continues(name) {
            let name = String::from_utf8_lossy(name).into_owned();
            self.push(name.clone(), name, kind, Some(detail), None, OWN);
        }
    }

    /// One of the language's words, in the case typed.
    fn word(
        &mut self,
        name: &str,
        kind: lsp::CompletionItemKind,
        detail: Option<String>,
        documentation: Option<lsp::Documentation>,
    ) {
        if self.continues(name.as_bytes()) {
            let rank = match kind {
                lsp::CompletionItemKind::VARIABLE => SYSTEM,
                _ if name.starts_with(['G', 'M'])
                    && name[1..].bytes().all(|b| b.is_ascii_digit()) =>
                {
                    FUNCTIONS
                }
                _ => LANGUAGE,
            };
            let text = self.cased(name);
            self.push(name.to_string(), text, kind, detail, documentation, rank);
        }
    }

    /// A cycle, its parameters as a snippet's placeholders where the client
    /// takes snippets.
    fn cycle(&mut self, cycle: &cycles::Cycle, snippets: bool) {
        if !self.continues(cycle.name.as_bytes()) {
            return;
        }
        let name = self.cased(cycle.name);
        let text = match snippets {
            true => {
                let placeholders: Vec<String> = (cycle.parameters.iter().enumerate())
                    .map(|(i, p)| format!("${{{}:{}}}", i + 1, p.name))
                    .collect();
                format!("{name}({})$0", placeholders.join(","))
            }
            false => format!("{name}("),
        };
        let documentation = documented(cycle.what, cycle.manual);
        let detail = format!("cycle, {} parameters", cycle.parameters.len());
        let kind = lsp::CompletionItemKind::FUNCTION;
        let label = cycle.name.to_string();
        self.push(
            label,
            text,
            kind,
            Some(detail),
            Some(documentation),
            LANGUAGE,
        );
        if let Some(item) = self.out.last_mut() {
            if snippets {
                item.insert_text_format = Some(lsp::InsertTextFormat::SNIPPET);
            }
        }
    }

    fn cased(&self, name: &str) -> String {
        match self.lower {
            true => name.to_ascii_lowercase(),
            false => name.to_string(),
        }
    }

    fn push(
        &mut self,
        label: String,
        text: String,
        kind: lsp::CompletionItemKind,
        detail: Option<String>,
        documentation: Option<lsp::Documentation>,
        rank: &str,
    ) {
        self.out.push(lsp::CompletionItem {
            sort_text: Some(format!("{rank}{label}")),
            filter_text: Some(label.clone()),
            text_edit: Some(lsp::CompletionTextEdit::Edit(lsp::TextEdit::new(
                self.range, text,
            ))),
            label,
            kind: Some(kind),
            detail,
            documentation,
            ..lsp::CompletionItem::default()
        });
    }
}
