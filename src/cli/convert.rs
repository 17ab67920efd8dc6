//! `sinuprep convert`: angles from one rotation sequence to another, three
//! given on the command line or one triple per line on stdin.

use std::io::{IsTerminal, Read};

use crate::cli::args::ConvertArgs;
use crate::cli::error::CliError;
use crate::cli::{write_stdout, ExitStatus};
use crate::rotation::{convert, convert_all, Angles, Conversion, Sequence};

pub fn run(args: &ConvertArgs) -> Result<ExitStatus, CliError> {
    let text = match args.angles.as_deref() {
        Some(&[a1, a2, a3]) => {
            let conversion = convert(args.from, [a1, a2, a3], args.to);
            if args.json {
                json(args.to, &conversion)
            } else {
                table(args.from, args.to, &conversion)
            }
        }
        _ => batch(args)?,
    };
    write_stdout(text.as_bytes())?;
    Ok(ExitStatus::Success)
}

/// Every triple of stdin, converted together (`convert_all`). The whole
/// input is read and checked before anything is printed: a bad line stops
/// the run without a partial output.
fn batch(args: &ConvertArgs) -> Result<String, CliError> {
    // Waiting for a terminal to type triples would look like a hang.
    if std::io::stdin().is_terminal() {
        return Err(CliError::NoAngles);
    }
    let mut input = Vec::new();
    std::io::stdin()
        .lock()
        .read_to_end(&mut input)
        .map_err(|source| CliError::Read {
            path: "<stdin>".into(),
            source,
        })?;
    let triples = read_triples(&String::from_utf8_lossy(&input))?;
    let mut text = String::with_capacity(triples.len() * 64);
    for conversion in convert_all(args.from, &triples, args.to) {
        if args.json {
            text.push_str(&json(args.to, &conversion));
        } else {
            // Shortest text that reads back as the same f64.
            let [a, b, c] = conversion.output.angles;
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
                Ok(value) if value.is_finite() => numbers.push(value),
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

fn table(from: Sequence, to: Sequence, conversion: &Conversion) -> String {
    let angles = |a: [f64; 3]| a.map(|x| format!("{x:>12.6}")).join(" ");
    let mut text = format!(
        "{from} (code {}) -> {to} (code {})\n\nangles       {}\nalternative  {}\n\nrotation matrix\n",
        from.code(),
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
