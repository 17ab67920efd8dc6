//! `sinuprep convert`: three angles from one rotation sequence to another.

use crate::cli::args::ConvertArgs;
use crate::cli::error::CliError;
use crate::cli::{write_stdout, ExitStatus};
use crate::rotation::{convert, Conversion, Sequence};

pub fn run(args: &ConvertArgs) -> Result<ExitStatus, CliError> {
    let conversion = convert(args.from, [args.a1, args.a2, args.a3], args.to);
    let text = if args.json {
        json(args.to, &conversion)
    } else {
        table(args.from, args.to, &conversion)
    };
    write_stdout(text.as_bytes())?;
    Ok(ExitStatus::Success)
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
