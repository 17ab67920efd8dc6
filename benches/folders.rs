//! Many programs: `check` over n small programs in one folder, the same n
//! split over folders of 100 (per-program time should be the same), and n
//! subprograms in folders of 100 (each folder's subprograms are read for the
//! calls; what is kept of them must not grow with n), with
//! the time to the first finding printed (findings come as files finish, in
//! their order, not after the last) and the peak resident memory; and one
//! program under 250, 500 and 1,000 folders one in the other (linear in the
//! depth).
//!
//! `cargo bench --bench folders` (counts: `SINUPREP_BENCH_FOLDERS`, default
//! `2000 8000 50000`; another build to compare: `SINUPREP_BENCH_BINARY`).
//! Needs `/usr/bin/time`; nothing is asserted.

use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Instant;

#[path = "support/process.rs"]
#[allow(dead_code)] // the process's memory is not measured here
mod process;

fn main() {
    let counts: Vec<usize> = std::env::var("SINUPREP_BENCH_FOLDERS")
        .unwrap_or_else(|_| "2000 8000 50000".to_string())
        .split_whitespace()
        .filter_map(|n| n.parse().ok())
        .collect();
    let binary = process::release_binary();
    let dir = std::env::temp_dir().join(format!("sinuprep-bench-folders-{}", std::process::id()));
    println!("shape  programs   total s   µs/program   first line s   peak RSS MiB");
    for &count in &counts {
        let _ = std::fs::remove_dir_all(&dir);
        let flat = dir.join("flat");
        let split = dir.join("split");
        let cycles = dir.join("cycles");
        for i in 0..count {
            let name = format!("P{i:06}.MPF");
            // One finding each (N001, a jump to no label), so that every
            // program prints a line.
            let program = format!("G0 X{i} Y0\nGOTOF NOWHERE\nM30\n");
            let folder = format!("D{:04}", i / 100);
            let cycle = (
                cycles.join(&folder).join(format!("C{i:06}.SPF")),
                format!("PROC C{i:06}(REAL _A)\nG0 X=_A\nGOTOF NOWHERE\nM17\n"),
            );
            let written = [
                (flat.join(&name), program.clone()),
                (split.join(&folder).join(&name), program),
                cycle,
            ];
            for (path, text) in written {
                if let Some(parent) = path.parent() {
                    std::fs::create_dir_all(parent).expect("bench directory");
                }
                std::fs::write(path, text).expect("write");
            }
        }
        for (shape, path) in [("flat", &flat), ("split", &split), ("cycles", &cycles)] {
            let (total, first, peak) = measure(&binary, path);
            println!(
                "{shape:<6} {count:>8} {total:>9.2} {:>12.1} {first:>14.3} {:>14.1}",
                total * 1e6 / count as f64,
                peak as f64 / 1024.0
            );
        }
    }
    // One program at the bottom of folders one in the other: each folder's
    // settings lookup must not list every folder above it again.
    println!("\nshape  depth      total s");
    for depth in [250, 500, 1000] {
        let _ = std::fs::remove_dir_all(&dir);
        let mut deep = dir.join("deep");
        for _ in 0..depth {
            deep.push("d");
        }
        std::fs::create_dir_all(&deep).expect("bench directory");
        std::fs::write(deep.join("P.MPF"), "GOTOF NOWHERE\nM30\n").expect("write");
        let (total, _, _) = measure(&binary, &dir.join("deep"));
        println!("deep   {depth:>5} {total:>12.3}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Seconds to the end, seconds to the first byte on stdout, peak RSS in KiB.
fn measure(binary: &Path, folder: &Path) -> (f64, f64, u64) {
    let start = Instant::now();
    let mut child = Command::new("/usr/bin/time")
        .args(["-f", "%M"])
        .arg(binary)
        .args(["check", "--quiet", "--format", "short"])
        .arg(folder)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("/usr/bin/time runs");
    let mut stdout = child.stdout.take().expect("piped");
    let mut buffer = vec![0; 1 << 16];
    let mut first = None;
    while let Ok(n) = stdout.read(&mut buffer) {
        if n == 0 {
            break;
        }
        first.get_or_insert_with(|| start.elapsed().as_secs_f64());
    }
    let output = child.wait_with_output().expect("finishes");
    let total = start.elapsed().as_secs_f64();
    let peak = String::from_utf8_lossy(&output.stderr)
        .lines()
        .last()
        .and_then(|l| l.trim().parse().ok())
        .unwrap_or(0);
    (total, first.unwrap_or(total), peak)
}
