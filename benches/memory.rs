//! The process's own memory by every path, on inputs built to make it grow:
//! a CAM program with one CYCLE600 near its end (what lies between two
//! lines that are not plain was held whole), read by `check`, `rewrite` (to
//! stdout, `-o`, `--in-place`) and `eval`, from the file, from `< FILE` and
//! from a pipe; and one line of address words (`X1 X1 ...`).
//!
//! `cargo bench --bench memory` (size in MB: `SINUPREP_BENCH_MB`, default
//! 1000; the long line is 40 MB). The goal is at most 32 MiB of anonymous
//! memory on each row; nothing is asserted (tests/memory.rs holds a smaller
//! case under a data limit).

use std::path::PathBuf;

#[path = "support/process.rs"]
mod process;

use process::{measure, release_binary, Input};

fn main() {
    let megabytes: usize = std::env::var("SINUPREP_BENCH_MB")
        .ok()
        .and_then(|m| m.parse().ok())
        .unwrap_or(1000);
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let binary = release_binary();
    let binary = binary.to_str().expect("utf-8");
    let heads = root.join("samples/HEAD_DEF.SPF");
    let heads = heads.to_str().expect("utf-8");
    let dir = std::env::temp_dir().join("sinuprep-bench-memory");
    std::fs::create_dir_all(&dir).expect("bench directory");

    let program = dir.join("ONE_CALL.MPF");
    write_one_call(&program, megabytes * 1_000_000);
    let long_line = dir.join("LONG_LINE.MPF");
    std::fs::write(
        &long_line,
        format!("{}\nM30\n", "X1 ".repeat(40_000_000 / 3)),
    )
    .expect("write");
    let copy = dir.join("COPY.MPF");
    let out = dir.join("OUT.MPF");
    let (path, long, copy_path, out_path) = (
        program.to_str().expect("utf-8"),
        long_line.to_str().expect("utf-8"),
        copy.to_str().expect("utf-8"),
        out.to_str().expect("utf-8"),
    );

    println!(
        "{:<52} {:>9} {:>10} {:>10}",
        "run", "seconds", "peak MiB", "anon MiB"
    );
    let runs: Vec<(&str, Vec<&str>, Input)> = vec![
        ("check FILE", vec!["check", path], Input::Nothing),
        ("check - < FILE", vec!["check", "-"], Input::File(&program)),
        (
            "check - from a pipe",
            vec!["check", "-"],
            Input::Pipe(&program),
        ),
        ("rewrite FILE", vec!["rewrite", path], Input::Nothing),
        (
            "rewrite - < FILE",
            vec!["rewrite", "-"],
            Input::File(&program),
        ),
        (
            "rewrite - from a pipe",
            vec!["rewrite", "-"],
            Input::Pipe(&program),
        ),
        (
            "rewrite FILE -o OUT",
            vec!["rewrite", path, "-o", out_path],
            Input::Nothing,
        ),
        (
            "rewrite --in-place COPY",
            vec!["rewrite", "--in-place", "--no-backup", copy_path],
            Input::Nothing,
        ),
        ("eval FILE", vec!["eval", path], Input::Nothing),
        (
            "eval - from a pipe",
            vec!["eval", "-"],
            Input::Pipe(&program),
        ),
        ("check, one 40 MB line", vec!["check", long], Input::Nothing),
        (
            "check -, one 40 MB line from a pipe",
            vec!["check", "-"],
            Input::Pipe(&long_line),
        ),
        (
            "rewrite, one 40 MB line",
            vec!["rewrite", long],
            Input::Nothing,
        ),
    ];
    for (label, args, input) in runs {
        if args.contains(&"--in-place") {
            std::fs::copy(&program, &copy).expect("copy");
        }
        let mut command = vec![binary, args[0], "--heads", heads];
        command.extend(&args[1..]);
        let (seconds, peak, anon) = measure(&command, input);
        println!(
            "{label:<52} {seconds:>9.2} {:>10.1} {:>10.1}",
            peak as f64 / 1024.0,
            anon as f64 / 1024.0
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// About `size` bytes of motion blocks between a DEF and one CYCLE600 near
/// the end, written a block at a time.
fn write_one_call(path: &std::path::Path, size: usize) {
    use std::io::Write;
    let file = std::fs::File::create(path).expect("create");
    let mut out = std::io::BufWriter::new(file);
    let block = b"G1 X12.345 Y67.891 Z-1.234 F1000\n";
    out.write_all(b"DEF REAL DEPTH=1\n").expect("write");
    for _ in 0..size / block.len() {
        out.write_all(block).expect("write");
    }
    out.write_all(
        b"N99 CYCLE600 (0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 1, 39, 0, 0, 0)\nG1 Z=DEPTH\nM30\n",
    )
    .expect("write");
    out.flush().expect("flush");
}
