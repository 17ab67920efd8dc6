//! What the server answers about one document, read from one analysis of
//! it: the model, the CYCLE600 walk and the table of uses.

use lsp_types as lsp;

use crate::diagnostic::Diagnostic;
use crate::document::archive::Opened;
use crate::document::held;
use crate::document::text::Text;
use crate::lint::Settings;
use crate::machine::MachineData;
use crate::run::{Programs, Setup};
use crate::semantic::cycle800;
use crate::semantic::uses::{Namespace, Role, Use, Uses};
use crate::semantic::walk;
use crate::semantic::words::{is_language_word, is_machine_axis};
use crate::semantic::{Analysis, Model};
use crate::span::{ColumnUnit, Span};
use crate::syntax::tree::StatementKind;

use super::convert;

/// The kind of the action that makes every safe fix at once, as ruff names
/// its own (`source.fixAll.ruff`).
pub const FIX_ALL: &str = "source.fixAll.sinuprep";

/// The most findings an editor is given for one document: the rest are
/// counted, not sent. A finding costs a few hundred bytes of JSON, so a
/// program with one on each of its millions of lines would cost gigabytes
/// for no editor to show.
pub const MOST_SHOWN_FINDINGS: usize = 10_000;

/// The most bytes of a program whose words are coloured in one answer: the
/// words of 10 MB of CAM program are megabytes of JSON, asked for again
/// after every change.
pub const MOST_COLOURED_BYTES: usize = 10_000_000;

/// One version of a document, analysed, for the requests about it.
pub struct Snapshot<'a, 't> {
    pub(super) text: &'t Text,
    name: &'a str,
    pub(super) model: &'a Model<'t>,
    walk: Option<&'a Analysis>,
    findings: &'a [Diagnostic],
    analysis: held::Analysis<'a, 't>,
    pub(super) unit: ColumnUnit,
    pub(super) settings: &'a Settings,
    /// Why the document's settings could not be read (it is not checked).
    refused: Option<&'a str>,
}

impl<'a, 't> Snapshot<'a, 't> {
    pub fn new(
        analysis: held::Analysis<'a, 't>,
        name: &'a str,
        settings: &'a Settings,
        unit: ColumnUnit,
        refused: Option<&'a str>,
    ) -> Self {
        let analyzed = analysis.analyzed;
        Self {
            text: analysis.text,
            name,
            model: &analyzed.model,
            walk: analyzed.walk.as_ref(),
            findings: &analyzed.findings,
            analysis,
            unit,
            settings,
            refused,
        }
    }

    pub(super) fn uses(&self) -> &Uses {
        self.analysis.uses()
    }

    fn calls(&self) -> impl Iterator<Item = &crate::semantic::CallSite> {
        self.walk.into_iter().flat_map(|walk| &walk.calls)
    }

    /// The findings of the document at `uri`: the first
    /// [`MOST_SHOWN_FINDINGS`] by position, and past those one more that
    /// says how many there are and where every one is listed.
    pub fn diagnostics(&self, uri: &lsp::Uri) -> Vec<lsp::Diagnostic> {
        if let Some(why) = self.refused {
            return vec![lsp::Diagnostic {
                range: lsp::Range::default(),
                severity: Some(lsp::DiagnosticSeverity::ERROR),
                source: Some("sinuprep".to_string()),
                message: why.to_string(),
                ..lsp::Diagnostic::default()
            }];
        }
        let mut shown: Vec<lsp::Diagnostic> = self
            .findings
            .iter()
            .take(MOST_SHOWN_FINDINGS)
            .map(|found| convert::diagnostic(self.text, uri, found, self.unit))
            .collect();
        if let Some(first_unshown) = self.findings.get(MOST_SHOWN_FINDINGS) {
            let start = self.range(first_unshown.span).start;
            let check = match convert::path(uri) {
                Some(path) => format!("`sinuprep check {}`", path.display()),
                None => "`sinuprep check` of the saved file".to_string(),
            };
            shown.push(lsp::Diagnostic {
                range: lsp::Range::new(start, start),
                severity: Some(lsp::DiagnosticSeverity::INFORMATION),
                source: Some("sinuprep".to_string()),
                message: format!(
                    "{MOST_SHOWN_FINDINGS} of the {} findings are shown, those before here; \
                     {check} lists every one",
                    self.findings.len(),
                ),
                ..lsp::Diagnostic::default()
            });
        }
        shown
    }

    pub(super) fn offset(&self, position: lsp::Position) -> usize {
        convert::offset(self.text, position, self.unit)
    }

    pub(super) fn range(&self, span: Span) -> lsp::Range {
        convert::range(self.text, span, self.unit)
    }

    fn line_text(&self, row: usize) -> String {
        let content = self.model.lines.raw(row).content;
        String::from_utf8_lossy(content.of(self.text.bytes()))
            .trim()
            .to_string()
    }

    pub fn hover(&self, position: lsp::Position) -> Option<lsp::Hover> {
        let at = self.offset(position);
        let source = self.text.bytes();
        if let Some(site) = self.calls().find(|site| contains(site.statement, at)) {
            let machine = self.settings.machine.as_deref();
            let table = crate::report::call::call_table(
                site,
                self.name,
                source,
                &self.settings.emit,
                machine,
            );
            let mut text = format!("```\n{table}```");
            // As `eval --machine` adds: where the head's axes go.
            let on_machine = self.settings.machine.as_ref().and_then(|machine| {
                let positions = crate::report::swivel::swivel_text(site, machine)?;
                Some(format!("\n\nOn `{}`: {positions}", machine.name))
            });
            text.extend(on_machine);
            return Some(markdown(text, self.range(site.statement)));
        }
        if let Some(hover) = self.cycle800_hover(at) {
            return Some(hover);
        }
        if let Some(hover) = self.function_hover(at) {
            return Some(hover);
        }
        let Some(found) = self.uses().at(at) else {
            return self.run_hover(position.line as usize);
        };
        let text = match self.uses().definition(self.model, found) {
            Some(definition) if definition.span == found.span => {
                let users = self.uses().references(found).count() - 1;
                format!("{}: used {users} times", self.describe(found))
            }
            Some(definition) => format!(
                "{}, defined on line {}:\n```\n{}\n```",
                self.describe(found),
                definition.row + 1,
                self.line_text(definition.row)
            ),
            None => self.elsewhere(found),
        };
        let text = match found.namespace {
            Namespace::Variable => text + &self.variable_facts(found),
            _ => text,
        };
        // An R parameter's value above, what R parameters are below.
        let r_parameter = found.namespace == Namespace::Variable
            && crate::semantic::vocabulary::is_r_parameter(found.name.as_bytes());
        let language = r_parameter
            .then(|| crate::semantic::vocabulary::word(found.name.as_bytes()))
            .flatten();
        let text = match language {
            Some(word) => format!("{text}\n\n{} ({})", word.meaning, word.manual),
            None => text,
        };
        Some(markdown(text, self.range(found.span)))
    }

    /// On a block, given a machine whose data describe its axes: where the
    /// dry run (`sinuprep run`) takes each machine axis by the block's end,
    /// the first time the program passes it, and the time so far; a block
    /// past a software limit says so.
    fn run_hover(&self, row: usize) -> Option<lsp::Hover> {
        let machine = self.settings.machine.as_deref()?;
        let setup = Setup::of(&MachineData::read(&machine.source)).with_records(&machine.machine);
        if setup.axes.iter().all(|a| a.machine.is_none()) {
            return None;
        }
        let options = crate::run::Options {
            block_limit: 1_000_000,
            ..crate::run::Options::default()
        };
        let programs = Programs::alone(self.model);
        let mut passed: Option<(Vec<Option<f64>>, f64)> = None;
        let report = crate::run::run(
            &programs,
            &setup,
            &self.settings.supplied,
            &options,
            |end| {
                if passed.is_none() && end.program.is_none() && end.line == row + 1 {
                    passed = Some((end.mcs.to_vec(), end.t_s));
                }
            },
        );
        let (mcs, t) = passed?;
        let positions: Vec<String> = setup
            .axes
            .iter()
            .zip(&mcs)
            .filter_map(|(axis, v)| {
                Some(format!(
                    "{} {}",
                    axis.machine_name(),
                    crate::number::format((*v)?, 3)
                ))
            })
            .collect();
        if positions.is_empty() {
            return None;
        }
        let mut text = format!(
            "Dry run on `{}`, at the block's end (its first pass): {}; {} s so far",
            machine.name,
            positions.join(" · "),
            crate::number::format(t, 3)
        );
        for violation in report
            .violations
            .iter()
            .filter(|v| v.program.is_none() && v.line == row + 1)
        {
            text.push_str(&format!(
                "\n\n**{} past its software limit** {} (reaches {})",
                violation.axis,
                crate::number::format(violation.limit, 3),
                crate::number::format(violation.value, 3)
            ));
        }
        let line = self.model.lines.raw(row).content;
        Some(markdown(text, self.range(line)))
    }

    /// On a variable: the type its DEF or PROC gives it, and the value it
    /// holds at this use as the CYCLE600 walk finds it offline, with where
    /// that comes from; a value the walk cannot know is said to be unknown,
    /// with why.
    fn variable_facts(&self, found: &Use) -> String {
        let mut text = String::new();
        let declared = self
            .uses()
            .definition(self.model, found)
            .and_then(|definition| self.declaration(definition));
        if let Some((data_type, parameter)) = &declared {
            text.push_str(&format!("\n\nType: `{data_type}`"));
            if *parameter && found.role == Role::Defines {
                text.push_str("\n\nValue: given by the caller");
                return text;
            }
        }
        // Gone stale while the walk was made: no one reads this answer.
        let Some(values) = self.analysis.values(&found.name, self.settings) else {
            return text;
        };
        let Some(seen) = values.at(found.span) else {
            return text;
        };
        let value = match seen.clone() {
            walk::Seen::Value {
                value: Ok(value),
                origin,
                ..
            } => {
                let shown = crate::report::call::value_text(&Ok(value));
                match origin {
                    Some(origin) => format!("`{shown}`, {origin}"),
                    None => format!("`{shown}`"),
                }
            }
            walk::Seen::Value {
                value: Err(why), ..
            } => why.to_string(),
            walk::Seen::NotReached => {
                "not known offline: the walk does not reach this line".to_string()
            }
            walk::Seen::Differs => {
                "not known offline: it depends on the way the program comes here".to_string()
            }
        };
        let when = if matches!(found.role, Role::Writes | Role::Defines) {
            "Value after this line"
        } else {
            "Value here"
        };
        text.push_str(&format!("\n\n{when}: {value}"));
        text
    }

    /// The type a DEF or a PROC parameter (`true`) gives the name it defines
    /// at `definition`, as written: the model's symbol.
    fn declaration(&self, definition: &Use) -> Option<(String, bool)> {
        let symbol = self
            .model
            .symbols
            .iter()
            .find(|s| s.span == definition.span)?;
        let written = symbol.data_type.span.of(self.text.bytes());
        Some((
            String::from_utf8_lossy(written).into_owned(),
            symbol.parameter,
        ))
    }

    /// On a CYCLE800 call: each parameter's meaning, the plane's tool
    /// axis, and with a machine the rotary axes' positions.
    fn cycle800_hover(&self, at: usize) -> Option<lsp::Hover> {
        let source = self.text.bytes();
        let row = self.text.position(at, ColumnUnit::Bytes).row - 1;
        let block = self.model.lines.block(row)?;
        let (statement, call) =
            block
                .statements
                .iter()
                .find_map(|statement| match &statement.kind {
                    StatementKind::Call(call)
                        if call.name.is(source, "CYCLE800") && contains(statement.span, at) =>
                    {
                        Some((statement.span, call))
                    }
                    _ => None,
                })?;
        if call.arguments.items.iter().all(|a| a.value.is_none()) {
            let text = "**CYCLE800()**, without arguments: takes the swivel plane back, as CAM \
                        post-processors write it to end a tilted plane (no Siemens text found \
                        says exactly what it resets; `sinuprep run` takes the swivel frame and \
                        the tool carrier's offsets back and leaves the rotary axes where they are)";
            return Some(markdown(text.to_string(), self.range(statement)));
        }
        let mut text =
            String::from("**CYCLE800**, swivel plane\n\n| | argument | meaning |\n|---|---|---|\n");
        for parameter in cycle800::describe(source, call) {
            let written = parameter.written.replace('|', "\\|");
            text.push_str(&format!(
                "| `{}` | {written} | {} |\n",
                parameter.name, parameter.meaning
            ));
        }
        if let Some(asked) = crate::semantic::swivels::of_cycle800(source, call) {
            let z = asked.rotation * nalgebra::Vector3::z();
            let n = |v: f64| crate::number::format(v, 6);
            text.push_str(&format!(
                "\nTool axis of the new plane, in the frame before it: ({}, {}, {})\n",
                n(z.x),
                n(z.y),
                n(z.z)
            ));
            if let Some(machine) = &self.settings.machine {
                let positions = crate::report::swivel::swivel_on(&asked, machine);
                text.push_str(&format!("\nOn `{}`: {positions}\n", machine.name));
            }
        }
        Some(markdown(text, self.range(statement)))
    }

    /// On a word of the language (a keyword, command, function, procedure,
    /// a G or M function, a system variable), what it does or holds, and
    /// the manual that says so; on a cycle's name, what it does and its
    /// parameters. A name the program defines for itself, and an R
    /// parameter the table of uses holds (whose hover gives its value), are
    /// left to the hover on names.
    fn function_hover(&self, at: usize) -> Option<lsp::Hover> {
        use crate::semantic::highlight::Class;
        use crate::semantic::{cycles, vocabulary};
        let row = self.text.position(at, ColumnUnit::Bytes).row - 1;
        let tokens = crate::semantic::highlight::tokens(self.model, self.uses(), row..row + 1);
        let token = tokens
            .into_iter()
            .find(|t| t.span.start <= at && at < t.span.end.max(t.span.start + 1))?;
        let word = token.span.of(self.text.bytes());
        let found = self.uses().at(token.span.start);
        let defined_here =
            found.is_some_and(|found| self.uses().definition(self.model, found).is_some());
        // `STOPRE` or `SUPA` alone is coloured as a name: the table of uses
        // says whether it is one.
        let text = match token.class {
            Class::Function | Class::Variable if defined_here => return None,
            Class::SystemVariable if found.is_some() && vocabulary::is_r_parameter(word) => {
                return None
            }
            Class::Function => match cycles::cycle(word) {
                Some(cycle) => {
                    let mut text = format!(
                        "**{}**: {} ({})\n\n| | parameter | meaning |\n|---|---|---|\n",
                        cycle.name, cycle.what, cycle.manual
                    );
                    for (place, parameter) in cycle.parameters.iter().enumerate() {
                        text.push_str(&format!(
                            "| {} | `{}` | {} |\n",
                            place + 1,
                            parameter.name,
                            parameter.meaning.replace('|', "\\|")
                        ));
                    }
                    text
                }
                None => vocabulary::explain(word)?,
            },
            Class::Keyword | Class::SystemVariable | Class::Variable | Class::Address => {
                vocabulary::explain(word)?
            }
            _ => return None,
        };
        Some(markdown(text, self.range(token.span)))
    }

    /// A name the program does not define: where the control finds it.
    fn elsewhere(&self, found: &Use) -> String {
        let environment = &self.settings.environment;
        let procedure = environment.procedures.get(&found.name);
        match (found.namespace, procedure, self.defined_elsewhere(found)) {
            (Namespace::Subprogram, Some(procedure), Some((file, _))) => format!(
                "{}: PROC in `{}`, {} parameter(s)",
                self.describe(found),
                file.display(),
                procedure.parameters.len()
            ),
            (Namespace::Subprogram, Some(procedure), None) => format!(
                "{}: a subprogram of an archive, {} parameter(s)",
                self.describe(found),
                procedure.parameters.len()
            ),
            (_, _, Some((file, _))) => {
                format!("{}: defined in `{}`", self.describe(found), file.display())
            }
            _ => format!("{}: not defined in this program", self.describe(found)),
        }
    }

    fn describe(&self, found: &Use) -> String {
        let what = match (found.namespace, found.role) {
            (Namespace::Label, Role::JumpsTo) => "jump to",
            (Namespace::Label, _) => "label",
            (Namespace::Variable, _) => "variable",
            (Namespace::Subprogram, Role::Defines) => "PROC",
            (Namespace::Subprogram, _) => "call of",
        };
        format!("{what} `{}`", found.name)
    }

    /// The definition in this program, or for a subprogram it does not
    /// define, the PROC of the file the control would call.
    pub fn definition(&self, uri: &lsp::Uri, position: lsp::Position) -> Option<lsp::Location> {
        let found = self.uses().at(self.offset(position))?;
        match self.uses().definition(self.model, found) {
            Some(definition) => Some(lsp::Location::new(uri.clone(), self.range(definition.span))),
            None => {
                let (file, span) = self.defined_elsewhere(found)?;
                let text = Text::new(crate::workspace::file::read(file).ok()?);
                let uri = convert::uri(file)?;
                Some(lsp::Location::new(
                    uri,
                    convert::range(&text, *span, self.unit),
                ))
            }
        }
    }

    /// Where a name the program does not define is defined, as the control
    /// finds it: a subprogram's PROC in the program's folder or the cycle
    /// directories, a GUD variable or a macro in the definition files.
    fn defined_elsewhere(&self, found: &Use) -> Option<&(std::path::PathBuf, Span)> {
        let environment = &self.settings.environment;
        match found.namespace {
            Namespace::Subprogram => environment.procedures.get(&found.name)?.defined.as_ref(),
            Namespace::Variable => environment.defined_in.get(&found.name),
            Namespace::Label => None,
        }
    }

    pub fn references(
        &self,
        uri: &lsp::Uri,
        position: lsp::Position,
        with_declaration: bool,
    ) -> Vec<lsp::Location> {
        let Some(found) = self.uses().at(self.offset(position)) else {
            return Vec::new();
        };
        self.uses()
            .references(found)
            .filter(|u| with_declaration || u.role != Role::Defines)
            .map(|u| lsp::Location::new(uri.clone(), self.range(u.span)))
            .collect()
    }

    /// PROCs, labels and DEF variables, and the CYCLE600 calls.
    #[allow(deprecated)] // `DocumentSymbol::deprecated` must still be written.
    pub fn symbols(&self) -> Vec<lsp::DocumentSymbol> {
        let defined = self.uses().all().iter().filter(|u| u.role == Role::Defines);
        let mut symbols: Vec<lsp::DocumentSymbol> = defined
            .filter_map(|u| {
                let kind = match u.namespace {
                    Namespace::Subprogram => lsp::SymbolKind::FUNCTION,
                    Namespace::Variable => lsp::SymbolKind::VARIABLE,
                    // Block numbers are every line's: only labels are named.
                    Namespace::Label if is_block_number(&u.name) => return None,
                    Namespace::Label => lsp::SymbolKind::KEY,
                };
                Some(symbol(
                    u.name.clone(),
                    kind,
                    self.range(u.span),
                    self.range(u.span),
                ))
            })
            .collect();
        for site in self.calls() {
            let range = self.range(site.statement);
            symbols.push(symbol(
                "CYCLE600".to_string(),
                lsp::SymbolKind::EVENT,
                range,
                range,
            ));
        }
        symbols.sort_by_key(|s| (s.range.start.line, s.range.start.character));
        symbols
    }

    /// IF ... ENDIF, WHILE, FOR, LOOP, REPEAT ... UNTIL.
    pub fn folding(&self) -> Vec<lsp::FoldingRange> {
        let mut ranges: Vec<lsp::FoldingRange> = self
            .model
            .blocks
            .closed()
            .iter()
            .map(|block| lsp::FoldingRange {
                start_line: block.row as u32,
                end_line: block.end as u32,
                ..lsp::FoldingRange::default()
            })
            .collect();
        ranges.extend(self.comment_runs().map(|(first, last)| lsp::FoldingRange {
            start_line: first as u32,
            end_line: last as u32,
            kind: Some(lsp::FoldingRangeKind::Comment),
            ..lsp::FoldingRange::default()
        }));
        ranges.sort_by_key(|r| (r.start_line, r.end_line));
        ranges
    }

    /// Runs of two or more lines that hold only a comment: their first and
    /// last line.
    fn comment_runs(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        let source = self.text.bytes();
        let lines = &self.model.lines;
        let is_comment = move |row: usize| {
            let content = lines.raw(row).content.of(source);
            let first = content.iter().position(|b| !b.is_ascii_whitespace());
            first.is_some_and(|at| content[at] == b';')
        };
        let mut row = 0;
        std::iter::from_fn(move || {
            while row < lines.len() {
                let first = row;
                while row < lines.len() && is_comment(row) {
                    row += 1;
                }
                if row - first >= 2 {
                    return Some((first, row - 1));
                }
                row += 1;
            }
            None
        })
    }

    /// Within `range`: each finding's fix, a suppression comment for each
    /// finding, and the rewrite of each CYCLE600 that can be written as
    /// native code (the edits `rewrite` makes); when `only` asks for source
    /// actions (the editor's "fix on save", its source action menu), every
    /// safe fix of the document at once.
    pub fn code_actions(
        &self,
        uri: &lsp::Uri,
        range: lsp::Range,
        only: Option<&[lsp::CodeActionKind]>,
    ) -> Vec<lsp::CodeActionOrCommand> {
        let wanted = convert::span(self.text, range, self.unit);
        let touches = |span: Span| span.start <= wanted.end && wanted.start <= span.end;
        let mut actions = Vec::new();
        for found in self.findings.iter().filter(|found| touches(found.span)) {
            let diagnostic = convert::diagnostic(self.text, uri, found, self.unit);
            if let Some(fix) = &found.fix {
                let safe = fix.applicability == crate::diagnostic::Applicability::Safe;
                let mut action =
                    self.action(uri, &fix.title, &fix.edits, lsp::CodeActionKind::QUICKFIX);
                action.diagnostics = Some(vec![diagnostic.clone()]);
                action.is_preferred = Some(safe);
                actions.push(lsp::CodeActionOrCommand::CodeAction(action));
            }
            if let Some(edit) = self.suppression(found) {
                let title = format!("Ignore {} on this line", found.code());
                let mut action = self.action(uri, &title, &[edit], lsp::CodeActionKind::QUICKFIX);
                action.diagnostics = Some(vec![diagnostic]);
                actions.push(lsp::CodeActionOrCommand::CodeAction(action));
            }
        }
        let source = |kind: &lsp::CodeActionKind| {
            let kind = kind.as_str();
            FIX_ALL.starts_with(kind) && (kind == "source" || kind.starts_with("source."))
        };
        if only.is_some_and(|only| only.iter().any(source)) {
            actions.extend(self.fix_all(uri).map(lsp::CodeActionOrCommand::CodeAction));
        }
        for site in self.calls().filter(|site| touches(site.statement)) {
            let options = &self.settings.emit;
            let machine = self.settings.machine.as_deref();
            if let Some(edits) =
                crate::emit::cycle600::call_edits(self.model, site, options, machine)
            {
                let title = format!("Rewrite this CYCLE600 as {}", options.form.native());
                let kind = lsp::CodeActionKind::REFACTOR_REWRITE;
                actions.push(lsp::CodeActionOrCommand::CodeAction(
                    self.action(uri, &title, &edits, kind),
                ));
            }
        }
        actions
    }

    /// Every safe fix of the document at once, as `check --fix` makes them
    /// (the library's [`Opened::fixes`]: an archive program by program);
    /// `None` when there is nothing to fix. Its kind, `source.fixAll.sinuprep`,
    /// is what an editor asks for to fix on save.
    fn fix_all(&self, uri: &lsp::Uri) -> Option<lsp::CodeAction> {
        let bytes = self.text.bytes();
        let opened = Opened::read(bytes, self.name).ok()?;
        let fixes = if opened.archive.is_some() {
            // The archive's findings are placed in it; its programs' own,
            // at their own offsets, are what the fixes are made from.
            let outcomes: Vec<_> = opened
                .programs(bytes)
                .iter()
                .map(|program| program.document.check_outcome(self.settings))
                .collect();
            opened.fixes(bytes, outcomes.iter().map(|o| &o.diagnostics[..]), false)
        } else {
            opened.fixes(bytes, [self.findings], false)
        };
        if fixes.edits.is_empty() {
            return None;
        }
        let s = if fixes.answered == 1 { "" } else { "s" };
        let title = format!("Fix all: {} finding{s} (sinuprep)", fixes.answered);
        let kind = lsp::CodeActionKind::new(FIX_ALL);
        Some(self.action(uri, &title, &fixes.edits, kind))
    }

    fn action(
        &self,
        uri: &lsp::Uri,
        title: &str,
        edits: &[crate::edit::Edit],
        kind: lsp::CodeActionKind,
    ) -> lsp::CodeAction {
        let edits = edits
            .iter()
            .map(|edit| lsp::TextEdit {
                range: self.range(edit.span),
                new_text: String::from_utf8_lossy(&edit.text).into_owned(),
            })
            .collect();
        lsp::CodeAction {
            title: title.to_string(),
            kind: Some(kind),
            edit: Some(lsp::WorkspaceEdit {
                changes: Some(std::iter::once((uri.clone(), edits)).collect()),
                ..lsp::WorkspaceEdit::default()
            }),
            ..lsp::CodeAction::default()
        }
    }

    /// `; sinuprep: ignore CODE` at the end of the finding's line, or in its
    /// comment; none where the comment already holds a `sinuprep:` text
    /// (the first one on a line is the one read).
    fn suppression(&self, found: &Diagnostic) -> Option<crate::edit::Edit> {
        let source = self.text.bytes();
        let row = self.text.position(found.span.start, ColumnUnit::Bytes).row - 1;
        let content = self.model.lines.raw(row).content;
        let directive = format!("sinuprep: ignore {}", found.code());
        let comment = self.model.lines.block(row).and_then(|block| block.comment);
        let (at, text) = match comment {
            Some(comment) => {
                let text = String::from_utf8_lossy(comment.of(source)).to_ascii_lowercase();
                if text.contains("sinuprep:") {
                    return None;
                }
                (comment.end, format!(" {directive}"))
            }
            None if content.is_empty() => (content.end, format!("; {directive}")),
            None => (content.end, format!(" ; {directive}")),
        };
        Some(crate::edit::Edit::replace(Span::new(at, at), text))
    }
}

impl Snapshot<'_, '_> {
    /// The name under the cursor, if it can be renamed here.
    pub fn prepare_rename(&self, position: lsp::Position) -> Result<lsp::Range, String> {
        if let Some(shared) = self.shared_name(position) {
            return Ok(self.range(shared.span));
        }
        let found = self
            .uses()
            .at(self.offset(position))
            .ok_or("no name of this program here")?;
        self.renamable(found)?;
        Ok(self.range(found.span))
    }

    /// Every use of the name under the cursor renamed `new_name`: refused
    /// for a name defined outside this program that the programs do not
    /// share (a shared one is [`Self::rename_across`]'s), for a block number (renumbering is no rename), for a
    /// name the control would not take, and for one this program already
    /// uses for another thing of the same kind.
    pub fn rename(
        &self,
        uri: &lsp::Uri,
        position: lsp::Position,
        new_name: &str,
    ) -> Result<lsp::WorkspaceEdit, String> {
        let found = self
            .uses()
            .at(self.offset(position))
            .ok_or("no name of this program here")?;
        self.renamable(found)?;
        refuse_new_name(new_name)?;
        let upper = new_name.to_ascii_uppercase();
        if upper != found.name
            && self
                .uses()
                .all()
                .iter()
                .any(|u| u.namespace == found.namespace && u.name == upper)
        {
            return Err(format!("`{new_name}` is already a name of this program"));
        }
        let edits = self
            .uses()
            .references(found)
            .map(|u| lsp::TextEdit::new(self.range(u.span), new_name.to_string()))
            .collect();
        Ok(lsp::WorkspaceEdit {
            changes: Some(std::iter::once((uri.clone(), edits)).collect()),
            ..lsp::WorkspaceEdit::default()
        })
    }

    fn renamable(&self, found: &Use) -> Result<(), String> {
        if found.namespace == Namespace::Label && is_block_number(&found.name) {
            return Err("a block number is renumbered, not renamed".to_string());
        }
        if !self
            .uses()
            .references(found)
            .any(|u| u.role == Role::Defines)
        {
            return Err(format!(
                "`{}` is not defined in this program: renaming it here would leave its other files",
                found.name
            ));
        }
        Ok(())
    }

    /// The class of each word, for the client to colour: of the lines
    /// `range` touches, or of the whole document; refused past
    /// [`MOST_COLOURED_BYTES`], the editor's own colours staying.
    pub fn semantic_tokens(
        &self,
        range: Option<lsp::Range>,
    ) -> Result<lsp::SemanticTokens, String> {
        let lines = self.model.lines.len();
        let rows = match range {
            Some(range) => range.start.line as usize..(range.end.line as usize + 1).min(lines),
            None => 0..lines,
        };
        let bytes = match (rows.start, rows.end.checked_sub(1)) {
            (first, Some(last)) if first <= last => {
                self.model.lines.raw(last).full().end - self.model.lines.raw(first).content.start
            }
            _ => 0,
        };
        if bytes > MOST_COLOURED_BYTES {
            return Err(format!(
                "sinuprep colours at most {} MB of a program at once; {:.1} MB were asked for \
                 (the editor's own highlighting stays; a range of lines is coloured)",
                MOST_COLOURED_BYTES / 1_000_000,
                bytes as f64 / 1e6
            ));
        }
        let tokens = crate::semantic::highlight::tokens(self.model, self.uses(), rows);
        Ok(lsp::SemanticTokens {
            result_id: None,
            data: convert::semantic_tokens(self.text, &tokens, self.unit),
        })
    }

    /// After each CYCLE600 evaluated offline, the angles it computes; after
    /// each CYCLE800's constant `_MODE`, what it makes of the angles.
    pub fn inlay_hints(&self, range: lsp::Range) -> Vec<lsp::InlayHint> {
        let wanted = convert::span(self.text, range, self.unit);
        let precision = self.settings.emit.precision.min(4);
        let n = |v: f64| crate::number::format(v, precision);
        let mut hints: Vec<lsp::InlayHint> = self
            .calls()
            .filter(|site| wanted.start <= site.statement.end && site.statement.start <= wanted.end)
            .filter_map(|site| {
                let evaluation = site.evaluation.as_ref()?;
                let [a, b, c] = evaluation.output.angles;
                let sequence = &evaluation.parameters.output;
                let label = format!("→ {sequence} {} {} {}", n(a), n(b), n(c));
                Some(self.hint(site.statement.end, label))
            })
            .collect();
        hints.extend(self.cycle800_modes(wanted));
        hints.sort_by_key(|hint| (hint.position.line, hint.position.character));
        hints
    }

    fn cycle800_modes(&self, wanted: Span) -> Vec<lsp::InlayHint> {
        if !crate::semantic::mentions_cycle(self.text.bytes(), b"800") {
            return Vec::new();
        }
        let source = self.text.bytes();
        let first = self.text.position(wanted.start, ColumnUnit::Bytes).row - 1;
        let last = self.text.position(wanted.end, ColumnUnit::Bytes).row - 1;
        let mut hints = Vec::new();
        for row in first..=last.min(self.model.lines.len().saturating_sub(1)) {
            let Some(block) = self.model.lines.block(row) else {
                continue;
            };
            for statement in &block.statements {
                let StatementKind::Call(call) = &statement.kind else {
                    continue;
                };
                let Some(argument) = call.arguments.items.get(3) else {
                    continue;
                };
                if !call.name.is(source, "CYCLE800") || argument.value.is_none() {
                    continue;
                }
                let arguments = cycle800::Arguments::of(source, call);
                if let Some(mode) = arguments.number(3).and_then(cycle800::Mode::of) {
                    hints.push(self.hint(argument.span.end, mode.to_string()));
                }
            }
        }
        hints
    }

    fn hint(&self, at: usize, label: String) -> lsp::InlayHint {
        lsp::InlayHint {
            position: convert::position(self.text, at, self.unit),
            label: lsp::InlayHintLabel::String(label),
            kind: None,
            text_edits: None,
            tooltip: None,
            padding_left: Some(true),
            padding_right: None,
            data: None,
        }
    }
}

/// A name the control takes for a variable or a label: 2 to 31 characters,
/// letters, digits and underscores, the first two letters or underscores
/// (Programming Manual Fundamentals, "Variables": user-defined names).
/// Why `new_name` cannot be a user's name, if it cannot.
pub(super) fn refuse_new_name(new_name: &str) -> Result<(), String> {
    if !is_user_name(new_name) {
        return Err(format!(
            "`{new_name}` is not a name the control takes: up to 31 letters, digits and \
             underscores, the first two letters or underscores"
        ));
    }
    if is_language_word(new_name.as_bytes()) || is_machine_axis(new_name.as_bytes()) {
        return Err(format!(
            "`{new_name}` is a word of the language (a keyword, function, command, cycle \
             or machine axis), not a name the control takes for a user's"
        ));
    }
    Ok(())
}

fn is_user_name(name: &str) -> bool {
    let bytes = name.as_bytes();
    (2..=31).contains(&bytes.len())
        && bytes[..2]
            .iter()
            .all(|b| b.is_ascii_alphabetic() || *b == b'_')
        && bytes
            .iter()
            .all(|b| b.is_ascii_alphanumeric() || *b == b'_')
}

fn is_block_number(name: &str) -> bool {
    name.strip_prefix('N').is_some_and(is_number)
}

fn contains(span: Span, at: usize) -> bool {
    (span.start..=span.end).contains(&at)
}

fn is_number(text: &str) -> bool {
    !text.is_empty() && text.bytes().all(|b| b.is_ascii_digit())
}

fn markdown(value: String, range: lsp::Range) -> lsp::Hover {
    lsp::Hover {
        contents: lsp::HoverContents::Markup(lsp::MarkupContent {
            kind: lsp::MarkupKind::Markdown,
            value,
        }),
        range: Some(range),
    }
}

#[allow(deprecated)] // `DocumentSymbol::deprecated` must still be written.
fn symbol(
    name: String,
    kind: lsp::SymbolKind,
    range: lsp::Range,
    selection_range: lsp::Range,
) -> lsp::DocumentSymbol {
    lsp::DocumentSymbol {
        name,
        detail: None,
        kind,
        tags: None,
        deprecated: None,
        range,
        selection_range,
        children: None,
    }
}
