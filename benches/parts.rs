//! In-process costs of the parts, measured with divan: a motion block
//! scanned, a block of code parsed, an expression parsed and evaluated, one
//! rotation conversion; a hand-written program formatted whole and in a
//! range of five lines (an editor's). `cargo bench --bench parts`; whole programs are
//! `throughput`'s job, many conversions `rotation`'s.

use divan::{black_box, Bencher};
use sinuprep::rotation::{convert, Sequence};
use sinuprep::semantic::eval::{evaluate, Lookup};
use sinuprep::semantic::value::{Unknown, Value};
use sinuprep::syntax::expr::parse_expr;
use sinuprep::syntax::lexer::Input;
use sinuprep::syntax::lines::raw_lines;
use sinuprep::syntax::plain::scanned_lines;
use sinuprep::syntax::LineParser;

fn main() {
    divan::main();
}

/// A CAM motion block, the most common line there is.
const MOTION: &[u8] = b"N1230 G1 X-213.049 Y-222.592 Z-29.973 B-4.987 C100.633\n";
/// A block that only the full parser reads.
const CODE: &[u8] = b"N40 IF (R1 > 0) AND ($AA_IW[X] < 100.5) GOTOF PROBE_END ; probe\n";
const EXPRESSION: &[u8] = b"SIN(R1 * 2 + 30) / COS(R1 - 5) + SQRT(ABS(-16)) * _OVR[16]";

#[divan::bench]
fn scan_motion_block() -> usize {
    scanned_lines(black_box(MOTION)).count()
}

#[divan::bench]
fn parse_motion_block() -> usize {
    parse_lines(black_box(MOTION))
}

#[divan::bench]
fn parse_code_block() -> usize {
    parse_lines(black_box(CODE))
}

/// Every line parsed into its tree (what `scanned_lines` spares motion blocks).
fn parse_lines(source: &[u8]) -> usize {
    let mut parser = LineParser::default();
    raw_lines(source)
        .map(|raw| parser.parse_line(source, raw).1.is_none() as usize)
        .sum()
}

struct Variables;

impl Lookup for Variables {
    fn variable(&self, key: &str) -> Result<Value, Unknown> {
        Ok(Value::Number(if key == "R1" { 10.0 } else { -0.5 }))
    }
}

#[divan::bench]
fn evaluate_expression(bencher: Bencher) {
    let (_, expr) = parse_expr(Input::new(EXPRESSION, 0)).expect("the expression parses");
    bencher.bench(|| evaluate(EXPRESSION, black_box(&expr), &Variables));
}

#[divan::bench]
fn parse_and_evaluate_expression() -> Option<Value> {
    let source = black_box(EXPRESSION);
    let (_, expr) = parse_expr(Input::new(source, 0)).ok()?;
    evaluate(source, &expr, &Variables).ok()
}

#[divan::bench]
fn convert_one_rotation(bencher: Bencher) {
    let from: Sequence = "extrinsic:XYZ".parse().expect("a sequence");
    let to: Sequence = "intrinsic:ZXY".parse().expect("a sequence");
    bencher.bench(|| convert(from, black_box([30.0, 45.0, 60.0]), to));
}

/// 100,000 lines of hand-written code every line of which `fmt` changes
/// (lower case, blanks, nesting to indent).
fn untidy_program() -> Vec<u8> {
    let section =
        "if r1>5\ng1  x=r1*2   y2 f100 ; c\nr1=r1+1\nendif\nwhile r2<3\nr2=r2+1\nendwhile\n";
    let mut program = section.repeat(100_000 / 7);
    program.push_str("m30\n");
    program.into_bytes()
}

#[divan::bench(args = ["whole", "five lines"])]
fn format_untidy_program(bencher: Bencher, range: &str) {
    use sinuprep::format::{format, format_rows, Settings};
    use sinuprep::syntax::ProgramKind;
    let program = untidy_program();
    let settings = Settings::default();
    bencher.bench(|| {
        let source = black_box(&program[..]);
        let edits = match range {
            "whole" => format("P.MPF", source, ProgramKind::Main, &settings).edits,
            _ => {
                format_rows(
                    "P.MPF",
                    source,
                    ProgramKind::Main,
                    &settings,
                    50_000..50_005,
                )
                .edits
            }
        };
        edits.len()
    });
}
