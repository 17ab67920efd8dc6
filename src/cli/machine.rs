//! `sinuprep machine`: what a machine's own data say, for people and for
//! scripts: the machine axes with their names, software limits and dynamics
//! (`machine::axes`), the swivel data records, how many data were read and
//! what could not be (K006 for machine data, K001 for records), each on its
//! line. It reads and prints; it writes nothing.

use std::io::IsTerminal;

use serde_json::json;

use crate::archive::{MemberKind, Part};
use crate::cli::args::{MachineArgs, MachineFormat};
use crate::cli::error::CliError;
use crate::cli::render::{human, FileReport};
use crate::cli::{write_stdout, ExitStatus};
use crate::diagnostic::Severity;
use crate::machine::{axes, base_frames, frames, tools, Axis, MachineData};
use crate::number::format;
use crate::semantic::machine::{Machine, Reading};
use crate::semantic::Environment;
use crate::span::LineIndex;

pub fn run(args: &MachineArgs) -> Result<ExitStatus, CliError> {
    let path = &args.path;
    let unreadable = |source| CliError::Read {
        path: path.clone(),
        source,
    };
    let shown = path.display().to_string();
    let (setup, (gud, macros)) = if path.is_dir() {
        let files = crate::workspace::file::setup_files(path).map_err(unreadable)?;
        let setup = crate::archive::setup_data_of_files(&shown, &files)
            .map_err(|error| CliError::archive(&shown, error))?;
        let beside = crate::workspace::definitions_beside(&path.join("-"));
        let read: Vec<(String, Vec<u8>)> = beside
            .iter()
            .filter_map(|p| Some((p.display().to_string(), std::fs::read(p).ok()?)))
            .collect();
        (setup, definitions(&read))
    } else {
        let bytes = std::fs::read(path).map_err(unreadable)?;
        let setup = crate::archive::setup_data(&bytes, &shown)
            .map_err(|error| CliError::archive(&shown, error))?;
        let setup = crate::archive::SetupData {
            bytes: std::borrow::Cow::Owned(setup.bytes.into_owned()),
            ..setup
        };
        (setup, definitions(&[(shown.clone(), bytes)]))
    };
    let source = &setup.bytes[..];
    let data = MachineData::read(source);
    let records = Machine::read(source, Reading::default());
    let axes = axes(&data);
    let mut diagnostics = data.diagnostics.clone();
    diagnostics.extend(records.diagnostics.iter().cloned());
    diagnostics.sort_by_key(|d| d.span.start);
    let status = if diagnostics.iter().any(|d| d.severity == Severity::Error) {
        ExitStatus::Failure
    } else {
        ExitStatus::Success
    };
    let by_file = Part::split(&setup.parts, &diagnostics);
    let text = match args.format {
        MachineFormat::Json => {
            let mut unreadable = Vec::new();
            for (part, found) in &by_file {
                let part = &setup.parts[*part];
                let index = LineIndex::new(&source[part.range.clone()]);
                for d in found {
                    let at = index.position(d.span.start);
                    unreadable.push(json!({"file": part.name, "line": at.row, "column": at.column, "code": d.code(), "message": d.message}));
                }
            }
            let records: Vec<_> = records
                .records
                .iter()
                .map(|r| json!({"number": r.number, "name": r.name, "kinematics": r.kinematics.letter().to_string()}))
                .collect();
            let document = json!({
                "machine": setup.name,
                "axes": axes,
                "records": records,
                "frames": frames(&data),
                "base_frames": base_frames(&data),
                "tools": tools(&data),
                "definitions": {"gud": gud, "macros": macros},
                "data": data.data.len(),
                "unreadable": unreadable,
            });
            let mut text = serde_json::to_string_pretty(&document).expect("JSON of plain values");
            text.push('\n');
            text
        }
        MachineFormat::Human => {
            let mut text = table(&setup.name, &axes, &data, &records);
            if gud + macros > 0 {
                text.push_str(&format!(
                    "definitions: {gud} GUD variables, {macros} macros\n"
                ));
            }
            let colour = crate::cli::colour(std::io::stdout().is_terminal());
            for (part, found) in &by_file {
                let part = &setup.parts[*part];
                let report = FileReport {
                    name: &part.name,
                    source: &source[part.range.clone()],
                    diagnostics: found,
                };
                human(&report, colour, &mut text);
            }
            text
        }
    };
    write_stdout(text.as_bytes())?;
    Ok(status)
}

/// How many GUD variables and macros the definition files among `files`
/// (name, bytes) and the definition members of the archives among them
/// define (a member or file that cannot be read is passed over: `check`
/// of it reports why).
fn definitions(files: &[(String, Vec<u8>)]) -> (usize, usize) {
    let mut environment = Environment::default();
    for (name, bytes) in files {
        match crate::archive::read(bytes, name) {
            Some(Ok(archive)) => {
                for member in archive.members {
                    if member.kind == MemberKind::Definitions {
                        let _ = environment.read_definitions(&bytes[member.data], None);
                    }
                }
            }
            Some(Err(_)) => {}
            None if MemberKind::of_name(name) == MemberKind::Definitions => {
                let _ = environment.read_definitions(bytes, None);
            }
            None => {}
        }
    }
    (environment.variables.len(), environment.macros.len())
}

/// The axes as a table, the records as a line each.
fn table(name: &str, axes: &[Axis], data: &MachineData, records: &Machine) -> String {
    let frames = frames(data);
    let mut text = format!(
        "{name}: {} data, {} machine axes, {} swivel data records, {} cutting edges, {} settable frames\n",
        data.data.len(),
        axes.len(),
        records.records.len(),
        tools(data).len(),
        frames.len(),
    );
    if !axes.is_empty() {
        let header = [
            "axis", "machine", "name", "kind", "limits", "limits 2", "velocity", "accel.", "jerk",
        ];
        let mut rows = vec![header.map(str::to_string).to_vec()];
        for axis in axes {
            let kind = match (axis.rotary, axis.modulo) {
                (Some(true), Some(true)) => "rotary, modulo",
                (Some(true), _) => "rotary",
                (Some(false), _) => "linear",
                (None, _) => "?",
            };
            rows.push(vec![
                format!("AX{}", axis.index),
                axis.machine_name.clone().unwrap_or_else(|| "-".into()),
                axis.name.clone().unwrap_or_else(|| "-".into()),
                kind.to_string(),
                pair(axis.limits),
                pair(axis.limits2),
                value(axis.max_velocity),
                values(&axis.max_acceleration),
                values(&axis.max_jerk),
            ]);
        }
        let widths: Vec<usize> = (0..header.len())
            .map(|column| {
                rows.iter()
                    .map(|r| r[column].chars().count())
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        for row in rows {
            let cells: Vec<String> = row
                .iter()
                .zip(&widths)
                .map(|(cell, width)| format!("{cell:<width$}"))
                .collect();
            text.push_str(cells.join("  ").trim_end());
            text.push('\n');
        }
        text.push_str("units as the control stores them: mm (inch) or degrees; velocity mm/min or rev/min; acceleration m/s² or rev/s²; jerk m/s³ or rev/s³, by dynamic response group; `-` where the data hold no value\n");
    }
    let base = base_frames(data);
    let named = frames
        .iter()
        .map(|(name, axes)| (format!("frame {name}"), axes))
        .chain(
            base.iter()
                .map(|(name, axes)| (format!("base frame {name}"), axes)),
        );
    for (name, axes) in named {
        let components: Vec<String> = axes
            .iter()
            .map(|(axis, c)| {
                let parts = [
                    ("TR", c.tr),
                    ("FI", c.fi),
                    ("RT", c.rt),
                    ("SC", c.sc),
                    ("MI", c.mi),
                ];
                let set: Vec<String> = parts
                    .iter()
                    .filter_map(|(what, v)| v.map(|v| format!("{what} {}", format(v, 6))))
                    .collect();
                format!("{axis}: {}", set.join(", "))
            })
            .collect();
        text.push_str(&format!("{name}: {}\n", components.join("; ")));
    }
    for record in &records.records {
        text.push_str(&format!(
            "record {} `{}`: kinematics {}\n",
            record.number,
            record.name,
            record.kinematics.letter()
        ));
    }
    text
}

fn value(value: Option<f64>) -> String {
    value.map_or_else(|| "-".to_string(), |v| format(v, 6))
}

fn pair([low, high]: [Option<f64>; 2]) -> String {
    match (low, high) {
        (None, None) => "-".to_string(),
        _ => format!("{} .. {}", value(low), value(high)),
    }
}

fn values(values: &[Option<f64>]) -> String {
    if values.is_empty() {
        return "-".to_string();
    }
    values
        .iter()
        .map(|v| value(*v))
        .collect::<Vec<_>>()
        .join(" ")
}
