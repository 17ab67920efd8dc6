//! `textDocument/hover`: a CYCLE600's evaluation, a CYCLE800's arguments, a
//! word of the language, a name with its definition and values, a block's
//! dry run.

use lsp_types as lsp;

use crate::run::on_machine::run_on;
use crate::semantic::uses::{Namespace, Role, Use};
use crate::semantic::{cycle800, walk};
use crate::span::ColumnUnit;
use crate::syntax::tree::StatementKind;

use super::{contains, markdown, Snapshot};

impl Snapshot<'_, '_> {
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
        let mut passed: Option<(Vec<Option<f64>>, f64)> = None;
        let supplied = &self.settings.supplied;
        let (setup, report) = run_on(self.model, machine, supplied, |end| {
            if passed.is_none() && end.program.is_none() && end.line == row + 1 {
                passed = Some((end.mcs.to_vec(), end.t_s));
            }
        })?;
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
}
