//! Helpers shared by the integration tests: where the inputs are, and a
//! readable dump of a syntax tree for snapshots.
#![allow(dead_code)]

pub mod dump;

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// Runs the built binary in the repository with `args`, feeding `stdin`.
pub fn run(args: &[&str], stdin: &[u8]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    // A command that stops before reading stdin (a refused option) closes
    // the pipe: that is its answer, not the test's failure.
    let written = child.stdin.take().expect("stdin").write_all(stdin);
    if let Err(error) = written {
        assert_eq!(
            error.kind(),
            std::io::ErrorKind::BrokenPipe,
            "write stdin: {error}"
        );
    }
    child.wait_with_output().expect("binary ends")
}

pub fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// The exit status must be `code`; on failure, show what the tool said.
pub fn assert_exit(output: &Output, code: i32) {
    assert_eq!(
        output.status.code(),
        Some(code),
        "stderr: {}",
        String::from_utf8_lossy(&output.stderr)
    );
}

pub fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every file below `dir`, sorted.
pub fn files_below(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.expect("directory entry").path();
            if path.is_dir() {
                stack.push(path);
            } else {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// The outside corpus of real programs (`../shared/corpus`, or
/// `SINUPREP_CORPUS`). Absent under CI it fails the test; elsewhere it says
/// loudly that it was skipped.
pub fn corpus_files() -> Vec<PathBuf> {
    let dir = std::env::var_os("SINUPREP_CORPUS")
        .map(PathBuf::from)
        .unwrap_or_else(|| repo().join("../shared/corpus"));
    if !dir.is_dir() {
        let message = format!("outside corpus not found at {}", dir.display());
        if std::env::var("CI").is_ok_and(|v| v == "true") {
            panic!("{message}: CI must test it (set SINUPREP_CORPUS)");
        }
        eprintln!("NOTE: {message}; the outside corpus was SKIPPED");
        return Vec::new();
    }
    files_below(&dir)
        .into_iter()
        .filter(|p| p.file_name().is_some_and(|n| n != "PROVENANCE.md"))
        .collect()
}

/// Samples and every fixture.
pub fn own_inputs() -> Vec<PathBuf> {
    let mut files = files_below(&repo().join("samples"));
    files.extend(files_below(&repo().join("tests/fixtures")));
    files
}

/// The syntax errors of `source`, each as its code, its message and the text
/// of its line, sorted: what a rewrite must leave exactly as it found them
/// (their positions move as lines are added, and so do the line numbers a
/// message names, which are masked).
pub fn syntax_errors(source: &[u8]) -> Vec<(&'static str, String, Vec<u8>)> {
    let mut errors: Vec<_> = sinuprep::syntax::parse(source)
        .diagnostics
        .into_iter()
        .map(|d| {
            let at = d.span.start.min(source.len());
            let start = source[..at]
                .iter()
                .rposition(|&b| b == b'\n' || b == b'\r')
                .map_or(0, |p| p + 1);
            let end = source[at..]
                .iter()
                .position(|&b| b == b'\n' || b == b'\r')
                .map_or(source.len(), |p| at + p);
            let message = d
                .message
                .split("line ")
                .enumerate()
                .map(|(n, part)| match n {
                    0 => part.to_string(),
                    _ => part
                        .trim_start_matches(|c: char| c.is_ascii_digit())
                        .to_string(),
                })
                .collect::<Vec<_>>()
                .join("line _");
            (d.code, message, source[start..end].to_vec())
        })
        .collect();
    errors.sort();
    errors
}
