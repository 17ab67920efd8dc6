//! `sinuprep eval`: for each CYCLE600 call, what it evaluates to and why, so
//! a user can check the numbers before the program goes to the control.

use crate::cli::analysis;
use crate::cli::args::EvalArgs;
use crate::cli::axes;
use crate::cli::error::CliError;
use crate::cli::input::{binary, named_or_stdin, read, skip_binary, Found};
use crate::cli::parallel;
use crate::cli::render::printable;
use crate::cli::walk::files;
use crate::cli::{write_stdout, ExitStatus};
use crate::document::archive::Opened;
use crate::emit::cycle600::{code_on, Options};
use crate::emit::number::format;
use crate::emit::split::{
    about_tool_line, describe, head_frame_document, head_frame_line, positioning, table_line,
};
use crate::kinematics::{Record, Swivel};
use crate::semantic::cycle600::{Argument, Provenance};
use crate::semantic::swivels::{self, Asked, OnMachine, Unsolved};
use crate::semantic::value::Value;
use crate::semantic::CallSite;
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
                        let mut call = json(site, source, options, machine.as_deref());
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
                    table(
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

/// A swivel solved on its record, or why it could not be.
type Solved = Result<(Record, Swivel), String>;

/// A swivel asked of the machine, solved on the record it names.
fn solve_asked(asked: &Asked, machine: &OnMachine) -> Solved {
    match swivels::solve_on(asked, &machine.machine) {
        Ok((record, swivel)) => Ok((record.clone(), swivel)),
        Err(Unsolved::NoRecord) => Err(format!(
            "{} defines no record `{}`",
            machine.name, asked.record
        )),
        Err(Unsolved::Unusable(_, error)) => Err(format!("record `{}`: {error}", asked.record)),
    }
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

/// Where the rotary axes go for a swivel asked of `machine`, or why they
/// cannot (an editor's hover on a CYCLE800 shows it).
pub(crate) fn swivel_on(asked: &Asked, machine: &OnMachine) -> String {
    solved_text(&solve_asked(asked, machine))
}

fn solved_text(solved: &Solved) -> String {
    match solved {
        Err(why) => why.clone(),
        Ok((record, swivel)) => axes::taken(record, swivel),
    }
}

fn solved_json(solved: &Solved) -> serde_json::Value {
    match solved {
        Err(why) => serde_json::json!({ "error": why }),
        Ok((record, swivel)) => axes::document(record, swivel),
    }
}

/// Where a call's swivel takes the machine's axes, in one line (an
/// editor's hover on a CYCLE600 shows it); a split, [`swivel_lines`] joined.
pub(crate) fn swivel_text(site: &CallSite, machine: &OnMachine) -> Option<String> {
    let asked = swivels::of_cycle600(site)?;
    if swivels::split_on(&asked, machine).is_some() {
        return Some(swivel_lines(site, machine)?.join("; "));
    }
    Some(solved_text(&solve_asked(&asked, machine)))
}

/// What `eval` prints of a call's swivel on the machine: the positions the
/// head record takes, or, with a table under the head, the split as `axes
/// --table` prints it (the table and its block, the head's frame in the
/// call's `_MODE`, the head's positions, the rotation about the tool).
fn swivel_lines(site: &CallSite, machine: &OnMachine) -> Option<Vec<String>> {
    let asked = swivels::of_cycle600(site)?;
    let Some(over) = swivels::split_on(&asked, machine) else {
        return Some(vec![format!(
            "axes     {}",
            solved_text(&solve_asked(&asked, machine))
        )]);
    };
    let split = match &over.split {
        Ok(split) => split,
        Err(error) => {
            return Some(vec![format!(
                "table    record {} under record {}: {error}",
                describe(over.table),
                describe(over.head)
            )])
        }
    };
    let mut lines = vec![table_line(over.table, split)];
    lines.extend(positioning(over.table, split).map(|block| format!("table block: {block}")));
    lines.push(head_frame_line(asked.sequence, split));
    lines.push(format!("axes     {}", axes::taken(over.head, &split.head)));
    lines.extend(split.head.residual.as_ref().map(about_tool_line));
    Some(lines)
}

/// A call's swivel on the machine as JSON: `axes --json`'s object, with a
/// table under the head its `table` and `head_frame` too.
fn swivel_json(site: &CallSite, machine: &OnMachine) -> serde_json::Value {
    let Some(asked) = swivels::of_cycle600(site) else {
        return serde_json::Value::Null;
    };
    let Some(over) = swivels::split_on(&asked, machine) else {
        return solved_json(&solve_asked(&asked, machine));
    };
    match &over.split {
        Err(error) => {
            serde_json::json!({ "error": format!("record `{}` under record `{}`: {error}", describe(over.table), describe(over.head)) })
        }
        Ok(split) => {
            let mut document = axes::document(over.head, &split.together());
            document["table"] = axes::table_document(over.table, split);
            document["head_frame"] = head_frame_document(asked.sequence, split);
            document
        }
    }
}

/// A value as `eval` prints it (an editor's hover on a variable too).
pub(crate) fn value_text(value: &Result<Value, crate::semantic::value::Unknown>) -> String {
    match value {
        Ok(Value::Number(n)) => format(*n, 9),
        Ok(Value::Text(t)) => format!("\"{t}\""),
        Err(_) => "unknown".to_string(),
    }
}

/// The arguments in the order they stand in the call (the 19-value form's
/// reserved value is the 14th).
fn in_call_order(bound: &crate::semantic::cycle600::Bound) -> Vec<&Argument> {
    let mut arguments: Vec<&Argument> = bound.reserved.iter().chain(&bound.arguments).collect();
    arguments.sort_by_key(|a| a.span.start);
    arguments
}

fn provenance_text(argument: &Argument) -> String {
    match (&argument.provenance, &argument.value) {
        (_, Err(why)) => why.to_string(),
        (Provenance::Empty, _) => "empty: 0".to_string(),
        (Provenance::Literal, _) => "literal".to_string(),
        (Provenance::Expression, _) => "expression".to_string(),
        (
            Provenance::Variable {
                key,
                origin: Some(origin),
            },
            _,
        ) => format!("{key}: {origin}"),
        (Provenance::Variable { key, origin: None }, _) => key.clone(),
    }
}

/// The table `eval` prints for one call (an editor's hover shows it).
pub(crate) fn call_table(
    site: &CallSite,
    name: &str,
    source: &[u8],
    options: &Options,
    machine: Option<&OnMachine>,
) -> String {
    let mut out = String::new();
    let index = LineIndex::new(source);
    table(site, name, source, &index, options, machine, &mut out);
    out
}

fn table(
    site: &CallSite,
    name: &str,
    source: &[u8],
    index: &LineIndex,
    options: &Options,
    machine: Option<&OnMachine>,
    out: &mut String,
) {
    let row = index.position(site.statement.start).row;
    out.push_str(&format!(
        "{name}:{row}: {}\n",
        String::from_utf8_lossy(site.statement.of(source))
    ));
    if let Some(bound) = &site.bound {
        out.push_str(&format!(
            "  {:<10} {:<14} {:<16} {}\n",
            "parameter", "argument", "value", "from"
        ));
        for argument in in_call_order(bound) {
            out.push_str(&format!(
                "  {:<10} {:<14} {:<16} {}\n",
                argument.name,
                argument.text,
                value_text(&argument.value),
                provenance_text(argument)
            ));
        }
    }
    match &site.evaluation {
        None => out.push_str("  not evaluated offline (see the diagnostics)\n"),
        Some(evaluation) => {
            let p = &evaluation.parameters;
            let n = |v: f64| format(v, options.precision);
            let angles = |a: [f64; 3]| a.map(n).join("  ");
            out.push_str(&format!(
                "  input    {} (code {})  {}\n",
                p.input,
                p.input.code(),
                angles(p.angles)
            ));
            out.push_str(&format!(
                "  output   {} (code {})  {}\n",
                p.output,
                p.output.code(),
                angles(evaluation.output.angles)
            ));
            out.push_str(&format!(
                "  other    {}\n",
                angles(evaluation.output.alternative)
            ));
            if p.additive {
                let how = if evaluation.additive_on_control {
                    "added on the control to the active rotation (unknown offline)"
                } else {
                    "composed with the active rotation"
                };
                out.push_str(&format!("  additive {how}\n"));
            }
            let m = evaluation.target.matrix();
            for r in 0..3 {
                let label = if r == 0 { "matrix" } else { "" };
                out.push_str(&format!(
                    "  {label:<8} {:>10.6} {:>10.6} {:>10.6}\n",
                    m[(r, 0)] + 0.0,
                    m[(r, 1)] + 0.0,
                    m[(r, 2)] + 0.0
                ));
            }
            let gud: Vec<String> = evaluation
                .gud()
                .iter()
                .enumerate()
                .map(|(i, v)| match v {
                    Value::Number(x) => format!("_CYC600_{}={}", i + 1, n(*x)),
                    Value::Text(t) => format!("_CYC600_{}=\"{t}\"", i + 1),
                })
                .collect();
            out.push_str(&format!("  results  {}\n", gud.join(" ")));
            match code_on(site, evaluation, options, machine) {
                Ok(blocks) => {
                    for (i, block) in blocks.iter().enumerate() {
                        out.push_str(&format!(
                            "  {:<8} {block}\n",
                            if i == 0 { "emits" } else { "" }
                        ));
                    }
                }
                Err(problem) => out.push_str(&format!("  emits    nothing: {}\n", problem.message)),
            }
        }
    }
    out.push('\n');
}

fn json(
    site: &CallSite,
    source: &[u8],
    options: &Options,
    machine: Option<&OnMachine>,
) -> serde_json::Value {
    let arguments: Vec<serde_json::Value> = site
        .bound
        .iter()
        .flat_map(in_call_order)
        .map(|a| {
            let value = match &a.value {
                Ok(Value::Number(n)) => serde_json::json!(n),
                Ok(Value::Text(t)) => serde_json::json!(t),
                Err(_) => serde_json::Value::Null,
            };
            serde_json::json!({ "name": a.name, "text": a.text, "value": value, "from": provenance_text(a), "offset": a.span.start, "length": a.span.len() })
        })
        .collect();
    let evaluation = site.evaluation.as_ref().map(|e| {
        let m = e.target.matrix();
        let matrix = [0, 1, 2].map(|r| [0, 1, 2].map(|c| m[(r, c)] + 0.0));
        let results: Vec<serde_json::Value> = e
            .gud()
            .iter()
            .map(|v| match v {
                Value::Number(n) => serde_json::json!(n),
                Value::Text(t) => serde_json::json!(t),
            })
            .collect();
        serde_json::json!({
            "input": { "sequence": e.parameters.input.to_string(), "code": e.parameters.input.code(), "angles": e.parameters.angles },
            "output": { "sequence": e.parameters.output.to_string(), "code": e.parameters.output.code(), "angles": e.output.angles, "alternative": e.output.alternative, "gimbal_lock": e.output.gimbal_lock },
            "matrix": matrix,
            "additive_on_control": e.additive_on_control,
            "results": results,
            "emits": code_on(site, e, options, machine).ok(),
        })
    });
    serde_json::json!({
        "line": site.line + 1,
        "call": String::from_utf8_lossy(site.statement.of(source)),
        "arguments": arguments,
        "evaluation": evaluation,
        "diagnostics": site.diagnostics.iter().map(|d| serde_json::json!({ "code": d.code(), "severity": d.severity, "message": d.message })).collect::<Vec<_>>(),
    })
}
