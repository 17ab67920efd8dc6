//! What `rewrite` does to the files around a program: only regular files
//! are replaced in place, links are written through, owner, group and mode
//! are kept, the backup is written atomically and never through a planted
//! link, temporary files are unguessable and cleaned up, `-o` onto the input
//! is an in-place rewrite, and directory walks take every file once.
//! Cases that need root say so on stderr and are skipped elsewhere.
//!
//! On Windows (run under Wine by `.ci/windows.sh`) the cases of symbolic
//! links, FIFOs, devices, modes and owners are left out, each where it is
//! (`cfg(unix)`): Windows has no FIFOs in the file system, no `/dev`, no
//! owner or mode bits, and makes symbolic links only with a privilege.

mod support;

use std::fs;
#[cfg(unix)]
use std::os::unix::fs::{symlink, MetadataExt, PermissionsExt};
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use support::{assert_exit, scratch};

const PROGRAM: &[u8] =
    b"N10 CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\nN20 M30\n";
const REFUSED: &[u8] =
    b"N10 CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, R20, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\nN20 M30\n";

fn heads() -> String {
    support::repo()
        .join("samples/HEAD_DEF.SPF")
        .to_string_lossy()
        .into_owned()
}

/// The binary in `dir`, with a bound on its time: a run that hangs fails.
fn run_in(dir: &Path, args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let started = Instant::now();
    while child.try_wait().expect("wait").is_none() {
        if started.elapsed() > Duration::from_secs(20) {
            let _ = child.kill();
            panic!("{args:?} hangs");
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    child.wait_with_output().expect("output")
}

fn rewrite_in_place(dir: &Path, path: &Path) -> Output {
    let heads = heads();
    run_in(
        dir,
        &[
            "rewrite",
            "--in-place",
            "--heads",
            &heads,
            path.to_str().expect("utf-8"),
        ],
    )
}

/// `text` with Windows' path separators as `/`: a walk there joins the
/// names it finds with `\\`, as people there read paths.
fn slashes(text: &str) -> String {
    if cfg!(windows) {
        text.replace('\\', "/")
    } else {
        text.to_string()
    }
}

fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .expect("dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[cfg(unix)]
fn is_root() -> bool {
    fs::metadata("/proc/self").is_ok_and(|m| m.uid() == 0)
}

#[test]
fn in_place_refuses_what_is_not_a_regular_file() {
    let dir = scratch("files-streams");
    let heads = heads();
    // `-` (the default path) and /dev/stdin: nothing to replace.
    let paths: &[&str] = if cfg!(unix) {
        &["-", "/dev/stdin"]
    } else {
        &["-"]
    };
    for &path in paths {
        let output = run_in(&dir, &["rewrite", "--in-place", "--heads", &heads, path]);
        assert_exit(&output, 2);
        assert!(
            String::from_utf8_lossy(&output.stderr).contains("cannot be rewritten in place"),
            "{path}: {}",
            String::from_utf8_lossy(&output.stderr)
        );
    }
    let output = run_in(&dir, &["rewrite", "--in-place", "--heads", &heads]);
    assert_exit(&output, 2);
    assert!(names(&dir).is_empty(), "written: {:?}", names(&dir));
    // A FIFO is refused before it is read (reading it would wait for a writer).
    let fifo = dir.join("PIPE.MPF");
    if self::fifo(&fifo) {
        let output = rewrite_in_place(&dir, &fifo);
        assert_exit(&output, 2);
        assert!(String::from_utf8_lossy(&output.stderr).contains("a FIFO"));
        assert_eq!(names(&dir), ["PIPE.MPF"]);
    }
    let _ = fs::remove_dir_all(&dir);
}

#[test]
#[cfg(unix)] // symbolic links, modes, owners: see the module's comment
fn in_place_writes_through_a_symlink_and_keeps_the_link() {
    let dir = scratch("files-symlink");
    let real = dir.join("real");
    fs::create_dir_all(&real).expect("dir");
    fs::write(real.join("PART.MPF"), PROGRAM).expect("write");
    let link = dir.join("LINK.MPF");
    symlink("real/PART.MPF", &link).expect("symlink");
    assert_exit(&rewrite_in_place(&dir, &link), 0);
    assert!(fs::symlink_metadata(&link)
        .expect("link")
        .file_type()
        .is_symlink());
    assert_eq!(
        fs::read_link(&link).expect("link"),
        Path::new("real/PART.MPF")
    );
    let rewritten = fs::read(real.join("PART.MPF")).expect("target");
    assert!(rewritten.starts_with(b"; sinuprep: CYCLE600"));
    // The backup and every temporary file are beside the target.
    assert_eq!(
        fs::read(real.join("PART.MPF.bak")).expect("backup"),
        PROGRAM
    );
    assert_eq!(names(&real), ["PART.MPF", "PART.MPF.bak"]);
    assert_eq!(names(&dir), ["LINK.MPF", "real"]);
    let _ = fs::remove_dir_all(&dir);
}

#[test]
#[cfg(unix)] // symbolic links, modes, owners: see the module's comment
fn in_place_keeps_the_mode_and_the_owner() {
    let dir = scratch("files-mode");
    let path = dir.join("PRIVATE.MPF");
    fs::write(&path, PROGRAM).expect("write");
    fs::set_permissions(&path, fs::Permissions::from_mode(0o600)).expect("chmod");
    assert_exit(&rewrite_in_place(&dir, &path), 0);
    let metadata = fs::metadata(&path).expect("metadata");
    assert_eq!(metadata.mode() & 0o7777, 0o600);
    assert_eq!(
        fs::metadata(dir.join("PRIVATE.MPF.bak"))
            .expect("bak")
            .mode()
            & 0o7777,
        0o600,
        "the backup is as private as the program"
    );
    if !is_root() {
        eprintln!("NOTE: not root; the owner and setuid cases were skipped");
        let _ = fs::remove_dir_all(&dir);
        return;
    }
    // Root rewriting or formatting a user's file leaves it the user's,
    // setuid and setgid bits and all (the owner is given before the mode:
    // a change of owner clears them).
    let users = dir.join("USERS.MPF");
    fs::write(&users, PROGRAM).expect("write");
    std::os::unix::fs::chown(&users, Some(4321), Some(4322)).expect("chown");
    fs::set_permissions(&users, fs::Permissions::from_mode(0o6750)).expect("chmod");
    assert_exit(&rewrite_in_place(&dir, &users), 0);
    let metadata = fs::metadata(&users).expect("metadata");
    assert_eq!((metadata.uid(), metadata.gid()), (4321, 4322));
    assert_eq!(metadata.mode() & 0o7777, 0o6750);
    fs::write(&users, b"N10  G1 X1 F100\n").expect("write");
    assert_exit(&run_in(&dir, &["fmt", "USERS.MPF"]), 0);
    assert_eq!(fs::read(&users).expect("formatted"), b"N10 G1 X1 F100\n");
    let metadata = fs::metadata(&users).expect("metadata");
    assert_eq!((metadata.uid(), metadata.gid()), (4321, 4322));
    assert_eq!(metadata.mode() & 0o7777, 0o6750);
    // A user who cannot keep the owner gets the file, without setuid/setgid.
    let shared = dir.join("shared");
    fs::create_dir_all(&shared).expect("dir");
    fs::set_permissions(&shared, fs::Permissions::from_mode(0o777)).expect("chmod");
    let theirs = shared.join("THEIRS.MPF");
    fs::write(&theirs, PROGRAM).expect("write");
    std::os::unix::fs::chown(&theirs, Some(4321), Some(4322)).expect("chown");
    fs::set_permissions(&theirs, fs::Permissions::from_mode(0o6777)).expect("chmod");
    let output = {
        use std::os::unix::process::CommandExt;
        Command::new(env!("CARGO_BIN_EXE_sinuprep"))
            .args(["rewrite", "--in-place", "--no-backup", "--heads", &heads()])
            .arg(&theirs)
            .current_dir(&shared)
            .uid(5555)
            .gid(5555)
            .output()
            .expect("runs as another user")
    };
    if output.status.code() == Some(0) {
        let metadata = fs::metadata(&theirs).expect("metadata");
        assert_eq!(metadata.uid(), 5555);
        assert_eq!(metadata.mode() & 0o7777, 0o0777, "setuid/setgid dropped");
    } else {
        eprintln!(
            "NOTE: the binary could not run as another user here ({}); the setuid case was skipped",
            String::from_utf8_lossy(&output.stderr).trim()
        );
    }
    let _ = fs::remove_dir_all(&dir);
}

#[test]
#[cfg(unix)] // symbolic links, modes, owners: see the module's comment
fn the_backup_is_never_written_through_a_planted_link() {
    let dir = scratch("files-backup-link");
    let path = dir.join("PART.MPF");
    fs::write(&path, PROGRAM).expect("write");
    let victim = dir.join("victim");
    fs::write(&victim, b"precious").expect("write");
    symlink(&victim, dir.join("PART.MPF.bak")).expect("symlink");
    assert_exit(&rewrite_in_place(&dir, &path), 0);
    assert_eq!(fs::read(&victim).expect("victim"), b"precious");
    let bak = dir.join("PART.MPF.bak");
    assert!(fs::symlink_metadata(&bak).expect("bak").is_file());
    assert_eq!(fs::read(&bak).expect("bak"), PROGRAM);
    let _ = fs::remove_dir_all(&dir);
}

/// `rewrite -o DIR` of several programs writes nothing through a link
/// planted inside DIR, at a file's name or on its way, and says which; the
/// other programs are written.
#[test]
#[cfg(unix)] // symbolic links: see the module's comment
fn an_output_folder_is_never_written_through_a_link_inside_it() {
    let dir = scratch("files-output-links");
    for folder in ["in/sub", "in/ok", "out", "elsewhere"] {
        fs::create_dir_all(dir.join(folder)).expect("folder");
    }
    for program in ["in/P.MPF", "in/sub/NEW.MPF", "in/ok/FINE.MPF"] {
        fs::write(dir.join(program), PROGRAM).expect("write");
    }
    fs::write(dir.join("victim"), b"precious").expect("write");
    symlink("../victim", dir.join("out/P.MPF")).expect("symlink");
    symlink("../elsewhere", dir.join("out/sub")).expect("symlink");
    let heads = heads();
    let output = run_in(&dir, &["rewrite", "--heads", &heads, "-o", "out", "in"]);
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("out/P.MPF is not written: it is a symbolic link"),
        "{stderr}"
    );
    assert!(
        stderr.contains("out/sub/NEW.MPF is not written: the folder out/sub on its way"),
        "{stderr}"
    );
    assert_eq!(fs::read(dir.join("victim")).expect("victim"), b"precious");
    assert!(names(&dir.join("elsewhere")).is_empty());
    let fine = fs::read(dir.join("out/ok/FINE.MPF")).expect("written");
    assert!(fine.windows(8).any(|w| w == b"CYCLE800"));
    // The output folder itself may be a link: the user named it.
    symlink("elsewhere", dir.join("linked")).expect("symlink");
    let output = run_in(&dir, &["rewrite", "--heads", &heads, "-o", "linked", "in"]);
    assert_exit(&output, 0);
    assert!(dir.join("elsewhere/sub/NEW.MPF").is_file());
    let _ = fs::remove_dir_all(&dir);
}

/// A file whose name takes all the 255 bytes a file system allows is
/// rewritten and formatted in place: the temporary name beside it is
/// shorter. Its backup's name cannot be: that is said, the file untouched.
/// Unix only: on Windows such a name puts the path past MAX_PATH, another
/// limit (Wine fails to read it back, "More data available").
#[test]
#[cfg(unix)]
fn a_name_of_255_bytes_is_rewritten_in_place() {
    let dir = scratch("files-long-name");
    let name = format!("{}.MPF", "P".repeat(251));
    let path = dir.join(&name);
    fs::write(&path, PROGRAM).expect("a name of 255 bytes");
    let output = rewrite_in_place(&dir, Path::new(&name));
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("--no-backup"), "{stderr}");
    assert_eq!(fs::read(&path).expect("untouched"), PROGRAM);
    let heads = heads();
    let args = [
        "rewrite",
        "--in-place",
        "--no-backup",
        "--heads",
        &heads,
        &name,
    ];
    assert_exit(&run_in(&dir, &args), 0);
    let rewritten = fs::read(&path).expect("rewritten");
    assert!(rewritten.windows(8).any(|w| w == b"CYCLE800"));
    fs::write(&path, b"N10  G1 X1 F100\n").expect("write");
    assert_exit(&run_in(&dir, &["fmt", &name]), 0);
    assert_eq!(fs::read(&path).expect("formatted"), b"N10 G1 X1 F100\n");
    assert_eq!(names(&dir), [name]);
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn leftover_temporary_files_of_killed_runs_are_removed_and_live_ones_kept() {
    let dir = scratch("files-leftovers");
    let path = dir.join("PART.MPF");
    fs::write(&path, PROGRAM).expect("write");
    // What a killed run left, under the old fixed name (this process's PID,
    // as a run under PID 1 in a container would meet it) and a random one.
    let stale = [
        format!(".PART.MPF.sinuprep-{}.tmp", std::process::id()),
        ".PART.MPF.sinuprep-0123456789abcdef.tmp".to_string(),
    ];
    for name in &stale {
        fs::write(dir.join(name), b"half a rewrite").expect("write");
    }
    // One that a running rewrite holds (its lock).
    let live_name = ".PART.MPF.sinuprep-fedcba9876543210.tmp";
    let live = fs::File::create(dir.join(live_name)).expect("create");
    live.lock().expect("lock");
    assert_exit(&rewrite_in_place(&dir, &path), 0);
    assert_eq!(names(&dir), [live_name, "PART.MPF", "PART.MPF.bak"]);
    drop(live);
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn output_onto_the_input_is_an_in_place_rewrite() {
    let dir = scratch("files-onto-input");
    let heads = heads();
    fs::write(dir.join("BAD.MPF"), REFUSED).expect("write");
    let output = run_in(
        &dir,
        &["rewrite", "--heads", &heads, "BAD.MPF", "-o", "./BAD.MPF"],
    );
    assert_exit(&output, 1);
    assert_eq!(fs::read(dir.join("BAD.MPF")).expect("read"), REFUSED);
    assert_eq!(names(&dir), ["BAD.MPF"]);
    fs::write(dir.join("GOOD.MPF"), PROGRAM).expect("write");
    let output = run_in(
        &dir,
        &["rewrite", "--heads", &heads, "GOOD.MPF", "-o", "GOOD.MPF"],
    );
    assert_exit(&output, 0);
    assert!(fs::read(dir.join("GOOD.MPF"))
        .expect("read")
        .starts_with(b"; sinuprep:"));
    assert_eq!(fs::read(dir.join("GOOD.MPF.bak")).expect("backup"), PROGRAM);
    let _ = fs::remove_dir_all(&dir);
}

#[test]
#[cfg(unix)] // symbolic links, modes, owners: see the module's comment
fn directory_walks_take_every_file_once_through_looping_links() {
    let dir = scratch("files-loops");
    let programs = dir.join("programs");
    fs::create_dir_all(programs.join("sub")).expect("dir");
    fs::write(programs.join("A.MPF"), b"N10 X1\nM30\n").expect("write");
    fs::write(programs.join("sub/B.SPF"), b"PROC B\nM17\n").expect("write");
    symlink(".", programs.join("a")).expect("symlink");
    symlink(".", programs.join("b")).expect("symlink");
    symlink("..", programs.join("sub/up")).expect("symlink");
    symlink("A.MPF", programs.join("SAME.MPF")).expect("symlink");
    let output = run_in(
        &dir,
        &["check", "--format", "json", "programs", "programs/A.MPF"],
    );
    assert_exit(&output, 0);
    let report: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json");
    let files: Vec<&str> = report["files"]
        .as_array()
        .expect("files")
        .iter()
        .map(|f| f["path"].as_str().expect("path"))
        .collect();
    assert_eq!(files.len(), 2, "{files:?}");
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn concurrent_in_place_rewrites_leave_one_whole_version_and_the_original_as_backup() {
    let dir = scratch("files-concurrent");
    let path = dir.join("PART.MPF");
    let heads = heads();
    fs::write(&path, PROGRAM).expect("write");
    assert_exit(&rewrite_in_place(&dir, &path), 0);
    let rewritten = fs::read(&path).expect("read");
    for round in 0..20 {
        fs::write(&path, PROGRAM).expect("write");
        let _ = fs::remove_file(dir.join("PART.MPF.bak"));
        let children: Vec<_> = (0..2)
            .map(|_| {
                Command::new(env!("CARGO_BIN_EXE_sinuprep"))
                    .args(["rewrite", "--in-place", "--heads", &heads])
                    .arg(&path)
                    .stderr(Stdio::null())
                    .spawn()
                    .expect("runs")
            })
            .collect();
        for mut child in children {
            assert!(child.wait().expect("ends").success(), "round {round}");
        }
        assert_eq!(fs::read(&path).expect("read"), rewritten, "round {round}");
        assert_eq!(
            fs::read(dir.join("PART.MPF.bak")).expect("backup"),
            PROGRAM,
            "round {round}: the backup is not the original"
        );
        assert_eq!(names(&dir), ["PART.MPF", "PART.MPF.bak"], "round {round}");
    }
    let _ = fs::remove_dir_all(&dir);
}

/// A folder of programs: `eval` reports each in order, `--check` names each that would change and fails,
/// `-o DIR` mirrors the tree, `--in-place` rewrites each file that can be
/// (one with errors stays as it was, and the status says so), one that fails
/// stops none of the others, and several programs with nowhere to go are
/// refused before anything is read.
#[test]
fn a_folder_is_rewritten_file_by_file() {
    let dir = scratch("files-folder");
    let heads = heads();
    fs::create_dir_all(dir.join("in/sub")).expect("dirs");
    fs::write(dir.join("in/A.MPF"), PROGRAM).expect("A");
    fs::write(dir.join("in/sub/B.MPF"), PROGRAM).expect("B");
    fs::write(dir.join("in/sub/BAD.MPF"), REFUSED).expect("BAD");
    fs::write(dir.join("in/sub/PLAIN.SPF"), b"G1 X1 F100\nM17\n").expect("PLAIN");

    let output = run_in(&dir, &["rewrite", "--heads", &heads, "in"]);
    assert_exit(&output, 2);
    assert!(String::from_utf8_lossy(&output.stderr)
        .contains("more than one program to rewrite (the folder in)"));

    let output = run_in(&dir, &["rewrite", "--check", "--heads", &heads, "in"]);
    assert_exit(&output, 1);
    let stderr = slashes(&String::from_utf8_lossy(&output.stderr));
    for name in ["in/A.MPF: would rewrite 1", "in/sub/B.MPF: would rewrite 1"] {
        assert!(stderr.contains(name), "{stderr}");
    }
    assert!(!stderr.contains("PLAIN.SPF: would"), "{stderr}");

    // eval over the folder: one JSON array, a document per program in order.
    let output = run_in(&dir, &["eval", "--json", "--heads", &heads, "in"]);
    let documents: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json");
    let paths: Vec<String> = documents
        .as_array()
        .expect("an array for a folder")
        .iter()
        .filter_map(|d| d["path"].as_str().map(slashes))
        .collect();
    assert_eq!(
        paths,
        [
            "in/A.MPF",
            "in/sub/B.MPF",
            "in/sub/BAD.MPF",
            "in/sub/PLAIN.SPF"
        ]
    );

    let output = run_in(&dir, &["rewrite", "--heads", &heads, "-o", "out", "in"]);
    assert_exit(&output, 1); // BAD.MPF's refused call is an error
    let rewritten = fs::read(dir.join("out/sub/B.MPF")).expect("mirrored");
    assert!(rewritten != PROGRAM && rewritten.windows(8).any(|w| w == b"CYCLE800"));
    assert_eq!(fs::read(dir.join("out/A.MPF")).expect("A"), rewritten);
    assert_eq!(
        fs::read(dir.join("out/sub/PLAIN.SPF")).expect("PLAIN"),
        b"G1 X1 F100\nM17\n"
    );

    // A file nobody may read (a mode Windows has no counterpart of).
    #[cfg(unix)]
    let unreadable = {
        fs::write(dir.join("in/sub/GONE.MPF"), b"").expect("GONE");
        fs::set_permissions(
            dir.join("in/sub/GONE.MPF"),
            fs::Permissions::from_mode(0o000),
        )
        .expect("mode");
        fs::read(dir.join("in/sub/GONE.MPF")).is_err() // root reads anything
    };
    #[cfg(not(unix))]
    let unreadable = false;
    let output = run_in(&dir, &["rewrite", "--in-place", "--heads", &heads, "in"]);
    assert_exit(&output, if unreadable { 2 } else { 1 });
    assert_eq!(fs::read(dir.join("in/A.MPF")).expect("A"), rewritten);
    assert_eq!(fs::read(dir.join("in/sub/B.MPF")).expect("B"), rewritten);
    assert_eq!(fs::read(dir.join("in/sub/BAD.MPF")).expect("BAD"), REFUSED);
    assert!(String::from_utf8_lossy(&output.stderr).contains("BAD.MPF: not rewritten in place"));

    let output = run_in(
        &dir,
        &["rewrite", "--heads", &heads, "empty-dir-that-is-not-there"],
    );
    assert_exit(&output, 2);
    fs::create_dir_all(dir.join("empty")).expect("empty");
    assert_exit(&run_in(&dir, &["rewrite", "--check", "empty"]), 2);
    assert_exit(
        &run_in(&dir, &["rewrite", "--check", "--allow-empty", "empty"]),
        0,
    );
    let _ = fs::remove_dir_all(&dir);
}

#[test]
#[cfg(unix)] // a FIFO: see the module's comment
fn check_prints_each_file_as_soon_as_the_files_before_it_are_done() {
    let dir = scratch("files-stream");
    fs::write(dir.join("A.MPF"), b"GOTOF NOWHERE\nM30\n").expect("write");
    // The second program comes through a FIFO: written only once the first
    // one's finding has been read.
    let fifo = dir.join("B.MPF");
    if !Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .is_ok_and(|s| s.success())
    {
        eprintln!("NOTE: mkfifo is not available here; the test was skipped");
        return;
    }
    let mut child = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
        .args(["check", "--format", "short", "A.MPF", "B.MPF"])
        .current_dir(&dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let stdout = child.stdout.take().expect("stdout");
    let (sender, first_line) = std::sync::mpsc::channel();
    let reader = std::thread::spawn(move || {
        use std::io::BufRead;
        let mut lines = std::io::BufReader::new(stdout).lines();
        let _ = sender.send(lines.next());
        lines.count()
    });
    let first = first_line.recv_timeout(Duration::from_secs(10));
    // Whatever came, the FIFO is written so that the run ends.
    fs::write(&fifo, b"GOTOF ELSEWHERE\nM30\n").expect("write the FIFO");
    let _ = reader.join();
    let output = child.wait_with_output().expect("ends");
    assert_exit(&output, 1);
    let first = first
        .expect("the first file's finding came before the second file was read")
        .expect("a line")
        .expect("text");
    assert!(first.starts_with("A.MPF:1:"), "{first}");
    let _ = fs::remove_dir_all(&dir);
}

/// A FIFO at `path`, or `false` (and a note) where mkfifo is missing (as
/// on Windows, which has no FIFOs in the file system).
fn fifo(path: &Path) -> bool {
    if cfg!(not(unix)) {
        eprintln!("NOTE: Windows has no FIFOs in the file system; the FIFO cases were skipped");
        return false;
    }
    let made = Command::new("mkfifo")
        .arg(path)
        .status()
        .is_ok_and(|s| s.success());
    if !made {
        eprintln!("NOTE: mkfifo is not available here; the FIFO cases were skipped");
    }
    made
}

#[test]
#[cfg(unix)] // symbolic links, modes, owners: see the module's comment
fn directory_walks_skip_links_and_whatever_is_no_regular_file_and_say_so() {
    let dir = scratch("files-walk-links");
    let programs = dir.join("programs");
    fs::create_dir_all(&programs).expect("dir");
    fs::write(programs.join("A.MPF"), b"N10 X1\nM30\n").expect("write");
    // Outside the tree: a file whose lines a report would print.
    fs::write(dir.join("secret"), b"SECRET LINE X\nM30\n").expect("write");
    symlink(dir.join("secret"), programs.join("shadow.MPF")).expect("symlink");
    symlink("/dev/zero", programs.join("zero.MPF")).expect("symlink");
    symlink("/", programs.join("root")).expect("symlink");
    let has_fifo = fifo(&programs.join("PIPE.MPF"));
    let output = run_in(&dir, &["check", "--format", "short", "programs"]);
    assert_exit(&output, 0);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(!String::from_utf8_lossy(&output.stdout).contains("SECRET"));
    for skipped in ["shadow.MPF", "zero.MPF", "programs/root"] {
        let note = format!(
            "note: skipped programs/{}",
            skipped.trim_start_matches("programs/")
        );
        assert!(stderr.contains(&note), "{note} in {stderr}");
    }
    if has_fifo {
        assert!(
            stderr.contains("skipped programs/PIPE.MPF: not a regular file"),
            "{stderr}"
        );
    }
    assert!(stderr.contains("in 1 file"), "{stderr}");

    // Asked to follow links, the walk reads the linked program, and still
    // opens no device or FIFO.
    fs::remove_file(programs.join("root")).expect("unlink");
    let output = run_in(
        &dir,
        &["check", "--format", "short", "--follow-links", "programs"],
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(String::from_utf8_lossy(&output.stdout).contains("shadow.MPF"));
    assert!(
        stderr.contains("skipped programs/zero.MPF: not a regular file"),
        "{stderr}"
    );
    assert!(stderr.contains("in 2 files"), "{stderr}");

    // A rewrite into a directory copies nothing from outside the tree.
    let output = run_in(&dir, &["rewrite", "-o", "out", "programs"]);
    assert_exit(&output, 0);
    assert_eq!(names(&dir.join("out")), ["A.MPF"]);
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn files_the_settings_name_must_be_regular_files_of_a_sane_size() {
    let dir = scratch("files-settings");
    fs::write(dir.join("A.MPF"), b"N10 X1\nM30\n").expect("write");
    // Sparse: 64 MiB and one byte, no disk taken.
    let big = fs::File::create(dir.join("BIG.DEF")).expect("create");
    big.set_len((64 << 20) + 1).expect("sparse");
    let mut cases = vec![
        vec!["check", "--definitions", "BIG.DEF", "A.MPF"],
        vec!["axes", "--from-a3200", "BIG.DEF"],
    ];
    if fifo(&dir.join("PIPE")) {
        cases.push(vec!["axes", "--from-a3200", "PIPE"]);
        for option in [
            "--definitions",
            "--machine",
            "--heads",
            "--values",
            "--config",
        ] {
            cases.push(vec!["check", option, "PIPE", "A.MPF"]);
        }
        cases.push(vec!["eval", "--values", "PIPE", "A.MPF"]);
        cases.push(vec!["rewrite", "--heads", "PIPE", "A.MPF"]);
    }
    for args in cases {
        let output = run_in(&dir, &args);
        assert_exit(&output, 2);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            stderr.contains("not a regular file") || stderr.contains("larger than 64 MiB"),
            "{args:?}: {stderr}"
        );
    }
    let _ = fs::remove_dir_all(&dir);
}

#[test]
#[cfg(unix)] // made with a Unix shell's `cd -P`; Windows' limit is another (MAX_PATH)
fn a_program_deeper_than_the_path_limit_is_an_error_that_names_it() {
    let dir = scratch("files-deep");
    fs::write(dir.join("TOP.MPF"), b"N10 X1\nM30\n").expect("write");
    // Folders of 200-character names, 30 one in the other: past any
    // system's path limit (Linux's is 4,096 bytes; 3,000 folders of one
    // letter are past it too, and slow to make).
    let name = "d".repeat(200);
    let script = format!(
        "mkdir deep && cd deep || exit 1; i=0; while [ $i -lt 30 ]; do mkdir {name} && cd -P {name} || exit 1; i=$((i+1)); done; echo M30 > PART.MPF"
    );
    let made = Command::new("sh")
        .arg("-c")
        .arg(script)
        .current_dir(&dir)
        .status()
        .expect("sh runs");
    assert!(made.success());
    let output = run_in(&dir, &["check", "."]);
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("cannot read ./deep/"), "{stderr}");
    let _ = fs::remove_dir_all(&dir);
}

#[test]
#[cfg(unix)] // symbolic links, modes, owners: see the module's comment
fn a_head_def_beside_the_program_is_not_read_through_a_link_unless_asked() {
    let dir = scratch("files-heads-link");
    let programs = dir.join("programs");
    fs::create_dir_all(&programs).expect("dir");
    fs::write(programs.join("P.MPF"), PROGRAM).expect("write");
    fs::write(
        dir.join("outside"),
        b"_HEAD_NAME=\"SECRETHEAD\"\n_HEAD_ALLOWED=1\n",
    )
    .expect("write");
    symlink(dir.join("outside"), programs.join("HEAD_DEF.SPF")).expect("symlink");
    let output = run_in(&dir, &["check", "--format", "human", "programs"]);
    let shown = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(!shown.contains("SECRETHEAD"), "{shown}");
    assert!(shown.contains("C610"), "HEAD_DEF is missing: {shown}");
    let output = run_in(
        &dir,
        &["check", "--format", "human", "--follow-links", "programs"],
    );
    let shown = String::from_utf8_lossy(&output.stdout);
    assert!(shown.contains("SECRETHEAD"), "{shown}");
    let _ = fs::remove_dir_all(&dir);
}

/// Names are found in any case, as the control and Windows find them:
/// `head_def.spf` beside a program is its HEAD_DEF and `SINUPREP.TOML` its
/// settings, on every platform; where the file system holds two names that
/// differ only in case, a program that would use them is an error naming
/// both (a copy to the control or to Windows keeps either one).
#[test]
fn names_are_found_in_any_case_and_two_spellings_are_an_error() {
    let dir = scratch("files-case");
    let parts = dir.join("parts");
    fs::create_dir_all(&parts).expect("dir");
    let repo = support::repo();
    fs::copy(
        repo.join("samples/PAPER_EXAMPLE3.MPF"),
        parts.join("PART.MPF"),
    )
    .expect("program");
    fs::copy(
        repo.join("samples/HEAD_DEF.SPF"),
        parts.join("head_def.spf"),
    )
    .expect("heads");
    fs::write(dir.join("SINUPREP.TOML"), "precision = 2\n").expect("settings");
    let output = run_in(&parts, &["rewrite", "PART.MPF"]);
    assert_exit(&output, 0);
    let rewritten = String::from_utf8_lossy(&output.stdout);
    assert!(
        rewritten.contains("37.79") && !rewritten.contains("37.792346"),
        "HEAD_DEF and the settings' precision: {rewritten}"
    );

    fs::write(parts.join("HEAD_DEF.SPF"), "PROC HEAD_DEF\nM17\n").expect("second");
    if names(&parts).len() < 3 {
        eprintln!("NOTE: this file system ignores case; the case of two spellings was skipped");
        let _ = fs::remove_dir_all(&dir);
        return;
    }
    let output = run_in(&parts, &["rewrite", "PART.MPF"]);
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("HEAD_DEF: ./HEAD_DEF.SPF and ./head_def.spf differ only in case"),
        "{stderr}"
    );
    fs::remove_file(parts.join("HEAD_DEF.SPF")).expect("remove");
    fs::write(dir.join("sinuprep.toml"), "precision = 3\n").expect("second");
    let output = run_in(&parts, &["check", "PART.MPF"]);
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("SINUPREP.TOML and") && stderr.contains("differ only in case"),
        "{stderr}"
    );
    let _ = fs::remove_dir_all(&dir);
}

/// Paths as people on Windows give them: a drive letter and backslashes
/// (`C:\CAM\OUT\PART.MPF`), forward slashes, the verbatim form (`\\?\C:\`),
/// from another directory; HEAD_DEF is found beside the program, the
/// backup written beside it, and a read-only file refused. UNC paths (`\\server\share\...`) need a share,
/// which Wine does not offer: they are not tried here.
#[test]
#[cfg(windows)]
fn windows_paths_with_a_drive_letter_and_backslashes() {
    let dir = scratch("files-windows-paths");
    let repo = support::repo();
    let original = fs::read(repo.join("samples/PAPER_EXAMPLE3.MPF")).expect("sample");
    fs::write(dir.join("PART.MPF"), &original).expect("program");
    fs::copy(repo.join("samples/HEAD_DEF.SPF"), dir.join("head_def.spf")).expect("heads");
    fs::copy(
        repo.join("tests/fixtures/lint/N022_trigger.mpf"),
        dir.join("N022.MPF"),
    )
    .expect("fixture");
    let expected = run_in(&dir, &["rewrite", "PART.MPF"]);
    assert_exit(&expected, 0);
    let program = dir.join("PART.MPF");
    let program = program.to_str().expect("utf-8");
    assert!(
        program.as_bytes().get(1) == Some(&b':') && program.contains('\\'),
        "{program}"
    );
    for path in [
        program.to_string(),
        program.replace('\\', "/"),
        format!(r"\\?\{program}"),
    ] {
        let output = run_in(&repo, &["rewrite", &path]);
        assert_exit(&output, 0);
        assert_eq!(output.stdout, expected.stdout, "{path}");
    }
    let output = run_in(&repo, &["rewrite", "--in-place", program]);
    assert_exit(&output, 0);
    assert_eq!(
        fs::read(dir.join("PART.MPF")).expect("read"),
        expected.stdout
    );
    assert_eq!(fs::read(dir.join("PART.MPF.bak")).expect("bak"), original);
    assert_eq!(
        names(&dir),
        ["N022.MPF", "PART.MPF", "PART.MPF.bak", "head_def.spf"]
    );
    // The read-only attribute is honoured: refused, the file untouched.
    let rewritten = dir.join("PART.MPF");
    fs::write(&rewritten, &original).expect("the original again");
    let mut permissions = fs::metadata(&rewritten).expect("metadata").permissions();
    permissions.set_readonly(true);
    // (Wine keeps the attribute as Unix mode bits, which do not stop root:
    // the tool must refuse by the attribute, whoever runs it.)
    fs::set_permissions(&rewritten, permissions.clone()).expect("read-only");
    let output = run_in(&repo, &["rewrite", "--in-place", "--no-backup", program]);
    assert_exit(&output, 2);
    assert!(String::from_utf8_lossy(&output.stderr).contains("read-only"));
    assert_eq!(fs::read(&rewritten).expect("read"), original);
    // Windows: the attribute cleared (no mode bits made world-writable).
    #[allow(clippy::permissions_set_readonly_false)]
    permissions.set_readonly(false);
    fs::set_permissions(&rewritten, permissions).expect("writable");
    // A finding names the file as it was given.
    let checked = dir.join("N022.MPF");
    let checked = checked.to_str().expect("utf-8");
    let output = run_in(&repo, &["check", "--format", "short", checked]);
    assert_exit(&output, 1);
    let report = String::from_utf8_lossy(&output.stdout);
    assert!(
        report.starts_with(&format!("{checked}:2:12: error[N022]")),
        "{report}"
    );
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn a_binary_file_is_skipped_by_a_walk_and_not_linted_when_named() {
    let dir = scratch("files-binary");
    let programs = dir.join("programs");
    fs::create_dir_all(&programs).expect("dir");
    fs::write(programs.join("A.MPF"), b"N10 X1\nM30\n").expect("write");
    // An executable saved under a program's name: text that would give
    // findings, after a NUL.
    let mut elf = b"\x7fELF\x02\x01\x01\0\0\0\0\0\0\0\0\0".to_vec();
    elf.extend_from_slice(b"GOTOF NOWHERE\nX=Y=Z\n");
    fs::write(programs.join("B.MPF"), &elf).expect("write");
    fs::write(programs.join("C.MPF"), b"N10 X2\nM30\n").expect("write");
    let output = run_in(&dir, &["check", "--format", "json", "programs"]);
    assert_exit(&output, 0);
    let stderr = String::from_utf8_lossy(&output.stderr).replace('\\', "/");
    assert!(
        stderr.contains("note: skipped programs/B.MPF: a binary file"),
        "{stderr}"
    );
    let files = reported(&output);
    assert_eq!(files, ["programs/A.MPF", "programs/C.MPF"]);

    // Named, it is no program to check: an error (exit 2), as in every
    // command. A UTF-16 text is named as such, with what to do.
    let output = run_in(&dir, &["check", "--format", "short", "programs/B.MPF"]);
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr).replace('\\', "/");
    assert!(
        output.stdout.is_empty(),
        "{}",
        String::from_utf8_lossy(&output.stdout)
    );
    assert!(
        stderr.contains("programs/B.MPF: a binary file (NUL bytes), not a program"),
        "{stderr}"
    );
    let utf16: Vec<u8> = [0xFF, 0xFE]
        .into_iter()
        .chain("N10 X1\r\nM30\r\n".bytes().flat_map(|b| [b, 0]))
        .collect();
    fs::write(dir.join("WIDE.MPF"), &utf16).expect("write");
    for command in ["check", "fmt", "rewrite", "eval"] {
        let output = run_in(&dir, &[command, "WIDE.MPF"]);
        assert_exit(&output, 2);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            stderr.contains("a UTF-16 text") && stderr.contains("iconv"),
            "{command}: {stderr}"
        );
    }

    // rewrite and eval skip it in a walk; named, it is no program to
    // rewrite or evaluate: an error, and the file untouched.
    for command in [&["rewrite", "--check"][..], &["eval"]] {
        let output = run_in(&dir, &[command, &["programs"]].concat());
        assert_exit(&output, 0);
        let stderr = String::from_utf8_lossy(&output.stderr).replace('\\', "/");
        assert!(
            stderr.contains("note: skipped programs/B.MPF: a binary file"),
            "{stderr}"
        );
    }
    let output = run_in(&dir, &["rewrite", "--in-place", "programs/B.MPF"]);
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr).replace('\\', "/");
    assert!(
        stderr.contains("a binary file (NUL bytes), not a program"),
        "{stderr}"
    );
    assert_eq!(fs::read(programs.join("B.MPF")).expect("read"), elf);
    let _ = fs::remove_dir_all(&dir);
}

/// The paths of the files a JSON report names.
fn reported(output: &Output) -> Vec<String> {
    let report: serde_json::Value = serde_json::from_slice(&output.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&output.stderr)));
    report["files"]
        .as_array()
        .expect("files")
        .iter()
        // A walk on Windows names `p\A.MPF`.
        .map(|f| f["path"].as_str().expect("path").replace('\\', "/"))
        .collect()
}

#[test]
fn a_walk_leaves_out_what_git_ignores_and_hidden_files_unless_asked() {
    let dir = scratch("files-gitignore");
    let p = dir.join("p");
    for folder in ["build", "sub", ".hidden"] {
        fs::create_dir_all(p.join(folder)).expect("dir");
    }
    for file in [
        "A.MPF",
        "build/B.MPF",
        "OLD.MPF",
        "KEEP.MPF",
        "sub/C.MPF",
        "sub/D.MPF",
        ".hidden/E.MPF",
        ".F.MPF",
    ] {
        fs::write(p.join(file), b"N10 X1\nM30\n").expect("write");
    }
    fs::write(p.join(".gitignore"), "build/\n*OLD.MPF\nKEEP.MPF\n").expect("write");
    // A deeper file takes back what one above ignored; .ignore applies
    // outside a repository too.
    fs::write(p.join("sub/.gitignore"), "!/C.MPF\n").expect("write");
    fs::write(p.join("sub/.ignore"), "D.MPF\n").expect("write");
    fs::write(p.join(".ignore"), "!KEEP.MPF\n").expect("write");
    let json = ["check", "--format", "json"];

    // Outside a git repository, .gitignore says nothing (as for git and
    // ripgrep).
    let output = run_in(&dir, &[&json[..], &["p"]].concat());
    assert_exit(&output, 0);
    assert_eq!(
        reported(&output),
        [
            "p/A.MPF",
            "p/KEEP.MPF",
            "p/OLD.MPF",
            "p/build/B.MPF",
            "p/sub/C.MPF"
        ]
    );

    fs::create_dir(dir.join(".git")).expect("a repository");
    let output = run_in(&dir, &[&json[..], &["p"]].concat());
    assert_exit(&output, 0);
    assert_eq!(reported(&output), ["p/A.MPF", "p/KEEP.MPF", "p/sub/C.MPF"]);

    // Named, an ignored file is read.
    let output = run_in(&dir, &[&json[..], &["p/OLD.MPF"]].concat());
    assert_eq!(reported(&output), ["p/OLD.MPF"]);

    let output = run_in(
        &dir,
        &[&json[..], &["--no-respect-gitignore", "--hidden", "p"]].concat(),
    );
    assert_exit(&output, 0);
    assert_eq!(
        reported(&output),
        [
            "p/.F.MPF",
            "p/.hidden/E.MPF",
            "p/A.MPF",
            "p/KEEP.MPF",
            "p/OLD.MPF",
            "p/build/B.MPF",
            "p/sub/C.MPF",
            "p/sub/D.MPF"
        ]
    );
    // A folder named is walked even if ignored, and the settings file can
    // turn the ignore files off.
    let output = run_in(&dir, &[&json[..], &["p/build"]].concat());
    assert_eq!(reported(&output), ["p/build/B.MPF"]);
    fs::write(dir.join("sinuprep.toml"), "respect-gitignore = false\n").expect("write");
    let output = run_in(&dir, &[&json[..], &["p"]].concat());
    assert_eq!(reported(&output).len(), 6, "{:?}", reported(&output));
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn include_and_exclude_say_what_a_walk_takes_relative_to_their_settings_file() {
    let dir = scratch("files-include");
    let p = dir.join("p");
    for folder in ["old", "draft", "x/draft", "control"] {
        fs::create_dir_all(p.join(folder)).expect("dir");
    }
    for file in [
        "A.MPF",
        "old/B.MPF",
        "draft/C.MPF",
        "x/draft/D.MPF",
        "control/_N_PART_MPF",
        "E.nc",
        "notes.txt",
    ] {
        fs::write(p.join(file), b"N10 X1\nM30\n").expect("write");
    }
    let json = ["check", "--format", "json"];
    // Only the NC extensions by default; a folder of other files says what
    // it left out and how to take it.
    let output = run_in(&dir, &["check", "p/control"]);
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("_N_PART_MPF"), "{stderr}");
    assert!(stderr.contains("extend-include"), "{stderr}");

    fs::write(
        dir.join("sinuprep.toml"),
        "extend-include = [\"*.NC\", \"_N_*_MPF\"]\nexclude = [\"old\", \"/p/draft\"]\n",
    )
    .expect("write");
    let output = run_in(&p, &[&json[..], &["."]].concat());
    assert_exit(&output, 0);
    assert_eq!(
        reported(&output),
        [
            "./A.MPF",
            "./E.nc",
            "./control/_N_PART_MPF",
            "./x/draft/D.MPF"
        ]
    );
    // --exclude replaces the file's `exclude`, relative to the current
    // directory; --extend-exclude adds to it.
    let output = run_in(&dir, &[&json[..], &["--exclude", "x", "p"]].concat());
    assert_eq!(
        reported(&output),
        [
            "p/A.MPF",
            "p/E.nc",
            "p/control/_N_PART_MPF",
            "p/draft/C.MPF",
            "p/old/B.MPF"
        ]
    );
    let output = run_in(
        &dir,
        &[&json[..], &["--extend-exclude", "*.nc,control", "p"]].concat(),
    );
    assert_eq!(reported(&output), ["p/A.MPF", "p/x/draft/D.MPF"]);
    // --include replaces the file's `include` and the default; the file's
    // `extend-include` still adds.
    let output = run_in(&dir, &[&json[..], &["--include", "*.nc", "p"]].concat());
    assert_eq!(reported(&output), ["p/E.nc", "p/control/_N_PART_MPF"]);
    fs::write(dir.join("sinuprep.toml"), "include = [\"*.MPF\"]\n").expect("write");
    let output = run_in(&dir, &[&json[..], &["--include", "notes.*", "p"]].concat());
    assert_eq!(reported(&output), ["p/notes.txt"]);
    let _ = fs::remove_dir_all(&dir);
}

/// An in-place write on Windows keeps the hidden, system, archive and
/// not-indexed attributes of the file it replaces, as it keeps read-only.
/// Where the file system cannot hold the hidden attribute (Wine without
/// extended attributes), there is nothing to keep, and the test says so.
#[test]
#[cfg(windows)]
fn an_in_place_write_keeps_a_hidden_files_attributes() {
    use std::io::Write as _;
    use std::os::windows::fs::{MetadataExt, OpenOptionsExt};
    const HIDDEN: u32 = 0x2;
    let dir = scratch("files-windows-hidden");
    let repo = support::repo();
    let original = fs::read(repo.join("samples/PAPER_EXAMPLE3.MPF")).expect("sample");
    fs::copy(repo.join("samples/HEAD_DEF.SPF"), dir.join("HEAD_DEF.SPF")).expect("heads");
    let program = dir.join("PART.MPF");
    let mut file = fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .attributes(HIDDEN)
        .open(&program)
        .expect("a hidden program");
    file.write_all(&original).expect("write");
    drop(file);
    let hidden = |path: &std::path::Path| {
        fs::metadata(path).expect("metadata").file_attributes() & HIDDEN != 0
    };
    if !hidden(&program) {
        eprintln!("this file system keeps no hidden attribute: nothing to keep");
        return;
    }
    let name = program.to_str().expect("utf-8");
    let output = run_in(&repo, &["rewrite", "--in-place", "--no-backup", name]);
    assert_exit(&output, 0);
    assert_ne!(fs::read(&program).expect("read"), original, "rewritten");
    assert!(hidden(&program), "the rewritten file is still hidden");
    let _ = fs::remove_dir_all(&dir);
}

/// The walk goes on while the first files are checked: their findings are
/// written before the walk reaches a folder far behind them. Checked by
/// order, not time: stdout and stderr share one file, and the note about a
/// link in the last folder can come only once the walk gets there, which a
/// walk that lists every file first does before any finding.
#[test]
#[cfg(unix)] // a symbolic link makes the note
fn findings_come_while_the_walk_goes_on() {
    let dir = scratch("files-streaming");
    let first = dir.join("programs/A");
    let last = dir.join("programs/Z");
    fs::create_dir_all(&first).expect("dir");
    fs::create_dir_all(&last).expect("dir");
    // More files than the threads may run ahead of what is written.
    for n in 0..300 {
        fs::write(
            first.join(format!("P{n:03}.MPF")),
            b"N10 GOTOF NOWHERE\nM30\n",
        )
        .expect("write");
    }
    symlink("../A/P000.MPF", last.join("LINK.MPF")).expect("symlink");
    let log = dir.join("log");
    let file = fs::File::create(&log).expect("log");
    let status = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
        .args(["check", "--format", "short", "programs"])
        .current_dir(&dir)
        .stdin(Stdio::null())
        .stdout(file.try_clone().expect("clone"))
        .stderr(file)
        .status()
        .expect("runs");
    assert_eq!(status.code(), Some(1));
    let log = fs::read_to_string(&log).expect("log");
    let note = log
        .find("skipped programs/Z/LINK.MPF")
        .expect("the link's note");
    let findings_before = log[..note].matches("error[N001]").count();
    // At most 64 files are worked on ahead of the one written next.
    assert!(
        findings_before >= 300 - 64 - 2,
        "{findings_before} findings before the note:\n{log}"
    );
    let _ = fs::remove_dir_all(&dir);
}

/// With no path, `fmt` and `rewrite --check` take the current folder, as
/// `check` does, whatever stdin is (in CI it is no terminal): a folder with
/// a file that fails fails, and stdin is read only when `-` is named.
#[test]
fn no_path_means_the_current_folder() {
    let dir = scratch("files-no-path");
    fs::write(dir.join("SPACED.MPF"), b"N10  X1\nM30\n").expect("write");
    fs::write(dir.join("P.MPF"), PROGRAM).expect("write");
    let heads = heads();
    for args in [
        &["fmt", "--check"][..],
        &["rewrite", "--check", "--heads", &heads],
    ] {
        let output = run_in(&dir, args);
        assert_exit(&output, 1);
    }
    let output = run_in(&dir, &["fmt"]);
    assert_exit(&output, 0);
    assert_eq!(
        fs::read(dir.join("SPACED.MPF")).expect("read"),
        b"N10 X1\nM30\n"
    );
    let _ = fs::remove_dir_all(&dir);
}

/// The settings of a folder hold for a program 300 folders below it, and
/// a settings file on the way holds below it (each folder is looked at
/// once, after its parent).
#[test]
fn settings_hold_far_down_a_deep_tree() {
    let dir = scratch("files-deep-settings");
    fs::write(dir.join("sinuprep.toml"), "ignore = [\"N001\"]\n").expect("write");
    let mut deep = dir.clone();
    for level in 0..300 {
        deep.push("d");
        if level == 200 {
            fs::create_dir_all(&deep).expect("dir");
            fs::write(deep.join("P.MPF"), b"GOTOF NOWHERE\nM30\n").expect("write");
        }
    }
    fs::create_dir_all(&deep).expect("dir");
    fs::write(deep.join("P.MPF"), b"GOTOF NOWHERE\nM30\n").expect("write");
    let output = run_in(&dir, &["check", "--format", "short", "."]);
    assert_exit(&output, 0);
    // A settings file half way down selects what the top one ignores.
    let half = (0..250).fold(dir.clone(), |path, _| path.join("d"));
    fs::write(half.join("sinuprep.toml"), "select = [\"N001\"]\n").expect("write");
    let output = run_in(&dir, &["check", "--format", "short", "."]);
    assert_exit(&output, 1);
    let found = stdout_lines(&output);
    assert_eq!(found.len(), 1, "{found:?}");
    let _ = fs::remove_dir_all(&dir);
}

fn stdout_lines(output: &Output) -> Vec<String> {
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(str::to_string)
        .collect()
}
