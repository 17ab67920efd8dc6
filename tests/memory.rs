//! Memory that does not grow with the input, held by the kernel: each run
//! gets a data limit (`ulimit -d`, RLIMIT_DATA: the heap and private
//! writable mappings; a program mapped read-only does not count), so a
//! command that holds what it read beyond the limit aborts instead of
//! passing. Linux only: elsewhere the limit means something else, or
//! nothing.
#![cfg(target_os = "linux")]

mod support;

use std::path::Path;
use std::process::{Command, Output, Stdio};

use support::scratch;

/// The process's own memory a run may take: below the program here, whose
/// rewrite held about 2.4 bytes a byte of it before; above what standard
/// input takes before it is spooled to a file (4 MiB, in a vector that may
/// double).
const LIMIT_KIB: u32 = 16 * 1024;

/// `sinuprep args` under the data limit, with `stdin` from a file (None: a
/// pipe fed from that file by another process) or nothing.
fn limited(args: &[&str], stdin: Option<(&Path, bool)>) -> Output {
    let script = format!("ulimit -d {LIMIT_KIB} && exec \"$0\" \"$@\"");
    let mut command = Command::new("sh");
    command
        .arg("-c")
        .arg(script)
        .arg(env!("CARGO_BIN_EXE_sinuprep"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let mut cat = None;
    match stdin {
        Some((path, true)) => {
            command.stdin(std::fs::File::open(path).expect("input"));
        }
        Some((path, false)) => {
            let mut child = Command::new("cat")
                .arg(path)
                .stdout(Stdio::piped())
                .spawn()
                .expect("cat runs");
            command.stdin(child.stdout.take().expect("a pipe"));
            cat = Some(child);
        }
        None => {
            command.stdin(Stdio::null());
        }
    }
    let output = command.output().expect("sh runs");
    // The pipe's end the command held is closed: `cat` cannot wait on it.
    drop(command);
    if let Some(mut cat) = cat {
        // It ends once the run has read its input or closed the pipe.
        let _ = cat.wait();
    }
    output
}

fn assert_within_limit(output: &Output, code: i32, what: &str) {
    assert_eq!(
        output.status.code(),
        Some(code),
        "{what}: stderr: {}",
        String::from_utf8_lossy(&output.stderr)
            .chars()
            .take(2000)
            .collect::<String>()
    );
}

const CALL: &str =
    "N99 CYCLE600 (0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 1, 39, 0, 0, 0)\n";

/// About `megabytes` MB of motion blocks between a DEF and one CYCLE600
/// near the end: the plain lines between two others were held whole.
fn cam_program(dir: &Path, megabytes: usize) -> std::path::PathBuf {
    let block = "G1 X12.345 Y67.891 Z-1.234 F1000\n";
    let mut text = String::from("DEF REAL DEPTH=1\n");
    text.push_str(&block.repeat(megabytes * 1_000_000 / block.len()));
    text.push_str(CALL);
    text.push_str("G1 Z=DEPTH\nM30\n");
    let path = dir.join("BIG.MPF");
    std::fs::write(&path, text).expect("program written");
    path
}

#[test]
fn check_rewrite_and_eval_of_a_large_program_stay_within_the_limit_by_every_path() {
    let dir = scratch("memory-large");
    let program = cam_program(&dir, 10);
    let name = program.to_str().expect("a UTF-8 path");
    let heads = ["--heads", "samples/HEAD_DEF.SPF"];
    let rewritten = "_CYC600_2=37.792346";

    let output = limited(&["check", "--format", "short", name], None);
    assert_within_limit(&output, 0, "check FILE");
    let output = limited(&["check", "--format", "short", "-"], Some((&program, true)));
    assert_within_limit(&output, 0, "check - < FILE");
    let output = limited(
        &["check", "--format", "short", "-"],
        Some((&program, false)),
    );
    assert_within_limit(&output, 0, "check - from a pipe");

    for (args, stdin, what) in [
        (vec!["rewrite", name], None, "rewrite FILE"),
        (
            vec!["rewrite", "-"],
            Some((program.as_path(), true)),
            "rewrite - < FILE",
        ),
        (
            vec!["rewrite", "-"],
            Some((program.as_path(), false)),
            "rewrite - from a pipe",
        ),
    ] {
        let output = limited(&[&args[..], &heads].concat(), stdin);
        assert_within_limit(&output, 0, what);
        let text = String::from_utf8_lossy(&output.stdout);
        assert!(text.contains(rewritten), "{what}: not rewritten");
        assert!(text.len() > 10_000_000, "{what}: output cut short");
    }

    let out = dir.join("OUT.MPF");
    let out_name = out.to_str().expect("a UTF-8 path");
    let output = limited(
        &[&["rewrite", name, "-o", out_name][..], &heads].concat(),
        None,
    );
    assert_within_limit(&output, 0, "rewrite -o");
    let copy = dir.join("COPY.MPF");
    std::fs::copy(&program, &copy).expect("copy");
    let copy_name = copy.to_str().expect("a UTF-8 path");
    let output = limited(
        &[&["rewrite", "--in-place", copy_name][..], &heads].concat(),
        None,
    );
    assert_within_limit(&output, 0, "rewrite --in-place");
    assert_eq!(
        std::fs::read(&out).expect("written"),
        std::fs::read(&copy).expect("rewritten"),
        "-o and --in-place wrote different bytes"
    );
    assert!(std::fs::read_to_string(&copy)
        .expect("rewritten")
        .contains(rewritten));

    let output = limited(&[&["eval", name][..], &heads].concat(), None);
    assert_within_limit(&output, 0, "eval FILE");
    assert!(String::from_utf8_lossy(&output.stdout).contains("37.792346"));
    let output = limited(
        &[&["eval", "-"][..], &heads].concat(),
        Some((&program, false)),
    );
    assert_within_limit(&output, 0, "eval - from a pipe");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn one_long_line_of_address_words_is_refused_within_the_limit() {
    // Address words alone were read into a tree at any length: 80 bytes a
    // word, 2 GB for a 40 MB line. Past 64 KiB no line is read (S009).
    let dir = scratch("memory-long-line");
    let path = dir.join("LONG.MPF");
    std::fs::write(&path, format!("{}\nM30\n", "X1 ".repeat(8_000_000))).expect("written");
    let name = path.to_str().expect("a UTF-8 path");
    for args in [
        vec!["check", "--format", "short", name],
        vec!["rewrite", name],
        vec!["eval", name],
    ] {
        let output = limited(&args, None);
        assert_within_limit(&output, 1, &args.join(" "));
    }
    let output = limited(&["check", "--format", "short", "-"], Some((&path, false)));
    assert_within_limit(&output, 1, "check - from a pipe");
    let report = String::from_utf8_lossy(&output.stdout);
    assert!(report.contains("error[S009]"), "{report}");
    assert!(
        !report.contains("N022"),
        "the line's words were read: {report}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
