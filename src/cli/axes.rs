//! `sinuprep axes`: one swivel computed on a machine, for people and for
//! scripts: both solutions with their axis positions, limits and Hirth
//! error, the one the control takes, the rotation left in the frame, the
//! zero-point shift. With a table under the head (`--table`), the split:
//! the table's position and its block, the frame left to the head as
//! CYCLE800 angles, and how far a work zero moves with the table. It
//! computes and prints; it writes no program.

use std::path::{Path, PathBuf};

use nalgebra::Vector3;

use crate::cli::analysis::MachinesTold;
use crate::cli::args::{AxesArgs, Export, MessageFormat, Prefer};
use crate::cli::error::CliError;
use crate::cli::{write_stdout, ExitStatus};
use crate::emit::split::{
    about_tool_line, describe, head_frame_document, head_frame_line, n, positioning, table_line,
};
use crate::kinematics::{
    a3200, solve, split, split_nearest_either_way, Direction, Preference, Record, Request, Split,
    Swivel, TableAsk,
};
use crate::number::format;
use crate::report::swivel::{document, table_document};
use crate::rotation::{matrix, Kind, Sequence};
use crate::semantic::machine::Machine;
use crate::workspace::{Config, Given, Workspace};

pub fn run(args: &AxesArgs) -> Result<ExitStatus, CliError> {
    if let Some(path) = &args.from_a3200 {
        return from_a3200(path, args.record.as_deref());
    }
    if args.mode & !63 != 0 {
        return Err(CliError::Mode(args.mode));
    }
    let sequence =
        Sequence::from_code(args.mode, Kind::Intrinsic).map_err(|_| CliError::Mode(args.mode))?;
    // The machine file is read as every command reads it.
    let workspace = Workspace::new(Given {
        config: args.config.clone(),
        machine: args.machine.clone(),
        fine_offsets: args.fine_offsets,
        ..Given::default()
    })?;
    let config = Config::find(args.config.as_deref(), Path::new("."))?;
    let on = workspace.machine(&config)?.ok_or(CliError::NoMachine)?;
    let data = MachinesTold::default().tell(Some(&on), MessageFormat::Human);
    let path = PathBuf::from(&on.name);
    let machine = &on.machine;
    let mut record = pick(machine, args.record.as_deref(), &path)?.clone();
    record.direction_axis = args.reference_axis.map(|axis| usize::from(axis) - 1);
    if let Some(Export::A3200) = args.export {
        let setup = a3200::setup_of(&record).map_err(|error| CliError::A3200 {
            path: path.clone(),
            why: format!("record {}: {error}", describe(&record)),
        })?;
        write_stdout(setup.text().as_bytes())?;
        return Ok(ExitStatus::Success.max(data));
    }
    let angles = [args.angles[0], args.angles[1], args.angles[2]];
    // The table `--table` names, or else sinuprep.toml's under a head.
    let table = match args.table.as_deref() {
        Some(name) => Some(pick(machine, Some(name), &path)?),
        None => on.table_under(&record),
    };
    // Where the axes stand before: `--from`, else $TC_CARR13/14.
    let mut current = record.specified();
    let mut table_current = table.map_or(0.0, |table| table.axes[0].angle);
    for given in &args.from {
        let (index, value) = from_position(given, &record, table, &path)?;
        match index {
            Some(i) => current[i] = value,
            None => table_current = value,
        }
    }
    let mut request = Request {
        rotation: matrix(sequence, angles),
        direction: if args.dir.unwrap_or(-1) > 0 {
            Direction::Plus
        } else {
            Direction::Minus
        },
        current,
    };
    let refused = |record: &Record, error: &dyn std::fmt::Display| CliError::Record {
        path: path.clone(),
        why: format!("record {}: {error}", describe(record)),
    };
    // Whether `_DIR` was chosen over both head solutions.
    let mut either_way = false;
    let (swivel, split) = match table {
        None => (
            solve(&record, &request).map_err(|error| refused(&record, &error))?,
            None,
        ),
        Some(table) => {
            let fixed = args
                .fix
                .as_deref()
                .map(|fix| fixed_position(fix, table, &path))
                .transpose()?;
            let ask = TableAsk {
                current: table_current,
                fixed,
                prefer: match args.prefer {
                    Prefer::Middle => Preference::Middle,
                    Prefer::Nearest => Preference::Nearest,
                },
            };
            either_way = args.dir.is_none() && args.prefer == Prefer::Nearest && fixed.is_none();
            let split = match (args.dir, args.prefer, fixed) {
                // `_DIR` left open: the nearer of both head solutions.
                (None, Prefer::Nearest, None) => {
                    let (split, direction) =
                        split_nearest_either_way(table, &record, &request, table_current)
                            .map_err(|error| refused(table, &error))?;
                    request.direction = direction;
                    split
                }
                _ => {
                    split(table, &record, &request, &ask).map_err(|error| refused(table, &error))?
                }
            };
            (split.together(), Some((table, split)))
        }
    };
    // The `_DIR` taken: as given, or the one the nearest split chose.
    let dir: i8 = match request.direction {
        Direction::Plus => 1,
        Direction::Minus => -1,
    };
    let work_zero = Vector3::from(args.work_zero.unwrap_or([0.0; 3]));
    let text = match (&split, args.json) {
        (None, true) => json(&record, &swivel),
        (None, false) => table_text(&record, sequence, angles, dir, &swivel),
        (Some((table_record, split)), true) => {
            let mut document = document(&record, &swivel);
            document["table"] = table_document(table_record, split);
            document["head_frame"] = head_frame_document(sequence, split);
            document["work_zero"] = serde_json::json!({
                "at": [work_zero.x, work_zero.y, work_zero.z],
                "moves": vector(&split.work_zero_moves(&work_zero)),
                "chain_end_moves": vector(&split.shift),
            });
            document["dir"] = serde_json::json!(dir);
            document["dir_chosen"] = serde_json::json!(either_way);
            format!(
                "{}\n",
                serde_json::to_string_pretty(&document).unwrap_or_default()
            )
        }
        (Some((table_record, split)), false) => {
            let mut text = table_text(&record, sequence, angles, dir, &swivel);
            if either_way {
                text.push_str(&format!(
                    "_DIR={dir:+} chosen: its head solution travels least of both (--dir fixes _DIR)\n"
                ));
            }
            let mut lines = table_lines(table_record, split);
            lines.push_str(&head_frame_line(sequence, split));
            lines.push('\n');
            // After the record's line and the frame's: the table is part
            // of the machine, and the head is asked for what it leaves.
            let at = text
                .match_indices('\n')
                .nth(1)
                .map_or(text.len(), |(n, _)| n + 1);
            text.insert_str(at, &lines);
            text.push_str(&work_zero_line(&work_zero, split));
            text
        }
    };
    write_stdout(text.as_bytes())?;
    let table_inside = split.as_ref().is_none_or(|(_, s)| s.table_within_limits);
    let found = if swivel.chosen.is_some() && table_inside {
        ExitStatus::Success
    } else {
        ExitStatus::Failure
    };
    Ok(found.max(data))
}

/// `--from-a3200 FILE`: the record an A3200 setup determines, as the
/// control's `$TC_CARRn[m]=value` assignments (record `--record` when it is
/// a number, else 1, named by `--record` when it is a name).
fn from_a3200(path: &Path, record: Option<&str>) -> Result<ExitStatus, CliError> {
    let text = crate::workspace::file::read(path).map_err(|source| CliError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    let refused = |error: a3200::A3200Error| CliError::A3200 {
        path: path.to_path_buf(),
        why: error.to_string(),
    };
    let setup = a3200::Setup::read(&String::from_utf8_lossy(&text)).map_err(refused)?;
    let mut found = a3200::record_of(&setup).map_err(refused)?;
    match record.map(str::trim) {
        Some(number) if number.parse::<u32>().is_ok_and(|n| n > 0) => {
            found.number = number.parse().unwrap_or(1);
        }
        Some(name) => {
            found.name = crate::cli::args::record_name(name).map_err(|why| CliError::A3200 {
                path: path.to_path_buf(),
                why: format!("--record {name:?}: {why}"),
            })?;
        }
        None => {}
    }
    let text = assignments(&found);
    // What is written is what a machine file reads: the record read back
    // with the reader `check --machine` uses, anything it says refused.
    let read = crate::semantic::machine::Machine::read(text.as_bytes(), Default::default());
    if let Some(said) = read.diagnostics.first() {
        return Err(CliError::A3200 {
            path: path.to_path_buf(),
            why: format!("the record it gives would not read back: {}", said.message),
        });
    }
    write_stdout(text.as_bytes())?;
    Ok(ExitStatus::Success)
}

/// A record as the control holds it: what the record has, in the shape of
/// `samples/MACHINE.SPF`.
fn assignments(record: &Record) -> String {
    let m = record.number;
    let value = |n: u32, v: f64| format!("$TC_CARR{n}[{m}]={}", v + 0.0);
    let text = |n: u32, t: &str| format!("$TC_CARR{n}[{m}]=\"{t}\"");
    let mut head = vec![text(23, &record.kinematics.letter().to_string())];
    if !record.name.is_empty() {
        head.push(text(34, &record.name));
    }
    for (n, axis) in [35, 36].into_iter().zip(&record.axes) {
        if !axis.name.is_empty() {
            head.push(text(n, &axis.name));
        }
    }
    let vector = |first: u32, v: &Vector3<f64>| {
        (0..3)
            .map(|i| value(first + i as u32, v[i]))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let [l1, l2, l3, l4] = &record.offsets;
    let lines = [
        head.join(" "),
        vector(7, &record.axes[0].vector),
        vector(10, &record.axes[1].vector),
        vector(1, l1),
        vector(4, l2),
        vector(15, l3),
        vector(18, l4),
    ];
    format!("{}\n", lines.join("\n"))
}

/// `--from B=10`: which axis (`None`: the table's, else the head's 0 or 1)
/// and its position.
fn from_position(
    given: &str,
    head: &Record,
    table: Option<&Record>,
    path: &Path,
) -> Result<(Option<usize>, f64), CliError> {
    let refused = |why: String| CliError::Record {
        path: path.to_path_buf(),
        why,
    };
    let mut names: Vec<(Option<usize>, String)> = (0..head.axis_count())
        .map(|i| (Some(i), head.axes[i].label(i)))
        .collect();
    if let Some(table) = table {
        names.insert(0, (None, table.axes[0].label(0)));
    }
    let known = names
        .iter()
        .map(|(_, name)| format!("`{name}`"))
        .collect::<Vec<_>>()
        .join(", ");
    let (name, value) = given.split_once('=').ok_or_else(|| {
        refused(format!(
            "`--from {given}`: write an axis and its position, as `--from {}=30`",
            names.first().map_or("A", |(_, name)| name.as_str())
        ))
    })?;
    let index = names
        .iter()
        .find(|(_, known)| known.eq_ignore_ascii_case(name.trim()))
        .map(|(index, _)| *index)
        .ok_or_else(|| {
            refused(format!(
                "`--from {given}`: no rotary axis `{}` here; the axes are {known}",
                name.trim()
            ))
        })?;
    let value = degrees(value).map_err(|why| refused(format!("`--from {given}`: {why}")))?;
    Ok((index, value))
}

/// `--fix B=30`: the table's position; the name must be the table axis's.
fn fixed_position(fix: &str, table: &Record, path: &Path) -> Result<f64, CliError> {
    let label = table.axes[0].label(0);
    let refused = |why: String| CliError::Record {
        path: path.to_path_buf(),
        why,
    };
    let (name, value) = fix.split_once('=').ok_or_else(|| {
        refused(format!(
            "`--fix {fix}`: write the table's axis and its position, as `--fix {label}=30`"
        ))
    })?;
    if !name.trim().eq_ignore_ascii_case(&label) {
        return Err(refused(format!(
            "`--fix {fix}`: the table {} turns axis `{label}`",
            describe(table)
        )));
    }
    degrees(value).map_err(|why| refused(format!("`--fix {fix}`: {why}")))
}

/// `value` as a number of degrees, within ±1e9 as every angle given.
fn degrees(value: &str) -> Result<f64, String> {
    match value.trim().parse::<f64>() {
        Ok(degrees) if degrees.is_finite() => crate::cli::notation::angle(degrees),
        _ => Err(format!("`{}` is no number of degrees", value.trim())),
    }
}

/// The table's part of a split: its position and how it was found, and
/// the block that positions it.
fn table_lines(table: &Record, split: &Split) -> String {
    let mut out = format!("{}\n", table_line(table, split));
    if let Some(block) = positioning(table, split) {
        out.push_str(&format!("table block: {block}\n"));
    }
    out
}

fn work_zero_line(at: &Vector3<f64>, split: &Split) -> String {
    let moves = split.work_zero_moves(at);
    format!(
        "work zero at X{} Y{} Z{} moves by X{} Y{} Z{} with the table (its chain's end by the zero-point shift)\n",
        n(at.x),
        n(at.y),
        n(at.z),
        n(moves.x),
        n(moves.y),
        n(moves.z)
    )
}

fn vector(v: &Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// The record asked for, or the only one with rotary axes.
fn pick<'m>(
    machine: &'m Machine,
    name: Option<&str>,
    path: &std::path::Path,
) -> Result<&'m Record, CliError> {
    let names: Vec<String> = machine.usable().map(describe).collect();
    let refused = |why: String| CliError::Record {
        path: path.to_path_buf(),
        why,
    };
    match name {
        Some(name) => machine.record(name).ok_or_else(|| {
            let known: Vec<&str> = machine.usable().map(|r| r.name.as_str()).collect();
            let meant = crate::suggest::closest(name, &known, 3)
                .map(|m| format!(" (did you mean `{m}`?)"))
                .unwrap_or_default();
            refused(format!(
                "no record `{name}`{meant}; the file defines {}",
                list(&names)
            ))
        }),
        None => {
            let mut usable = machine.usable();
            match (usable.next(), usable.next()) {
                (Some(only), None) => Ok(only),
                (None, _) => Err(refused("no record with a rotary axis".into())),
                _ => Err(refused(format!(
                    "{} records: name one with --record ({})",
                    names.len(),
                    names.join(", ")
                ))),
            }
        }
    }
}

fn list(names: &[String]) -> String {
    if names.is_empty() {
        "none with a rotary axis".into()
    } else {
        names.join(", ")
    }
}

fn kinematics_name(record: &Record) -> &'static str {
    match record.kinematics {
        crate::kinematics::Kinematics::Head => "head",
        crate::kinematics::Kinematics::Table => "table",
        crate::kinematics::Kinematics::Mixed => "mixed",
    }
}

fn table_text(
    record: &Record,
    sequence: Sequence,
    angles: [f64; 3],
    dir: i8,
    swivel: &Swivel,
) -> String {
    let count = record.axis_count();
    let labels: Vec<String> = (0..count).map(|i| record.axes[i].label(i)).collect();
    let reference = record.direction_reference();
    let mut out = format!(
        "record {}: {} {} ({}), _DIR refers to {}\n",
        describe(record),
        record.kinematics.letter(),
        kinematics_name(record),
        labels.join(", "),
        labels[reference.min(count - 1)],
    );
    let [a, b, c] = angles.map(n);
    out.push_str(&format!(
        "frame: {} {a} {b} {c} (_MODE {})\n",
        sequence.letters(),
        sequence.code()
    ));
    if swivel.solutions.is_empty() {
        out.push_str(
            "unreachable: no position of the rotary axes turns the tool onto the frame's Z axis\n",
        );
        return out;
    }
    for (index, solution) in swivel.solutions.iter().enumerate() {
        let positions: Vec<String> = (0..count)
            .map(|i| format!("{}={}", labels[i], n(solution.positions[i])))
            .collect();
        let mut notes = Vec::new();
        if !solution.within_limits {
            notes.push("outside the limits".to_string());
        }
        if solution.hirth_error_deg > 0.0 {
            notes.push(format!(
                "Hirth grid turns the tool {}°",
                format(solution.hirth_error_deg, 6)
            ));
        }
        out.push_str(&format!(
            "solution {}: {}{}\n",
            index + 1,
            positions.join(" "),
            if notes.is_empty() {
                String::new()
            } else {
                format!("  ({})", notes.join("; "))
            }
        ));
    }
    let sign = if dir > 0 {
        "+1, the higher"
    } else {
        "-1, the lower"
    };
    match swivel.chosen {
        Some(index) => out.push_str(&format!(
            "taken: solution {} (_DIR={sign} {})\n",
            index + 1,
            labels[reference.min(count - 1)]
        )),
        None => out.push_str("taken: none, no solution lies inside the limits\n"),
    }
    if let (Some(residual), Some(shift)) = (swivel.residual, swivel.shift) {
        out.push_str(&format!(
            "{}\nzero-point shift: X{} Y{} Z{}\n",
            about_tool_line(&residual),
            n(shift.x),
            n(shift.y),
            n(shift.z)
        ));
    }
    out
}

fn json(record: &Record, swivel: &Swivel) -> String {
    format!(
        "{}\n",
        serde_json::to_string_pretty(&document(record, swivel)).unwrap_or_default()
    )
}
