//! `sinuprep run`: the dry run of one program on the machine its own data
//! describe ([`crate::run`]), printed as a summary, as JSON (every block
//! with `--blocks`, written as the run goes) or as SARIF of the limits
//! passed. A limit passed fails the run (exit 1).

use std::io::{IsTerminal, Write};

use serde_json::json;

use crate::cli::args::{RunArgs, RunFormat};
use crate::cli::error::CliError;
use crate::cli::input::{read, Found};
use crate::cli::output::write_atomically;
use crate::cli::render::{human, FileReport, Located, Sarif};
use crate::cli::{write_stdout, write_stdout_with, ExitStatus};
use crate::diagnostic::Diagnostic;
use crate::machine::MachineData;
use crate::number::format;
use crate::run::{Options, Programs, Report, Setup};
use crate::semantic::Model;
use crate::workspace::{Given, Workspace};

pub fn run(args: &RunArgs) -> Result<ExitStatus, CliError> {
    let workspace = Workspace::new(Given {
        machine: args.machine.clone(),
        definitions: args.definitions.clone(),
        cycles: args.cycles.clone(),
        config: args.input.config.clone(),
        values: args.input.values.clone(),
        set: args.input.set.clone(),
        heads: args.input.heads.clone(),
        ..Given::default()
    })?;
    let file = read(&Found::named(args.path.clone()))?;
    let resolved = workspace.for_check(&args.path)?;
    let on = workspace.machine(&resolved.config)?;
    // Without a machine (or its axis data), the geometry axes alone:
    // positions and frames, no limits, no time.
    let data = MachineData::read(on.as_ref().map_or(&b""[..], |on| &on.source[..]));
    let setup = match &on {
        Some(on) => Setup::of(&data).with_records(&on.machine),
        None => Setup::of(&data),
    };
    let machine_name = on.as_ref().map(|on| on.name.clone());
    let kind = crate::syntax::program_kind(Some(&file.name), &file.bytes);
    let macros = &resolved.settings.environment.expansions;
    let model = Model::build_with(&file.bytes, kind, macros.clone());
    // The subprograms its calls reach, as the control finds them: beside
    // the program, then in the cycle directories.
    let files = workspace.subprogram_files(&resolved.config, &args.path)?;
    let sources = crate::run::subprogram_sources(&model, macros, |name| {
        crate::workspace::file::read(files.get(name)?).ok()
    });
    let programs = Programs::with(&model, &sources, macros);
    let times = match &resolved.config.run {
        Some(run) => run
            .times()
            .map_err(|why| crate::workspace::SettingsError::Config {
                path: resolved.config.path.clone().unwrap_or_default(),
                line: 1,
                column: 1,
                why,
            })?,
        None => Default::default(),
    };
    let (supplied, from_data) =
        crate::run::setup::values_with_data(&resolved.settings.supplied, &data);
    let options = Options {
        values_from_data: from_data,
        dynamic_group: usize::from(args.dynamic_group),
        second_limits: args.second_limits,
        times,
        ..Options::default()
    };
    let supplied = &supplied;
    let names: Vec<String> = setup.axes.iter().map(|a| a.machine_name()).collect();
    // The page's plots, kept as the run goes.
    let mut trace = args
        .html
        .as_ref()
        .map(|_| crate::run::plot::Trace::new(&setup, args.second_limits));
    let mut report = if args.blocks && args.format == RunFormat::Json {
        let mut written = None;
        write_stdout_with(|out| {
            let mut out = std::io::BufWriter::new(out);
            write!(out, "{{\"blocks\": [")?;
            let mut first = true;
            let mut failed: Option<std::io::Error> = None;
            let report = crate::run::run(&programs, &setup, supplied, &options, |end| {
                if let Some(trace) = &mut trace {
                    trace.record(&end);
                }
                if failed.is_some() {
                    return;
                }
                let mcs: serde_json::Map<String, serde_json::Value> = names
                    .iter()
                    .zip(end.mcs)
                    .filter_map(|(name, v)| Some((name.clone(), json!(v.as_ref()?))))
                    .collect();
                let mut block = json!({"line": end.line, "mcs": mcs, "t_s": end.t_s});
                if let Some(program) = end.program {
                    block["program"] = json!(program);
                }
                let comma = if first { "" } else { "," };
                first = false;
                if let Err(error) = write!(out, "{comma}\n  {block}") {
                    failed = Some(error);
                }
            });
            if let Some(error) = failed {
                return Err(error);
            }
            let summary = summary(&report, machine_name.as_deref());
            let text = serde_json::to_string_pretty(&summary).expect("JSON of plain values");
            // The summary's fields after the blocks, in the same object.
            write!(out, "\n],\n{}\n", &text[1..])?;
            out.flush()?;
            written = Some(report);
            Ok(())
        })?;
        match written {
            Some(report) => report,
            None => return Ok(ExitStatus::Success),
        }
    } else {
        crate::run::run(&programs, &setup, supplied, &options, |end| {
            if let Some(trace) = &mut trace {
                trace.record(&end);
            }
        })
    };
    report.violations.sort_by_key(|v| v.line);
    if let (Some(path), Some(trace)) = (&args.html, &trace) {
        let title = match &machine_name {
            Some(machine) => format!("{} on {machine}", file.name),
            None => file.name.clone(),
        };
        let page = crate::run::plot::html(trace, &report, &title);
        write_atomically(path, |out| out.write_all(page.as_bytes()), None)?;
    }
    let status = if report.violations.is_empty() {
        ExitStatus::Success
    } else {
        ExitStatus::Failure
    };
    // The findings by the file their block is in: the program, or a
    // subprogram it calls.
    let mut by_file = vec![Findings {
        name: file.name.clone(),
        path: args.path.clone(),
        source: &file.bytes,
        diagnostics: Vec::new(),
    }];
    for violation in &report.violations {
        let at = match &violation.program {
            None => 0,
            Some(name) => match by_file.iter().skip(1).position(|f| &f.name == name) {
                Some(at) => at + 1,
                None => {
                    let path = files.get(name);
                    let source = sources.iter().find(|(n, _)| n == name);
                    let (Some(path), Some((_, source))) = (path, source) else {
                        continue;
                    };
                    by_file.push(Findings {
                        name: path.display().to_string(),
                        path: path.clone(),
                        source,
                        diagnostics: Vec::new(),
                    });
                    by_file.len() - 1
                }
            },
        };
        by_file[at].diagnostics.push(violation.diagnostic());
    }
    match args.format {
        RunFormat::Json if args.blocks => {}
        RunFormat::Json => {
            let mut text = serde_json::to_string_pretty(&summary(&report, machine_name.as_deref()))
                .expect("JSON of plain values");
            text.push('\n');
            write_stdout(text.as_bytes())?;
        }
        RunFormat::Sarif => {
            let mut sarif = Sarif::default();
            for findings in by_file {
                let mut located =
                    Located::new(&findings.name, findings.source, findings.diagnostics);
                located.path =
                    (findings.path != std::path::Path::new("-")).then_some(findings.path);
                sarif.add(&located);
            }
            write_stdout(sarif.finish().as_bytes())?;
        }
        RunFormat::Human => {
            let mut text = text(&report, &file.name, machine_name.as_deref());
            let colour = crate::cli::colour(std::io::stdout().is_terminal());
            for findings in &by_file {
                let report = FileReport {
                    name: &findings.name,
                    source: findings.source,
                    diagnostics: &findings.diagnostics,
                };
                human(&report, colour, &mut text);
            }
            write_stdout(text.as_bytes())?;
        }
    }
    Ok(status)
}

/// The findings in one file: the program's, or a subprogram's.
struct Findings<'a> {
    /// As reports name it.
    name: String,
    path: std::path::PathBuf,
    source: &'a [u8],
    diagnostics: Vec<Diagnostic>,
}

/// The JSON contract (docs/guide.md).
fn summary(report: &Report, machine: Option<&str>) -> serde_json::Value {
    let upper = report.time_bounds_s[1];
    let axes: serde_json::Map<String, serde_json::Value> = report
        .axes
        .iter()
        .map(|t| {
            (
                t.axis.clone(),
                json!({"min": t.min, "max": t.max, "limits": t.limits}),
            )
        })
        .collect();
    json!({
        "machine": machine,
        "time_s": report.time_s,
        "time_bounds_s": [report.time_bounds_s[0], upper.is_finite().then_some(upper)],
        "blocks_without_time": report.blocks_without_time,
        "tools": report.tools,
        "axes": axes,
        "violations": report.violations,
        "violations_untold": report.violations_untold,
        "unknown": report.unknown,
        "assumptions": report.assumptions,
        "blocks_run": report.blocks,
        "endless": report.endless,
    })
}

/// The summary for people.
fn text(report: &Report, name: &str, machine: Option<&str>) -> String {
    let mut text = match machine {
        Some(machine) => format!("{name} on {machine}: {} blocks run\n", report.blocks),
        None => format!(
            "{name} without a machine (--machine): {} blocks run; no limits, times from the feeds alone\n",
            report.blocks
        ),
    };
    let upper = report.time_bounds_s[1];
    let upper = if upper.is_finite() {
        seconds(upper)
    } else {
        "? (a dynamic datum missing)".to_string()
    };
    text.push_str(&format!(
        "time {} (at least {}, at most {upper})",
        seconds(report.time_s),
        seconds(report.time_bounds_s[0])
    ));
    if report.blocks_without_time > 0 {
        let blocks = match report.blocks_without_time {
            1 => "1 block".to_string(),
            n => format!("{n} blocks"),
        };
        text.push_str(&format!(", {blocks} not timed"));
    }
    text.push('\n');
    if let Some(endless) = &report.endless {
        text.push_str(&endless_text(endless));
    }
    if !report.tools.is_empty() {
        let tools: Vec<String> = report
            .tools
            .iter()
            .map(|t| match t.t.as_str() {
                "none" => format!("no tool {}", seconds(t.time_s)),
                number => format!("T{number} {}", seconds(t.time_s)),
            })
            .collect();
        text.push_str(&format!("per tool: {}\n", tools.join(", ")));
    }
    let value = |v: Option<f64>| v.map_or_else(|| "-".to_string(), |v| format(v, 3));
    for travel in &report.axes {
        text.push_str(&format!(
            "{:<8} {:>12} .. {:<12} limits {} .. {}\n",
            travel.axis,
            value(travel.min),
            value(travel.max),
            value(travel.limits[0]),
            value(travel.limits[1])
        ));
    }
    if report.violations_untold > 0 {
        text.push_str(&format!(
            "note: {} more excursions past a limit than the {} listed below\n",
            report.violations_untold,
            crate::run::MOST_VIOLATIONS
        ));
    }
    for unknown in &report.unknown {
        match (unknown.line, &unknown.program) {
            (0, _) => text.push_str(&format!("note: {}\n", unknown.why)),
            (line, None) => text.push_str(&format!("line {line}: {}\n", unknown.why)),
            (line, Some(program)) => {
                text.push_str(&format!("{program}, line {line}: {}\n", unknown.why))
            }
        }
    }
    for assumption in &report.assumptions {
        text.push_str(&format!("assumed: {assumption}\n"));
    }
    text
}

/// What the summary says of a program that runs until stopped.
fn endless_text(endless: &crate::run::Endless) -> String {
    let place = match &endless.program {
        Some(program) => format!("{program}, line {}", endless.line),
        None => format!("line {}", endless.line),
    };
    let blocks = match endless.pass_blocks {
        1 => "1 block".to_string(),
        n => format!("{n} blocks"),
    };
    let guessed = if endless.rests_on_unknown {
        " as run here, with what it could not know taken as said below (give the values with --set)"
    } else {
        ""
    };
    let counting = match endless.counting.as_slice() {
        [] => String::new(),
        [name] => format!(" but for {name}, which counts on and which nothing else reads"),
        names => format!(
            " but for {}, which count on and which nothing else reads",
            names.join(", ")
        ),
    };
    format!(
        "endless: the jump back from line {} comes to {place} in a state the run was in before{counting}{guessed}: the program repeats every {blocks} ({}) until it is stopped; the figures are of the run until then\n",
        endless.from_line,
        seconds(endless.pass_s),
    )
}

fn seconds(s: f64) -> String {
    if s >= 60.0 {
        format!("{}:{:06.3} min", (s / 60.0).floor(), s % 60.0)
    } else {
        format!("{} s", format(s, 3))
    }
}
