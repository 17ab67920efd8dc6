//! `textDocument/completion`: what may be written where the cursor is.
//! After a jump, the labels it can reach (GOTOF forward, GOTOB backward),
//! and the block numbers once an `N` is typed;
//! after `$`, the control's system variables; elsewhere the language's
//! words ([`crate::semantic::vocabulary`]), the G and M functions, the
//! cycles with their parameters as a snippet, the program's variables, the
//! definition files' GUD variables and macros, the subprograms the control
//! finds and the machine's axes. Nothing in a comment or a string.

use lsp_types as lsp;

use std::collections::HashSet;

use crate::semantic::functions::{g_function, m_function, system_variable};
use crate::semantic::uses::{Namespace, Role};
use crate::semantic::vocabulary::{self, Kind};
use crate::semantic::{cycles, jumps};
use crate::syntax::block::block_number_digits;
use crate::syntax::tree::GotoKind;

use super::answers::Snapshot;

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
        let cursor = self.cursor(position);
        let before = &cursor.before;
        if before.in_comment_or_string {
            return Vec::new();
        }
        // The item replaces the whole word, the part after the cursor too.
        let mut items = Items {
            typed: before.word,
            range: self.range(cursor.word),
            lower: before.word.iter().any(u8::is_ascii_alphabetic)
                && !before.word.iter().any(u8::is_ascii_uppercase),
            seen: HashSet::new(),
            out: Vec::new(),
        };
        if let Some(search) = before.previous.and_then(label_search) {
            self.labels(&mut items, cursor.row, search);
        } else if before.word.first() == Some(&b'$') {
            system_variables(&mut items);
        } else {
            self.names(&mut items);
            language(&mut items, snippets);
        }
        items.out
    }

    /// The labels a word searching as `search` does on line `row` finds,
    /// each once (the first it would land on).
    fn labels(&self, items: &mut Items, row: usize, search: Search) {
        let finds = |label: usize| match search {
            Search::Jump(kind) => jumps::reaches(kind, label, row),
            // A REPEAT searches from the line before it.
            Search::Repeat => label < row,
        };
        let labels = self.uses().all().iter().filter(|u| {
            u.namespace == Namespace::Label
                && u.role == Role::Defines
                && !is_block_number(&u.name)
                && finds(u.row)
        });
        for label in labels {
            let written = label.span.of(self.text.bytes());
            let detail = format!("label, line {}", label.row + 1);
            items.own(written, lsp::CompletionItemKind::REFERENCE, detail);
        }
        // Block numbers once one is being typed (`GOTOF N2`): every block
        // may have one, and a jump names a label far more often.
        let typed = items.typed;
        if typed.first().is_some_and(|n| n.eq_ignore_ascii_case(&b'N'))
            && typed[1..].iter().all(u8::is_ascii_digit)
        {
            let (source, lines) = (self.text.bytes(), &self.model.lines);
            for row in (0..lines.len()).filter(|&row| finds(row)) {
                let line = lines.raw(row).content.of(source);
                // After the blanks and a skip level (`/`, `/1`), the number.
                let first = line.trim_ascii_start();
                let first = match first.strip_prefix(b"/") {
                    Some(skipped) => match skipped.split_first() {
                        Some((level, rest)) if level.is_ascii_digit() => rest,
                        _ => skipped,
                    }
                    .trim_ascii_start(),
                    None => first,
                };
                if let Some(digits) = block_number_digits(first).filter(|_| first[0] != b':') {
                    let detail = format!("block number, line {}", row + 1);
                    items.own(
                        &first[..1 + digits],
                        lsp::CompletionItemKind::REFERENCE,
                        detail,
                    );
                }
            }
        }
    }

    /// The program's variables and PROC parameters, and what the control
    /// holds outside it: GUD variables, macros, subprograms, axes.
    fn names(&self, items: &mut Items) {
        let source = self.text.bytes();
        for symbol in self.model.symbols.iter() {
            let what = if symbol.parameter { "parameter" } else { "DEF" };
            let written = String::from_utf8_lossy(symbol.data_type.span.of(source));
            let detail = format!("{what} {written}, line {}", symbol.row + 1);
            let kind = lsp::CompletionItemKind::VARIABLE;
            items.own(symbol.span.of(source), kind, detail);
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
        // A cycle is offered with its parameters, below.
        let subprograms = (environment.procedures.iter())
            .filter(|(name, _)| cycles::cycle(name.as_bytes()).is_none());
        for (name, procedure) in subprograms {
            let detail = format!("subprogram ({})", procedure.parameters.join(", "));
            items.own(name.as_bytes(), lsp::CompletionItemKind::FUNCTION, detail);
        }
        for axis in &environment.axes {
            let detail = "axis of the machine data".to_string();
            items.own(axis.as_bytes(), lsp::CompletionItemKind::FIELD, detail);
        }
    }
}

/// How the word before a label searches for it.
#[derive(Clone, Copy)]
enum Search {
    Jump(GotoKind),
    Repeat,
}

/// How the word `before` searches the label after it, if it names one.
fn label_search(before: &[u8]) -> Option<Search> {
    let words = [
        ("GOTOF", Search::Jump(GotoKind::Forward)),
        ("GOTOB", Search::Jump(GotoKind::Backward)),
        ("GOTO", Search::Jump(GotoKind::Both)),
        ("GOTOC", Search::Jump(GotoKind::Conditional)),
        ("REPEAT", Search::Repeat),
    ];
    words
        .into_iter()
        .find(|(name, _)| name.as_bytes().eq_ignore_ascii_case(before))
        .map(|(_, search)| search)
}

/// `N100`: a block number, which completion offers only once one is typed.
fn is_block_number(name: &str) -> bool {
    name.len() > 1 && name.starts_with('N') && name[1..].bytes().all(|b| b.is_ascii_digit())
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
    /// The labels offered so far: a name is offered once, its first.
    seen: HashSet<String>,
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
        if !self.seen.insert(label.to_ascii_uppercase()) {
            return;
        }
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
