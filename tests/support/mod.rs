//! Helpers shared by the integration tests: where the inputs are, and a
//! readable dump of a syntax tree for snapshots.
#![allow(dead_code)]

pub mod dump;

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// A fresh directory of this test process for `name`.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("sinuprep-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir
}

/// Runs the built binary in the repository with `args`, feeding `stdin`.
pub fn run(args: &[&str], stdin: &[u8]) -> Output {
    let spawn = || {
        Command::new(env!("CARGO_BIN_EXE_sinuprep"))
            .args(args)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
    };
    // Wine now and then fails to create a process (ERROR_INTERNAL_ERROR,
    // 1359) while many tests start theirs at once: tried again, a few times.
    let mut child = spawn();
    for _ in 0..4 {
        match &child {
            Err(error) if cfg!(windows) && error.raw_os_error() == Some(1359) => {
                std::thread::sleep(std::time::Duration::from_millis(200));
                child = spawn();
            }
            _ => break,
        }
    }
    let mut child = child.expect("binary runs");
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
    // Skipped only when asked: a note in a passing test's output is never
    // seen, so a checkout without the corpus would pass without testing it.
    if std::env::var_os("SINUPREP_CORPUS").is_some_and(|v| v == "none") {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "CI must test the outside corpus (SINUPREP_CORPUS=none)"
        );
        eprintln!("NOTE: SINUPREP_CORPUS=none: the outside corpus was SKIPPED");
        return Vec::new();
    }
    assert!(
        dir.is_dir(),
        "outside corpus not found at {}: put shared/ beside the repository (../shared/corpus), \
         point SINUPREP_CORPUS at the corpus, or set SINUPREP_CORPUS=none to skip it",
        dir.display()
    );
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
            (d.code(), message, source[start..end].to_vec())
        })
        .collect();
    errors.sort();
    errors
}

/// A series start-up archive as Sinumerik Operate writes it: the mark
/// record `@@MMCIBN.002`, then each member (its NC path, its bytes) as a
/// 512-byte header and the bytes padded with NULs to 512. Written here
/// field by field, apart from the code that reads archives.
pub fn binary_archive(members: &[(&str, &[u8])]) -> Vec<u8> {
    let mut out = Vec::new();
    let mut add = |name: &str, path: &str, data: &[u8]| {
        let mut header = [0u8; 512];
        let mut put = |at: usize, text: &[u8]| header[at..at + text.len()].copy_from_slice(text);
        put(0, name.as_bytes());
        put(50, name.to_ascii_uppercase().as_bytes());
        put(124, data.len().to_string().as_bytes());
        put(136, b"1733140800");
        put(257, path.as_bytes());
        put(384, format!("\\{}", name.to_ascii_uppercase()).as_bytes());
        let sum: u32 = header.iter().map(|&b| u32::from(b)).sum();
        header[148..148 + sum.to_string().len()].copy_from_slice(sum.to_string().as_bytes());
        out.extend_from_slice(&header);
        out.extend_from_slice(data);
        out.resize(out.len().div_ceil(512) * 512, 0);
    };
    add("@@MMCIBN.002", "", b"ARCHIVE 840D sl\r\n");
    for (path, data) in members {
        let name = path
            .rsplit('/')
            .next()
            .unwrap_or(path)
            .trim_start_matches("_N_");
        let dos = match name.rfind('_') {
            Some(at) => format!("{}.{}", &name[..at], &name[at + 1..]),
            None => name.to_string(),
        };
        add(&dos, path, data);
    }
    out
}

/// The members of a binary archive (NC path, bytes), each header's
/// checksum and the padding checked: what a control reading it back sees.
pub fn binary_members(bytes: &[u8]) -> Vec<(String, Vec<u8>)> {
    let mut members = Vec::new();
    let mut at = 0;
    while at + 512 <= bytes.len() {
        let header = &bytes[at..at + 512];
        let field = |range: std::ops::Range<usize>| {
            let text = &header[range];
            let end = text.iter().position(|&b| b == 0).unwrap_or(text.len());
            String::from_utf8_lossy(&text[..end]).into_owned()
        };
        let size: usize = field(124..136).parse().expect("size");
        let recorded: u32 = field(148..156).parse().expect("checksum");
        let sum: u32 = header
            .iter()
            .enumerate()
            .map(|(i, &b)| {
                if (148..156).contains(&i) {
                    0
                } else {
                    u32::from(b)
                }
            })
            .sum();
        assert_eq!(recorded, sum, "checksum of the header at {at}");
        let data = bytes[at + 512..at + 512 + size].to_vec();
        let end = at + 512 + size.div_ceil(512) * 512;
        assert!(
            bytes[at + 512 + size..end].iter().all(|&b| b == 0),
            "padding"
        );
        members.push((field(257..384), data));
        at = end;
    }
    assert_eq!(at, bytes.len(), "the archive ends after its last member");
    members
}
