//! Measuring a whole process from outside, for the benchmarks that run the
//! release binary: wall seconds, the peak resident set (file pages of a
//! mapped program included, which the kernel drops at will) and the peak of
//! the process's own anonymous memory (`RssAnon`, sampled every millisecond).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

/// The binary measured: `SINUPREP_BENCH_BINARY` (another build, to compare
/// with), else this checkout's release build, built now.
pub fn release_binary() -> PathBuf {
    if let Some(binary) = std::env::var_os("SINUPREP_BENCH_BINARY") {
        return PathBuf::from(binary);
    }
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let status = Command::new("cargo")
        .args(["build", "--release", "--quiet"])
        .current_dir(&root)
        .status();
    assert!(status.is_ok_and(|s| s.success()), "release build failed");
    root.join("target/release/sinuprep")
}

/// Where a measured command's standard input comes from.
#[derive(Clone, Copy)]
#[allow(dead_code)] // each bench uses the inputs it needs
pub enum Input<'a> {
    Nothing,
    /// The file itself, as `< FILE` gives it.
    File(&'a Path),
    /// A pipe that another process (`cat`) fills from the file.
    Pipe(&'a Path),
}

/// Best of three runs: wall seconds, peak resident memory and peak
/// anonymous memory, both in KiB.
pub fn measure(command: &[&str], input: Input) -> (f64, u64, u64) {
    let mut best = (f64::INFINITY, 0, 0);
    for _ in 0..3 {
        let (stdin, mut cat) = match input {
            Input::Nothing => (Stdio::null(), None),
            Input::File(path) => (Stdio::from(std::fs::File::open(path).expect("input")), None),
            Input::Pipe(path) => {
                let mut cat = Command::new("cat")
                    .arg(path)
                    .stdout(Stdio::piped())
                    .spawn()
                    .expect("cat runs");
                (Stdio::from(cat.stdout.take().expect("a pipe")), Some(cat))
            }
        };
        let started = Instant::now();
        let mut child = Command::new("/usr/bin/time")
            .arg("-f")
            .arg("%M")
            .args(command)
            .stdin(stdin)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .expect("/usr/bin/time runs");
        let mut anon = 0;
        while child.try_wait().expect("wait").is_none() {
            anon = anon.max(anonymous_kib(child.id()).unwrap_or(0));
            std::thread::sleep(std::time::Duration::from_millis(1));
        }
        let output = child.wait_with_output().expect("output");
        let seconds = started.elapsed().as_secs_f64();
        if let Some(cat) = cat.as_mut() {
            let _ = cat.wait();
        }
        let peak = String::from_utf8_lossy(&output.stderr)
            .lines()
            .last()
            .and_then(|l| l.trim().parse().ok())
            .unwrap_or(0);
        if seconds < best.0 {
            best = (seconds, peak, anon);
        }
    }
    best
}

/// `RssAnon` of the command `/usr/bin/time` (process `time`) runs, in KiB.
fn anonymous_kib(time: u32) -> Option<u64> {
    let children = std::fs::read_to_string(format!("/proc/{time}/task/{time}/children")).ok()?;
    let child: u32 = children.split_whitespace().next()?.parse().ok()?;
    let status = std::fs::read_to_string(format!("/proc/{child}/status")).ok()?;
    status
        .lines()
        .find_map(|l| l.strip_prefix("RssAnon:"))?
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}
