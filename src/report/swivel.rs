//! A swivel in words and as JSON: where a CYCLE600's or a CYCLE800's swivel
//! takes the machine's rotary axes (`axes`, `eval`, an editor's hover),
//! with a table under the head the split as `axes --table` words it.

use nalgebra::{Rotation3, Vector3};

use crate::emit::split::{
    about_tool, about_tool_line, describe, head_frame_document, head_frame_line, n, positioning,
    table_line,
};
use crate::kinematics::{Record, Split, Swivel, TableAngle};
use crate::number::format;
use crate::semantic::swivels::{self, Asked, OnMachine, Unsolved};
use crate::semantic::CallSite;

/// A swivel solved on its record, or why it could not be.
pub type Solved = Result<(Record, Swivel), String>;

/// A swivel asked of the machine, solved on the record it names.
pub fn solve_asked(asked: &Asked, machine: &OnMachine) -> Solved {
    match swivels::solve_on(asked, &machine.machine) {
        Ok((record, swivel)) => Ok((record.clone(), swivel)),
        Err(Unsolved::NoRecord) => Err(format!(
            "{} defines no record `{}`",
            machine.name, asked.record
        )),
        Err(Unsolved::Unusable(_, error)) => Err(format!("record `{}`: {error}", asked.record)),
    }
}

/// Where the rotary axes go for a swivel asked of `machine`, or why they
/// cannot (an editor's hover on a CYCLE800 shows it).
pub fn swivel_on(asked: &Asked, machine: &OnMachine) -> String {
    solved_text(&solve_asked(asked, machine))
}

pub fn solved_text(solved: &Solved) -> String {
    match solved {
        Err(why) => why.clone(),
        Ok((record, swivel)) => taken(record, swivel),
    }
}

pub fn solved_json(solved: &Solved) -> serde_json::Value {
    match solved {
        Err(why) => serde_json::json!({ "error": why }),
        Ok((record, swivel)) => document(record, swivel),
    }
}

/// Where a call's swivel takes the machine's axes, in one line (an
/// editor's hover on a CYCLE600 shows it); a split, [`swivel_lines`] joined.
pub fn swivel_text(site: &CallSite, machine: &OnMachine) -> Option<String> {
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
pub fn swivel_lines(site: &CallSite, machine: &OnMachine) -> Option<Vec<String>> {
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
    lines.push(format!("axes     {}", taken(over.head, &split.head)));
    lines.extend(split.head.residual.as_ref().map(about_tool_line));
    Some(lines)
}

/// A call's swivel on the machine as JSON: `axes --json`'s object, with a
/// table under the head its `table` and `head_frame` too.
pub fn swivel_json(site: &CallSite, machine: &OnMachine) -> serde_json::Value {
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
            let mut document = document(over.head, &split.together());
            document["table"] = table_document(over.table, split);
            document["head_frame"] = head_frame_document(asked.sequence, split);
            document
        }
    }
}

/// The swivel in one line: the record and the positions taken.
pub fn taken(record: &Record, swivel: &Swivel) -> String {
    let count = record.axis_count();
    let head = describe(record);
    if swivel.solutions.is_empty() {
        return format!("record {head}: unreachable, no position of the rotary axes turns the tool onto the frame's Z axis");
    }
    let Some(index) = swivel.chosen else {
        return format!("record {head}: no solution inside the limits");
    };
    let solution = &swivel.solutions[index];
    let positions: Vec<String> = (0..count)
        .map(|i| format!("{}={}", record.axes[i].label(i), n(solution.positions[i])))
        .collect();
    let hirth = if solution.hirth_error_deg > 0.0 {
        format!(
            ", Hirth grid turns the tool {}°",
            format(solution.hirth_error_deg, 6)
        )
    } else {
        String::new()
    };
    format!(
        "record {head}: {} (solution {} of {}{hirth})",
        positions.join(" "),
        index + 1,
        swivel.solutions.len()
    )
}

/// The swivel as the JSON object `axes --json` prints.
pub fn document(record: &Record, swivel: &Swivel) -> serde_json::Value {
    let count = record.axis_count();
    let axes = |positions: [f64; 2]| {
        let mut map = serde_json::Map::new();
        for (i, position) in positions.iter().enumerate().take(count) {
            map.insert(record.axes[i].label(i), serde_json::json!(position));
        }
        serde_json::Value::Object(map)
    };
    let solutions: Vec<serde_json::Value> = swivel
        .solutions
        .iter()
        .map(|s| {
            serde_json::json!({
                "axes": axes(s.positions),
                "exact": axes(s.exact),
                "reachable": true,
                "within_limits": s.within_limits,
                "hirth_error_deg": s.hirth_error_deg,
            })
        })
        .collect();
    let rows = |m: &Rotation3<f64>| {
        (0..3)
            .map(|r| (0..3).map(|c| m.matrix()[(r, c)]).collect::<Vec<f64>>())
            .collect::<Vec<_>>()
    };
    let vector = |v: &Vector3<f64>| [v.x, v.y, v.z];
    serde_json::json!({
        "record": record.name,
        "number": record.number,
        "kinematics": record.kinematics.letter().to_string(),
        "direction_reference": record.axes[record.direction_reference()].label(record.direction_reference()),
        "reachable": !swivel.solutions.is_empty(),
        "solutions": solutions,
        "chosen": swivel.chosen,
        "residual": swivel.residual.as_ref().map(rows),
        "about_tool_deg": swivel.residual.as_ref().map(about_tool),
        "shift": swivel.shift.as_ref().map(vector),
    })
}

pub fn table_document(table: &Record, split: &Split) -> serde_json::Value {
    let (found, prefer, beyond, nearest) = match split.found {
        TableAngle::Fixed => ("fixed", None, None, None),
        TableAngle::Chosen(prefer) => ("chosen", Some(prefer.name()), None, None),
        TableAngle::Beyond {
            solution,
            beyond_deg,
        } => ("beyond", None, Some(beyond_deg), Some(solution)),
        TableAngle::Unreachable => ("unreachable", None, None, None),
    };
    serde_json::json!({
        "record": table.name,
        "number": table.number,
        "axis": table.axes[0].label(0),
        "position": split.table,
        "within_limits": split.table_within_limits,
        "fixed": split.found == TableAngle::Fixed,
        "found": found,
        "prefer": prefer,
        "beyond_deg": beyond,
        "nearest_solution": nearest,
        "block": positioning(table, split),
    })
}
