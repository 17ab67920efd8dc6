//! A swivel split over a rotary table and the head above it, in the words
//! `axes --table`, `eval` and the rewrite's refusal (C620) share: where the
//! table goes and the block that takes it there, the head's frame as
//! CYCLE800 angles, the head's positions, the rotation left about the tool.
//! It words what `kinematics::split` computed; it writes no program, since
//! no native form of such a split is documented (`sinuprep rule C620`).

use nalgebra::Rotation3;

use crate::diagnostic::Diagnostic;
use crate::kinematics::{Preference, Record, Split, Swivel, TableAngle};
use crate::number::format;
use crate::registry::cycle600_split_over_table;
use crate::rotation::{decompose, Sequence};
use crate::semantic::swivels::{Asked, OverTable};

/// A position or an angle as these lines print it: four decimals.
pub fn n(value: f64) -> String {
    format(value, 4)
}

/// A record as a program names it: `HEAD_CA`, or its number.
fn called(record: &Record) -> String {
    if record.name.is_empty() {
        record.number.to_string()
    } else {
        record.name.clone()
    }
}

/// `2 (HEAD_CA)`, or the number alone.
pub fn describe(record: &Record) -> String {
    if record.name.is_empty() {
        record.number.to_string()
    } else {
        format!("{} ({})", record.number, record.name)
    }
}

/// How the table's angle was found, in a few words.
pub fn how(found: TableAngle) -> String {
    match found {
        TableAngle::Fixed => "fixed by --fix".to_string(),
        TableAngle::Chosen(Preference::Middle) => {
            "chosen: the head nearest the middles of its limits".to_string()
        }
        TableAngle::Chosen(Preference::Nearest) => {
            "chosen: the axes nearest their positions before".to_string()
        }
        TableAngle::Beyond {
            solution,
            beyond_deg,
        } => format!(
            "no table position brings the head inside its limits; this one brings it nearest: solution {} lies {}° beyond them",
            solution + 1,
            format(beyond_deg, 6)
        ),
        TableAngle::Unreachable => {
            "kept: at no table position can the head turn the tool onto the frame's Z axis"
                .to_string()
        }
    }
}

/// The table's line: its record, position, and how it was found.
pub fn table_line(table: &Record, split: &Split) -> String {
    let limits = if split.table_within_limits {
        ""
    } else {
        ", outside its limits"
    };
    format!(
        "table: record {}: {}={} ({}{limits})",
        describe(table),
        table.axes[0].label(0),
        n(split.table),
        how(split.found)
    )
}

/// The block that turns the table to its position, rapid and absolute;
/// `None` for a table axis without a name (`$TC_CARR35`).
pub fn positioning(table: &Record, split: &Split) -> Option<String> {
    let name = &table.axes[0].name;
    (!name.is_empty()).then(|| format!("G0 {name}={}", n(split.table)))
}

/// What the table leaves the head as CYCLE800 angles in `sequence`.
pub fn head_frame_angles(sequence: Sequence, split: &Split) -> [f64; 3] {
    decompose(sequence, &split.head_frame).angles
}

/// The head's frame in one line.
pub fn head_frame_line(sequence: Sequence, split: &Split) -> String {
    let [a, b, c] = head_frame_angles(sequence, split).map(n);
    format!(
        "head frame: {} {a} {b} {c} (_MODE {}): the frame with the table's turn taken out, CYCLE800's on the head's record",
        sequence.letters(),
        sequence.code()
    )
}

/// The head frame as JSON: `_MODE`, its letters and the angles.
pub fn head_frame_document(sequence: Sequence, split: &Split) -> serde_json::Value {
    serde_json::json!({
        "mode": sequence.code(),
        "sequence": sequence.letters(),
        "angles": head_frame_angles(sequence, split),
    })
}

/// The angle (degrees) of a residual about the tool axis, all there is of
/// it when the tool direction is met.
pub fn about_tool(residual: &Rotation3<f64>) -> f64 {
    residual.matrix()[(1, 0)]
        .atan2(residual.matrix()[(0, 0)])
        .to_degrees()
}

/// The rotation left about the tool, in one line.
pub fn about_tool_line(residual: &Rotation3<f64>) -> String {
    format!(
        "left in the frame: {}° about the tool axis",
        n(about_tool(residual))
    )
}

/// The positions the head takes: `C=0 A=20.7048`; `None` when no
/// solution lies inside its limits.
pub fn head_positions(head: &Record, swivel: &Swivel) -> Option<String> {
    let solution = &swivel.solutions[swivel.chosen?];
    Some(
        (0..head.axis_count())
            .map(|i| format!("{}={}", head.axes[i].label(i), n(solution.positions[i])))
            .collect::<Vec<_>>()
            .join(" "),
    )
}

/// C620: the rewrite writes no code for a swivel on a head with a table
/// under it, and says what the split would tell the machine.
pub fn refusal(asked: &Asked, over: &OverTable) -> Diagnostic {
    let (table, head) = (over.table, over.head);
    let head_name = called(head);
    let what = match &over.split {
        Err(error) => format!("the split cannot be computed: {error}"),
        Ok(split) => {
            let block = positioning(table, split)
                .unwrap_or_else(|| format!("{}={}", table.axes[0].label(0), n(split.table)));
            let found = match split.found {
                TableAngle::Chosen(_) => String::new(),
                found => format!(" ({})", how(found)),
            };
            let [a, b, c] = head_frame_angles(asked.sequence, split).map(n);
            let positions = head_positions(head, &split.head).map_or_else(
                || "no position inside its limits".to_string(),
                |positions| format!("to {positions}"),
            );
            let about = split
                .head
                .residual
                .as_ref()
                .map(|residual| format!(", {}° left about the tool axis", n(about_tool(residual))))
                .unwrap_or_default();
            format!(
                "the table to `{block}`{found}, then CYCLE800 on `{head_name}` with {} {a} {b} {c} (_MODE {}), its axes {positions}{about}",
                asked.sequence.letters(),
                asked.sequence.code()
            )
        }
    };
    cycle600_split_over_table::RULE
        .at(asked.span)
        .message(format!(
            "`{head_name}` has the rotary table `{}` under it (--table): the swivel splits over three rotary axes, {what}; no code is written, since no native form of such a split is documented",
            called(table)
        ))
        .label("a swivel over three rotary axes")
        .help("CYCLE800 drives one swivel data record (two rotary axes at most), and no Siemens text confirms that a table turned before it keeps its turn in the frame: position the table and swivel the head as the message says by hand, or keep CYCLE600 (`sinuprep rule C620`)")
}
