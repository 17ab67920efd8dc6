//! `sinuprep convert`: a rotation from one form to another (angles of any
//! sequence, matrix, quaternion, axis and angle, Gibbs vector, Sinumerik
//! frame statements, a post-processor's ROT_MAT), given on the command line
//! or read from stdin: one per line for numbers (angle triples side by
//! side), the whole input for statements.

use crate::cli::args::ConvertArgs;
use crate::cli::error::CliError;
use crate::cli::notation::{self, Notation};
use crate::cli::{write_stdout, ExitStatus};
use crate::number::format as fixed;
use crate::rotation::forms::Pose;
use crate::rotation::{convert, convert_all, decompose, Angles, Conversion, Sequence};

pub fn run(args: &ConvertArgs) -> Result<ExitStatus, CliError> {
    let text = match (args.from, args.to) {
        _ if !args.values.is_empty() => single(args, &args.values)?,
        (Notation::Angles(_), Notation::Angles(_)) => batch(args)?,
        _ => each_of_stdin(args)?,
    };
    write_stdout(text.as_bytes())?;
    Ok(ExitStatus::Success)
}

/// The rotation of the command line's values.
fn single(args: &ConvertArgs, values: &[String]) -> Result<String, CliError> {
    if let (Notation::Angles(from), Notation::Angles(to)) = (args.from, args.to) {
        let numbers = notation::numbers(&values.join(" ")).map_err(CliError::Form)?;
        let [a1, a2, a3] = numbers[..] else {
            return Err(CliError::Form(format!(
                "{} numbers where three angles are expected",
                numbers.len()
            )));
        };
        for value in [a1, a2, a3] {
            notation::angle(value).map_err(CliError::Form)?;
        }
        let conversion = convert(from, [a1, a2, a3], to);
        return Ok(if args.json {
            json(to, &conversion)
        } else {
            table(&format!("{from} (code {})", from.code()), to, &conversion)
        });
    }
    let pose = notation::read(args.from, values, false).map_err(CliError::Form)?;
    output(args, &pose)
}

/// `pose`'s rotation in the form asked for.
fn output(args: &ConvertArgs, pose: &Pose) -> Result<String, CliError> {
    if let Notation::Angles(to) = args.to {
        let conversion = Conversion {
            matrix: pose.rotation,
            output: decompose(to, &pose.rotation),
        };
        return Ok(if args.json {
            json(to, &conversion)
        } else {
            table(&args.from.to_string(), to, &conversion)
        });
    }
    let written = notation::write(args.to, pose, false, args.precision).map_err(CliError::Form)?;
    if let Some(warning) = &written.warning {
        tellln!("{warning}");
    }
    Ok(if args.json {
        format!("{}\n", written.json)
    } else {
        written.text
    })
}

/// stdin read whole: one rotation in statements, or one a line in numbers.
fn each_of_stdin(args: &ConvertArgs) -> Result<String, CliError> {
    let input = crate::cli::input::stdin_text(CliError::NoAngles)?;
    if args.from.is_text() {
        return single(args, &[input]);
    }
    let mut text = String::new();
    for (row, line) in input.lines().enumerate() {
        let line = line.split('#').next().unwrap_or_default();
        let at_line = |why: String| CliError::Form(format!("stdin:{}: {why}", row + 1));
        let numbers = notation::numbers(line).map_err(at_line)?;
        if numbers.is_empty() {
            continue;
        }
        let pose = notation::read_numbers(args.from, &numbers, false).map_err(at_line)?;
        text.push_str(&output(args, &pose)?);
    }
    Ok(text)
}

/// Every triple of stdin, converted together (`convert_all`). The whole
/// input is read and checked before anything is printed: a bad line stops
/// the run without a partial output.
fn batch(args: &ConvertArgs) -> Result<String, CliError> {
    let (Notation::Angles(from), Notation::Angles(to)) = (args.from, args.to) else {
        return each_of_stdin(args);
    };
    let triples = read_triples(&crate::cli::input::stdin_text(CliError::NoAngles)?)?;
    let mut text = String::with_capacity(triples.len() * 64);
    for conversion in convert_all(from, &triples, to) {
        if args.json {
            text.push_str(&json(to, &conversion));
        } else {
            let [a, b, c] = conversion.output.angles.map(|v| fixed(v, args.precision));
            let lock = if conversion.output.gimbal_lock {
                " gimbal-lock"
            } else {
                ""
            };
            text.push_str(&format!("{a} {b} {c}{lock}\n"));
        }
    }
    Ok(text)
}

/// One triple of finite angles per line; empty lines and `#` comments skipped.
fn read_triples(text: &str) -> Result<Vec<Angles>, CliError> {
    let mut triples = Vec::new();
    for (row, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or_default();
        let error = |column: usize, why: String| CliError::Angles {
            line: row + 1,
            column: column + 1,
            why,
        };
        let mut numbers = Vec::with_capacity(3);
        let mut at = 0;
        for field in line.split(|c: char| c.is_whitespace() || c == ',') {
            let column = at;
            at += field.len() + 1;
            if field.is_empty() {
                continue;
            }
            match field.parse::<f64>() {
                Ok(value) if value.is_finite() => numbers
                    .push(crate::cli::notation::angle(value).map_err(|why| error(column, why))?),
                _ => return Err(error(column, format!("`{field}` is not a finite angle"))),
            }
        }
        match numbers[..] {
            [] => {}
            [a, b, c] => triples.push([a, b, c]),
            _ => {
                return Err(error(
                    0,
                    format!("{} numbers where three angles are expected", numbers.len()),
                ))
            }
        }
    }
    Ok(triples)
}

fn rows(conversion: &Conversion) -> [[f64; 3]; 3] {
    let m = conversion.matrix.matrix();
    [0, 1, 2].map(|r| [0, 1, 2].map(|c| m[(r, c)] + 0.0))
}

fn json(to: Sequence, conversion: &Conversion) -> String {
    let value = serde_json::json!({
        "angles": conversion.output.angles,
        "alternative": conversion.output.alternative,
        "sequence": to.to_string(),
        "code": to.code(),
        "matrix": rows(conversion),
        "gimbal_lock": conversion.output.gimbal_lock,
    });
    format!("{value}\n")
}

/// For people: the angles and the matrix to six decimals, from `from` (a
/// sequence with its code, or the form's name).
fn table(from: &str, to: Sequence, conversion: &Conversion) -> String {
    let angles = |a: [f64; 3]| a.map(|x| format!("{x:>12.6}")).join(" ");
    let mut text = format!(
        "{from} -> {to} (code {})\n\nangles       {}\nalternative  {}\n\nrotation matrix\n",
        to.code(),
        angles(conversion.output.angles),
        angles(conversion.output.alternative),
    );
    for row in rows(conversion) {
        text.push_str(&format!(
            "  {}\n",
            row.map(|x| format!("{x:>10.6}")).join(" ")
        ));
    }
    if conversion.output.gimbal_lock {
        let letters: Vec<char> = to.axes.iter().map(|a| a.letter()).collect();
        text.push_str(&format!(
            "\nwarning: gimbal lock: the middle rotation aligns the first and third axes ({} and {}), so only their \
             combination is defined; the third angle is set to 0 and the first carries the whole rotation\n",
            letters[0], letters[2]
        ));
    }
    text
}
