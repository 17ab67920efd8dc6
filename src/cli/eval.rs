//! `sinuprep eval`: for each CYCLE600 call, what it evaluates to and why, so
//! a user can check the numbers before the program goes to the control.

use crate::cli::analysis;
use crate::cli::args::EvalArgs;
use crate::cli::error::CliError;
use crate::cli::input::{binary, named_or_stdin, read, skip_binary, Found};
use crate::cli::parallel;
use crate::cli::render::printable;
use crate::cli::walk::files;
use crate::cli::{write_stdout, ExitStatus};
use crate::document::archive::Opened;
use crate::report::call;
use crate::report::swivel::{
    solve_asked, solved_json, solved_text, swivel_json, swivel_lines, Solved,
};
use crate::semantic::swivels::{self, Asked, OnMachine};
use crate::span::LineIndex;
use crate::workspace::{Given, Workspace};
use std::sync::Arc;

pub fn run(args: &EvalArgs) -> Result<ExitStatus, CliError> {
    let named = named_or_stdin(&args.paths, "eval")?;
    let workspace = Workspace::new(Given {
        machine: args.machine.clone(),
        table: args.table.clone(),
        follow_links: args.walk.follow_links,
        fine_offsets: args.fine_offsets,
        walk: args.walk.given(),
        ..analysis::given_to_rewrite(&args.analysis)
    })?;
    let walk = args.walk.walk(&workspace);
    let mut files = files(&named, &walk);
    let mut worst = ExitStatus::Success;
    let mut json = JsonOut::default();
    let mut told = analysis::MachinesTold::default();
    let work = |found: Result<Found, CliError>| eval_file(&found?, args, &workspace);
    // Each file's evaluation printed as soon as it and those before it are done.
    parallel::each(&mut files, work, |outcome| {
        json.file()?;
        match outcome {
            Ok(evaluated) => {
                let format = args.analysis.message_format;
                worst = worst.max(told.tell(evaluated.machine.as_deref(), format));
                tell!("{}", evaluated.diagnostics);
                if evaluated.failed {
                    worst = worst.max(ExitStatus::Failure);
                }
                match evaluated.output {
                    Output::Text(text) => write_stdout(text.as_bytes())?,
                    Output::Json(programs) => programs
                        .into_iter()
                        .try_for_each(|program| json.add(program))?,
                }
            }
            Err(error) => {
                tellln!("{:?}", miette::Report::new(error));
                worst = ExitStatus::Error;
            }
        }
        Ok::<(), CliError>(())
    })?;
    // What ended the walk early is the run's error, once the JSON begun is
    // complete.
    let walked = files.end();
    if args.json {
        json.end()?;
    }
    walked?;
    Ok(worst)
}

/// `--json` on stdout as the programs come: one program's document by
/// itself; several (files, or an archive's programs) an array of them, in
/// order, as `serde_json` prints one. Only the first document waits, until
/// a second file or program says which it is.
#[derive(Default)]
struct JsonOut {
    files: usize,
    /// The first document, while it may be the only one.
    first: Option<serde_json::Value>,
    /// The array's elements written; `None` before it is begun.
    written: Option<usize>,
}

impl JsonOut {
    /// Another file's outcome is coming.
    fn file(&mut self) -> Result<(), CliError> {
        self.files += 1;
        if self.files > 1 {
            self.begin_array()?;
        }
        Ok(())
    }

    fn add(&mut self, document: serde_json::Value) -> Result<(), CliError> {
        if self.written.is_none() && self.first.is_none() {
            self.first = Some(document);
            return Ok(());
        }
        self.begin_array()?;
        self.element(&document)
    }

    /// Writes `[` and the document held, once.
    fn begin_array(&mut self) -> Result<(), CliError> {
        if self.written.is_none() {
            self.written = Some(0);
            write_stdout(b"[")?;
            if let Some(first) = self.first.take() {
                self.element(&first)?;
            }
        }
        Ok(())
    }

    /// One element of the array, indented as in a pretty-printed array (a
    /// JSON text holds no line break but between its tokens).
    fn element(&mut self, document: &serde_json::Value) -> Result<(), CliError> {
        let written = self.written.get_or_insert(0);
        let mut text = String::from(if *written == 0 { "\n" } else { ",\n" });
        *written += 1;
        for (n, line) in pretty(document).lines().enumerate() {
            if n > 0 {
                text.push('\n');
            }
            text.push_str("  ");
            text.push_str(line);
        }
        write_stdout(text.as_bytes())
    }

    fn end(self) -> Result<(), CliError> {
        let text = match (self.written, self.first) {
            (Some(0), _) => "]".to_string(),
            (Some(_), _) => "\n]".to_string(),
            (None, Some(only)) => pretty(&only),
            (None, None) => "[]".to_string(),
        };
        write_stdout(format!("{text}\n").as_bytes())
    }
}

fn pretty(value: &serde_json::Value) -> String {
    serde_json::to_string_pretty(value).unwrap_or_default()
}

enum Output {
    Text(String),
    /// One document per program (an archive holds several).
    Json(Vec<serde_json::Value>),
}

/// One program's evaluation, kept so that the programs come in their order.
struct Evaluated {
    output: Output,
    diagnostics: String,
    failed: bool,
    /// The machine the swivels were solved on, whose findings the run
    /// tells once.
    machine: Option<Arc<OnMachine>>,
}

fn eval_file(found: &Found, args: &EvalArgs, workspace: &Workspace) -> Result<Evaluated, CliError> {
    let path = found.path.as_path();
    let file = read(found)?;
    if binary(&file.bytes) {
        return Ok(Evaluated {
            output: if args.json {
                Output::Json(Vec::new())
            } else {
                Output::Text(String::new())
            },
            diagnostics: skip_binary(found, &file.name, &file.bytes)?,
            failed: false,
            machine: None,
        });
    }
    let resolved = workspace.for_rewrite(path)?;
    let machine = workspace.machine(&resolved.config)?;
    let mut settings = resolved.settings;
    // The rewrite's findings as `rewrite` has them on this machine.
    settings.machine = machine.clone();
    let opened = Opened::read(&file.bytes, &file.name)
        .map_err(|error| CliError::archive(&file.name, error))?;
    opened.settings(&file.bytes, &mut settings);
    let options = &settings.emit;
    let mut evaluated = Evaluated {
        output: if args.json {
            Output::Json(Vec::new())
        } else {
            Output::Text(String::new())
        },
        diagnostics: opened.unchecked(&file.bytes).unwrap_or_default(),
        failed: false,
        machine: machine.clone(),
    };
    for program in opened.programs(&file.bytes) {
        let (name, source) = (program.name.as_str(), program.document.source);
        let analyzed = program.document.rewrite(&settings);
        let format = args.analysis.message_format;
        evaluated.diagnostics += &analysis::report(&analyzed, name, source, format);
        evaluated.failed |= analyzed.has_errors();
        let calls = &analyzed.analysis.calls;
        match &mut evaluated.output {
            Output::Json(documents) => {
                let calls: Vec<serde_json::Value> = calls
                    .iter()
                    .map(|site| {
                        let mut call = call::json(site, source, options, machine.as_deref());
                        if let Some(machine) = &machine {
                            call["axes"] = swivel_json(site, machine);
                        }
                        call
                    })
                    .collect();
                let mut document = serde_json::json!({ "path": name, "calls": calls });
                if let Some(machine) = &machine {
                    let index = LineIndex::new(source);
                    let written: Vec<serde_json::Value> = cycle800_swivels(
                        &program.document,
                        analyzed.model.as_ref(),
                        &settings,
                        machine,
                    )
                    .iter()
                    .map(|(asked, solved)| {
                        serde_json::json!({
                            "line": index.position(asked.span.start).row,
                            "call": String::from_utf8_lossy(asked.span.of(source)),
                            "axes": solved_json(solved),
                        })
                    })
                    .collect();
                    document["cycle800"] = serde_json::Value::Array(written);
                }
                documents.push(document);
            }
            Output::Text(text) => {
                let name = printable(name);
                let name: &str = &name;
                let index = LineIndex::new(source);
                for site in calls {
                    call::table(
                        site,
                        name,
                        source,
                        &index,
                        options,
                        machine.as_deref(),
                        text,
                    );
                    if let Some(machine) = &machine {
                        if let Some(lines) = swivel_lines(site, machine) {
                            // Under the call's table, before its blank line.
                            text.pop();
                            for line in lines {
                                text.push_str(&format!("  {line}\n"));
                            }
                            text.push('\n');
                        }
                    }
                }
                if calls.is_empty() {
                    text.push_str(&format!("{name}: no CYCLE600 call\n"));
                }
                if let Some(machine) = &machine {
                    for (asked, solved) in cycle800_swivels(
                        &program.document,
                        analyzed.model.as_ref(),
                        &settings,
                        machine,
                    ) {
                        let row = index.position(asked.span.start).row;
                        text.push_str(&format!(
                            "{name}:{row}: {}\n  axes     {}\n\n",
                            String::from_utf8_lossy(asked.span.of(source)),
                            solved_text(&solved)
                        ));
                    }
                }
            }
        }
    }
    Ok(evaluated)
}

/// The CYCLE800 calls of a program whose arguments are constants, with the
/// axis positions each takes: found only where a machine is given. The
/// rewrite's model is read when it built one; a program without CYCLE600 is
/// parsed here, once, with the macros of `settings`.
fn cycle800_swivels(
    document: &crate::document::Document,
    model: Option<&crate::semantic::Model>,
    settings: &crate::lint::Settings,
    machine: &OnMachine,
) -> Vec<(Asked, Solved)> {
    if !crate::semantic::mentions_cycle(document.source, b"800") {
        return Vec::new();
    }
    let built;
    let model = match model {
        Some(model) => model,
        None => {
            let macros = settings.environment.expansions.clone();
            built = crate::semantic::Model::build_with(document.source, document.kind, macros);
            &built
        }
    };
    swivels::cycle800_calls(model)
        .into_iter()
        .map(|asked| {
            let solved = solve_asked(&asked, machine);
            (asked, solved)
        })
        .collect()
}
