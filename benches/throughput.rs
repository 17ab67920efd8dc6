//! Whole-program throughput of the release binary: generates its inputs (a
//! 5-axis CAM program, the outside corpus replicated, the machine builders'
//! hand-written cycles of that corpus replicated, the CAM program with
//! CYCLE600 calls scattered through it), runs `check` and `rewrite` on each,
//! and prints MB/s, blocks/s and peak memory, with `wc -l` as the floor.
//! First, in this process, the syntax layer alone on 10 MB of the CAM
//! program and of the hand-written cycles (`SINUPREP_BENCH_SYNTAX_MB`):
//! the syntax pass (plain lines scanned, the others parsed) and every line
//! parsed into its tree, each tree dropped once built.
//! Memory is given twice: the peak resident set (file pages of a mapped
//! program included, which the kernel drops at will) and the peak of the
//! process's own anonymous memory (`RssAnon`, sampled every millisecond).
//!
//! `cargo bench --bench throughput` (size in MB: `SINUPREP_BENCH_MB`, default
//! 100; `SINUPREP_BENCH_KEEP=1` keeps the inputs; `SINUPREP_BENCH_ONLY=syntax`
//! stops after the syntax table, `SINUPREP_BENCH_ONLY=run` measures the dry
//! run of the CAM program alone). The resident peak comes from
//! `/usr/bin/time -f %M`; nothing is asserted.
//!
//! `SINUPREP_BENCH_ONLY=syntax-pass-cam` or `syntax-pass-hand` runs the
//! syntax pass once over that input and does nothing else, for instruction
//! counts: `SINUPREP_BENCH_SYNTAX_MB=2 valgrind --tool=callgrind
//! --toggle-collect='sinuprep::syntax::diagnostics' <bench binary>`.

use std::hint::black_box;
use std::path::{Path, PathBuf};

use sinuprep::syntax::lines::raw_lines;
use sinuprep::syntax::LineParser;

#[path = "support/process.rs"]
mod process;
#[path = "support/best.rs"]
mod support;

fn main() {
    let megabytes: usize = std::env::var("SINUPREP_BENCH_MB")
        .ok()
        .and_then(|m| m.parse().ok())
        .unwrap_or(100);
    let size = megabytes * 1_000_000;
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let only = std::env::var("SINUPREP_BENCH_ONLY").unwrap_or_default();
    if let Some(input) = only.strip_prefix("syntax-pass-") {
        syntax_pass_once(&root, input);
        return;
    }
    if only != "run" {
        syntax_only(&root);
    }
    if only == "syntax" {
        return;
    }
    let binary = process::release_binary();
    let dir = std::env::temp_dir().join("sinuprep-bench");
    std::fs::create_dir_all(&dir).expect("bench directory");

    let cam = dir.join("CAM_5AXIS.MPF");
    std::fs::write(&cam, cam_program(size, 0)).expect("write");
    dry_run(&root, &binary, &cam);
    if only == "run" {
        return;
    }
    let with_cycle600 = dir.join("CAM_CYCLE600.MPF");
    std::fs::write(&with_cycle600, cam_program(size, 10_000)).expect("write");
    let corpus = dir.join("CORPUS.MPF");
    std::fs::write(&corpus, replicated_corpus(&root, size)).expect("write");
    let hand_written = dir.join("HAND_WRITTEN.MPF");
    std::fs::write(&hand_written, hand_written_cycles(&root, size)).expect("write");
    let heads = root.join("samples/HEAD_DEF.SPF");
    let heads = heads.to_str().expect("utf-8");

    println!(
        "{:<44} {:>9} {:>10} {:>12} {:>10} {:>10}",
        "run", "seconds", "MB/s", "blocks/s", "peak MiB", "anon MiB"
    );
    for input in [&cam, &corpus, &hand_written, &with_cycle600] {
        let bytes = std::fs::metadata(input).map(|m| m.len()).unwrap_or(0) as f64;
        let blocks = std::fs::read(input)
            .map(|b| b.iter().filter(|&&c| c == b'\n').count())
            .unwrap_or(0) as f64;
        let name = input.file_name().and_then(|n| n.to_str()).unwrap_or("?");
        let path = input.to_str().expect("utf-8");
        let output = dir.join("out.mpf");
        let runs: [(String, Vec<&str>); 4] = [
            (format!("wc -l {name}"), vec!["wc", "-l", path]),
            (
                format!("check {name}"),
                vec![
                    binary.to_str().expect("utf-8"),
                    "check",
                    "--format",
                    "short",
                    "--heads",
                    heads,
                    path,
                ],
            ),
            (
                format!("rewrite {name}"),
                vec![
                    binary.to_str().expect("utf-8"),
                    "rewrite",
                    "--heads",
                    heads,
                    "-o",
                    output.to_str().expect("utf-8"),
                    path,
                ],
            ),
            // The formatter's whole analysis, nothing to write: the
            // generated programs are laid out already.
            (
                format!("fmt --check {name}"),
                vec![binary.to_str().expect("utf-8"), "fmt", "--check", path],
            ),
        ];
        for (label, command) in runs {
            let (seconds, peak, anon) = process::measure(&command, process::Input::Nothing);
            println!(
                "{label:<44} {seconds:>9.2} {:>10.1} {:>12.0} {:>10.1} {:>10.1}",
                bytes / seconds / 1e6,
                blocks / seconds,
                peak as f64 / 1024.0,
                anon as f64 / 1024.0
            );
        }
    }
    // A CAM program whose every line changes (lower case, blanks doubled,
    // trailing blanks), formatted to stdout.
    let messy = dir.join("CAM_MESSY.MPF");
    let tidy = std::fs::read(&cam).expect("read");
    std::fs::write(&messy, messy_program(&tidy)).expect("write");
    let bytes = std::fs::metadata(&messy).map(|m| m.len()).unwrap_or(0) as f64;
    let blocks = bytecount_lines(&messy);
    let command = [binary.to_str().expect("utf-8"), "fmt", "-"];
    let (seconds, peak, anon) = process::measure(&command, process::Input::File(&messy));
    println!(
        "{:<44} {seconds:>9.2} {:>10.1} {:>12.0} {:>10.1} {:>10.1}",
        "fmt - < CAM_MESSY.MPF (every line changed)",
        bytes / seconds / 1e6,
        blocks / seconds,
        peak as f64 / 1024.0,
        anon as f64 / 1024.0
    );
    // Findings by the thousand: every did-you-mean searches thousands of
    // names (a quadratic search took 22 s on 2,000 x 2,000).
    let many = dir.join("MANY_FINDINGS.MPF");
    std::fs::write(&many, many_findings(5_000)).expect("write");
    let path = many.to_str().expect("utf-8");
    let command = [
        binary.to_str().expect("utf-8"),
        "check",
        "--format",
        "short",
        path,
    ];
    let (seconds, peak, anon) = process::measure(&command, process::Input::Nothing);
    println!(
        "{:<44} {seconds:>9.2} {:>10} {:>12} {:>10.1} {:>10.1}",
        "check MANY_FINDINGS.MPF (5,000 x 4 findings)",
        "",
        "",
        peak as f64 / 1024.0,
        anon as f64 / 1024.0
    );
    // SINUPREP_BENCH_KEEP=1 keeps the generated inputs for profiling.
    if std::env::var_os("SINUPREP_BENCH_KEEP").is_none() {
        let _ = std::fs::remove_dir_all(&dir);
    } else {
        println!("inputs kept in {}", dir.display());
    }
}

/// `sinuprep run` of the CAM program on the test machine's data
/// (tests/fixtures/run/MACHINE.INI: X, Y, Z and a modulo C; the program's
/// B and TRAORI are named, not followed), its summary as JSON.
fn dry_run(root: &Path, binary: &Path, cam: &Path) {
    let machine = root.join("tests/fixtures/run/MACHINE.INI");
    let bytes = std::fs::metadata(cam).map(|m| m.len()).unwrap_or(0) as f64;
    let blocks = bytecount_lines(cam);
    let command = [
        binary.to_str().expect("utf-8"),
        "run",
        "--machine",
        machine.to_str().expect("utf-8"),
        "--format",
        "json",
        cam.to_str().expect("utf-8"),
    ];
    let (seconds, peak, anon) = process::measure(&command, process::Input::Nothing);
    println!(
        "{:<44} {seconds:>9.2} {:>10.1} {:>12.0} {:>10.1} {:>10.1}",
        "run CAM_5AXIS.MPF",
        bytes / seconds / 1e6,
        blocks / seconds,
        peak as f64 / 1024.0,
        anon as f64 / 1024.0
    );
}

/// The syntax layer in this process, in MB/s (best of five after a warm-up):
/// the pass `check` and `rewrite` start with ([`sinuprep::syntax::diagnostics`]:
/// plain lines scanned, the others parsed), and every line parsed into its
/// tree and dropped.
fn syntax_only(root: &Path) {
    let megabytes: usize = std::env::var("SINUPREP_BENCH_SYNTAX_MB")
        .ok()
        .and_then(|m| m.parse().ok())
        .unwrap_or(10);
    let size = megabytes * 1_000_000;
    println!(
        "{:<44} {:>9} {:>10}",
        format!("syntax only, {megabytes} MB in process"),
        "seconds",
        "MB/s"
    );
    for (name, source) in [
        ("CAM program", cam_program(size, 0)),
        ("hand-written cycles", hand_written_cycles(root, size)),
    ] {
        let passes: [(&str, Pass); 2] = [
            ("syntax pass", syntax_pass),
            ("every line parsed", parse_every_line),
        ];
        for (pass, run) in passes {
            let seconds = support::best_of_five(|| run(black_box(&source)) as f64);
            println!(
                "{:<44} {seconds:>9.3} {:>10.1}",
                format!("{pass}, {name}"),
                source.len() as f64 / seconds / 1e6
            );
        }
    }
}

/// The syntax pass once over `SINUPREP_BENCH_SYNTAX_MB` of the CAM program
/// (`input` "cam") or the hand-written cycles ("hand"), for a profiler.
fn syntax_pass_once(root: &Path, input: &str) {
    let megabytes: usize = std::env::var("SINUPREP_BENCH_SYNTAX_MB")
        .ok()
        .and_then(|m| m.parse().ok())
        .unwrap_or(10);
    let source = match input {
        "cam" => cam_program(megabytes * 1_000_000, 0),
        "hand" => hand_written_cycles(root, megabytes * 1_000_000),
        _ => panic!("SINUPREP_BENCH_ONLY=syntax-pass-cam or syntax-pass-hand"),
    };
    let found = syntax_pass(black_box(&source));
    println!("{} bytes, {found} syntax diagnostics", source.len());
}

/// A pass over a program's bytes, and a count it makes.
type Pass = fn(&[u8]) -> usize;

/// The syntax diagnostics `check` and `rewrite` start with; their count.
fn syntax_pass(source: &[u8]) -> usize {
    sinuprep::syntax::diagnostics(source).len()
}

/// Every line parsed into its tree, which is dropped at once; the count of
/// lines with an error.
fn parse_every_line(source: &[u8]) -> usize {
    let mut parser = LineParser::default();
    raw_lines(source)
        .map(|raw| black_box(parser.parse_line(source, raw)).1.is_some() as usize)
        .sum()
}

/// `N.. G1 X.. Y.. Z.. B.. C..` with an occasional feed, after a header with
/// DEF, TRAORI and a cycle; a CYCLE600 every `every` blocks when not 0.
fn cam_program(size: usize, every: usize) -> Vec<u8> {
    let mut out = b"; generated 5-axis program\nDEF REAL _X_HOME, _Z_HOME\nN10 G17 G54 G90 G71\nN20 T=\"BALL_D6\" M6\nN30 TRAORI\nN40 CYCLE832(0.01,1,1)\n".to_vec();
    let mut state: u64 = 0x2545F4914F6CDD1D;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % 1_000_000) as f64 / 1000.0
    };
    let mut n = 50u64;
    while out.len() < size {
        n += 10;
        let feed = if n.is_multiple_of(970) { " F2000." } else { "" };
        let line = format!(
            "N{n} G1 X{:.3} Y{:.3} Z{:.3} B{:.3} C{:.3}{feed}\n",
            next() - 500.0,
            next() - 500.0,
            next() / 5.0 - 100.0,
            next() / 5.5 - 90.0,
            next() / 2.7 - 180.0
        );
        out.extend_from_slice(line.as_bytes());
        if every != 0 && n.is_multiple_of(every as u64 * 10) {
            out.extend_from_slice(b"CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 1.5, -0.5, 30, 0, 0, 0, 1, 39, 0, 0, 0)\n");
        }
    }
    out.extend_from_slice(b"TRAFOOF\nM30\n");
    out
}

/// `program` with every line made untidy for the formatter: lower case,
/// two blanks between words, a blank at the end.
fn messy_program(program: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(program.len() * 5 / 4);
    for &byte in program {
        match byte {
            b' ' => out.extend_from_slice(b"  "),
            b'\n' => out.extend_from_slice(b" \n"),
            _ => out.push(byte.to_ascii_lowercase()),
        }
    }
    out
}

fn bytecount_lines(path: &Path) -> f64 {
    std::fs::read(path)
        .map(|b| b.iter().filter(|&&c| c == b'\n').count())
        .unwrap_or(0) as f64
}

/// The real programs of the outside corpus, one after another until `size`.
fn replicated_corpus(root: &Path, size: usize) -> Vec<u8> {
    replicated(corpus_files(root, |_| true), size)
}

/// The programs of the outside corpus that people wrote rather than a CAM
/// system: machine builders' warm-up cycles with a PROC, DEF, IF, FOR and
/// EXTERN (`alloyx-828d`), small programs of control flow, CASE, GOTO,
/// arrays and expressions (`cead-examples`), and a setup file of system
/// variables with indices and strings (`philip-cas/KUL_DEMO.INI`); one
/// after another until `size`.
fn hand_written_cycles(root: &Path, size: usize) -> Vec<u8> {
    let files = corpus_files(root, |path| {
        let folder = path.parent().and_then(Path::file_name);
        folder.is_some_and(|f| f == "alloyx-828d" || f == "cead-examples")
            || path.file_name().is_some_and(|n| n == "KUL_DEMO.INI")
    });
    replicated(files, size)
}

/// The files of the outside corpus (`SINUPREP_CORPUS`, else
/// `../shared/corpus`) that `keep` accepts, in a fixed order.
fn corpus_files(root: &Path, keep: impl Fn(&Path) -> bool) -> Vec<Vec<u8>> {
    let dir = std::env::var_os("SINUPREP_CORPUS")
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join("../shared/corpus"));
    let mut paths = Vec::new();
    let mut stack = vec![dir];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).into_iter().flatten().flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_none_or(|e| e != "md") && keep(&path) {
                paths.push(path);
            }
        }
    }
    paths.sort();
    paths
        .iter()
        .filter_map(|path| std::fs::read(path).ok())
        .collect()
}

/// `files` one after another, each ending with a newline, until `size`.
fn replicated(files: Vec<Vec<u8>>, size: usize) -> Vec<u8> {
    let mut out = Vec::with_capacity(size);
    while !files.is_empty() && out.len() < size {
        for file in &files {
            out.extend_from_slice(file);
            if !out.ends_with(b"\n") {
                out.push(b'\n');
            }
        }
    }
    out
}

/// `n` labels and DEFs, then `n` jumps to labels and `n` reads of names one
/// letter off each (N001 and N005 with a did-you-mean), `n` names in other
/// capitals and `n` unused variables.
fn many_findings(n: usize) -> Vec<u8> {
    let mut text = String::new();
    for i in 0..n {
        text.push_str(&format!("DEF REAL VAR{i:05}\n"));
    }
    for i in 0..n {
        text.push_str(&format!("LBL{i:05}: X{i}\n"));
    }
    for i in 0..n {
        text.push_str(&format!("GOTOF LBX{i:05}\nR1=VAX{i:05}+var{i:05}\n"));
    }
    text.push_str("M30\n");
    text.into_bytes()
}
