//! Hostile input: each must give a clear diagnostic or a plain result, in
//! bounded time and memory, and never a panic or a lost byte.

mod support;

use sinuprep::emit::apply;
use sinuprep::emit::cycle600::{rewrite, Options};
use sinuprep::lint;
use sinuprep::semantic::{analyze, Heads, Model, Supplied};
use sinuprep::syntax::{parse, program_kind};
use support::{assert_exit, run};

/// Everything the tool does with a program: parse, print, lint, rewrite.
fn survive(name: &str, source: &[u8]) -> Vec<&'static str> {
    let program = parse(source);
    assert!(program.print() == source, "{name}: bytes lost");
    let heads = Heads::read(
        "HEAD_DEF".into(),
        b"_HEAD_NAME=\"UFK600\"\n_HEAD_ALLOWED=1\n",
    );
    let settings = lint::Settings {
        heads: Some(heads.clone()),
        ..lint::Settings::default()
    };
    let findings = lint::check(source, name, program_kind(Some(name), source), &settings);
    for finding in &findings {
        assert!(
            finding.span.end <= source.len(),
            "{name}: {} outside the input",
            finding.code()
        );
    }
    let model = Model::of(source);
    let analysis = analyze(&model, &Supplied::default(), Some(&heads));
    let output = apply(
        source,
        &rewrite(&model, &analysis, &Options::default()).edits,
    );
    assert_eq!(
        support::syntax_errors(&output),
        support::syntax_errors(source),
        "{name}: the rewrite changed the syntax errors"
    );
    let mut codes: Vec<&'static str> = findings.iter().map(|d| d.code()).collect();
    codes.sort_unstable();
    codes.dedup();
    codes
}

const CALL: &str = "CYCLE600(0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\n";

#[test]
fn a_million_arguments() {
    // Past 64 KiB a block is not read (S009); within it, as many arguments
    // as fit are parsed and counted.
    let source = format!("R1=SET({}1)\n", "1,".repeat(1_000_000));
    assert!(survive("million arguments", source.as_bytes()).contains(&"S009"));
    let call = format!("CYCLE600({}0)\n", "0,".repeat(1_000_000));
    assert!(survive("million CYCLE600 arguments", call.as_bytes()).contains(&"S009"));
    let call = format!("CYCLE600({}0)\n", "0,".repeat(30_000));
    assert!(survive("30,000 CYCLE600 arguments", call.as_bytes()).contains(&"C601"));
}

#[test]
fn a_hundred_thousand_nested_blocks_around_a_cycle600() {
    let depth = 100_000;
    let source = format!(
        "{}{CALL}{}M30\n",
        "IF R1>0\n".repeat(depth),
        "ENDIF\n".repeat(depth)
    );
    // The call is too deep to walk: reported, never passed over in silence.
    assert!(survive("nested IF", source.as_bytes()).contains(&"C618"));
    let source = format!(
        "{}{CALL}{}M30\n",
        "WHILE R1>0\n".repeat(depth),
        "ENDWHILE\n".repeat(depth)
    );
    assert!(survive("nested WHILE", source.as_bytes()).contains(&"C618"));
    let source = format!(
        "R1=1\n{}{CALL}{}M30\n",
        "IF R1>0\n".repeat(depth),
        "ENDIF\n".repeat(depth)
    );
    assert!(survive("nested known IF", source.as_bytes()).contains(&"C618"));
    // `eval` lists it, and `rewrite --check` fails on it.
    let eval = run(&["eval", "-"], source.as_bytes());
    assert!(String::from_utf8_lossy(&eval.stdout).contains("CYCLE600"));
    assert_exit(&run(&["rewrite", "--check", "-"], source.as_bytes()), 1);
}

#[test]
fn a_hundred_thousand_nested_parentheses() {
    let source = format!("R1={}1{}\n", "(".repeat(100_000), ")".repeat(100_000));
    assert!(survive("nested parentheses", source.as_bytes()).contains(&"S009"));
    let source = format!("R1={}1{}\n", "(".repeat(30_000), ")".repeat(30_000));
    assert!(survive("nested parentheses", source.as_bytes()).contains(&"S008"));
}

/// A label written fifty thousand times and as many jumps to it: each
/// jump's search splits the label's lines at the jump (it walked them all,
/// 49 s for `check` of this program).
#[test]
fn fifty_thousand_jumps_to_a_label_written_fifty_thousand_times() {
    let source = "LA:\nGOTO LA\nLB:\nREPEAT LB P=2\nGOTOF LA\n".repeat(50_000) + "M30\n";
    let codes = survive("one label, many times", source.as_bytes());
    // Each GOTO finds LA both ways (N003); the last GOTOF finds none after
    // it, only before (N002).
    assert_eq!(codes, ["N002", "N003"]);
}

#[test]
fn numbers_beyond_any_range() {
    let huge = format!("R1=1{}\n", "0".repeat(10_000));
    assert!(survive("10,000 digits", huge.as_bytes()).contains(&"S003"));
    let tiny = format!("R1=0.{}1\nM30\n", "0".repeat(10_000));
    // A value too small for a REAL is 0, not an error (the block is too long, though).
    assert_eq!(survive("10,000 decimals", tiny.as_bytes()), ["N008"]);
    assert!(survive("exponent", b"R1=1EX99999\n").contains(&"S003"));
}

#[test]
fn expressions_without_a_value_in_cycle600_arguments() {
    for angle in [
        "ASIN(2)", "0/0", "SQRT(-1)", "LN(0)", "1/0", "ACOS(-2)", "\"TEXT\"",
    ] {
        let source = format!("CYCLE600(0, \"UFK600\", 1, 57, 0, 0, 0, {angle}, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\nM30\n");
        assert!(
            survive(angle, source.as_bytes()).contains(&"C609"),
            "{angle}"
        );
    }
}

#[test]
fn control_bytes_invalid_utf8_and_nothing_at_all() {
    survive("NUL", b"N10 X1\0\x01\x02 Y2\nM30\n");
    survive("invalid UTF-8", b"N10 X1 ; \xff\xfe\n\xc3\x28 X2\nM30\n");
    survive("empty", b"");
    survive("only line ends", b"\r\n\r\n\n\r");
}

#[test]
fn loops_the_evaluator_could_follow_forever() {
    let endless = format!("R1=0\nLOOP\nR1=R1+1\n{CALL}ENDLOOP\nM30\n");
    survive("LOOP", endless.as_bytes());
    let while_true = format!("WHILE 1\n{CALL}ENDWHILE\nM30\n");
    survive("WHILE 1", while_true.as_bytes());
    let gotob = format!("L1: R1=R1+1\n{CALL}GOTOB L1\nM30\n");
    survive("GOTOB loop", gotob.as_bytes());
    let gotos = format!("R1=R1+1\n{CALL}GOTOS\n");
    survive("GOTOS", gotos.as_bytes());
}

#[test]
fn the_cli_on_empty_input_and_on_a_directory() {
    let empty = run(&["rewrite", "-"], b"");
    assert_exit(&empty, 0);
    assert!(empty.stdout.is_empty());
    assert_exit(&run(&["check", "--format", "short", "-"], b""), 0);
    // A directory is several programs: rewrite has only stdout for them and
    // refuses; eval tells each (PROBE_ALIGN's measured angles are errors).
    let rewrite = run(&["rewrite", "samples"], b"");
    assert_exit(&rewrite, 2);
    assert!(String::from_utf8_lossy(&rewrite.stderr).contains("more than one program to rewrite"));
    let eval = run(&["eval", "samples"], b"");
    assert_exit(&eval, 1);
    assert!(String::from_utf8_lossy(&eval.stdout).contains("samples/PROBE_ALIGN.MPF"));
}

/// A large program with a CYCLE600, so that an in-place rewrite has work to do.
fn large_program() -> Vec<u8> {
    let mut source =
        b"N5 CYCLE600(0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\n"
            .to_vec();
    for n in 0..100_000 {
        source.extend_from_slice(
            format!("N{} G1 X{}.125 Y-{}.5 Z3.25\n", 10 + n, n % 997, n % 89).as_bytes(),
        );
    }
    source.extend_from_slice(b"M30\n");
    source
}

/// Whether the file system of `dir` makes nameless files (Linux `O_TMPFILE`).
#[cfg(target_os = "linux")]
fn nameless_files_in(dir: &std::path::Path) -> bool {
    use std::os::unix::fs::OpenOptionsExt;
    std::fs::OpenOptions::new()
        .write(true)
        .custom_flags(libc::O_TMPFILE)
        .mode(0o600)
        .open(dir)
        .is_ok()
}

#[cfg(not(target_os = "linux"))]
fn nameless_files_in(_: &std::path::Path) -> bool {
    false
}

#[test]
fn a_killed_in_place_rewrite_never_leaves_a_truncated_file() {
    let dir = std::env::temp_dir().join(format!("sinuprep-kill-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let original = large_program();
    let heads = support::repo().join("samples/HEAD_DEF.SPF");
    let path = dir.join("BIG.MPF");
    let rewrite = || {
        std::process::Command::new(env!("CARGO_BIN_EXE_sinuprep"))
            .args(["rewrite", "--in-place", "--heads"])
            .arg(&heads)
            .arg(&path)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("runs")
    };
    // How long a whole run takes here, to kill it at points spread over it,
    // up to the very end (the write and the rename).
    std::fs::write(&path, &original).expect("write");
    let started = std::time::Instant::now();
    assert!(rewrite().wait().expect("ends").success());
    let whole = started.elapsed();
    let (mut untouched, mut replaced, mut linked_not_renamed) = (0, 0, 0);
    let backup = dir.join("BIG.MPF.bak");
    let temporaries = || -> Vec<std::path::PathBuf> {
        std::fs::read_dir(&dir)
            .expect("dir")
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.to_string_lossy().ends_with(".tmp"))
            .collect()
    };
    let is_the_whole_rewrite = |bytes: &[u8]| {
        bytes.starts_with(b"; sinuprep: CYCLE600")
            && bytes.ends_with(b"M30\n")
            && bytes.len() > original.len()
    };
    // On Linux the temporary file has no name until it is complete: a kill
    // leaves nothing, except in the instant between its link under a
    // temporary name and the rename over the target (`linkat` cannot
    // replace a name). What is left there is the whole rewrite, which the
    // next run removes; a partial temporary file is never seen.
    let kill_left_no_partial_file = |when: &str| -> usize {
        let left = temporaries();
        for temporary in &left {
            let bytes = std::fs::read(temporary).expect("readable");
            assert!(
                is_the_whole_rewrite(&bytes),
                "killed {when}: a partial temporary file was left ({} bytes)",
                bytes.len()
            );
        }
        left.len()
    };
    let nameless = nameless_files_in(&dir);
    if !nameless {
        eprintln!(
            "NOTE: no nameless temporary files in {}: leftovers are removed by the next run only",
            dir.display()
        );
    }
    for percent in [2u32, 25, 50, 75, 90, 100, 110, 200, 300] {
        std::fs::write(&path, &original).expect("write");
        let _ = std::fs::remove_file(&backup);
        let mut child = rewrite();
        std::thread::sleep(whole * percent / 100);
        let _ = child.kill();
        let _ = child.wait();
        let now = std::fs::read(&path).expect("the file is still there");
        let rewritten = is_the_whole_rewrite(&now);
        assert!(now == original || rewritten, "killed at {percent}%: the file is neither the original nor the whole rewrite ({} bytes)", now.len());
        // The backup is written (atomically) before the rewrite: absent, or
        // the whole original, and always there once the file is rewritten.
        match std::fs::read(&backup) {
            Ok(bak) => assert!(bak == original, "killed at {percent}%: a partial backup"),
            Err(_) => assert!(
                now == original,
                "killed at {percent}%: rewritten without a backup"
            ),
        }
        // (On a file system without O_TMPFILE it is named while written,
        // as elsewhere, and a kill may leave it partial for the next run.)
        if nameless {
            linked_not_renamed += kill_left_no_partial_file(&format!("at {percent}%"));
        }
        if now == original {
            untouched += 1
        } else {
            replaced += 1
        }
    }
    // Killed while the rewrite is being written: the backup is written
    // first, so its arrival is the moment the rewrite's own write begins.
    let mut caught = 0;
    for _ in 0..5 {
        std::fs::write(&path, &original).expect("write");
        let _ = std::fs::remove_file(&backup);
        let mut child = rewrite();
        while !backup.exists() && child.try_wait().expect("wait").is_none() {
            std::hint::spin_loop();
        }
        let _ = child.kill();
        let _ = child.wait();
        let now = std::fs::read(&path).expect("the file is still there");
        caught += usize::from(now == original);
        if nameless {
            linked_not_renamed += kill_left_no_partial_file("while writing");
        }
    }
    eprintln!("whole run {whole:?}: {untouched} kills left the original, {replaced} found the whole rewrite; {caught} of 5 killed while writing; {linked_not_renamed} between link and rename");
    // A later run removes what killed runs left.
    std::fs::write(&path, &original).expect("write");
    assert!(rewrite().wait().expect("ends").success());
    assert_eq!(
        temporaries(),
        Vec::<std::path::PathBuf>::new(),
        "temporary files left after a whole run"
    );
    // The early kills cannot have finished, the late ones must have: the test
    // saw both sides of the write.
    assert!(
        untouched > 0 && replaced > 0,
        "{untouched} untouched, {replaced} replaced"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_read_only_file_is_a_clear_error_and_stays_untouched() {
    let dir = std::env::temp_dir().join(format!("sinuprep-ro-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let path = dir.join("RO.MPF");
    let original =
        b"N10 CYCLE600(0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\nM30\n";
    std::fs::write(&path, original).expect("write");
    let mut permissions = std::fs::metadata(&path).expect("metadata").permissions();
    permissions.set_readonly(true);
    std::fs::set_permissions(&path, permissions).expect("read-only");
    let heads = support::repo().join("samples/HEAD_DEF.SPF");
    let output = run(
        &[
            "rewrite",
            "--in-place",
            "--heads",
            heads.to_str().expect("utf-8"),
            path.to_str().expect("utf-8"),
        ],
        b"",
    );
    assert_exit(&output, 2);
    assert!(String::from_utf8_lossy(&output.stderr).contains("read-only"));
    assert_eq!(std::fs::read(&path).expect("read"), original);
    let leftovers = std::fs::read_dir(&dir).expect("dir").count();
    assert_eq!(leftovers, 1, "no temporary file or backup left");
    let mut permissions = std::fs::metadata(&path).expect("metadata").permissions();
    #[allow(clippy::permissions_set_readonly_false)]
    permissions.set_readonly(false);
    let _ = std::fs::set_permissions(&path, permissions);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Inputs the fuzzers found crashes with, kept so they stay fixed.
#[test]
fn fuzzer_findings_stay_fixed() {
    for path in support::files_below(&support::repo().join("tests/fixtures/regressions")) {
        survive(
            &path.display().to_string(),
            &std::fs::read(&path).expect("readable"),
        );
    }
}

/// Found by fuzzing: a recalculation-only CYCLE600 must not make the active
/// rotation unknown (not when its results are known only at run time, not
/// when a loop or a backward jump repeats it), or a second rewrite, where the
/// call is gone, would evaluate more than the first.
#[test]
fn rewriting_regressions_again_changes_nothing() {
    let heads = Heads::read(
        "HEAD_DEF".into(),
        b"_HEAD_NAME=\"UFK600\"\n_HEAD_ALLOWED=1\n",
    );
    for path in support::files_below(&support::repo().join("tests/fixtures/regressions")) {
        let source = std::fs::read(&path).expect("readable");
        for options in [
            Options::default(),
            Options {
                runtime: Some(None),
                inline_results: true,
                ..Options::default()
            },
        ] {
            let run = |bytes: &[u8]| {
                let model = Model::of(bytes);
                let analysis = analyze(&model, &Supplied::default(), Some(&heads));
                apply(bytes, &rewrite(&model, &analysis, &options).edits)
            };
            let once = run(&source);
            assert!(run(&once) == once, "{}: not idempotent", path.display());
        }
    }
}

/// The human format renders a finding far out on a long line as an excerpt
/// of the line, with its real column; a line too long to read (S009) too.
/// (Columns past 65,535, which miette counts in 16 bits, are rendered by the
/// `check` fuzz target, which shifts every finding 70,000 columns right.)
#[test]
fn a_finding_far_out_on_a_long_line_renders() {
    // A plain block just short of the limit; a suppression that suppresses
    // nothing at its end is a finding (N099) at its code, column 65,030.
    let mut source = format!("N10 X1 {}", "G1 ".repeat(21_667)).into_bytes();
    let position = format!("1:{}", source.len() + "; sinuprep: ignore ".len() + 1);
    source.extend_from_slice(b"; sinuprep: ignore N005\nM30\n");
    let too_long = format!("N10 X1 {}\nM30\n", "G1 ".repeat(30_000));
    for format in ["human", "short"] {
        let output = run(&["check", "--format", format, "-"], &source);
        assert_exit(&output, 0);
        let text = String::from_utf8_lossy(&output.stdout);
        assert!(text.contains("N099"), "{format}: {text}");
        assert!(text.contains(&position), "{format}: {text}");
        assert!(text.len() < 4000, "{format}: the whole line shown");
        let output = run(&["check", "--format", format, "-"], too_long.as_bytes());
        assert_exit(&output, 1);
        let text = String::from_utf8_lossy(&output.stdout);
        assert!(text.contains("S009"), "{format}: {text}");
        assert!(text.len() < 4000, "{format}: the whole line shown");
    }
    for command in [&["rewrite", "-"][..], &["eval", "-"][..]] {
        let mut call = source.clone();
        call.extend_from_slice(CALL.as_bytes());
        let output = run(command, &call);
        assert!(output.status.code() != Some(101), "{command:?} panicked");
    }
}

/// A block far longer than the control takes is refused (S009) rather than
/// read into a tree of some 50 bytes a byte; address words alone too (80
/// bytes a word), and their repeats are then not reported.
#[test]
fn a_five_megabyte_block_is_refused_not_read() {
    let call = format!("R1=MAX({}1)\nM30\n", "1,".repeat(2_500_000));
    let codes = survive("long call", call.as_bytes());
    assert!(codes.contains(&"S009"), "{codes:?}");
    let limit = sinuprep::syntax::MAX_PARSED_LINE;
    let just_under = format!("R1=MAX({}1)\nM30\n", "1,".repeat((limit - 10) / 2));
    assert!(!survive("call under the limit", just_under.as_bytes()).contains(&"S009"));
    let plain = format!("N10 {}\nM30\n", "X1 Y2 ".repeat(1_000_000));
    let codes = survive("long plain block", plain.as_bytes());
    assert!(
        codes.contains(&"S009") && !codes.contains(&"N022"),
        "{codes:?}"
    );
    let just_under = format!("N10 {}\nM30\n", "X1 Y2 ".repeat((limit - 10) / 6));
    let codes = survive("plain block under the limit", just_under.as_bytes());
    assert!(
        !codes.contains(&"S009") && codes.contains(&"N022"),
        "{codes:?}"
    );
}

#[test]
fn names_with_line_breaks_and_escape_sequences_are_printed_escaped() {
    let dir = support::scratch("hostile-names");
    let program = b"GOTOF NOWHERE\nM30\n";
    std::fs::write(dir.join("A\n::error file=X::forged.MPF"), program).expect("write");
    std::fs::write(dir.join("B\x1b]0;title\x07\x1b[2J.MPF"), program).expect("write");
    // An archive whose member's name holds a line break and an escape.
    let archive = support::binary_archive(&[(
        "/_N_MPF_DIR/_N_C\n::error file=Y::member\x1b[31m_MPF",
        &program[..],
    )]);
    std::fs::write(dir.join("SAVED.ARC"), archive).expect("write");
    let folder = dir.to_str().expect("utf-8");
    for format in ["short", "human", "github"] {
        let output = run(&["check", "--format", format, folder], b"");
        assert_exit(&output, 1);
        let text = String::from_utf8_lossy(&output.stdout);
        for name in ["forged.MPF", "title", "member\\u{1b}[31m_MPF"] {
            assert!(text.contains(name), "{format}: {name} missing in {text}");
        }
        assert!(
            !text.contains('\x1b') && !text.contains('\x07'),
            "{format}: {text:?}"
        );
        // Every finding's line begins as the format begins one.
        let begins = match format {
            "short" => dir.to_str().expect("utf-8"),
            "github" => "::error ",
            _ => "",
        };
        for line in text
            .lines()
            .filter(|l| l.contains("forged") || l.contains("member"))
        {
            assert!(line.contains(begins), "{format}: {line:?}");
            assert!(!line.starts_with("::error file=X"), "{format}: {line:?}");
            assert!(!line.starts_with("::error file=Y"), "{format}: {line:?}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn names_ending_in_characters_of_several_bytes_are_only_names() {
    // A folder's names are compared by their ends (`.SPF`, `_DEF`,
    // `.DEF`): a name whose last bytes cut a character (`Größe`, `€€`) is
    // neither, and the folder is checked as usual.
    let dir = support::scratch("hostile-multibyte-names");
    for name in ["Größe", "€€", "Ä.spf€", "ÜBER_DEF€", "€.SPF", "ö_DEF"] {
        std::fs::write(dir.join(name), b"").expect("write");
    }
    std::fs::write(dir.join("A.MPF"), b"G0 X1\nM30\n").expect("write");
    let program = dir.join("A.MPF");
    let output = run(
        &[
            "check",
            "--format",
            "short",
            program.to_str().expect("utf-8"),
        ],
        b"",
    );
    assert_exit(&output, 0);
    let _ = std::fs::remove_dir_all(&dir);
}
