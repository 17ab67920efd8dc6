//! The built binary: exit codes, stdin, each output format, `convert`.

use std::io::Write;
use std::process::{Command, Stdio};

mod support;

use support::{assert_exit, run, scratch, stdout};

#[test]
fn check_of_clean_samples_exits_0() {
    let output = run(&["check", "--format", "short", "samples"], b"");
    assert_exit(&output, 0);
    // Only information: the probe sample's angles are measured on the machine.
    let text = stdout(&output);
    assert!(text.lines().all(|l| l.contains(": info[")), "{text}");
}

#[test]
fn check_json_of_samples_follows_the_schema() {
    let output = run(&["check", "--format", "json", "samples/"], b"");
    assert_exit(&output, 0);
    insta::assert_snapshot!(stdout(&output));
}

#[test]
fn check_reports_errors_with_exit_1_in_every_format() {
    let broken = b"N10 G1 X10\nN20 MSG(\"open\nN30 X=(1+2\n";
    let short = run(&["check", "--format", "short", "-"], broken);
    assert_exit(&short, 1);
    insta::assert_snapshot!("short", stdout(&short));
    let json = run(&["check", "--format", "json", "-"], broken);
    assert_exit(&json, 1);
    insta::assert_snapshot!("json", stdout(&json));
    let human = run(&["check", "-"], broken);
    assert_exit(&human, 1);
    insta::assert_snapshot!("human", stdout(&human));
}

#[test]
fn check_of_a_missing_file_exits_2_and_names_it() {
    let output = run(&["check", "no/such/file.mpf"], b"");
    assert_exit(&output, 2);
    assert!(String::from_utf8_lossy(&output.stderr).contains("no/such/file.mpf"));
}

#[test]
fn check_takes_named_files_whatever_their_extension() {
    let output = run(
        &[
            "check",
            "--format",
            "short",
            "tests/fixtures/invalid/bad_number.mpf",
            "README.md",
        ],
        b"",
    );
    assert_exit(&output, 1);
    assert!(stdout(&output).contains("bad_number.mpf:1:6: error[S003]"));
}

/// The report for people shows each finding's own lines, far into a file
/// too, and names the same line and column as the short format (CRLF and
/// Latin-1 here).
#[test]
fn human_reports_show_the_right_lines_far_into_a_file() {
    let mut program: Vec<u8> = (1..=5000)
        .flat_map(|n| format!("N{} X1\r\n", n * 10).into_bytes())
        .collect();
    program.extend_from_slice(b"GOTOF NOWHERE\r\nX\xe4\r\nM30\r\n");
    let short = stdout(&run(&["check", "--format", "short", "-"], &program));
    assert!(short.contains(":5001:7: error[N001]") && short.contains(":5002:2: error[S004]"));
    let human = stdout(&run(&["check", "-"], &program));
    for expected in [
        ":5001:7]",
        " 5000 \u{2502} N50000 X1",
        " 5001 \u{2502} GOTOF NOWHERE",
        ":5002:2]",
        " 5002 \u{2502} X\u{e4}",
        " 5003 \u{2502} M30",
    ] {
        assert!(human.contains(expected), "{expected:?} not in\n{human}");
    }
}

/// A program large enough to be mapped instead of read (`cli::mapped`) is
/// checked and rewritten exactly as the same bytes read from stdin.
#[test]
fn a_mapped_program_reads_as_the_same_bytes_read_whole() {
    let mut program =
        std::fs::read(support::repo().join("samples/PAPER_EXAMPLE3.MPF")).expect("sample");
    program.truncate(program.len() - b"M30\n".len());
    for n in 0..200_000 {
        program.extend_from_slice(format!("N{} G1 X{n}.5 Y-2 Z3\r\n", 200 + n * 2).as_bytes());
    }
    program.extend_from_slice(b"GOTOF NOWHERE\r\nX\xe4\r\nM30\r\n");
    assert!(program.len() > 4 << 20, "not large enough to be mapped");
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("MAPPED.MPF");
    std::fs::write(&path, &program).expect("temporary file");
    let name = path.to_str().expect("UTF-8 path");
    for format in ["short", "json", "human"] {
        let mapped = run(&["check", "--format", format, name], b"");
        let read = run(
            &["check", "--format", format, "--stdin-filename", name, "-"],
            &program,
        );
        assert_exit(&mapped, 1);
        assert_eq!(stdout(&mapped), stdout(&read), "--format {format}");
    }
    let mapped = run(&["rewrite", name], b"");
    let read = run(&["rewrite", "-"], &program);
    assert_exit(&mapped, 1);
    assert!(mapped.stdout.len() > program.len(), "nothing rewritten");
    assert!(mapped.stdout == read.stdout, "the rewrites differ");
}

#[test]
fn rewrite_gives_every_byte_back_when_there_is_nothing_to_rewrite() {
    let input = b"N10 G1 X1\r\n\xe4\xf6 broken ( \"\rN20 X2";
    let output = run(&["rewrite", "-"], input);
    // The syntax errors are reported (exit 1), and not a byte is lost.
    assert_exit(&output, 1);
    assert_eq!(output.stdout, input);
    let clean = b"N10 G1 X1\r\nN20 X2";
    let output = run(&["rewrite", "-"], clean);
    assert_exit(&output, 0);
    assert_eq!(output.stdout, clean);
}

#[test]
fn rewrite_of_the_paper_example_replaces_only_the_cycle600_blocks() {
    let sample = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/samples/PAPER_EXAMPLE3.MPF"
    ))
    .expect("sample");
    let output = run(&["rewrite", "samples/PAPER_EXAMPLE3.MPF"], b"");
    assert_exit(&output, 0);
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(text.contains("N120 _CYC600_1=\"UFK600\" _CYC600_2=37.792346 _CYC600_3=20.704811 _CYC600_4=49.106605 _CYC600_5=1 _CYC600_6=39\n"));
    let original = String::from_utf8_lossy(&sample);
    let kept = original
        .lines()
        .filter(|l| !l.contains("CYCLE600"))
        .all(|l| text.lines().any(|o| o == l));
    assert!(kept, "every other line is kept");
}

#[test]
fn rewrite_of_a_directory_is_a_tool_error() {
    let output = run(&["rewrite", "samples"], b"");
    assert_exit(&output, 2);
}

#[test]
fn rule_codes_are_checked_trimmed_and_case_free() {
    let unknown = run(&["check", "--select", "N05", "-"], b"M30\n");
    assert_exit(&unknown, 2);
    let stderr = String::from_utf8_lossy(&unknown.stderr);
    assert!(
        stderr.contains("`N05`") && stderr.contains("`N005`"),
        "{stderr}"
    );
    // N010 is ignored in lower case with a blank: the program without M30 passes.
    let ignored = run(
        &["check", "--deny-warnings", "--ignore", "n010, N005", "-"],
        b"G0 X0\n",
    );
    assert_exit(&ignored, 0);
    let reported = run(&["check", "--deny-warnings", "-"], b"G0 X0\n");
    assert_exit(&reported, 1);
}

#[test]
fn convert_prints_the_papers_angles() {
    let output = run(
        &[
            "convert",
            "30",
            "45",
            "60",
            "--from",
            "e:XYZ",
            "--to",
            "intrinsic:ZXY",
        ],
        b"",
    );
    assert_exit(&output, 0);
    insta::assert_snapshot!(stdout(&output));
}

#[test]
fn convert_json_has_full_precision() {
    let output = run(
        &[
            "convert", "30", "45", "60", "--from", "e:57", "--to", "e:39", "--json",
        ],
        b"",
    );
    assert_exit(&output, 0);
    let value: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json");
    assert_eq!(value["sequence"], "extrinsic:ZXY");
    assert_eq!(value["code"], 39);
    assert_eq!(value["gimbal_lock"], false);
    let angles: Vec<f64> = value["angles"]
        .as_array()
        .expect("angles")
        .iter()
        .map(|a| a.as_f64().expect("number"))
        .collect();
    assert!(
        (angles[0] - 39.6393).abs() < 5e-5
            && (angles[1] + 16.2799).abs() < 5e-5
            && (angles[2] - 50.3607).abs() < 5e-5
    );
    insta::assert_snapshot!(stdout(&output));
}

#[test]
fn convert_accepts_negative_angles_and_warns_at_gimbal_lock() {
    let output = run(
        &[
            "convert", "-16.28", "90", "10", "--from", "i:ZYX", "--to", "i:ZYX",
        ],
        b"",
    );
    assert_exit(&output, 0);
    insta::assert_snapshot!(stdout(&output));
}

#[test]
fn convert_refuses_bad_input_with_exit_2() {
    for args in [
        vec!["convert", "1", "2", "3", "--from", "i:ZZX", "--to", "i:XYZ"],
        vec!["convert", "1", "2", "3", "--from", "e:58", "--to", "i:XYZ"],
        vec![
            "convert", "1", "two", "3", "--from", "i:XYZ", "--to", "i:XYZ",
        ],
        vec![
            "convert", "1", "NaN", "3", "--from", "i:XYZ", "--to", "i:XYZ",
        ],
        vec![
            "convert", "1", "inf", "3", "--from", "i:XYZ", "--to", "i:XYZ",
        ],
    ] {
        let output = run(&args, b"");
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert!(!output.stderr.is_empty());
    }
    let output = run(
        &["convert", "1", "2", "3", "--from", "x:ZYX", "--to", "i:XYZ"],
        b"",
    );
    insta::assert_snapshot!(String::from_utf8_lossy(&output.stderr));
}

#[test]
fn a_closed_pipe_is_not_a_failure() {
    // Far more output than a pipe buffers, of which 10 bytes are read before
    // the pipe is closed (as `| head -c 10` does; no shell, so that it runs
    // on Windows too).
    let input = "N10 X=(1\n".repeat(20_000);
    let mut child = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
        .args(["check", "--format", "short", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("binary runs");
    let mut stdin = child.stdin.take().expect("stdin");
    let feeder = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
    let mut first = [0u8; 10];
    std::io::Read::read_exact(&mut child.stdout.take().expect("stdout"), &mut first)
        .expect("the first bytes");
    let status = child.wait().expect("ends");
    feeder.join().expect("fed").expect("all of the input read");
    // It found errors (1), and did not fail (2) on the pipe.
    assert_eq!(status.code(), Some(1));
}

#[test]
fn eval_shows_parameters_provenance_and_results() {
    let output = run(&["eval", "samples/PAPER_EXAMPLE3.MPF"], b"");
    assert_exit(&output, 0);
    insta::assert_snapshot!(stdout(&output));
}

#[test]
fn eval_json_of_a_probe_program_with_supplied_values() {
    let output = run(
        &[
            "eval",
            "samples/PROBE_ALIGN.MPF",
            "--set",
            "R10=0.215",
            "--set",
            "R11=-0.113",
            "--json",
        ],
        b"",
    );
    assert_exit(&output, 0);
    let value: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json");
    let call = &value["calls"][0];
    assert_eq!(call["arguments"][7]["name"], "_ANG_1");
    assert_eq!(
        call["arguments"][7]["from"],
        "R10: supplied by --set R10=0.215"
    );
    assert_eq!(call["evaluation"]["output"]["code"], 39);
    insta::assert_snapshot!(stdout(&output));
}

#[test]
fn malformed_supplied_values_are_tool_errors() {
    for args in [
        vec!["rewrite", "samples/PROBE_ALIGN.MPF", "--set", "R10"],
        vec!["rewrite", "samples/PROBE_ALIGN.MPF", "--set", "R10=R11+1"],
        vec!["rewrite", "samples/PROBE_ALIGN.MPF", "--set", "R10=(1"],
        vec![
            "rewrite",
            "samples/PROBE_ALIGN.MPF",
            "--values",
            "no/such/file",
        ],
        vec![
            "rewrite",
            "samples/PROBE_ALIGN.MPF",
            "--values",
            "samples/PAPER_EXAMPLE3.MPF",
        ],
    ] {
        let output = run(&args, b"");
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert!(
            output.stdout.is_empty(),
            "nothing is written when the tool fails"
        );
    }
    let output = run(
        &["rewrite", "samples/PROBE_ALIGN.MPF", "--set", "R10=R11+1"],
        b"",
    );
    insta::assert_snapshot!(String::from_utf8_lossy(&output.stderr));
}

#[test]
fn convert_reads_triples_from_stdin_and_matches_single_conversions() {
    let input = b"30 45 60\n# comment\n\n-16.28, 90, 10\r\n200 -100 400 # beyond the ranges\n";
    let args = ["convert", "--from", "e:XYZ", "--to", "i:ZXY"];
    let text = run(&args, input);
    assert_exit(&text, 0);
    insta::assert_snapshot!(stdout(&text));
    // The batch computes side by side; each line must be, to the last bit
    // (compared as text: serde_json's parser may round), what a single
    // conversion prints.
    let json = run(&[&args[..], &["--json"]].concat(), input);
    assert_exit(&json, 0);
    let lines: Vec<String> = stdout(&json).lines().map(str::to_string).collect();
    let triples = [
        ["30", "45", "60"],
        ["-16.28", "90", "10"],
        ["200", "-100", "400"],
    ];
    assert_eq!(lines.len(), triples.len());
    for (line, angles) in lines.iter().zip(triples) {
        let single = run(
            &[&args[..1], &angles[..], &args[1..], &["--json"]].concat(),
            b"",
        );
        assert_eq!(stdout(&single).trim_end(), line);
    }
}

#[test]
fn convert_from_stdin_refuses_a_bad_line_without_partial_output() {
    for (input, message) in [
        (
            &b"30 45 60\n1 2\n"[..],
            "stdin:2:1: 2 numbers where three angles are expected",
        ),
        (&b"30 45 x\n"[..], "stdin:1:7: `x` is not a finite angle"),
        (&b"1 2 inf\n"[..], "stdin:1:5: `inf` is not a finite angle"),
    ] {
        let output = run(&["convert", "--from", "e:XYZ", "--to", "i:ZXY"], input);
        assert_exit(&output, 2);
        assert!(output.stdout.is_empty(), "partial output");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(stderr.contains(message), "{stderr}");
    }
}

/// A directory of its own for one test, emptied first.
const FIXABLE: &str =
    "DEF REAL Depth\nR1=DEPTH+1 ; sinuprep: ignore N005, N016\nR2=DEPTHH\nGOTOF ENDE\nEND1:\nM30\n";

#[test]
fn check_fix_applies_the_safe_fixes_and_reports_what_remains() {
    let dir = scratch("fix");
    let path = dir.join("PART.MPF");
    std::fs::write(&path, FIXABLE).expect("write");
    let name = path.to_str().expect("utf-8");
    let output = run(
        &[
            "check", "--fix", "--select", "N,N015", "--format", "short", name,
        ],
        b"",
    );
    assert_exit(&output, 1);
    let fixed = std::fs::read_to_string(&path).expect("read");
    // N015 (capitals of the DEF) and N099 (the unused codes) are safe; the
    // did-you-mean corrections are not.
    assert_eq!(
        fixed,
        "DEF REAL Depth\nR1=Depth+1\nR2=DEPTHH\nGOTOF ENDE\nEND1:\nM30\n"
    );
    let report = stdout(&output);
    assert!(
        report.contains("N005") && report.contains("N001"),
        "{report}"
    );
    assert!(
        !report.contains("N099") && !report.contains("N015"),
        "{report}"
    );
    assert!(String::from_utf8_lossy(&output.stderr).contains("fixed 3 findings"));

    let output = run(
        &[
            "check",
            "--fix",
            "--unsafe-fixes",
            "--format",
            "short",
            name,
        ],
        b"",
    );
    assert_exit(&output, 0);
    assert_eq!(
        std::fs::read_to_string(&path).expect("read"),
        "DEF REAL Depth\nR1=Depth+1\nR2=DEPTH\nGOTOF END1\nEND1:\nM30\n"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// C619's fix is the rewrite's own code: `check --select C619 --fix` writes
/// what `rewrite` prints, with the emit settings of sinuprep.toml.
#[test]
fn the_cycle600_fix_writes_what_rewrite_writes() {
    let dir = scratch("fix-cycle600");
    let samples = support::repo().join("samples");
    for name in ["PAPER_EXAMPLE3.MPF", "HEAD_DEF.SPF"] {
        std::fs::copy(samples.join(name), dir.join(name)).expect("copy");
    }
    std::fs::write(dir.join("sinuprep.toml"), "precision = 4\n").expect("config");
    let path = dir.join("PAPER_EXAMPLE3.MPF");
    let name = path.to_str().expect("utf-8");
    let rewritten = run(&["rewrite", name], b"");
    assert_exit(&rewritten, 0);
    let text = stdout(&rewritten);
    assert!(
        text.contains("_CYC600_2=37.7923 "),
        "4 decimals as sinuprep.toml says: {text}"
    );

    let unasked = run(&["check", "--format", "short", name], b"");
    assert!(!stdout(&unasked).contains("C619"), "off by default");
    let output = run(
        &[
            "check", "--select", "C619", "--fix", "--format", "short", name,
        ],
        b"",
    );
    assert_exit(&output, 0);
    assert_eq!(std::fs::read(&path).expect("read"), rewritten.stdout);
    assert!(String::from_utf8_lossy(&output.stderr).contains("fixed 2 findings"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_fix_leaves_a_file_with_syntax_errors_and_refuses_stdin() {
    let dir = scratch("fix-syntax");
    let path = dir.join("PART.MPF");
    let text = format!("{FIXABLE}IFF R1==1\n");
    std::fs::write(&path, &text).expect("write");
    let name = path.to_str().expect("utf-8");
    let output = run(&["check", "--fix", "--unsafe-fixes", name], b"");
    assert_exit(&output, 1);
    assert_eq!(std::fs::read_to_string(&path).expect("read"), text);
    assert!(
        String::from_utf8_lossy(&output.stderr).contains("not fixed, because of its syntax errors")
    );

    let output = run(&["check", "--fix", "-"], FIXABLE.as_bytes());
    assert_exit(&output, 2);
    assert!(String::from_utf8_lossy(&output.stderr).contains("standard input"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn json_findings_carry_their_fixes() {
    let output = run(&["check", "--format", "json", "-"], FIXABLE.as_bytes());
    let document: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
    let fixes: Vec<(String, String, String)> = document["files"][0]["diagnostics"]
        .as_array()
        .expect("diagnostics")
        .iter()
        .filter(|d| !d["fix"].is_null())
        .map(|d| {
            let edit = &d["fix"]["edits"][0];
            let (offset, length) = (
                edit["offset"].as_u64().unwrap_or(0) as usize,
                edit["length"].as_u64().unwrap_or(0) as usize,
            );
            (
                d["code"].as_str().unwrap_or("").to_string(),
                d["fix"]["applicability"].as_str().unwrap_or("").to_string(),
                format!(
                    "{} -> {}",
                    &FIXABLE[offset..offset + length],
                    edit["text"].as_str().unwrap_or("")
                ),
            )
        })
        .collect();
    assert_eq!(
        fixes,
        [
            (
                "N099".into(),
                "safe".into(),
                " ; sinuprep: ignore N005, N016 -> ".into()
            ),
            (
                "N099".into(),
                "safe".into(),
                " ; sinuprep: ignore N005, N016 -> ".into()
            ),
            ("N005".into(), "unsafe".into(), "DEPTHH -> DEPTH".into()),
            ("N001".into(), "unsafe".into(), "ENDE -> END1".into()),
        ]
    );
}

#[test]
fn a_folder_without_programs_is_an_error_unless_allowed() {
    let dir = scratch("empty");
    std::fs::write(dir.join("notes.txt"), "no program here\n").expect("write");
    let name = dir.to_str().expect("utf-8");
    let output = run(&["check", name], b"");
    assert_exit(&output, 2);
    assert!(String::from_utf8_lossy(&output.stderr).contains("holds no program"));
    let output = run(&["check", "--allow-empty", name], b"");
    assert_exit(&output, 0);
    assert!(String::from_utf8_lossy(&output.stderr).contains("no findings in 0 files"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Machine data name the axes of every channel whatever the file holding
/// them is called: a file whose first block assigns machine data is read as
/// machine data given as a definition file, as the machine, or as an
/// archive's member (#31 section 2).
#[test]
fn machine_data_by_their_content_name_every_channels_axes() {
    let dir = scratch("machine-data-content");
    // The counter spindle's channel, saved from the control as text.
    let data = "; channel 2: counter spindle\nCHANDATA(2)\nN20060 $MC_AXCONF_GEOAX_NAME_TAB[0]=\"XS\"\n\
N20080 $MC_AXCONF_CHANAX_NAME_TAB[2]=\"ZS\"\nN10000 $MN_AXCONF_MACHAX_NAME_TAB[7]=\"SP_GEGEN\"\nM17\n";
    std::fs::write(dir.join("CH2_MD.TXT"), data).expect("write");
    let part = "N10 G0 POS[ZS]=-200 FA[ZS]=5000\nN20 SPOS[SP_GEGEN]=0\nN30 WAITP(ZS)\nN40 M30\n";
    let program = dir.join("TRANSFER.MPF");
    std::fs::write(&program, part).expect("write");
    let (program, data) = (
        program.to_str().expect("utf-8"),
        dir.join("CH2_MD.TXT").display().to_string(),
    );
    let check = |given: &[&str], path: &str| {
        let mut args = vec!["check", "--format", "short", "--select", "N005"];
        args.extend(given);
        args.push(path);
        run(&args, b"")
    };
    let alone = check(&[], program);
    assert_eq!(
        stdout(&alone).matches("N005").count(),
        2,
        "{}",
        stdout(&alone)
    );
    for given in [
        ["--definitions", data.as_str()],
        ["--machine", data.as_str()],
    ] {
        let output = check(&given, program);
        assert_exit(&output, 0);
        assert!(
            !stdout(&output).contains("N005"),
            "{given:?}: {}",
            stdout(&output)
        );
    }
    let archive = dir.join("SETUP.ARC");
    std::fs::write(
        &archive,
        format!(
            "%_N_TRANSFER_MPF\n;$PATH=/_N_MPF_DIR\n{part}%_N_CH2_MD_TXT\n{data}",
            data = std::fs::read_to_string(&data).expect("read")
        ),
    )
    .expect("write");
    let output = check(&[], archive.to_str().expect("utf-8"));
    assert_exit(&output, 0);
    assert!(!stdout(&output).contains("N005"), "{}", stdout(&output));
    let notes = String::from_utf8_lossy(&output.stderr);
    assert!(!notes.contains("not checked"), "{notes}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn globals_macros_and_axes_of_definition_files_are_defined() {
    let dir = scratch("definitions");
    std::fs::write(
        dir.join("MGUD.DEF"),
        "DEF NCK REAL ZERO_X\nDEF CHAN INT PART_COUNT\n",
    )
    .expect("write");
    std::fs::write(dir.join("SMAC.DEF"), "DEFINE SAFE_Z AS 250\n").expect("write");
    // Machine data: the axis names of MD20080 (only those lines are read).
    std::fs::write(
        dir.join("CH1_TEA.INI"),
        "CHANDATA(1)\n$MC_AXCONF_CHANAX_NAME_TAB[0]=\"XC\"\n$MC_AXCONF_CHANAX_NAME_TAB[1]=\"ZC\"\n$MC_CHAN_NAME=\"CHAN1\"\nM17\n",
    )
    .expect("write");
    let program = dir.join("PART.MPF");
    std::fs::write(
        &program,
        "N10 X=ZERO_X+PART_COUNT Z=SAFE_Z\nN20 G0 POS[ZC]=1 FA[XC]=100 X=TABLE\nN30 M30\n",
    )
    .expect("write");
    let name = program.to_str().expect("utf-8");
    let args = ["check", "--format", "short", "--select", "N005", name];
    let output = run(&args, b"");
    assert_exit(&output, 0);
    // The DEF files beside the program are found; the machine data's axis
    // names (XC, ZC) and TABLE are not known without them being named.
    assert_eq!(
        stdout(&output).matches("N005").count(),
        3,
        "{}",
        stdout(&output)
    );
    // The files' axis names add to sinuprep.toml's.
    std::fs::write(
        dir.join("sinuprep.toml"),
        "definitions = [\"MGUD.DEF\", \"SMAC.DEF\", \"CH1_TEA.INI\"]\naxes = [\"TABLE\"]\n",
    )
    .expect("toml");
    let output = run(&args, b"");
    assert_exit(&output, 0);
    assert!(!stdout(&output).contains("N005"), "{}", stdout(&output));
    // A macro that stands for an end command ends the program where it is
    // written, as the control expands it (N010, N027).
    std::fs::write(
        dir.join("SMAC.DEF"),
        "DEFINE SAFE_Z AS 250\nDEFINE ENDE AS M30\n",
    )
    .expect("write");
    let ended = dir.join("ENDED.MPF");
    std::fs::write(&ended, "N10 G0 X0\nN20 ENDE\n").expect("write");
    let after = dir.join("AFTER.MPF");
    std::fs::write(&after, "N10 G0 X0\nN20 ENDE\nN30 G1 X5 F100\n").expect("write");
    let (ended, after) = (
        ended.to_str().expect("utf-8"),
        after.to_str().expect("utf-8"),
    );
    let ends = run(
        &[
            "check",
            "--format",
            "short",
            "--select",
            "N010,N027",
            ended,
            after,
        ],
        b"",
    );
    assert_eq!(
        stdout(&ends),
        format!("{after}:3:5: warning[N027] this block comes after the program's end (`ENDE`) and no jump reaches it: it never runs\n")
    );
    // A broken definition file is a tool error at its line and column.
    std::fs::write(dir.join("SMAC.DEF"), "DEFINE SAFE_Z AS 250\nDEF REAL (\n").expect("write");
    let output = run(&args, b"");
    assert_exit(&output, 2);
    assert!(
        String::from_utf8_lossy(&output.stderr).contains("SMAC.DEF:2:"),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `check --machine` (or `machine` in sinuprep.toml) solves the swivels on
/// the machine's records; `hirth-tolerance` sets what K004 lets pass.
#[test]
fn swivels_are_checked_on_the_machine() {
    let dir = scratch("swivels");
    let machine = support::repo().join("samples/MACHINE.SPF");
    std::fs::copy(&machine, dir.join("MACHINE.SPF")).expect("machine");
    let program = dir.join("PART.MPF");
    std::fs::write(
        &program,
        "N10 CYCLE800(1,\"HIRTH_CA\",0,57,0,0,0,31.3,0,0,0,0,0,-1)\nN20 CYCLE800(1,\"HEAD_AC\",0,57,0,0,0,0,30,0,0,0,0,-1)\nN30 M30\n",
    )
    .expect("program");
    let name = program.to_str().expect("utf-8");
    let codes = |output: &std::process::Output| -> Vec<String> {
        stdout(output)
            .lines()
            .filter_map(|l| l.split_once('[').and_then(|(_, r)| r.split_once(']')))
            .map(|(code, _)| code.to_string())
            .collect()
    };
    // Without a machine nothing is solved.
    let output = run(&["check", "--format", "short", name], b"");
    assert_exit(&output, 0);
    assert!(codes(&output).is_empty(), "{}", stdout(&output));
    let given = [
        "check",
        "--format",
        "short",
        "--machine",
        machine.to_str().expect("utf-8"),
        name,
    ];
    let output = run(&given, b"");
    assert_exit(&output, 1);
    assert_eq!(codes(&output), ["K004", "K005"], "{}", stdout(&output));
    std::fs::write(
        dir.join("sinuprep.toml"),
        "machine = \"MACHINE.SPF\"\nhirth-tolerance = 1.5\n",
    )
    .expect("toml");
    let output = run(&["check", "--format", "short", name], b"");
    assert_eq!(codes(&output), ["K005"], "{}", stdout(&output));
    // A machine file that cannot be read names the key.
    std::fs::write(dir.join("sinuprep.toml"), "machine = \"NONE.SPF\"\n").expect("toml");
    let output = run(&["check", name], b"");
    assert_exit(&output, 2);
    assert!(
        flat(&output.stderr).contains("machine"),
        "{}",
        flat(&output.stderr)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// N018 knows the subprograms the control would find: the program's own
/// directory first, then the cycle directories of sinuprep.toml or
/// `--cycles`, in their order.
#[test]
fn calls_are_checked_against_the_subprograms_of_the_search_path() {
    let dir = scratch("cycles");
    std::fs::create_dir_all(dir.join("parts")).expect("parts");
    std::fs::create_dir_all(dir.join("CUS")).expect("CUS");
    std::fs::create_dir_all(dir.join("CST")).expect("CST");
    std::fs::write(
        dir.join("parts/PART.MPF"),
        "N10 ALIGN(1, 2, 3)\nN20 PROBE(1, 2)\nN30 CYCLE_X(1)\nN40 M30\n",
    )
    .expect("program");
    std::fs::write(
        dir.join("parts/align.spf"),
        "; beside\nPROC ALIGN(REAL _A, REAL _B)\nM17\n",
    )
    .expect("sub");
    // CUS comes first: its PROBE takes two, CST's one.
    std::fs::write(
        dir.join("CUS/PROBE.SPF"),
        "PROC PROBE(REAL _A, REAL _B) SAVE\nM17\n",
    )
    .expect("cus");
    std::fs::write(dir.join("CST/PROBE.SPF"), "PROC PROBE(REAL _A)\nM17\n").expect("cst");
    std::fs::write(dir.join("CST/CYCLE_X.SPF"), "PROC CYCLE_X\nM17\n").expect("cst");
    let program = dir.join("parts/PART.MPF");
    let name = program.to_str().expect("utf-8");

    let findings = |output: &std::process::Output| {
        stdout(output)
            .lines()
            .filter(|l| l.contains("N018"))
            .map(|l| l.split(": ").nth(1).unwrap_or_default().to_string())
            .collect::<Vec<_>>()
    };
    let own = run(
        &["check", "--select", "N018", "--format", "short", name],
        b"",
    );
    assert_eq!(
        findings(&own),
        ["warning[N018] `ALIGN` takes 2 argument(s), this call passes 3"]
    );

    std::fs::write(dir.join("sinuprep.toml"), "cycles = [\"CUS\", \"CST\"]\n").expect("config");
    let configured = run(
        &["check", "--select", "N018", "--format", "short", name],
        b"",
    );
    assert_eq!(
        findings(&configured),
        [
            "warning[N018] `ALIGN` takes 2 argument(s), this call passes 3",
            "warning[N018] `CYCLE_X` takes 0 argument(s), this call passes 1",
        ]
    );
    let cst = dir.join("CST");
    let given = run(
        &[
            "check",
            "--select",
            "N018",
            "--format",
            "short",
            "--cycles",
            cst.to_str().expect("utf-8"),
            name,
        ],
        b"",
    );
    assert_eq!(findings(&given).len(), 3, "CST alone: PROBE takes one");

    std::fs::write(dir.join("sinuprep.toml"), "cycles = [\"CMA\"]\n").expect("config");
    let missing = run(&["check", name], b"");
    assert_exit(&missing, 2);
    // Flat: a longer temporary directory (Windows') wraps the line elsewhere.
    let stderr = flat(&missing.stderr);
    assert!(stderr.contains("named by `cycles` in"), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A report as one line: miette's wrapping and frame taken out.
fn flat(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes)
        .replace(['│', '×', '╰', '─', '▶'], " ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// `axes` on the sample machine: both solutions, the one `_DIR` takes, the
/// JSON document scripts read, an unreachable orientation, and the
/// records a user can name.
#[test]
fn axes_computes_a_swivel_on_the_sample_machine() {
    let machine = support::repo().join("samples/MACHINE.SPF");
    let machine = machine.to_str().expect("utf-8");
    let axes = |extra: &[&str]| {
        let mut args = vec!["axes", "--machine", machine];
        args.extend_from_slice(extra);
        run(&args, b"")
    };
    // A C-A head tilted 30° about X: C ±90 (or 0/180), A ±30; _DIR -1 takes A -30.
    let output = axes(&[
        "--record", "HEAD_CA", "--mode", "57", "30", "0", "0", "--json",
    ]);
    assert_exit(&output, 0);
    let document: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
    let solutions = document["solutions"].as_array().expect("solutions");
    assert_eq!(solutions.len(), 2);
    let chosen = &solutions[document["chosen"].as_u64().expect("chosen") as usize];
    assert!(
        (chosen["axes"]["A"].as_f64().expect("A") + 30.0).abs() < 1e-9,
        "{chosen}"
    );
    assert_eq!(document["record"], "HEAD_CA");
    assert_eq!(document["residual"].as_array().map(Vec::len), Some(3));
    let plus = axes(&[
        "--record", "HEAD_CA", "30", "0", "0", "--dir", "1", "--json",
    ]);
    let plus: serde_json::Value = serde_json::from_slice(&plus.stdout).expect("JSON");
    let taken = &plus["solutions"][plus["chosen"].as_u64().expect("chosen") as usize];
    assert!((taken["axes"]["A"].as_f64().expect("A") - 30.0).abs() < 1e-9);

    // A -100 lies outside the table's -120..30 only as +100: the other is taken.
    let table = axes(&["--record", "table_ac", "-100", "0", "0"]);
    assert_exit(&table, 0);
    let text = stdout(&table);
    assert!(
        text.contains("solution 1: A=100 C=180  (outside the limits)"),
        "{text}"
    );
    assert!(text.contains("taken: solution 2"), "{text}");

    // A 45° nutating head tilts the tool at most 90°.
    let unreachable = axes(&["--record", "3", "120", "0", "0"]);
    assert_exit(&unreachable, 1);
    assert!(stdout(&unreachable).contains("unreachable"));

    let several = axes(&["0", "30", "0"]);
    assert_exit(&several, 2);
    assert!(flat(&several.stderr).contains("6 records: name one with --record"));
    let misspelt = axes(&["--record", "HEAD_AC", "0", "30", "0"]);
    assert!(flat(&misspelt.stderr).contains("did you mean `HEAD_CA`?"));
    let mode = axes(&["--record", "1", "--mode", "64", "0", "30", "0"]);
    assert_exit(&mode, 2);

    // At a pole (the tool straight down, A=0) C is free: it keeps the
    // record's specified angle $TC_CARR13, the position offline.
    let dir = scratch("axes-specified");
    let specified = dir.join("M.SPF");
    let sample = std::fs::read_to_string(machine).expect("machine");
    std::fs::write(&specified, format!("{sample}\n$TC_CARR13[1]=45\n")).expect("write");
    let pole = run(
        &[
            "axes",
            "--machine",
            specified.to_str().expect("utf-8"),
            "--record",
            "HEAD_CA",
            "0",
            "0",
            "0",
        ],
        b"",
    );
    assert!(
        stdout(&pole).contains("solution 1: C=45 A=0"),
        "{}",
        stdout(&pole)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Three rotary axes: the sample's B table under its C-A head. A table
/// about Y under a head tilting about X makes the frame as `R_y(β) R_x(α)
/// R_z(γ)`: the intrinsic Y, X', Z'' angles `convert` gives (computed
/// apart, from the rotation matrix) are the table's angle, the head's tilt
/// and what is left about the tool axis.
#[test]
fn axes_splits_a_swivel_between_a_table_and_a_head() {
    let machine = support::repo().join("samples/MACHINE.SPF");
    let machine = machine.to_str().expect("utf-8");
    let split = |extra: &[&str]| {
        let mut args = vec![
            "axes",
            "--machine",
            machine,
            "--record",
            "HEAD_H",
            "--table",
            "TABLE_B",
            "--dir",
            "1",
        ];
        args.extend_from_slice(extra);
        run(&args, b"")
    };
    let convert = run(
        &[
            "convert", "30", "45", "60", "--from", "i:XYZ", "--to", "i:YXZ", "--json",
        ],
        b"",
    );
    let angles: serde_json::Value = serde_json::from_slice(&convert.stdout).expect("JSON");
    let angle = |i: usize| angles["angles"][i].as_f64().expect("angle");
    let output = split(&["--json", "30", "45", "60"]);
    assert_exit(&output, 0);
    let document: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
    let table = &document["table"];
    assert_eq!(
        (&table["record"], &table["axis"], &table["fixed"]),
        (&"TABLE_B".into(), &"B".into(), &false.into())
    );
    assert!(
        (table["position"].as_f64().expect("B") - angle(0)).abs() < 1e-7,
        "{table}"
    );
    let taken = &document["solutions"][document["chosen"].as_u64().expect("chosen") as usize];
    assert!(
        (taken["axes"]["A"].as_f64().expect("A") - angle(1)).abs() < 1e-7,
        "{taken}"
    );
    assert!(
        taken["axes"]["C"].as_f64().expect("C").abs() < 1e-6,
        "{taken}"
    );
    let residual = &document["residual"];
    let about_z = residual[1][0]
        .as_f64()
        .expect("r10")
        .atan2(residual[0][0].as_f64().expect("r00"));
    assert!((about_z.to_degrees() - angle(2)).abs() < 1e-6, "{residual}");

    // Fixed, the table leaves the head more to tilt; outside the head's
    // reach, nothing is taken (exit 1).
    let fixed = split(&["--fix", "b=20", "30", "45", "60"]);
    assert_exit(&fixed, 0);
    assert!(
        stdout(&fixed).contains("table: record 5 (TABLE_B): B=20 (fixed by --fix)"),
        "{}",
        stdout(&fixed)
    );
    let beyond = split(&["--fix", "B=-60", "30", "45", "60"]);
    assert_exit(&beyond, 1);
    assert!(
        stdout(&beyond).contains("taken: none"),
        "{}",
        stdout(&beyond)
    );
    let wrong = split(&["--fix", "C=20", "30", "45", "60"]);
    assert_exit(&wrong, 2);
    assert!(flat(&wrong.stderr).contains("turns axis `B`"));
    let not_a_table = run(
        &[
            "axes",
            "--machine",
            machine,
            "--record",
            "HEAD_H",
            "--table",
            "HEAD_CA",
            "30",
            "45",
            "60",
        ],
        b"",
    );
    assert_exit(&not_a_table, 2);
    assert!(flat(&not_a_table.stderr).contains("must be kinematics \"P\" with one rotary axis"));
}

/// What `axes --table` tells the machine, checked against a forward model
/// of the chain written here: the table turned (about its pivot, `l2`), the
/// head turned, the rotation left about the tool: together the requested
/// frame; the head's frame (CYCLE800's angles in the `_MODE` asked for) the
/// request with the table's turn taken out; the work zero moved as a point
/// on the table. Both preferences; `nearest` moves the axes no more than
/// `middle` does from the positions given with `--from`.
#[test]
fn axes_tells_the_table_block_the_head_frame_and_the_work_zero() {
    use nalgebra::{Rotation3, Unit, Vector3};
    let dir = scratch("axes-told");
    let machine = dir.join("M.SPF");
    let sample =
        std::fs::read_to_string(support::repo().join("samples/MACHINE.SPF")).expect("machine");
    // TABLE_B's pivot 500 mm along X and 300 mm up, closed by l4.
    std::fs::write(
        &machine,
        format!(
            "{sample}\n$TC_CARR4[5]=500 $TC_CARR6[5]=300 $TC_CARR18[5]=-500 $TC_CARR20[5]=-300\n"
        ),
    )
    .expect("write");
    let machine = machine.to_str().expect("utf-8");
    let turn = |axis: Vector3<f64>, degrees: f64| {
        Rotation3::from_axis_angle(&Unit::new_normalize(axis), degrees.to_radians())
    };
    let (x, y, z) = (Vector3::x(), Vector3::y(), Vector3::z());
    // _MODE 27: Z, Y', X''.
    let requested = turn(z, 30.0) * turn(y, 45.0) * turn(x, 60.0);
    let pivot = Vector3::new(500.0, 0.0, 300.0);
    let work_zero = Vector3::new(120.0, -40.0, 75.0);
    let from = [100.0, 10.0, -20.0];
    let mut travels = Vec::new();
    for prefer in ["middle", "nearest"] {
        let args = [
            "axes",
            "--machine",
            machine,
            "--record",
            "HEAD_H",
            "--table",
            "TABLE_B",
            "--mode",
            "27",
            "--prefer",
            prefer,
            "--from",
            "B=100,C=10",
            "--from",
            "a=-20",
            "--work-zero=120,-40,75",
        ];
        let output = run(&[&args[..], &["--json", "30", "45", "60"]].concat(), b"");
        assert_exit(&output, 0);
        let document: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
        let number = |value: &serde_json::Value| value.as_f64().expect("number");
        let table = number(&document["table"]["position"]);
        assert_eq!(document["table"]["prefer"], prefer);
        let taken = &document["solutions"][document["chosen"].as_u64().expect("chosen") as usize];
        let (c, a) = (number(&taken["axes"]["C"]), number(&taken["axes"]["A"]));
        let residual = &document["residual"];
        let about_tool = number(&residual[1][0])
            .atan2(number(&residual[0][0]))
            .to_degrees();
        assert!((number(&document["about_tool_deg"]) - about_tool).abs() < 1e-12);
        // The table's vector is entered reversed (0, -1, 0): it turns the
        // workpiece by R(v, B)⁻¹ in the model; the head by R(z, C) R(x, A).
        let v = Vector3::new(0.0, -1.0, 0.0);
        let table_turn = turn(v, table);
        let made = table_turn.inverse() * turn(z, c) * turn(x, a) * turn(z, about_tool);
        assert!(
            (made.matrix() - requested.matrix()).norm() < 1e-9,
            "{prefer}: {made} against {requested}"
        );
        let frame = &document["head_frame"];
        assert_eq!(frame["mode"], 27);
        let angles: Vec<f64> = (0..3).map(|i| number(&frame["angles"][i])).collect();
        let head_frame = turn(z, angles[0]) * turn(y, angles[1]) * turn(x, angles[2]);
        assert!(
            (head_frame.matrix() - (table_turn * requested).matrix()).norm() < 1e-9,
            "{prefer}: {head_frame}"
        );
        let moved = pivot + table_turn * (work_zero - pivot) - work_zero;
        let told = &document["work_zero"]["moves"];
        let told = Vector3::new(number(&told[0]), number(&told[1]), number(&told[2]));
        assert!(
            (told - moved).norm() < 1e-9,
            "{prefer}: {told} against {moved}"
        );
        let chain_end = &document["work_zero"]["chain_end_moves"];
        let chain_end = Vector3::new(
            number(&chain_end[0]),
            number(&chain_end[1]),
            number(&chain_end[2]),
        );
        assert!(
            (chain_end - (pivot - table_turn * pivot)).norm() < 1e-9,
            "{chain_end}"
        );
        assert_eq!(
            document["table"]["block"].as_str(),
            Some(format!("G0 B={}", format_position(table)).as_str())
        );
        travels.push(
            [table - from[0], c - from[1], a - from[2]]
                .iter()
                .fold(0.0f64, |m, d| m.max(d.abs())),
        );
        let text = stdout(&run(&[&args[..], &["30", "45", "60"]].concat(), b""));
        assert!(text.contains("table block: G0 B="), "{text}");
        assert!(text.contains("head frame: ZYX "), "{text}");
        assert!(
            text.contains("work zero at X120 Y-40 Z75 moves by X"),
            "{text}"
        );
    }
    assert!(travels[1] <= travels[0] + 1e-9, "{travels:?}");
    assert!(
        travels[1] < travels[0] - 1.0,
        "nearest moves less here: {travels:?}"
    );

    // Tool along Y: the table about Y cannot help, and A reaches 45° only.
    let beyond = run(
        &[
            "axes",
            "--machine",
            machine,
            "--record",
            "HEAD_H",
            "--table",
            "TABLE_B",
            "--",
            "-90",
            "0",
            "0",
        ],
        b"",
    );
    assert_exit(&beyond, 1);
    assert!(
        stdout(&beyond).contains("(no table position brings the head inside its limits; this one brings it nearest: solution 1 lies 45° beyond them)"),
        "{}",
        stdout(&beyond)
    );
    let wrong = run(
        &[
            "axes",
            "--machine",
            machine,
            "--record",
            "HEAD_H",
            "--table",
            "TABLE_B",
            "--from",
            "Q=1",
            "0",
            "0",
            "0",
        ],
        b"",
    );
    assert_exit(&wrong, 2);
    assert!(flat(&wrong.stderr).contains("no rotary axis `Q` here; the axes are `B`, `C`, `A`"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// A position as `axes` prints it (4 decimals, no trailing zeros).
fn format_position(value: f64) -> String {
    let text = format!("{value:.4}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".into()
    } else {
        text.into()
    }
}

/// A machine file's bad data is told at its line, and a record it makes
/// unusable gives no answer.
#[test]
fn axes_tells_bad_swivel_data_and_refuses_its_record() {
    let dir = scratch("axes-bad");
    let path = dir.join("MACHINE.SPF");
    std::fs::write(
        &path,
        "$TC_CARR34[1]=\"PARALLEL\" $TC_CARR9[1]=1 $TC_CARR12[1]=-1\n$TC_CARR48[1]=0\n",
    )
    .expect("write");
    let name = path.to_str().expect("utf-8");
    let output = run(
        &[
            "axes",
            "--machine",
            name,
            "--record",
            "PARALLEL",
            "0",
            "30",
            "0",
        ],
        b"",
    );
    assert_exit(&output, 2);
    let stderr = flat(&output.stderr);
    assert!(stderr.contains("K001"), "{stderr}");
    assert!(
        stderr.contains("`$TC_CARR48` is no swivel data parameter"),
        "{stderr}"
    );
    assert!(
        stderr.contains("the two rotary axes are parallel"),
        "{stderr}"
    );
    assert!(output.stdout.is_empty(), "no answer from a broken record");

    std::fs::write(dir.join("sinuprep.toml"), "machine = \"nowhere.spf\"\n").expect("config");
    let config = dir.join("sinuprep.toml");
    let missing = run(
        &[
            "axes",
            "--config",
            config.to_str().expect("utf-8"),
            "0",
            "30",
            "0",
        ],
        b"",
    );
    assert_exit(&missing, 2);
    assert!(flat(&missing.stderr).contains("named by `machine` in"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Runs the binary as [`run`] does, but gives up after `seconds`: a hang
/// fails the test instead of stopping the suite.
fn run_within(seconds: u64, args: &[&str]) -> std::process::Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(seconds);
    while child.try_wait().expect("wait").is_none() {
        if std::time::Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            panic!(
                "`sinuprep {}` still running after {seconds} s",
                args.join(" ")
            );
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.wait_with_output().expect("binary ends")
}

/// Every command reads a machine file the one way and finds the same in
/// it: a record no machine can have (a zero or parallel axis vector, text
/// where a number goes, an axis limit of 1EX300, whose placement once
/// stepped through the turns in between for ever) is K001 for `check`,
/// `eval`, `rewrite` and `axes` alike, and an error: exit 1 (`axes`
/// refuses the record, exit 2, as it did). `check` reports the machine
/// file once, however many programs it checks on it.
#[test]
fn an_unusable_machine_file_fails_every_command_alike() {
    let dir = scratch("machine-unusable");
    let head = "$TC_CARR34[1]=\"H\" $TC_CARR9[1]=1 $TC_CARR10[1]=1\n";
    let cases = [
        (
            "zero",
            "$TC_CARR34[1]=\"H\" $TC_CARR9[1]=0 $TC_CARR10[1]=1\n".to_string(),
            "K001",
            "has no direction vector",
        ),
        (
            "parallel",
            "$TC_CARR34[1]=\"H\" $TC_CARR9[1]=1 $TC_CARR12[1]=-1\n".to_string(),
            "K001",
            "parallel",
        ),
        (
            "text",
            "$TC_CARR34[1]=\"H\" $TC_CARR9[1]=\"1\" $TC_CARR10[1]=1\n".to_string(),
            "K001",
            "a number expected",
        ),
        (
            "limit",
            format!("{head}$TC_CARR31[1]=-10 $TC_CARR33[1]=1EX300\n"),
            "K001",
            "its maximum position 1e300 is no rotary axis's",
        ),
        (
            "limit11",
            format!("{head}$TC_CARR30[1]=-1EX11\n"),
            "K001",
            "its minimum position -1e11",
        ),
        (
            "number",
            format!("{head}$TC_CARR12[1]=1EX400\n"),
            "S003",
            "1EX400",
        ),
    ];
    let first = dir.join("P.MPF");
    let second = dir.join("Q.MPF");
    let program = "N10 CYCLE800(1,\"H\",0,57,0,0,0,0,30,0,0,0,0,-1)\nN20 M30\n";
    std::fs::write(&first, program).expect("program");
    std::fs::write(&second, program).expect("program");
    let (p, q) = (
        first.to_str().expect("utf-8"),
        second.to_str().expect("utf-8"),
    );
    for (name, records, code, says) in cases {
        let machine = dir.join(format!("{name}.SPF"));
        std::fs::write(&machine, &records).expect("machine");
        let m = machine.to_str().expect("utf-8");
        let finding = format!("error[{code}]");

        let check = run_within(60, &["check", "--format", "short", "--machine", m, p]);
        assert_exit(&check, 1);
        let text = stdout(&check);
        assert!(
            text.contains(&finding) && text.contains(says),
            "{name}: {text}"
        );
        assert!(
            text.lines().all(|line| line.starts_with(m)),
            "{name}: {text}"
        );
        let two = run_within(60, &["check", "--format", "short", "--machine", m, p, q]);
        assert_eq!(stdout(&two), text, "{name}: told once a run");

        for command in ["eval", "rewrite"] {
            let output = run_within(60, &[command, "--machine", m, p]);
            assert_exit(&output, 1);
            let stderr = flat(&output.stderr);
            assert!(
                stderr.contains(code) && stderr.contains(says),
                "{name}, {command}: {stderr}"
            );
        }
        let axes = run_within(
            60,
            &["axes", "--machine", m, "--record", "H", "0", "30", "0"],
        );
        let stderr = flat(&axes.stderr);
        assert!(
            stderr.contains(code) && stderr.contains(says),
            "{name}, axes: {stderr}"
        );
        assert_ne!(axes.status.code(), Some(0), "{name}, axes: {stderr}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `eval --machine`: a rotating CYCLE600 shows the axis positions its
/// CYCLE800 gets on the record named by its head.
#[test]
fn eval_shows_the_axis_positions_of_each_swivel() {
    let dir = scratch("eval-machine");
    let samples = support::repo().join("samples");
    std::fs::copy(samples.join("HEAD_DEF.SPF"), dir.join("HEAD_DEF.SPF")).expect("heads");
    let machine = std::fs::read_to_string(samples.join("MACHINE.SPF")).expect("machine");
    std::fs::write(
        dir.join("M.SPF"),
        machine.replace("\"HEAD_CA\"", "\"UFK600\""),
    )
    .expect("write");
    let program = dir.join("P.MPF");
    std::fs::write(
        &program,
        "N10 CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 20, 0, 0, 0, 0, 0, 1, 39, 0, 0, 0)\nN15 CYCLE800(1,\"UFK600\",0,57,0,0,0,0,30,0,0,0,0,-1)\nN16 CYCLE800(1,\"UFK600\",0,57,0,0,0,0,R1,0,0,0,0,-1)\nN20 M30\n",
    )
    .expect("program");
    let (m, p) = (
        dir.join("M.SPF"),
        program.to_str().expect("utf-8").to_string(),
    );
    let output = run(&["eval", "--machine", m.to_str().expect("utf-8"), &p], b"");
    assert_exit(&output, 0);
    // Extrinsic X 20 is CYCLE800 ZXY 0 20 0: the A axis tilts 20°, _DIR -1 the lower.
    assert!(
        stdout(&output).contains("  axes     record 1 (UFK600): C=-180 A=-20 (solution 1 of 2)"),
        "{}",
        stdout(&output)
    );
    // A CYCLE800 written with constant arguments: B 30 about Y is C -90
    // (R_z(-90) R_x(-30) Z = (0.5, 0, 0.866), the Z axis turned 30° about Y);
    // one with a variable is not known offline and not listed.
    let text = stdout(&output);
    assert!(
        text.contains(":2: CYCLE800(1,\"UFK600\",0,57,0,0,0,0,30,0,0,0,0,-1)\n  axes     record 1 (UFK600): C=-90 A=-30 (solution 1 of 2)"),
        "{text}"
    );
    assert!(!text.contains("R1,0"), "{text}");
    std::fs::write(dir.join("sinuprep.toml"), "machine = \"M.SPF\"\n").expect("config");
    let json = run(&["eval", "--json", &p], b"");
    let document: serde_json::Value = serde_json::from_slice(&json.stdout).expect("JSON");
    let axes = &document["calls"][0]["axes"];
    assert_eq!(axes["record"], "UFK600");
    assert_eq!(axes["solutions"].as_array().map(Vec::len), Some(2));
    let written = document["cycle800"].as_array().expect("the CYCLE800 calls");
    assert_eq!(written.len(), 1);
    assert_eq!(
        (&written[0]["line"], &written[0]["axes"]["record"]),
        (&2.into(), &"UFK600".into())
    );
    // The rewrite names the positions above the code it writes (the
    // machine from sinuprep.toml); without a machine it does not.
    let rewritten = stdout(&run(&["rewrite", &p], b""));
    assert!(
        rewritten.starts_with("; sinuprep: CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 20, 0, 0, 0, 0, 0, 1, 39, 0, 0, 0)\n; sinuprep: on UFK600 the axes go to C=-180 A=-20\nN10 CYCLE800(0,\"UFK600\",0,39,"),
        "{rewritten}"
    );
    std::fs::remove_file(dir.join("sinuprep.toml")).expect("remove");
    assert!(!stdout(&run(&["rewrite", &p], b"")).contains("axes go to"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// A program swivelling on the sample machine's head HEAD_H, which has the
/// rotary table TABLE_B under it (`samples/MACHINE.SPF`, records 5 and 6).
const TABLE_PROGRAM: &str = "tests/fixtures/table/TABLE_HEAD.MPF";

/// `--machine samples/MACHINE.SPF --table TABLE_B` for `command`, then `more`.
fn on_the_table<'a>(command: &'a str, more: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        command,
        "--machine",
        "samples/MACHINE.SPF",
        "--table",
        "TABLE_B",
    ];
    args.extend_from_slice(more);
    args
}

/// The text between `before` and the next `after` in `text`.
fn between<'t>(text: &'t str, before: &str, after: &str) -> &'t str {
    let start = text
        .find(before)
        .unwrap_or_else(|| panic!("no `{before}` in {text}"))
        + before.len();
    let length = text[start..]
        .find(after)
        .unwrap_or_else(|| panic!("no `{after}` in {text}"));
    &text[start..start + length]
}

fn number(text: &str) -> f64 {
    text.trim()
        .parse()
        .unwrap_or_else(|_| panic!("`{text}` is no number"))
}

/// With a table under the head, `rewrite` writes no code for the swivel: it
/// refuses (exit 1) with the split's numbers, which put the tool where the
/// call asks on a model of the machine written here, and which `axes
/// --table` gives for the same frame; the call's bytes stay, the other call
/// is rewritten. Without `--table` the call is CYCLE800 of the head.
#[test]
fn rewrite_refuses_a_swivel_over_a_table_with_the_splits_numbers() {
    use nalgebra::{Rotation3, Unit, Vector3};
    let program = std::fs::read_to_string(TABLE_PROGRAM).expect("program");
    let output = run(
        &on_the_table("rewrite", &["--message-format", "short", TABLE_PROGRAM]),
        b"",
    );
    assert_exit(&output, 1);
    let rewritten = stdout(&output);
    let swivel =
        "N40 CYCLE600(0, \"HEAD_H\", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 57, 0, 0, 0)\n";
    assert!(
        rewritten.contains(&format!("N30 D1 S2500 M3\n{swivel}N50 ")),
        "{rewritten}"
    );
    assert!(!rewritten.contains("CYCLE800(0,\"HEAD_H\""), "{rewritten}");
    assert!(
        rewritten.contains("N70 _CYC600_1=\"HEAD_H\""),
        "{rewritten}"
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    let finding = stderr
        .lines()
        .find(|line| line.contains("[C620]"))
        .unwrap_or_else(|| panic!("{stderr}"));
    assert!(
        finding.starts_with(&format!(
            "{TABLE_PROGRAM}:8:5: error[C620] `HEAD_H` has the rotary table `TABLE_B` under it"
        )),
        "{finding}"
    );
    let table = number(between(finding, "the table to `G0 B=", "`"));
    let frame: Vec<f64> = between(finding, "with XYZ ", " (_MODE")
        .split(' ')
        .map(number)
        .collect();
    assert!(finding.contains("(_MODE 57)"), "{finding}");
    let c = number(between(finding, "its axes to C=", " A="));
    let a = number(between(finding, " A=", ","));
    let about = number(
        between(finding, "A=", "° left about the tool axis")
            .rsplit(", ")
            .next()
            .expect("angle"),
    );
    // The machine: TABLE_B turns the workpiece about (0, -1, 0) as entered
    // (by R(v, B)⁻¹ in the model), HEAD_H the tool by R(z, C) R(x, A).
    let turn = |axis: Vector3<f64>, degrees: f64| {
        Rotation3::from_axis_angle(&Unit::new_normalize(axis), degrees.to_radians())
    };
    let (x, y, z) = (Vector3::x(), Vector3::y(), Vector3::z());
    // The call: extrinsic X 30, Y 45, Z 60.
    let requested = turn(z, 60.0) * turn(y, 45.0) * turn(x, 30.0);
    let table_turn = turn(Vector3::new(0.0, -1.0, 0.0), table);
    let made = table_turn.inverse() * turn(z, c) * turn(x, a) * turn(z, about);
    // Four decimals printed: a ten-thousandth of a degree each.
    assert!(
        (made.matrix() - requested.matrix()).norm() < 1e-5,
        "{made} against {requested}"
    );
    let head_frame = turn(x, frame[0]) * turn(y, frame[1]) * turn(z, frame[2]);
    assert!(
        (head_frame.matrix() - (table_turn * requested).matrix()).norm() < 1e-5,
        "{head_frame}"
    );
    assert!((-45.0..=45.0).contains(&a), "HEAD_H's A limits: {a}");
    // `axes --table` on the frame the call hands CYCLE800 (intrinsic XYZ,
    // _DIR -1) tells the same.
    let eval = run(&on_the_table("eval", &["--json", TABLE_PROGRAM]), b"");
    let document: serde_json::Value = serde_json::from_slice(&eval.stdout).expect("JSON");
    let angles: Vec<String> = (0..3)
        .map(|i| document["calls"][0]["evaluation"]["output"]["angles"][i].to_string())
        .collect();
    let axes = run(
        &[
            &on_the_table(
                "axes",
                &["--record", "HEAD_H", "--mode", "57", "--dir", "-1", "--"],
            )[..],
            &angles.iter().map(String::as_str).collect::<Vec<_>>()[..],
        ]
        .concat(),
        b"",
    );
    assert_exit(&axes, 0);
    let told = stdout(&axes);
    for line in [
        format!("table block: G0 B={}", format_position(table)),
        format!(
            "head frame: XYZ {} (_MODE 57)",
            between(finding, "with XYZ ", " (_MODE")
        ),
        format!(
            "solution 1: C={} A={}",
            format_position(c),
            format_position(a)
        ),
        "taken: solution 1".to_string(),
        format!(
            "left in the frame: {}° about the tool axis",
            format_position(about)
        ),
    ] {
        assert!(told.contains(&line), "{line}\n{told}");
    }
    // The frames form names no record: it is written, the split above it.
    let frames = run(
        &on_the_table("rewrite", &["--emit", "frames", TABLE_PROGRAM]),
        b"",
    );
    assert_exit(&frames, 0);
    assert!(
        stdout(&frames).contains("; sinuprep: with the table TABLE_B under HEAD_H the axes go to B=50.361 C=0 A=-16.28\nN40 TRANS X0 Y0 Z0\n"),
        "{}",
        stdout(&frames)
    );
    // Without the table, the head takes the whole swivel as CYCLE800,
    // which it cannot reach within its limits: said (K002), exit 1.
    let plain = run(
        &[
            "rewrite",
            "--machine",
            "samples/MACHINE.SPF",
            "--message-format",
            "short",
            TABLE_PROGRAM,
        ],
        b"",
    );
    assert_exit(&plain, 1);
    assert!(
        stdout(&plain).contains("N40 CYCLE800(0,\"HEAD_H\",0,57,"),
        "{}",
        stdout(&plain)
    );
    let stderr = String::from_utf8_lossy(&plain.stderr);
    assert!(
        stderr.contains(&format!("{TABLE_PROGRAM}:8:5: error[K002] record `HEAD_H` reaches this orientation only outside its axis limits")),
        "{stderr}"
    );
    assert_ne!(stdout(&plain), program);
    // The refusal as a person reads it.
    let human = run(&on_the_table("rewrite", &[TABLE_PROGRAM]), b"");
    assert_exit(&human, 1);
    insta::assert_snapshot!(format!(
        "{}\n--- stderr\n{}",
        stdout(&human),
        String::from_utf8_lossy(&human.stderr)
    ));
}

/// `found` is `expected` but for numbers, which agree to 1e-9.
fn assert_close(found: &serde_json::Value, expected: &serde_json::Value, at: &str) {
    use serde_json::Value;
    match (found, expected) {
        (Value::Number(f), Value::Number(e)) => {
            let (f, e) = (f.as_f64().expect("f64"), e.as_f64().expect("f64"));
            assert!((f - e).abs() < 1e-9, "{at}: {f} against {e}");
        }
        (Value::Array(f), Value::Array(e)) => {
            assert_eq!(f.len(), e.len(), "{at}");
            for (i, (f, e)) in f.iter().zip(e).enumerate() {
                assert_close(f, e, &format!("{at}[{i}]"));
            }
        }
        (Value::Object(f), Value::Object(e)) => {
            assert_eq!(
                f.keys().collect::<Vec<_>>(),
                e.keys().collect::<Vec<_>>(),
                "{at}"
            );
            for (key, f) in f {
                assert_close(f, &e[key], &format!("{at}.{key}"));
            }
        }
        _ => assert_eq!(found, expected, "{at}"),
    }
}

/// `eval` shows the split of each swivel over the table, in text and JSON,
/// as `axes --table` computes it; the rewrite's finding comes with it.
#[test]
fn eval_shows_a_swivels_split_over_a_table() {
    let output = run(&on_the_table("eval", &[TABLE_PROGRAM]), b"");
    assert_exit(&output, 1);
    let text = stdout(&output);
    for line in [
        "  table: record 5 (TABLE_B): B=50.3607 (chosen: the head nearest the middles of its limits)\n  table block: G0 B=50.3607\n  head frame: XYZ -16.2799 0 39.6393 (_MODE 57): the frame with the table's turn taken out, CYCLE800's on the head's record\n  axes     record 6 (HEAD_H): C=0 A=-16.2799 (solution 1 of 2)\n  left in the frame: 39.6393° about the tool axis\n",
        "  emits    nothing: `HEAD_H` has the rotary table `TABLE_B` under it",
    ] {
        assert!(text.contains(line), "{line}\n{text}");
    }
    assert!(
        flat(&output.stderr).contains("C620"),
        "{}",
        flat(&output.stderr)
    );
    let json = run(&on_the_table("eval", &["--json", TABLE_PROGRAM]), b"");
    let document: serde_json::Value = serde_json::from_slice(&json.stdout).expect("JSON");
    let call = &document["calls"][0];
    assert_eq!(call["evaluation"]["emits"], serde_json::Value::Null);
    let split = &call["axes"];
    let angles: Vec<String> = (0..3)
        .map(|i| call["evaluation"]["output"]["angles"][i].to_string())
        .collect();
    let axes = run(
        &[
            &on_the_table(
                "axes",
                &[
                    "--json", "--record", "HEAD_H", "--mode", "57", "--dir", "-1", "--",
                ],
            )[..],
            &angles.iter().map(String::as_str).collect::<Vec<_>>()[..],
        ]
        .concat(),
        b"",
    );
    let mut expected: serde_json::Value = serde_json::from_slice(&axes.stdout).expect("JSON");
    // `axes` alone tells where a work zero goes. Its frame is made again from
    // the angles, eval's is the call's matrix: the last bits may differ.
    // And the `_DIR` it took, which in eval is the call's own.
    let object = expected.as_object_mut().expect("object");
    for key in ["work_zero", "dir", "dir_chosen"] {
        object.remove(key);
    }
    assert_close(split, &expected, "axes");
    assert_eq!(split["table"]["block"], "G0 B=50.3607");
    assert_eq!(split["head_frame"]["mode"], 57);
    // The table from sinuprep.toml, beside the machine.
    let dir = scratch("eval-table");
    for name in ["TABLE_HEAD.MPF", "HEAD_DEF.SPF"] {
        std::fs::copy(
            support::repo().join("tests/fixtures/table").join(name),
            dir.join(name),
        )
        .expect("copy");
    }
    // Beside the settings file, named relative to it (a path of this
    // machine's would not be one on Windows, where the test runs too).
    std::fs::copy(
        support::repo().join("samples/MACHINE.SPF"),
        dir.join("MACHINE.SPF"),
    )
    .expect("copy");
    std::fs::write(
        dir.join("sinuprep.toml"),
        "machine = \"MACHINE.SPF\"\ntable = \"TABLE_B\"\n",
    )
    .expect("config");
    let program = dir.join("TABLE_HEAD.MPF");
    let configured = run(&["eval", program.to_str().expect("utf-8")], b"");
    assert!(
        stdout(&configured).contains("  table block: G0 B=50.3607\n"),
        "{}",
        stdout(&configured)
    );
    assert_exit(&run(&["rewrite", program.to_str().expect("utf-8")], b""), 1);
    // `axes` reads the machine, and the table under its heads, alike.
    let config = dir.join("sinuprep.toml");
    let axes = run(
        &[
            "axes",
            "--config",
            config.to_str().expect("utf-8"),
            "--record",
            "HEAD_H",
            "30",
            "45",
            "60",
        ],
        b"",
    );
    assert!(
        stdout(&axes).contains("\ntable block: G0 B="),
        "{}",
        stdout(&axes)
    );
    // A table that is no table, or none in the machine, is the tool's error.
    for (table, says) in [
        (
            "HEAD_H",
            "the table `HEAD_H` must be a record of kinematics \"P\" with one rotary axis",
        ),
        (
            "TABLE_BB",
            "no record `TABLE_BB` for the table (did you mean `TABLE_B`?)",
        ),
    ] {
        let wrong = run(
            &[
                "eval",
                "--machine",
                "samples/MACHINE.SPF",
                "--table",
                table,
                TABLE_PROGRAM,
            ],
            b"",
        );
        assert_exit(&wrong, 2);
        assert!(
            flat(&wrong.stderr).contains(says),
            "{}",
            flat(&wrong.stderr)
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Completions and the man page come from the clap definition: every
/// command and option is in them.
#[test]
fn completions_and_the_man_page_name_every_command() {
    for shell in ["bash", "zsh", "fish", "powershell", "elvish"] {
        let output = run(&["completions", shell], b"");
        assert_exit(&output, 0);
        let script = stdout(&output);
        for name in [
            "check",
            "rewrite",
            "axes",
            "machine",
            "format",
            "fine-offsets",
        ] {
            assert!(script.contains(name), "{shell} lacks {name}");
        }
    }
    let output = run(&["manpage"], b"");
    assert_exit(&output, 0);
    let page = stdout(&output);
    assert!(page.contains(".TH sinuprep 1"), "{page}");
    for command in ["check", "rewrite", "eval", "rule", "convert", "axes"] {
        assert!(page.contains(command), "the man page lacks {command}");
    }
    assert_exit(&run(&["completions", "tcsh"], b""), 2);
}

/// A reader that goes away (`sinuprep check 2>&1 | head -1`) takes standard
/// output and standard error with it: the run ends with its own status, not
/// a panic (exit 101).
#[test]
fn a_closed_stdout_and_stderr_are_no_panic() {
    for args in [
        &["check", "tests/fixtures/lint"][..],
        &["rewrite", "samples/PAPER_EXAMPLE3.MPF"][..],
        &["eval", "samples/PAPER_EXAMPLE3.MPF"][..],
    ] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
            .args(args)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("binary runs");
        // Both pipes closed before the first byte is written.
        drop(child.stdout.take());
        drop(child.stderr.take());
        let status = child.wait().expect("binary ends");
        assert!(matches!(status.code(), Some(0..=2)), "{args:?}: {status:?}");
    }
}

/// `check` with no path checks the current directory (stdin only with `-`
/// or --stdin-filename); `rewrite` and `eval` with no path read a program
/// piped in.
#[test]
fn no_path_is_the_current_directory_for_check_and_stdin_for_rewrite() {
    let dir = scratch("no-path");
    std::fs::copy(
        support::repo().join("tests/fixtures/lint/N022_trigger.mpf"),
        dir.join("PART.MPF"),
    )
    .expect("copied");
    let output = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
        .args(["check", "--format", "short"])
        .current_dir(&dir)
        .stdin(Stdio::null())
        .output()
        .expect("binary runs");
    assert_exit(&output, 1);
    assert!(
        stdout(&output).contains("PART.MPF:2:12: error[N022]"),
        "{}",
        stdout(&output)
    );
    let program =
        std::fs::read(support::repo().join("samples/PAPER_EXAMPLE3.MPF")).expect("sample");
    for command in ["rewrite", "eval"] {
        let output = run(&[command], &program);
        assert!(
            stdout(&output).contains("37.792346"),
            "{command}: {}",
            stdout(&output)
        );
    }
    let output = run(
        &[
            "check",
            "--format",
            "short",
            "--stdin-filename",
            "samples/X.MPF",
        ],
        b"N10 G1 X1 X2\nM30\n",
    );
    assert!(
        stdout(&output).contains("samples/X.MPF:1:"),
        "{}",
        stdout(&output)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A file that cannot be read is an error of its own (exit 2), never
/// summed up as "no findings in 0 files", which reads as a pass.
#[test]
fn an_unreadable_file_is_not_summed_up_as_a_pass() {
    let output = run(&["check", "--format", "short", "NOT_THERE.MPF"], b"");
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("cannot read") && !stderr.contains("in 0 files"),
        "{stderr}"
    );
    let output = run(
        &[
            "check",
            "--format",
            "short",
            "NOT_THERE.MPF",
            "samples/PAPER_EXAMPLE3.MPF",
        ],
        b"",
    );
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("in 1 file; 1 file could not be checked"),
        "{stderr}"
    );
}

/// `rule` takes a rule's name as well as its code, and suggests the nearest
/// of either for one it does not know.
#[test]
fn rule_takes_a_name_and_suggests_the_nearest() {
    let by_code = run(&["rule", "N005"], b"");
    let by_name = run(&["rule", "undefined-variable"], b"");
    assert_exit(&by_name, 0);
    assert_eq!(by_code.stdout, by_name.stdout);
    let output = run(&["rule", "N05"], b"");
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("did you mean `N005`?"), "{stderr}");
}

/// `--exit-zero` reports the findings and exits 0; a tool failure still
/// exits 2.
#[test]
fn exit_zero_reports_without_failing() {
    let trigger = "tests/fixtures/lint/N022_trigger.mpf";
    let output = run(&["check", "--format", "short", "--exit-zero", trigger], b"");
    assert_exit(&output, 0);
    assert!(stdout(&output).contains("error[N022]"));
    let output = run(&["check", "--exit-zero", "NOT_THERE.MPF"], b"");
    assert_exit(&output, 2);
}

/// `--color always` colours a report sent to a pipe, `never` and NO_COLOR
/// keep it plain, CLICOLOR_FORCE colours it where NO_COLOR is not set.
#[test]
fn colour_follows_the_option_and_the_environment() {
    let trigger = "tests/fixtures/lint/N022_trigger.mpf";
    let coloured = |args: &[&str], env: &[(&str, &str)]| {
        let output = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
            .args(args)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .env_remove("NO_COLOR")
            .env_remove("CLICOLOR_FORCE")
            .envs(env.iter().copied())
            .stdin(Stdio::null())
            .output()
            .expect("binary runs");
        output.stdout.contains(&0x1b)
    };
    assert!(!coloured(&["check", trigger], &[]));
    assert!(coloured(&["check", "--color", "always", trigger], &[]));
    assert!(!coloured(
        &["check", "--color", "never", trigger],
        &[("CLICOLOR_FORCE", "1")]
    ));
    assert!(coloured(&["check", trigger], &[("CLICOLOR_FORCE", "1")]));
    assert!(!coloured(
        &["check", trigger],
        &[("CLICOLOR_FORCE", "1"), ("NO_COLOR", "1")]
    ));
}

/// The summary says how many findings `--fix` would answer, and how many
/// more `--unsafe-fixes` would.
#[test]
fn the_summary_counts_what_fix_would_answer() {
    let output = run(
        &[
            "check",
            "--format",
            "short",
            "tests/fixtures/lint/N001_trigger.mpf",
            "tests/fixtures/lint/N099_trigger.mpf",
        ],
        b"",
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("in 2 files (1 fixable with `--fix`, 1 more with `--unsafe-fixes`)"),
        "{stderr}"
    );
    let output = run(
        &["check", "--format", "short", "samples/PAPER_EXAMPLE3.MPF"],
        b"",
    );
    assert!(!String::from_utf8_lossy(&output.stderr).contains("fixable"));
}

/// `--output-file` writes the report that stdout would carry, whole, and
/// leaves stdout empty; the summary stays on stderr. A file that cannot be
/// written is a tool error.
#[test]
fn output_file_holds_the_report_stdout_would() {
    let dir = scratch("output-file");
    let trigger = "tests/fixtures/lint/N001_trigger.mpf";
    for format in ["short", "json", "sarif", "github", "human"] {
        let to_stdout = run(&["check", "--format", format, trigger], b"");
        let path = dir.join(format!("report.{format}"));
        std::fs::write(&path, "an older report, replaced whole\n").expect("write");
        let path_text = path.to_str().expect("path");
        let to_file = run(
            &[
                "check",
                "--format",
                format,
                "--output-file",
                path_text,
                trigger,
            ],
            b"",
        );
        assert_exit(&to_file, 1);
        assert!(to_file.stdout.is_empty(), "{}", stdout(&to_file));
        assert_eq!(
            std::fs::read(&path).expect("report"),
            to_stdout.stdout,
            "{format}"
        );
        assert_eq!(to_file.stderr, to_stdout.stderr);
    }
    let missing = dir.join("no/such/dir/report.txt");
    let output = run(
        &["check", "-o", missing.to_str().expect("path"), trigger],
        b"",
    );
    assert_exit(&output, 2);
    assert!(!missing.exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--statistics` counts the findings of each rule instead of listing them,
/// as ruff does: count, code, `[*]` where `--fix` answers some, name.
#[test]
fn statistics_count_the_findings_of_each_rule() {
    let files = [
        "tests/fixtures/lint/N001_trigger.mpf",
        "tests/fixtures/lint/N099_trigger.mpf",
    ];
    let output = run(&[&["check", "--statistics"][..], &files].concat(), b"");
    assert_exit(&output, 1);
    assert_eq!(
        stdout(&output),
        "4\tN001\t[ ] undefined-label\n3\tN099\t[*] unused-suppression\n2\tN005\t[ ] undefined-variable\n"
    );
    let output = run(
        &[&["check", "--statistics", "--format", "json"][..], &files].concat(),
        b"",
    );
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
    assert_eq!(json[0]["code"], "N001");
    assert_eq!(json[0]["count"], 4);
    assert_eq!(json[1]["fixable"], true);
}

/// A file that cannot be checked is an entry of the JSON report (its path,
/// the error, no diagnostics) and a notification of the SARIF log's
/// invocation, which is then no success; not only a message on stderr.
#[test]
fn an_unreadable_file_is_an_entry_of_the_json_and_sarif_reports() {
    let dir = scratch("unreadable-entry");
    // An archive cut short cannot be read; a file that is not there neither.
    let damaged = dir.join("CUT.ARC");
    std::fs::write(&damaged, b"@@MMCIBN.002, and no header after it").expect("write");
    let damaged = damaged.to_str().expect("path");
    let files = ["NOT_THERE.MPF", "samples/PAPER_EXAMPLE3.MPF", damaged];
    let output = run(&[&["check", "--format", "json"][..], &files].concat(), b"");
    assert_exit(&output, 2);
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
    let entries = json["files"].as_array().expect("files");
    assert_eq!(entries.len(), 3, "{json}");
    assert_eq!(entries[0]["path"], "NOT_THERE.MPF");
    let error = entries[0]["error"].as_str().expect("error");
    assert!(error.starts_with("cannot read NOT_THERE.MPF: "), "{error}");
    assert_eq!(entries[0]["diagnostics"], serde_json::json!([]));
    assert!(entries[1].get("error").is_none());
    assert_eq!(entries[2]["path"], damaged);
    let output = run(&[&["check", "--format", "sarif"][..], &files].concat(), b"");
    assert_exit(&output, 2);
    let sarif: serde_json::Value = serde_json::from_slice(&output.stdout).expect("SARIF");
    let invocation = &sarif["runs"][0]["invocations"][0];
    assert_eq!(invocation["executionSuccessful"], false);
    let notes = invocation["toolExecutionNotifications"]
        .as_array()
        .expect("notifications");
    assert_eq!(notes.len(), 2);
    assert_eq!(notes[0]["level"], "error");
    assert_eq!(
        notes[0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
        "NOT_THERE.MPF"
    );
    let fine = run(
        &["check", "--format", "sarif", "samples/PAPER_EXAMPLE3.MPF"],
        b"",
    );
    let sarif: serde_json::Value = serde_json::from_slice(&fine.stdout).expect("SARIF");
    assert_eq!(
        sarif["runs"][0]["invocations"][0]["executionSuccessful"],
        true
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Every format counts columns alike, in UTF-16 code units (LSP's and
/// SARIF's default): `ü` is one, `𝜑` (beyond the Basic Multilingual Plane)
/// two, a Latin-1 byte one. The human header counted bytes.
#[test]
fn every_format_counts_columns_alike() {
    let dir = scratch("columns");
    let path = dir.join("COL.MPF");
    let program = [
        &b"N10 MSG(\"\xc3\xbc\") X1 X1\n"[..],
        b"N20 MSG(\"\xf0\x9d\x9c\x91\") X1 X1\n",
        b"M30\n",
    ]
    .concat();
    let latin1 = dir.join("LATIN1.MPF");
    std::fs::write(&path, &program).expect("write");
    std::fs::write(&latin1, b"N10 MSG(\"\xfc\") X1 X1\nM30\n").expect("write");
    for (file, columns) in [(&path, &[17, 18][..]), (&latin1, &[17][..])] {
        let file = file.to_str().expect("path");
        let format = |format: &str| stdout(&run(&["check", "--format", format, file], b""));
        let found = |text: &str, before: &str, after: char| -> Vec<usize> {
            text.split(before)
                .skip(1)
                .map(|rest| rest.split(after).next().unwrap_or("").trim())
                .map(|n| n.parse().unwrap_or_else(|_| panic!("{n}: {text}")))
                .collect()
        };
        let short = format("short");
        let short: Vec<usize> = short
            .lines()
            .map(|l| l[file.len() + 1..].split(':').nth(1).unwrap_or(""))
            .map(|n| n.parse().expect("column"))
            .collect();
        assert_eq!(short, columns, "short");
        assert_eq!(found(&format("github"), ",col=", ','), columns, "github");
        let human: Vec<usize> = format("human")
            .split(&format!("[{file}:"))
            .skip(1)
            .map(|rest| rest.split(']').next().unwrap_or(""))
            .map(|at| at.split(':').nth(1).unwrap_or("").parse().expect("column"))
            .collect();
        assert_eq!(human, columns, "human");
        let json: serde_json::Value = serde_json::from_str(&format("json")).expect("JSON");
        let json: Vec<u64> = json["files"][0]["diagnostics"]
            .as_array()
            .expect("diagnostics")
            .iter()
            .map(|d| d["location"]["column"].as_u64().expect("column"))
            .collect();
        assert_eq!(
            json,
            columns.iter().map(|&c| c as u64).collect::<Vec<_>>(),
            "json"
        );
        let sarif: serde_json::Value = serde_json::from_str(&format("sarif")).expect("SARIF");
        assert_eq!(sarif["runs"][0]["columnKind"], "utf16CodeUnits");
        let sarif: Vec<u64> = sarif["runs"][0]["results"]
            .as_array()
            .expect("results")
            .iter()
            .map(|r| {
                r["locations"][0]["physicalLocation"]["region"]["startColumn"]
                    .as_u64()
                    .expect("column")
            })
            .collect();
        assert_eq!(
            sarif,
            columns.iter().map(|&c| c as u64).collect::<Vec<_>>(),
            "sarif"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A UTF-8 byte-order mark at the start of a file is named, and `--fix`
/// removes it (its three bytes, nothing else), although it is a syntax
/// error: a program with syntax errors gets only their own safe fixes.
#[test]
fn a_byte_order_mark_is_named_and_fix_removes_it() {
    let dir = scratch("bom");
    let path = dir.join("BOM.MPF");
    let program = b"N10 G0 X1\r\nN20 R1=2^3\r\nM30\r\n";
    std::fs::write(&path, [&b"\xef\xbb\xbf"[..], program].concat()).expect("write");
    let name = path.to_str().expect("path");
    let output = run(&["check", "--format", "short", name], b"");
    assert_exit(&output, 1);
    let text = stdout(&output);
    assert!(
        text.starts_with(&format!(
            "{name}:1:1: error[S004] byte-order mark U+FEFF at the start of the file"
        )),
        "{text}"
    );
    let fixed = run(&["check", "--fix", "--format", "short", name], b"");
    assert_exit(&fixed, 1);
    assert_eq!(std::fs::read(&path).expect("read"), program);
    // What is left is the other syntax error, which has no fix.
    assert_eq!(stdout(&fixed).lines().count(), 1, "{}", stdout(&fixed));
    let _ = std::fs::remove_dir_all(&dir);
}

/// A file name that is no UTF-8 (`Kühl.MPF` saved in Latin-1) is named in
/// SARIF by its own bytes, percent-encoded (it was `K%EF%BF%BDhl.MPF`, the
/// replacement character, which names no file); people read it lossily.
#[cfg(unix)]
#[test]
fn sarif_names_a_file_by_the_bytes_of_its_name() {
    use std::os::unix::ffi::OsStrExt;
    let dir = scratch("latin1-name");
    let path = dir.join(std::ffi::OsStr::from_bytes(b"K\xfchl.MPF"));
    std::fs::write(&path, b"N10 G1 X1\nM30\n").expect("write");
    let output = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
        .args(["check", "--format", "sarif"])
        .arg(&path)
        .output()
        .expect("binary runs");
    let sarif: serde_json::Value = serde_json::from_slice(&output.stdout).expect("SARIF");
    let uri = sarif["runs"][0]["results"][0]["locations"][0]["physicalLocation"]
        ["artifactLocation"]["uri"]
        .as_str()
        .expect("uri");
    assert!(uri.starts_with("file:///"), "{uri}");
    assert!(uri.ends_with("/K%FChl.MPF"), "{uri}");
    let output = Command::new(env!("CARGO_BIN_EXE_sinuprep"))
        .args(["check", "--format", "short"])
        .arg(&path)
        .output()
        .expect("binary runs");
    assert!(stdout(&output).contains("K\u{fffd}hl.MPF:1:"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// A name with letters beyond ASCII, as shops name programs on Windows
/// (`Kühl_Maß.MPF`; there UTF-16, here UTF-8): read, named in every format
/// (SARIF by its UTF-8 bytes, percent-encoded), and rewritten in place under
/// the same name with its backup. Runs under Wine too.
#[test]
fn a_name_beyond_ascii_is_read_named_and_rewritten_in_place() {
    let dir = scratch("umlaut-name");
    let repo = support::repo();
    let path = dir.join("Kühl_Maß.MPF");
    let original = std::fs::read(repo.join("samples/PAPER_EXAMPLE3.MPF")).expect("sample");
    std::fs::write(&path, &original).expect("write");
    std::fs::copy(repo.join("samples/HEAD_DEF.SPF"), dir.join("HEAD_DEF.SPF")).expect("heads");
    let run_on = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_sinuprep"))
            .args(args)
            .arg(&path)
            .output()
            .expect("binary runs")
    };
    let sarif = run_on(&["check", "--select", "C619", "--format", "sarif"]);
    let sarif: serde_json::Value = serde_json::from_slice(&sarif.stdout).expect("SARIF");
    let uri = sarif["runs"][0]["results"][0]["locations"][0]["physicalLocation"]
        ["artifactLocation"]["uri"]
        .as_str()
        .expect("uri");
    assert!(uri.ends_with("/K%C3%BChl_Ma%C3%9F.MPF"), "{uri}");
    let short = run_on(&["check", "--select", "C619", "--format", "short"]);
    assert!(
        stdout(&short).contains("Kühl_Maß.MPF:"),
        "{}",
        stdout(&short)
    );

    let rewritten = run_on(&["rewrite", "--in-place"]);
    assert_exit(&rewritten, 0);
    let text = std::fs::read_to_string(&path).expect("rewritten");
    assert!(text.contains("_CYC600_2=37.792346"), "{text}");
    assert_eq!(
        std::fs::read(dir.join("Kühl_Maß.MPF.bak")).expect("backup"),
        original
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The main page's list of commands refers to `sinuprep-check(1)` and the
/// others: `manpage --dir` writes each of them, `manpage check` prints one.
#[test]
fn manpage_writes_every_page_the_main_page_refers_to() {
    let dir = scratch("manpages");
    let output = run(&["manpage", "--dir", dir.to_str().expect("path")], b"");
    assert_exit(&output, 0);
    let main = std::fs::read_to_string(dir.join("sinuprep.1")).expect("sinuprep.1");
    assert_eq!(main, stdout(&run(&["manpage"], b"")));
    let referred: Vec<&str> = main
        .lines()
        .filter_map(|line| line.strip_prefix("sinuprep\\-"))
        .filter_map(|line| line.strip_suffix("(1)"))
        .collect();
    assert!(
        referred.contains(&"check") && referred.len() >= 8,
        "{referred:?}"
    );
    for command in referred {
        let page = std::fs::read_to_string(dir.join(format!("sinuprep-{command}.1")))
            .unwrap_or_else(|e| panic!("sinuprep-{command}.1: {e}"));
        assert!(
            page.contains(&format!(".TH sinuprep-{command} 1")),
            "{page}"
        );
        assert_eq!(page, stdout(&run(&["manpage", command], b"")));
    }
    assert_exit(&run(&["manpage", "nope"], b""), 2);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `check` and `rewrite` name their output-format option alike,
/// `--output-format` (ruff's name); `--format` and `--message-format` stay
/// as aliases.
#[test]
fn check_and_rewrite_name_the_output_format_alike() {
    let broken = b"N10 X=(1+2\nM30\n";
    for (command, alias) in [("check", "--format"), ("rewrite", "--message-format")] {
        let named = run(&[command, "--output-format", "short", "-"], broken);
        assert_exit(&named, 1);
        let shown = if command == "check" {
            stdout(&named)
        } else {
            String::from_utf8_lossy(&named.stderr).into_owned()
        };
        assert!(shown.starts_with("<stdin>:1:"), "{command}: {shown}");
        let aliased = run(&[command, alias, "short", "-"], broken);
        assert_eq!(aliased.stdout, named.stdout);
        assert_eq!(aliased.stderr, named.stderr);
    }
}

#[test]
fn per_file_ignores_leave_out_rules_in_the_files_they_match() {
    let dir = scratch("per-file-ignores");
    std::fs::create_dir_all(dir.join("probe")).expect("dir");
    for path in ["probe/P.MPF", "Q.MPF"] {
        std::fs::write(dir.join(path), "GOTOF NOWHERE\nM30\n").expect("write");
    }
    std::fs::write(
        dir.join("sinuprep.toml"),
        "[per-file-ignores]\n\"probe/*\" = [\"N001\"]\n",
    )
    .expect("config");
    let name = dir.to_str().expect("utf-8");
    let output = run(&["check", "--format", "short", name], b"");
    assert_exit(&output, 1);
    let out = stdout(&output);
    assert!(out.contains("Q.MPF"), "{out}");
    assert!(!out.contains("P.MPF"), "{out}");
    std::fs::write(
        dir.join("sinuprep.toml"),
        "[per-file-ignores]\n\"probe/*\" = [\"N0001\"]\n",
    )
    .expect("config");
    let output = run(&["check", name], b"");
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("per-file-ignores"), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--force-exclude` (or `force-exclude = true`) leaves out a file named on
/// the command line that `exclude` matches, or that lies in a folder it
/// matches, as pre-commit passes every changed file; by default a file
/// named is taken.
#[test]
fn force_exclude_leaves_out_files_named_that_exclude_matches() {
    let dir = scratch("force-exclude");
    std::fs::create_dir_all(dir.join("old")).expect("dir");
    for path in ["old/P.MPF", "Q.MPF"] {
        std::fs::write(dir.join(path), "GOTOF NOWHERE\nM30\n").expect("write");
    }
    std::fs::write(dir.join("sinuprep.toml"), "exclude = [\"old\"]\n").expect("config");
    let old = dir.join("old").join("P.MPF");
    let (old, q) = (old.to_str().expect("utf-8"), dir.join("Q.MPF"));
    let q = q.to_str().expect("utf-8");
    let output = run(&["check", "--format", "short", old, q], b"");
    assert_exit(&output, 1);
    assert!(stdout(&output).contains("P.MPF"), "{}", stdout(&output));
    let output = run(
        &["check", "--format", "short", "--force-exclude", old, q],
        b"",
    );
    assert_exit(&output, 1);
    let (out, stderr) = (stdout(&output), String::from_utf8_lossy(&output.stderr));
    assert!(!out.contains("P.MPF") && out.contains("Q.MPF"), "{out}");
    assert!(stderr.contains("is excluded (force-exclude)"), "{stderr}");
    std::fs::write(
        dir.join("sinuprep.toml"),
        "exclude = [\"old\"]\nforce-exclude = true\n",
    )
    .expect("config");
    let output = run(&["check", "--format", "short", old], b"");
    assert_exit(&output, 0);
    // A file that does not exist is matched as its path reads, however
    // spelt (`dir/./old`, `//dir`): left out on Unix, never a crash. (On
    // Windows the path as typed may not begin as the folder's resolved
    // name does: the file is then taken, and is not found.)
    let gone = dir.join(".").join("old").join("GONE.MPF");
    let mut spellings = vec![gone.to_str().expect("utf-8").to_owned()];
    if cfg!(unix) {
        spellings.push(format!("/{}", dir.join("old").join("GONE.MPF").display()));
    }
    for gone in &spellings {
        let output = run(&["check", "--format", "short", gone], b"");
        let stderr = String::from_utf8_lossy(&output.stderr);
        if cfg!(windows) {
            assert!(
                matches!(output.status.code(), Some(0 | 2)),
                "{gone}: {stderr}"
            );
            continue;
        }
        assert_exit(&output, 0);
        assert!(
            stderr.contains("is excluded (force-exclude)"),
            "{gone}: {stderr}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `X,Y,Z` of a point, each number in full precision.
fn xyz(p: nalgebra::Point3<f64>) -> String {
    format!("{},{},{}", p.x, p.y, p.z)
}

fn numbers(value: &serde_json::Value) -> Vec<f64> {
    value
        .as_array()
        .expect("an array")
        .iter()
        .map(|v| v.as_f64().expect("a number"))
        .collect()
}

fn probe_json(args: &[&str]) -> serde_json::Value {
    // A head of the sample machine, unless one is given: without one no call
    // is written.
    let mut all = vec!["probe", "--json"];
    if !args.contains(&"--head") {
        all.extend_from_slice(&["--head", "HEAD_CA"]);
    }
    all.extend_from_slice(args);
    let output = run(&all, b"");
    assert_exit(&output, 0);
    serde_json::from_slice(&output.stdout).expect("json")
}

/// Four probe points on the face through `centre` turned by `angles`
/// (extrinsic X, Y), given in the frame `(origin, active)`.
fn probe_points(
    angles: [f64; 2],
    centre: nalgebra::Point3<f64>,
    active: nalgebra::Rotation3<f64>,
    origin: nalgebra::Vector3<f64>,
) -> [String; 4] {
    use nalgebra::Vector3;
    let r = sinuprep::measure::face::rotation(angles);
    let local =
        |p: nalgebra::Point3<f64>| nalgebra::Point3::from(active.inverse() * (p.coords - origin));
    let (ex, ey) = (r * Vector3::x(), r * Vector3::y());
    [
        centre,
        centre + ex * 100.0,
        centre + ey * 20.0,
        centre + ey * 90.0,
    ]
    .map(|p| xyz(local(p)))
}

#[test]
fn probe_prints_the_face_angles_and_the_calls() {
    // reference/kinematics.md section 6: Lx = 100, Δz +2, Ly = 80, Δz -1.5.
    let output = run(
        &[
            "probe",
            "--along-x",
            "0,0,0",
            "100,0,2",
            "--along-y",
            "0,0,0",
            "0,80,-1.5",
            "--head",
            "UFK600",
        ],
        b"",
    );
    assert_exit(&output, 0);
    insta::assert_snapshot!(stdout(&output));
}

#[test]
fn probe_json_has_the_sequence_and_exact_angles_in_every_form() {
    let centre = nalgebra::Point3::new(250.0, -40.0, 12.5);
    let angles = [12.0, -25.0];
    let [p1, p2, p3, p4] = probe_points(
        angles,
        centre,
        nalgebra::Rotation3::identity(),
        nalgebra::Vector3::zeros(),
    );
    let normal = sinuprep::measure::face::rotation(angles) * nalgebra::Vector3::z();
    let normal = format!("{},{},{}", normal.x, normal.y, normal.z * 2.0 / 2.0);
    for args in [
        vec!["--along-x", &p1, &p2, "--along-y", &p3, &p4],
        vec!["--points", &p1, &p2, &p4],
        vec!["--normal", &normal],
    ] {
        let value = probe_json(&args);
        assert_eq!(value["sequence"], "extrinsic:XYZ", "{args:?}");
        assert_eq!(value["code"], 57);
        let got = numbers(&value["angles"]);
        assert!(
            (got[0] - angles[0]).abs() < 1e-12
                && (got[1] - angles[1]).abs() < 1e-12
                && got[2] == 0.0,
            "{args:?}: {got:?}"
        );
    }
    let value = probe_json(&["--along-x", &p1, &p2, "--along-y", &p3, &p4]);
    // The centre is the first point, kept in full precision.
    let got = numbers(&value["centre"]);
    assert!((got[0] - 250.0).abs() < 1e-12 && (got[2] - 12.5).abs() < 1e-12);
    // The same angles `convert` reads in intrinsic Z, Y', X'' (CYCLE800's 27).
    let out = numbers(&value["output"]["angles"]);
    assert_eq!(value["output"]["sequence"], "intrinsic:ZYX");
    // Another output sequence, as the paper's Example 3 (Z, X', Y''); none
    // CYCLE800 cannot take.
    let zxy = probe_json(&["--normal", &normal, "--to", "i:ZXY"]);
    assert_eq!(zxy["output"]["code"], 39);
    assert!(zxy["cycle800"]
        .as_str()
        .expect("text")
        .starts_with("CYCLE800(0,\"HEAD_CA\",0,39,"));
    let output = run(&["probe", "--normal", &normal, "--to", "i:ZXZ"], b"");
    assert_exit(&output, 2);
    assert!(String::from_utf8_lossy(&output.stderr)
        .contains("--to: intrinsic:ZXZ is a proper Euler sequence"));
    assert!((out[1] - angles[1]).abs() < 1e-12 && (out[2] - angles[0]).abs() < 1e-12);
}

#[test]
fn probe_cycle800_is_what_rewrite_makes_of_its_cycle600() {
    let value = probe_json(&[
        "--points", "10,20,0", "110,25,3", "15,90,-2", "--head", "UFK600",
    ]);
    let call = format!("N10 {}\n", value["cycle600"].as_str().expect("text"));
    let output = run(
        &["rewrite", "--heads", "samples/HEAD_DEF.SPF", "-"],
        call.as_bytes(),
    );
    assert_exit(&output, 0);
    let rewritten = stdout(&output);
    let cycle800 = value["cycle800"].as_str().expect("text");
    assert!(
        rewritten.contains(&format!("N10 {cycle800}")),
        "{rewritten}\n{cycle800}"
    );
}

#[test]
fn probe_in_a_rotated_frame_composes_with_it() {
    use nalgebra::{Point3, Rotation3, Vector3};
    // The face's true angles in the machine, probed in a frame turned 30°
    // about Z (a CYCLE800 in _MODE 27) with its zero point at 100,0,0.
    let true_angles = [10.0, -20.0];
    let centre = Point3::new(200.0, 50.0, -30.0);
    let active = sinuprep::rotation::matrix("i:ZYX".parse().expect("valid"), [30.0, 0.0, 0.0]);
    let origin = Vector3::new(100.0, 0.0, 0.0);
    let [p1, p2, p3, p4] = probe_points(true_angles, centre, active, origin);
    let in_frame = [
        "--in-frame",
        "30,0,0",
        "--in-frame-sequence",
        "i:ZYX",
        "--in-frame-origin",
        "100,0,0",
    ];
    let mut args = vec!["--along-x", &p1, &p2, "--along-y", &p3, &p4];
    args.extend_from_slice(&in_frame);
    let value = probe_json(&args);
    let angles = numbers(&value["angles"]);
    let rotation = sinuprep::rotation::matrix(
        "e:XYZ".parse().expect("valid"),
        [angles[0], angles[1], angles[2]],
    );
    // The composed rotation turns the tool onto the face's true normal, and
    // keeps the active frame's turn about it: it is R_active · R_measured.
    let normal = sinuprep::measure::face::rotation(true_angles) * Vector3::z();
    assert!(
        (rotation * Vector3::z() - normal).norm() < 1e-12,
        "{angles:?}"
    );
    let measured = numbers(&value["measured"]);
    let expected = active * sinuprep::measure::face::rotation([measured[0], measured[1]]);
    assert!((rotation.matrix() - expected.matrix()).abs().max() < 1e-12);
    assert!(
        angles[2].abs() > 1.0,
        "an active turn about Z stays: {angles:?}"
    );
    // The centre, the first point, in machine coordinates.
    let got = Point3::from(Vector3::from_vec(numbers(&value["centre"])));
    assert!((got - centre).norm() < 1e-12, "{got}");
    // Read as machine coordinates, the same points give another face: the trap.
    let naive = probe_json(&["--along-x", &p1, &p2, "--along-y", &p3, &p4]);
    let naive = numbers(&naive["angles"]);
    let naive = sinuprep::rotation::matrix(
        "e:XYZ".parse().expect("valid"),
        [naive[0], naive[1], naive[2]],
    );
    assert!((naive * Vector3::z() - normal).norm() > 0.1);
    let _ = Rotation3::<f64>::identity();
    // The table says what the angles are relative to.
    let mut args = vec!["probe", "--along-x", &p1, &p2, "--along-y", &p3, &p4];
    args.extend_from_slice(&in_frame);
    args.extend_from_slice(&["--head", "HEAD_CA"]);
    let output = run(&args, b"");
    assert_exit(&output, 0);
    insta::assert_snapshot!(stdout(&output));
}

#[test]
fn probe_in_inch_gives_the_same_angles_and_the_centre_in_inch() {
    let mm = [
        "12.7,25.4,0",
        "266.7,25.4,5.08",
        "12.7,25.4,0",
        "12.7,279.4,-3.81",
    ];
    let inch = ["0.5,1,0", "10.5,1,0.2", "0.5,1,0", "0.5,11,-0.15"];
    let metric = probe_json(&["--along-x", mm[0], mm[1], "--along-y", mm[2], mm[3]]);
    let imperial = probe_json(&[
        "--along-x",
        inch[0],
        inch[1],
        "--along-y",
        inch[2],
        inch[3],
        "--units",
        "inch",
    ]);
    let (a, b) = (numbers(&metric["angles"]), numbers(&imperial["angles"]));
    assert!(
        a.iter().zip(&b).all(|(a, b)| (a - b).abs() < 1e-12),
        "{a:?} {b:?}"
    );
    assert_eq!(metric["units"], "mm");
    assert_eq!(imperial["units"], "inch");
    let (a, b) = (numbers(&metric["centre"]), numbers(&imperial["centre"]));
    assert!(
        a.iter().zip(&b).all(|(a, b)| (a / 25.4 - b).abs() < 1e-12),
        "{a:?} {b:?}"
    );
    // The default tolerance is a length in the unit: 0.01 mm, 0.0005 inch.
    assert_eq!(metric["tolerance"], 0.01);
    assert_eq!(imperial["tolerance"], 0.0005);
    // 0.002 inch off the plane: within 0.01 read as mm, not as inch.
    let off = ["0.5,1,0", "10.5,1,0.2", "0.5,1,0.002", "0.5,11,-0.148"];
    let output = run(
        &[
            "probe",
            "--along-x",
            off[0],
            off[1],
            "--along-y",
            off[2],
            off[3],
            "--units",
            "inch",
        ],
        b"",
    );
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("0.001999 inch off the face") && stderr.contains("0.0005 inch"),
        "{stderr}"
    );
    let output = run(
        &[
            "probe",
            "--along-x",
            off[0],
            off[1],
            "--along-y",
            off[2],
            off[3],
        ],
        b"",
    );
    assert_exit(&output, 0);
    // The table tells which G function the calls' lengths need.
    let output = run(
        &[
            "probe",
            "--along-x",
            inch[0],
            inch[1],
            "--along-y",
            inch[2],
            inch[3],
            "--units",
            "inch",
        ],
        b"",
    );
    assert!(stdout(&output).contains("run them under G70 (inch)"));
}

#[test]
fn probe_centre_is_the_point_that_stays() {
    use nalgebra::{Point3, Vector3};
    let points = ["40,10,5", "140,10,7", "40,90,3.5"];
    // By default the first point: the new zero is where it was probed.
    let value = probe_json(&["--points", points[0], points[1], points[2]]);
    let call = value["cycle800"].as_str().expect("text").to_string();
    assert!(call.contains(",40,10,5,"), "{call}");
    // A point given: CYCLE800's _X0 _Y0 _Z0, and the new system's frame
    // T = Trans(centre) · R keeps it, with the face in the new XY plane.
    let value = probe_json(&[
        "--points",
        points[0],
        points[1],
        points[2],
        "--center",
        "90,50,5.25",
    ]);
    let call = value["cycle800"].as_str().expect("text").to_string();
    assert!(call.contains(",90,50,5.25,"), "{call}");
    assert!(value["height"].as_f64().expect("number").abs() < 1e-12);
    let angles = numbers(&value["angles"]);
    let rotation = sinuprep::rotation::matrix(
        "e:XYZ".parse().expect("valid"),
        [angles[0], angles[1], angles[2]],
    );
    let centre = Vector3::new(90.0, 50.0, 5.25);
    let normal = Vector3::from_vec(numbers(&value["normal"]));
    for local in [Point3::new(30.0, -20.0, 0.0), Point3::new(-5.0, 60.0, 0.0)] {
        // The frame CYCLE800 makes: turned, then shifted to the centre.
        let machine = Point3::from(centre + rotation * local.coords);
        assert!(normal.dot(&(machine - Point3::new(40.0, 10.0, 5.0))).abs() < 1e-12);
    }
    // A centre off the face: the face lies below the new zero.
    let value = probe_json(&[
        "--points", points[0], points[1], points[2], "--center", "40,10,15",
    ]);
    let height = value["height"].as_f64().expect("number");
    assert!((height - 10.0 * normal.z).abs() < 1e-12, "{height}");
}

#[test]
fn probe_refuses_points_that_give_no_face_naming_the_argument() {
    let cases: [&[&str]; 8] = [
        &["--normal", "1e300,0,1"],
        &[
            "--along-x",
            "0,0,0",
            "0,0,0.005",
            "--along-y",
            "0,0,0",
            "0,80,1",
        ],
        &[
            "--along-x",
            "0,0,0",
            "100,0,1",
            "--along-y",
            "0,10,0",
            "50,10,0.5",
        ],
        &[
            "--along-x",
            "0,0,0",
            "100,0,1",
            "--along-y",
            "0,0,0.5",
            "0,80,1.5",
        ],
        &[
            "--along-x",
            "0,0,0",
            "100,0,0",
            "--along-y",
            "0,0,0",
            "0,0,50",
        ],
        &["--points", "0,0,0", "100,0,1", "200,0,2"],
        &["--normal", "0,0,0"],
        &[
            "--along-x",
            "0,0,0",
            "1e,0,0",
            "--along-y",
            "0,0,0",
            "0,80,1",
        ],
    ];
    let mut all = String::new();
    for args in cases {
        let mut full = vec!["probe"];
        full.extend_from_slice(args);
        let output = run(&full, b"");
        assert_exit(&output, 2);
        assert!(output.stdout.is_empty());
        all.push_str(&format!(
            "$ {}\n{}\n",
            full.join(" "),
            String::from_utf8_lossy(&output.stderr)
        ));
    }
    insta::assert_snapshot!(all);
}

/// A point 1 mm from the plane normal to the axis, 800 mm out: both exact
/// roots (0.2° apart), said to be inseparable within the default tolerance,
/// and separable within a finer one.
#[test]
fn axis_of_a_turn_gives_close_roots_both_and_says_so() {
    let measured = [
        "axis",
        "--angle",
        "90",
        "--before",
        "799.9993749997559,0,1",
        "--after",
        "0,799.999374999756,1",
    ];
    let output = run(&measured, b"");
    assert_exit(&output, 0);
    let text = stdout(&output);
    assert!(text.contains("cannot tell apart"), "{text}");
    assert!(text.contains("  1  0 0 1   residual 0\n"), "{text}");
    assert_eq!(text.matches("residual 0\n").count(), 2, "{text}");
    let json = run(&[&measured[..], &["--json"]].concat(), b"");
    let value: serde_json::Value = serde_json::from_slice(&json.stdout).expect("json");
    assert_eq!(value["axes"].as_array().map(Vec::len), Some(2));
    assert_eq!(value["separable"], false);
    let fine = run(
        &[&measured[..], &["--json", "--tolerance", "0.0001"]].concat(),
        b"",
    );
    let value: serde_json::Value = serde_json::from_slice(&fine.stdout).expect("json");
    assert_eq!(value["separable"], true);
}

#[test]
fn axis_of_a_turn_gives_both_solutions() {
    let output = run(
        &[
            "axis", "--angle", "90", "--before", "100,0,50", "--after", "0,100,50",
        ],
        b"",
    );
    assert_exit(&output, 0);
    insta::assert_snapshot!(stdout(&output));
    let output = run(
        &[
            "axis",
            "--angle",
            "-90",
            "--before",
            "100,0,50",
            "--after",
            "0,-100,50",
            "--json",
            "--rotary",
            "2",
            "--record",
            "3",
        ],
        b"",
    );
    assert_exit(&output, 0);
    let value: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json");
    let axes = value["axes"].as_array().expect("axes");
    assert_eq!(axes.len(), 2);
    let first = numbers(&axes[0]);
    assert!(
        (first[2] - 1.0).abs() < 1e-12 && first[0].abs() < 1e-12,
        "{first:?}"
    );
    assert_eq!(
        value["tc_carr"][0],
        "$TC_CARR10[3]=0 $TC_CARR11[3]=0 $TC_CARR12[3]=1"
    );
    // A half turn: one axis, e and -e.
    let output = run(
        &[
            "axis", "--angle", "180", "--before", "100,0,50", "--after", "0,100,50",
        ],
        b"",
    );
    assert_exit(&output, 0);
    let text = stdout(&output);
    assert!(
        text.contains("one, either way round") && text.contains("  1  0.57735 0.57735 0.57735 "),
        "{text}"
    );
}

#[test]
fn axis_says_why_no_axis_fits() {
    let cases: [&[&str]; 6] = [
        &["--angle", "10", "--before", "100,0,0", "--after", "0,100,0"],
        &["--angle", "90", "--before", "100,0,0", "--after", "0,120,0"],
        &["--angle", "0", "--before", "100,0,0", "--after", "0,100,0"],
        &[
            "--angle", "180", "--before", "100,0,0", "--after", "-100,0,0",
        ],
        &["--positions", "0,0,0", "100,0,0", "200,0,0.001"],
        &[
            "--angle",
            "45",
            "--positions",
            "0,0,0",
            "100,0,0",
            "200,0,10",
        ],
    ];
    let mut all = String::new();
    for args in cases {
        let mut full = vec!["axis"];
        full.extend_from_slice(args);
        let output = run(&full, b"");
        assert_exit(&output, 2);
        all.push_str(&format!(
            "$ {}\n{}\n",
            full.join(" "),
            String::from_utf8_lossy(&output.stderr)
        ));
    }
    insta::assert_snapshot!(all);
}

#[test]
fn axis_from_measured_positions_gives_the_axis_and_a_point_on_it() {
    use nalgebra::{Point3, Vector3};
    // A C axis tilted 0.01 rad towards Y, through 5,-3,0; a sphere at
    // 150,0,40 measured at 0°, 45° and 90°.
    let axis = Vector3::new(0.0, 0.01, 1.0).normalize();
    let through = Point3::new(5.0, -3.0, 0.0);
    let sphere = Point3::new(150.0, 0.0, 40.0);
    let at = |degrees: f64| {
        through + sinuprep::rotation::frame::from_axis_angle(axis, degrees) * (sphere - through)
    };
    let [p1, p2, p3] = [0.0, 45.0, 90.0].map(|d| xyz(at(d)));
    let output = run(&["axis", "--json", "--positions", &p1, &p2, &p3], b"");
    assert_exit(&output, 0);
    let value: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json");
    let found = Vector3::from_vec(numbers(&value["axes"][0]));
    assert!((found - axis).norm() < 1e-12, "{found}");
    let point = Point3::from(Vector3::from_vec(numbers(&value["point"])));
    let off = (point - through) - axis * axis.dot(&(point - through));
    assert!(off.norm() < 1e-9, "{point}");
    let turns = numbers(&value["turns"]);
    assert!((turns[0] - 45.0).abs() < 1e-9 && (turns[1] - 45.0).abs() < 1e-9);
    // Two positions, the angle and the nominal direction: the point on the axis.
    let output = run(
        &[
            "axis",
            "--angle",
            "45",
            "--direction",
            "0,0,1",
            "--positions",
            &p1,
            &p2,
        ],
        b"",
    );
    assert_exit(&output, 0);
    insta::assert_snapshot!(stdout(&output));
}

// ---- every form, in and out; another control's words ---------------------

/// The post-processor seed's example: its nine ROT_MAT and three
/// TRANS_MAT assignments in its own statement form (`ROT_MAT1=1;`), and read
/// back to the same angles.
#[test]
fn convert_writes_and_reads_the_post_processors_rot_mat() {
    let output = run(
        &["convert", "30", "0", "0", "--from", "e:XYZ", "--to", "gpp"],
        b"",
    );
    assert_exit(&output, 0);
    insta::assert_snapshot!(stdout(&output));
    let back = run(
        &["convert", "--from", "gpp", "--to", "e:XYZ", "--json"],
        &output.stdout,
    );
    assert_exit(&back, 0);
    let value: serde_json::Value = serde_json::from_slice(&back.stdout).expect("JSON");
    let angles: Vec<f64> = value["angles"]
        .as_array()
        .expect("angles")
        .iter()
        .map(|a| a.as_f64().expect("number"))
        .collect();
    // Twelve decimals in the text: the angles come back to 1e-10.
    assert!((angles[0] - 30.0).abs() < 1e-10 && angles[1].abs() < 1e-10 && angles[2].abs() < 1e-10);
    // The seed's unit matrix is the identity.
    let unit = b"ROT_MAT1=1;\nROT_MAT2=0;\nROT_MAT3=0;\nROT_MAT4=0;\nROT_MAT5=1;\nROT_MAT6=0;\nROT_MAT7=0;\nROT_MAT8=0;\nROT_MAT9=1;\nTRANS_MATX=0;\nTRANS_MATY=0;\nTRANS_MATZ=0;\n";
    let identity = run(&["convert", "--from", "gpp", "--to", "quaternion"], unit);
    assert_exit(&identity, 0);
    assert_eq!(stdout(&identity), "1 0 0 0\n");
}

/// One rotation, the paper's example 2 (extrinsic X, Y, Z 30, 45, 60), in
/// every form but the sequences, each read back to the paper's angles.
#[test]
#[allow(clippy::approx_constant)] // the paper's matrix, printed to 4 decimals
fn convert_gives_the_papers_rotation_in_every_form_and_reads_each_back() {
    let mut shown = String::new();
    for form in [
        "matrix",
        "quaternion",
        "axis-angle",
        "gibbs",
        "sinumerik",
        "gpp",
        "chain",
    ] {
        let output = run(
            &["convert", "30", "45", "60", "--from", "e:XYZ", "--to", form],
            b"",
        );
        assert_exit(&output, 0);
        shown.push_str(&format!("--to {form}\n{}\n", stdout(&output)));
        // Statements an argument a block, numbers an argument each.
        let text = stdout(&output);
        let values: Vec<String> = if matches!(form, "sinumerik" | "gpp") {
            text.lines().map(str::to_string).collect()
        } else {
            text.split_whitespace().map(str::to_string).collect()
        };
        let mut args = vec!["convert"];
        args.extend(values.iter().map(String::as_str));
        args.extend(["--from", form, "--to", "e:XYZ", "--json"]);
        let back = run(&args, b"");
        assert_exit(&back, 0);
        let value: serde_json::Value = serde_json::from_slice(&back.stdout).expect("JSON");
        for (angle, expected) in value["angles"]
            .as_array()
            .expect("angles")
            .iter()
            .zip([30.0, 45.0, 60.0])
        {
            // The text holds 12 decimals: the angles come back to 1e-10.
            let angle = angle.as_f64().expect("number");
            assert!(
                (angle - expected).abs() < 1e-10,
                "{form}: {angle} != {expected}"
            );
        }
    }
    insta::assert_snapshot!(shown);
    // The matrix is the paper's (eq. 20), printed there to 4 decimals.
    let matrix = run(
        &[
            "convert", "30", "45", "60", "--from", "e:XYZ", "--to", "matrix", "--json",
        ],
        b"",
    );
    let value: serde_json::Value = serde_json::from_slice(&matrix.stdout).expect("JSON");
    let paper = [
        [0.3536, -0.5732, 0.7392],
        [0.6124, 0.7392, 0.2803],
        [-0.7071, 0.3536, 0.6124],
    ];
    for (r, row) in paper.iter().enumerate() {
        for (c, expected) in row.iter().enumerate() {
            let found = value["matrix"][r][c].as_f64().expect("number");
            assert!((found - expected).abs() < 5e-5, "({r}, {c}): {found}");
        }
    }
}

/// Frame statements evaluated as the control composes them: TRANS, then
/// AROT blocks about the turned axes, as the frames form of a rewrite emits
/// them; ROT in one block is RPY; the JSON gives the 4x4 matrix.
#[test]
fn frame_converts_sinumerik_statements_into_every_form() {
    let statements = ["TRANS X10 Y20 Z30", "AROT X=30", "AROT Y=45", "AROT Z=60"];
    let mut shown = String::new();
    for form in ["i:XYZ", "matrix", "quaternion", "sinumerik", "gpp"] {
        let mut args = vec!["frame"];
        args.extend(statements);
        args.extend(["--from", "sinumerik", "--to", form]);
        let output = run(&args, b"");
        assert_exit(&output, 0);
        shown.push_str(&format!("--to {form}\n{}\n", stdout(&output)));
    }
    insta::assert_snapshot!(shown);
    // AROT blocks about the turned axes = CYCLE800's axis-by-axis intrinsic X, Y', Z''.
    let angles = run(
        &[
            "frame",
            "10",
            "20",
            "30",
            "30",
            "45",
            "60",
            "--from",
            "i:XYZ",
            "--to",
            "sinumerik",
        ],
        b"",
    );
    let back = run(
        &["frame", "--from", "sinumerik", "--to", "i:XYZ"],
        &angles.stdout,
    );
    assert_exit(&back, 0);
    let numbers: Vec<f64> = stdout(&back)
        .split_whitespace()
        .map(|n| n.parse().expect("number"))
        .collect();
    for (found, expected) in numbers.iter().zip([10.0, 20.0, 30.0, 30.0, 45.0, 60.0]) {
        assert!((found - expected).abs() < 1e-12, "{numbers:?}");
    }
}

/// T_SP = T_PO^-1 · T_SO (seed 004): the tool 100 along X and 500 up, turned
/// 30° about Z; the piece 20, 30 along X, Y, turned -15°: the tool is turned
/// 45° from the piece, at the piece's coordinates of the tool's origin.
#[test]
fn frame_gives_the_tool_to_piece_chain_in_the_seeds_order() {
    let output = run(
        &[
            "frame",
            "--from",
            "sinumerik",
            "--tool",
            "TRANS X100 Z500",
            "--tool",
            "AROT Z=30",
            "--piece",
            "TRANS X20 Y30",
            "--piece",
            "AROT Z=-15",
            "--to",
            "chain",
            "--json",
        ],
        b"",
    );
    assert_exit(&output, 0);
    let value: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
    assert_eq!(value["sequence"], "intrinsic:ZXY");
    assert!((value["alpha_z"].as_f64().expect("alpha") - 45.0).abs() < 1e-12);
    let (s, c) = 15f64.to_radians().sin_cos();
    let expected = [80.0 * c + 30.0 * s, 80.0 * s - 30.0 * c, 500.0];
    for (i, e) in expected.iter().enumerate() {
        let found = value["translation"][i].as_f64().expect("number");
        assert!((found - e).abs() < 1e-12, "{found} != {e}");
    }
    insta::assert_snapshot!(stdout(&output));
}

#[test]
fn convert_and_frame_refuse_what_is_no_rotation_with_exit_2() {
    // A 4x4 matrix is a rotation when it has no translation.
    let four = "0 -1 0 0 1 0 0 0 0 0 1 0 0 0 0 1";
    let turned = run(&["convert", four, "--from", "matrix", "--to", "e:XYZ"], b"");
    assert_exit(&turned, 0);
    assert!(stdout(&turned).contains("    0.000000     0.000000    90.000000"));
    let shifted = "0 -1 0 5 1 0 0 0 0 0 1 0 0 0 0 1";
    let refused = run(
        &["convert", shifted, "--from", "matrix", "--to", "e:XYZ"],
        b"",
    );
    assert_exit(&refused, 2);
    assert!(flat(&refused.stderr).contains("translation X5 Y0 Z0"));
    for (args, stdin, message) in [
        (
            vec![
                "convert", "1", "0", "0", "0", "1", "0", "0", "0", "2", "--from", "matrix", "--to",
                "i:XYZ",
            ],
            "",
            "not orthonormal",
        ),
        (
            vec![
                "convert", "1", "0", "0", "0", "1", "0", "0", "0", "-1", "--from", "matrix",
                "--to", "i:XYZ",
            ],
            "",
            "mirror",
        ),
        (
            vec![
                "convert",
                "0",
                "0",
                "0",
                "0",
                "--from",
                "quaternion",
                "--to",
                "i:XYZ",
            ],
            "",
            "length 0",
        ),
        (
            vec![
                "convert",
                "1",
                "0",
                "0",
                "180",
                "--from",
                "axis-angle",
                "--to",
                "gibbs",
            ],
            "",
            "half turn",
        ),
        (
            vec![
                "convert",
                "TRANS X5",
                "--from",
                "sinumerik",
                "--to",
                "i:XYZ",
            ],
            "",
            "sinuprep frame",
        ),
        (
            vec![
                "convert",
                "SCALE X2",
                "--from",
                "sinumerik",
                "--to",
                "i:XYZ",
            ],
            "",
            "scales",
        ),
        (
            vec!["convert", "--from", "gpp", "--to", "i:XYZ"],
            "ROT_MAT1=1;\n",
            "ROT_MAT2 is not given",
        ),
        (
            vec!["convert", "--from", "quaternion", "--to", "i:XYZ"],
            "1 0 0 0\n1 2\n",
            "stdin:2: 2 numbers where 4",
        ),
        (
            vec!["convert", "1", "2", "--from", "e:XYZ", "--to", "matrix"],
            "",
            "2 numbers where three angles",
        ),
        (
            vec![
                "convert", "1", "2", "3", "--from", "euler", "--to", "matrix",
            ],
            "",
            "is no form",
        ),
        (
            vec!["frame", "1", "2", "3", "--from", "e:XYZ", "--to", "matrix"],
            "",
            "3 numbers where 6",
        ),
        (
            vec![
                "frame",
                "--from",
                "sinumerik",
                "--tool",
                "AROT X=R1",
                "--piece",
                "TRANS",
                "--to",
                "matrix",
            ],
            "",
            "--tool number 1: line 1",
        ),
    ] {
        let output = run(&args, stdin.as_bytes());
        assert_exit(&output, 2);
        assert!(output.stdout.is_empty(), "{args:?}: partial output");
        let stderr = flat(&output.stderr);
        assert!(stderr.contains(message), "{args:?}: {stderr}");
    }
}

/// The A3200 application note's machine as a swivel data record: the part
/// on the A table (about z), 15 mm above its top and 10 mm off its centre in
/// X; A on the B trunnion (about y), whose axis lies 12 mm above A's point.
const A3200_MACHINE: &str =
    "$TC_CARR23[1]=\"P\" $TC_CARR34[1]=\"A3200_SEED\" $TC_CARR35[1]=\"B\" $TC_CARR36[1]=\"A\"
$TC_CARR7[1]=0 $TC_CARR8[1]=1 $TC_CARR9[1]=0
$TC_CARR10[1]=0 $TC_CARR11[1]=0 $TC_CARR12[1]=1
$TC_CARR4[1]=10 $TC_CARR5[1]=0 $TC_CARR6[1]=-3
$TC_CARR15[1]=0 $TC_CARR16[1]=0 $TC_CARR17[1]=-12
$TC_CARR18[1]=-10 $TC_CARR19[1]=0 $TC_CARR20[1]=15
";

/// The seed's example setup (`10, 0, -15` and `12, 0, 0`) comes out of the
/// machine it describes; read back, it gives the same record.
#[test]
fn axes_exports_the_a3200_setup_of_the_seeds_machine_and_reads_it_back() {
    let dir = scratch("a3200");
    let machine = dir.join("A3200.SPF");
    std::fs::write(&machine, A3200_MACHINE).expect("machine");
    let machine = machine.to_str().expect("utf-8");
    let output = run(
        &[
            "axes",
            "--machine",
            machine,
            "--record",
            "A3200_SEED",
            "--export",
            "a3200",
        ],
        b"",
    );
    assert_exit(&output, 0);
    assert_eq!(
        stdout(&output),
        "ROTATION 1 InputAxes x y z OutputAxes X Y Z\n\
         ROTATION 1 ANGLE A 1, 0\n\
         ROTATION 1 Displacement 10, 0, -15\n\
         ROTATION 2 InputAxes z x y OutputAxes Z X Y\n\
         ROTATION 2 ANGLE B 1, 0\n\
         ROTATION 2 Displacement 12, 0, 0\n"
    );
    let setup = dir.join("SETUP.PGM");
    std::fs::write(&setup, &output.stdout).expect("setup");
    let record = run(
        &[
            "axes",
            "--from-a3200",
            setup.to_str().expect("utf-8"),
            "--record",
            "A3200_SEED",
        ],
        b"",
    );
    assert_exit(&record, 0);
    insta::assert_snapshot!(stdout(&record));
    let back = dir.join("BACK.SPF");
    std::fs::write(&back, &record.stdout).expect("record");
    let again = run(
        &[
            "axes",
            "--machine",
            back.to_str().expect("utf-8"),
            "--export",
            "a3200",
        ],
        b"",
    );
    assert_exit(&again, 0);
    assert_eq!(again.stdout, output.stdout);
    // Both swivel the same way: the same axis positions and zero-point shift.
    let swivel = |file: &str| {
        let output = run(
            &[
                "axes",
                "--machine",
                file,
                "--mode",
                "57",
                "20",
                "-35",
                "0",
                "--json",
            ],
            b"",
        );
        assert_exit(&output, 0);
        let value: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
        (value["solutions"].clone(), value["shift"].clone())
    };
    assert_eq!(swivel(machine), swivel(back.to_str().expect("utf-8")));
}

#[test]
fn axes_refuses_an_a3200_export_it_cannot_write() {
    let sample = support::repo().join("samples/MACHINE.SPF");
    let sample = sample.to_str().expect("utf-8");
    for (record, message) in [
        ("HEAD_CA", "swivel head (T)"),
        ("NUTATING_M", "mixed kinematics"),
    ] {
        let output = run(
            &[
                "axes",
                "--machine",
                sample,
                "--record",
                record,
                "--export",
                "a3200",
            ],
            b"",
        );
        assert_exit(&output, 2);
        assert!(flat(&output.stderr).contains(message), "{record}");
    }
    let dir = scratch("a3200-bad");
    let setup = dir.join("BAD.PGM");
    std::fs::write(&setup, "ROTATION 1 InputAxes x z y OutputAxes X Z Y\n").expect("setup");
    let output = run(
        &["axes", "--from-a3200", setup.to_str().expect("utf-8")],
        b"",
    );
    assert_exit(&output, 2);
    assert!(flat(&output.stderr).contains("right-handed"));
    // The record read from a setup is written only as a machine file reads
    // it back: an axis name an NC string cannot carry (`"` ended it), a
    // displacement no machine has, a record name beyond $TC_CARR34's.
    let table = "ROTATION 1 InputAxes x y z OutputAxes X Y Z\n";
    for (text, record, why) in [
        (
            format!("{table}ROTATION 1 ANGLE C\"Q 1, 0\nROTATION 1 Displacement 0, 0, 0\n"),
            None,
            "the ANGLE's axis `C\"Q`: an axis is named with letters",
        ),
        (
            format!("{table}ROTATION 1 ANGLE C 1, 0\nROTATION 1 Displacement 1e300, 0, 0\n"),
            None,
            "beyond ±1e9",
        ),
        (
            format!("{table}ROTATION 1 ANGLE C 1, 0\nROTATION 1 Displacement 0, 0, 0\n"),
            Some("TABLE\"1"),
            "cannot stand in an NC string",
        ),
        (
            format!("{table}ROTATION 1 ANGLE C 1, 0\nROTATION 1 Displacement 0, 0, 0\n"),
            Some(&*"T".repeat(33)),
            "1 to 32 characters",
        ),
    ] {
        std::fs::write(&setup, &text).expect("setup");
        let mut args = vec!["axes", "--from-a3200", setup.to_str().expect("utf-8")];
        args.extend(record.iter().flat_map(|name| ["--record", name]));
        let output = run(&args, b"");
        assert_exit(&output, 2);
        assert!(output.stdout.is_empty(), "{text}");
        assert!(
            flat(&output.stderr).contains(why),
            "{text}: {}",
            flat(&output.stderr)
        );
    }
}

/// Numbers at the ends of the doubles, in every numeric form of `convert`
/// and `frame`: an answer or a refusal, never a crash.
#[test]
fn convert_and_frame_take_extreme_numbers_without_a_crash() {
    let forms = [
        ("e:XYZ", 3, 6),
        ("i:ZXZ", 3, 6),
        ("matrix", 9, 16),
        ("quaternion", 4, 7),
        ("axis-angle", 4, 7),
        ("gibbs", 3, 6),
        ("chain", 3, 6),
    ];
    for (form, rotation, frame) in forms {
        for value in ["1e308", "-1e308", "5e-324", "0", "1e200"] {
            for (command, count) in [("convert", rotation), ("frame", frame)] {
                for to in ["i:XYZ", "gibbs", "gpp", "sinumerik", "axis-angle"] {
                    let mut args = vec![command, "--from", form, "--to", to, "--"];
                    args.extend(std::iter::repeat_n(value, count));
                    let output = run(&args, b"");
                    let code = output.status.code();
                    assert!(code == Some(0) || code == Some(2), "{args:?}: {code:?}");
                }
            }
        }
    }
    for statements in [
        "AROT X=1EX300",
        "TRANS X=1E300*1E300",
        "ROTS X90 Y90",
        "AROT Z=1e300",
    ] {
        let output = run(
            &["frame", "--from", "sinumerik", "--to", "gpp", statements],
            b"",
        );
        let code = output.status.code();
        assert!(code == Some(0) || code == Some(2), "{statements}: {code:?}");
    }
}

/// Without values, a numeric form is read from stdin one rotation a line
/// (comments and empty lines skipped), each printed in turn.
#[test]
fn convert_reads_one_rotation_a_line_in_any_numeric_form() {
    let input = b"1 0 0 0 # the identity\n\n0, 0, 0.7071067811865476, 0.7071067811865476\n";
    let output = run(
        &["convert", "--from", "quaternion", "--to", "axis-angle"],
        input,
    );
    assert_exit(&output, 0);
    let lines: Vec<Vec<f64>> = stdout(&output)
        .lines()
        .map(|l| l.split(' ').map(|n| n.parse().expect("number")).collect())
        .collect();
    assert_eq!(lines.len(), 2);
    assert_eq!(lines[0], [0.0, 0.0, 1.0, 0.0]);
    // w = 0: a half turn about (0, 1, 1)/√2.
    let [x, y, z, angle] = lines[1][..] else {
        panic!("four numbers")
    };
    assert!(x.abs() < 1e-15 && (y - z).abs() < 1e-15 && (angle - 180.0).abs() < 1e-12);
}

/// The frame statements a rewrite emits (`--emit frames`: TRANS, three AROT
/// blocks, ATRANS) read back, composed as the control composes them, as the
/// rotation of the CYCLE600 call they replace: the paper's extrinsic X, Y, Z
/// 30, 45, 60, whether written as intrinsic or as extrinsic Z, X, Y.
#[test]
fn frame_statements_a_rewrite_emits_read_back_as_the_calls_rotation() {
    let rewritten = run(
        &[
            "rewrite",
            "--emit",
            "frames",
            "--precision",
            "15",
            "tests/fixtures/rewrite/paper_swivel_frames.mpf",
        ],
        b"",
    );
    assert_exit(&rewritten, 0);
    let text = stdout(&rewritten);
    let lines: Vec<&str> = text.lines().collect();
    let mut calls = 0;
    for (i, line) in lines.iter().enumerate() {
        if !line.starts_with("; sinuprep: CYCLE600") {
            continue;
        }
        calls += 1;
        let blocks: Vec<&str> = lines[i + 1..i + 6].to_vec();
        assert!(
            blocks[0].contains("TRANS") && blocks[4].starts_with("ATRANS"),
            "{blocks:?}"
        );
        let mut args = vec!["convert"];
        args.extend(&blocks);
        args.extend(["--from", "sinumerik", "--to", "e:XYZ", "--json"]);
        let output = run(&args, b"");
        assert_exit(&output, 0);
        let value: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
        for (angle, expected) in value["angles"]
            .as_array()
            .expect("angles")
            .iter()
            .zip([30.0, 45.0, 60.0])
        {
            let angle = angle.as_f64().expect("number");
            // 15 decimals move an angle by at most 5e-16 degrees.
            assert!((angle - expected).abs() < 1e-12, "{blocks:?}: {angle}");
        }
    }
    assert_eq!(calls, 2);
}

#[test]
fn fmt_writes_in_place_lists_with_check_and_reads_stdin() {
    let dir = scratch("fmt-cli");
    let messy = b"n10 if r1==1\r\ng1   x10  \r\n\r\n\r\n\r\nendif\r\nm30\r\n";
    let tidy = b"N10 IF R1==1\r\n  G1 X10\r\n\r\nENDIF\r\nM30\r\n";
    let part = dir.join("PART.MPF");
    let nested = dir.join("sub");
    std::fs::create_dir_all(&nested).expect("folder");
    let other = nested.join("OTHER.SPF");
    std::fs::write(&part, messy).expect("write");
    std::fs::write(&other, tidy).expect("write");
    let dir_arg = dir.to_str().expect("utf-8");
    // --check lists the files that would change, writes nothing, exit 1.
    let check = run(&["fmt", "--check", dir_arg], b"");
    assert_exit(&check, 1);
    assert!(stdout(&check).contains("PART.MPF"), "{}", stdout(&check));
    assert!(!stdout(&check).contains("OTHER.SPF"), "{}", stdout(&check));
    assert_eq!(std::fs::read(&part).expect("read"), messy);
    // --diff shows it, writes nothing.
    let diff = run(&["fmt", "--diff", part.to_str().expect("utf-8")], b"");
    assert_exit(&diff, 0);
    assert!(stdout(&diff).contains("+  G1 X10"), "{}", stdout(&diff));
    assert_eq!(std::fs::read(&part).expect("read"), messy);
    // stdin to stdout, CRLF kept.
    let piped = run(&["fmt", "-"], messy);
    assert_exit(&piped, 0);
    assert_eq!(piped.stdout, tidy);
    // In place over a folder; a second run finds nothing to do.
    assert_exit(&run(&["fmt", dir_arg], b""), 0);
    assert_eq!(std::fs::read(&part).expect("read"), tidy);
    assert_eq!(std::fs::read(&other).expect("read"), tidy);
    assert_exit(&run(&["fmt", "--check", dir_arg], b""), 0);
    // No backup, no temporary file left beside it.
    let names: Vec<_> = std::fs::read_dir(&dir)
        .expect("list")
        .map(|e| e.expect("entry").file_name())
        .collect();
    assert_eq!(names.len(), 2, "{names:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn fmt_leaves_a_program_with_syntax_errors_and_says_why() {
    let dir = scratch("fmt-errors");
    let path = dir.join("BROKEN.MPF");
    let source = b"  g1 x10\nIF R1==\n  m30\n";
    std::fs::write(&path, source).expect("write");
    let output = run(&["fmt", path.to_str().expect("utf-8")], b"");
    assert_exit(&output, 1);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("not formatted"), "{stderr}");
    assert_eq!(std::fs::read(&path).expect("read"), source);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn fmt_reads_its_settings_and_renumbers() {
    let dir = scratch("fmt-settings");
    std::fs::write(
        dir.join("sinuprep.toml"),
        "[format]\nindent = 4\ncase = \"lower\"\nmax-blank-lines = 0\n",
    )
    .expect("write");
    let path = dir.join("P.MPF");
    std::fs::write(
        &path,
        "N5 IF R1==1 GOTOF N30\nWHILE R1<2\nG1 X1\n\nENDWHILE\nN30 M30\n",
    )
    .expect("write");
    let path_arg = path.to_str().expect("utf-8");
    let output = run(&["fmt", "--renumber", "100,100", path_arg], b"");
    assert_exit(&output, 0);
    assert_eq!(
        std::fs::read_to_string(&path).expect("read"),
        "n100 if r1==1 gotof n200\nwhile r1<2\n    g1 x1\nendwhile\nn200 m30\n"
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("2 block numbers changed"), "{stderr}");
    // A value the settings cannot take is the tool's error.
    std::fs::write(dir.join("sinuprep.toml"), "[format]\nindent = 40\n").expect("write");
    assert_exit(&run(&["fmt", path_arg], b""), 2);
    assert_exit(&run(&["fmt", "--renumber", "10,0", path_arg], b""), 2);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Every numeric option is bounded with a clear error (exit 2), never a
/// panic: decimals from 0 to 15, angles within ±1e9 degrees.
#[test]
fn numeric_options_out_of_range_are_refused_with_the_reason() {
    let split = [
        "axes",
        "--machine",
        "samples/MACHINE.SPF",
        "--record",
        "HEAD_H",
        "--table",
        "TABLE_B",
    ];
    let fixed = [&split[..], &["--fix", "B=1e300", "30", "45", "60"]].concat();
    let from = [
        &split[..],
        &["--prefer", "nearest", "--from", "B=1e300", "30", "45", "60"],
    ]
    .concat();
    let cases: [(&[&str], &str); 11] = [
        (&fixed, "`--fix B=1e300`: 1e300 degrees is beyond ±1e9"),
        (&from, "`--from B=1e300`: 1e300 degrees is beyond ±1e9"),
        (
            &["probe", "--normal", "0,0,1", "--tolerance", "1e300"],
            "at most 1e9",
        ),
        (
            &[
                "axis",
                "--angle",
                "90",
                "--before",
                "1,0,0",
                "--after",
                "0,1,0",
                "--tolerance",
                "1e300",
            ],
            "at most 1e9",
        ),
        (
            &["probe", "--precision", "65536", "--normal", "0,0,1"],
            "from 0 to 15",
        ),
        (
            &[
                "axis",
                "--precision",
                "65536",
                "--angle",
                "90",
                "--before",
                "1,0,0",
                "--after",
                "0,1,0",
            ],
            "from 0 to 15",
        ),
        (
            &[
                "convert", "1e308", "1e308", "1e308", "--from", "e:XYZ", "--to", "i:ZYX",
            ],
            "beyond ±1e9",
        ),
        (
            &[
                "convert",
                "0",
                "0",
                "1",
                "1e10",
                "--from",
                "axis-angle",
                "--to",
                "i:ZYX",
            ],
            "beyond ±1e9",
        ),
        (
            &[
                "convert", "1e300", "0", "0", "--from", "e:XYZ", "--to", "matrix",
            ],
            "beyond ±1e9",
        ),
        (
            &[
                "axis", "--angle", "1e12", "--before", "1,0,0", "--after", "0,1,0",
            ],
            "beyond ±1e9",
        ),
        (
            &[
                "axes",
                "--machine",
                "samples/MACHINE.SPF",
                "--record",
                "TABLE_AC",
                "--mode",
                "57",
                "1e12",
                "0",
                "0",
            ],
            "beyond ±1e9",
        ),
    ];
    for (args, why) in cases {
        let output = run(args, b"");
        assert_exit(&output, 2);
        let stderr = flat(&output.stderr);
        assert!(stderr.contains(why), "{args:?}: {stderr}");
        assert!(output.stdout.is_empty(), "{args:?}");
    }
    let output = run(
        &["convert", "--from", "e:XYZ", "--to", "i:ZYX"],
        b"1e308 0 0\n",
    );
    assert_exit(&output, 2);
    assert!(String::from_utf8_lossy(&output.stderr).contains("beyond ±1e9"));
    // At the bound an angle is taken.
    let output = run(
        &[
            "convert", "1e9", "0", "0", "--from", "e:XYZ", "--to", "i:ZYX",
        ],
        b"",
    );
    assert_exit(&output, 0);
}

/// The counts an emitted text is built from are bounded where they are
/// given, on the command line and in sinuprep.toml, with the reason: an R
/// parameter's number for the run-time code (past the end of `u32` it
/// panicked), a record's number (`$TC_CARR7[0]` is no record a machine
/// file reads), the decimals and a tolerance of the settings file.
#[test]
fn counts_of_emitted_text_are_bounded_on_the_command_line_and_in_settings() {
    let runtime = "tests/fixtures/rewrite/runtime_r_parameters.mpf";
    for (args, why) in [
        (
            &[
                "rewrite",
                "--emit-runtime",
                "--runtime-r",
                "4294967290",
                runtime,
            ][..],
            "0..=99999",
        ),
        (
            &[
                "axis", "--angle", "90", "--before", "1,0,0", "--after", "0,1,0", "--record", "0",
            ],
            "1..=999999",
        ),
    ] {
        let output = run(args, b"");
        assert_exit(&output, 2);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(stderr.contains(why), "{args:?}: {stderr}");
        assert!(output.stdout.is_empty(), "{args:?}");
    }
    // At the bounds the text is written, and a machine file reads it back.
    let output = run(
        &["rewrite", "--emit-runtime", "--runtime-r", "99999", runtime],
        b"",
    );
    assert_exit(&output, 0);
    assert!(stdout(&output).contains("R99999="), "{}", stdout(&output));
    let output = run(
        &[
            "axis", "--angle", "90", "--before", "1,0,0", "--after", "0,1,0", "--record", "999999",
        ],
        b"",
    );
    assert_exit(&output, 0);
    assert!(
        stdout(&output).contains("$TC_CARR9[999999]=1"),
        "{}",
        stdout(&output)
    );

    let dir = scratch("bounded-settings");
    let program = dir.join("P.MPF");
    std::fs::copy(runtime, &program).expect("copy");
    let name = program.to_str().expect("utf-8");
    for (settings, why) in [
        (
            "precision = 200\n",
            "precision 200 is no count of decimals from 0 to 15",
        ),
        (
            "emit-runtime = true\nruntime-r = 4294967295\n",
            "runtime-r 4294967295 is no R parameter's number from 0 to 99999",
        ),
        (
            "hirth-tolerance = nan\n",
            "hirth-tolerance NaN is no angle from 0 to 180 degrees",
        ),
        ("hirth-tolerance = -1\n", "hirth-tolerance -1 is no angle"),
    ] {
        std::fs::write(dir.join("sinuprep.toml"), settings).expect("settings");
        let output = run(&["rewrite", name], b"");
        assert_exit(&output, 2);
        // The report wraps at its width, also after a hyphen
        // ("hirth-\ntolerance") and at the folder's length: compare the
        // words without any blank.
        let squeezed = |text: &str| text.split_whitespace().collect::<String>();
        let stderr = squeezed(&flat(&output.stderr));
        assert!(stderr.contains(&squeezed(why)), "{settings}: {stderr}");
        assert!(stderr.contains("sinuprep.toml:"), "{settings}: {stderr}");
        assert!(output.stdout.is_empty(), "{settings}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `convert` and `frame` print as many decimals as the conversion holds
/// exactly (`45`, not `44.99999999999999`), or as many as asked; a link
/// of a chain may start with a minus sign.
#[test]
fn convert_and_frame_print_exact_digits() {
    for (command, stdin, expected) in [
        ("convert --from e:XYZ --to e:ZYX", "0 45 0\n", "0 45 0\n"),
        (
            "frame 1 2 3 30 45 60 --from e:XYZ --to sinumerik",
            "",
            "TRANS X=1 Y=2 Z=3\nAROT X=30 Y=45 Z=60\n",
        ),
        (
            "convert 30 45 60 --from e:XYZ --to quaternion --precision 3",
            "",
            "0.822 0.022 0.44 0.36\n",
        ),
        (
            "frame --from e:XYZ --to e:XYZ --tool -1,0,0,0,0,0 --piece 0,0,0,0,0,0",
            "",
            "-1 0 0 0 0 0\n",
        ),
    ] {
        let args: Vec<&str> = command.split(' ').collect();
        let output = run(&args, stdin.as_bytes());
        assert_exit(&output, 0);
        assert_eq!(stdout(&output), expected, "{command}");
    }
}

/// `probe` writes calls that `check` passes, or none: no call without a
/// head, a head that an NC string cannot carry refused.
#[test]
fn probe_writes_only_calls_check_passes() {
    let output = run(&["probe", "--normal", "0.1,0,1"], b"");
    assert_exit(&output, 0);
    let text = stdout(&output);
    assert!(
        !text.contains("CYCLE600(") && !text.contains("CYCLE800("),
        "{text}"
    );
    assert!(text.contains("give --head NAME"), "{text}");
    let value = probe_json(&["--normal", "0.1,0,1", "--head", "HEAD_CA"]);
    let program = format!(
        "N10 {}\nN20 {}\nN30 M30\n",
        value["cycle600"].as_str().expect("text"),
        value["cycle800"].as_str().expect("text")
    );
    let check = run(
        &[
            "check",
            "--format",
            "short",
            "--machine",
            "samples/MACHINE.SPF",
            "--select",
            "S,C6,K",
            "-",
        ],
        program.as_bytes(),
    );
    assert!(!stdout(&check).contains("error"), "{}", stdout(&check));
    for head in ["A\"B", "A\nB", "", &"H".repeat(33)] {
        let output = run(&["probe", "--normal", "0.1,0,1", "--head", head], b"");
        assert_exit(&output, 2);
        assert!(output.stdout.is_empty(), "{head:?}");
    }
}

/// `axes --export a3200` writes a setup only for a record that makes one:
/// parallel axes, or a name an ANGLE cannot carry, are refused (exit 2)
/// with nothing on stdout.
#[test]
fn a3200_export_writes_nothing_for_a_record_that_makes_no_setup() {
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("A3200_BAD.SPF");
    std::fs::write(
        &path,
        "$TC_CARR23[1]=\"P\" $TC_CARR34[1]=\"PAR\" $TC_CARR35[1]=\"A\" $TC_CARR36[1]=\"C\"\n\
         $TC_CARR7[1]=-1 $TC_CARR8[1]=0 $TC_CARR9[1]=0\n\
         $TC_CARR10[1]=-1 $TC_CARR11[1]=0 $TC_CARR12[1]=0\n\
         $TC_CARR23[2]=\"P\" $TC_CARR34[2]=\"NAMED\" $TC_CARR35[2]=\"A X\" $TC_CARR36[2]=\"C\"\n\
         $TC_CARR7[2]=-1 $TC_CARR8[2]=0 $TC_CARR9[2]=0\n\
         $TC_CARR10[2]=0 $TC_CARR11[2]=0 $TC_CARR12[2]=-1\nM17\n",
    )
    .expect("machine file");
    let machine = path.to_str().expect("UTF-8 path");
    for (record, why) in [("PAR", "parallel"), ("NAMED", "letters, digits")] {
        let output = run(
            &[
                "axes",
                "--machine",
                machine,
                "--record",
                record,
                "--export",
                "a3200",
            ],
            b"",
        );
        assert_exit(&output, 2);
        assert!(output.stdout.is_empty(), "{record}: {}", stdout(&output));
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(stderr.contains(why), "{record}: {stderr}");
    }
}

/// `axes --table --prefer nearest` without `--dir` takes the head solution
/// that travels least of both, and says which `_DIR` selects it; `--dir`
/// fixes it.
#[test]
fn the_nearest_split_chooses_dir_unless_given() {
    let ask = |dir: &[&str]| {
        let output = run(
            &[
                &[
                    "axes",
                    "--machine",
                    "samples/MACHINE.SPF",
                    "--record",
                    "HEAD_H",
                    "--table",
                    "TABLE_B",
                    "--prefer",
                    "nearest",
                    "--mode",
                    "57",
                    "--json",
                ][..],
                dir,
                &["--", "30", "45", "60"],
            ]
            .concat(),
            b"",
        );
        assert_exit(&output, 0);
        serde_json::from_slice::<serde_json::Value>(&output.stdout).expect("JSON")
    };
    let travel = |value: &serde_json::Value| {
        let chosen = value["chosen"].as_u64().expect("taken") as usize;
        let axes = value["solutions"][chosen]["axes"]
            .as_object()
            .expect("axes");
        let table = value["table"]["position"].as_f64().expect("table");
        axes.values()
            .map(|p| p.as_f64().expect("position").abs())
            .fold(table.abs(), f64::max)
    };
    let open = ask(&[]);
    assert_eq!(open["dir"], 1);
    assert_eq!(open["dir_chosen"], true);
    let minus = ask(&["--dir", "-1"]);
    assert_eq!(minus["dir"], -1);
    assert_eq!(minus["dir_chosen"], false);
    assert!(
        travel(&open) < travel(&minus),
        "{} against {}",
        travel(&open),
        travel(&minus)
    );
}

/// `machine` prints what the machine's data say, and what it could not
/// read on its line; the JSON is a contract (docs/guide.md).
#[test]
fn machine_prints_the_axes_records_and_what_it_could_not_read() {
    let path = "tests/fixtures/machine/INITIAL.INI";
    let json = run(&["machine", "--format", "json", path], b"");
    assert_exit(&json, 0);
    insta::assert_snapshot!("machine_json", stdout(&json));
    let human = run(&["machine", path], b"");
    assert_exit(&human, 0);
    insta::assert_snapshot!("machine_human", stdout(&human));
    // An archive: its data member, and its definition members counted.
    let archive = run(
        &[
            "machine",
            "--format",
            "json",
            "tests/fixtures/machine/SETUP.ARC",
        ],
        b"",
    );
    assert_exit(&archive, 0);
    let read: serde_json::Value = serde_json::from_str(&stdout(&archive)).expect("JSON");
    assert_eq!(
        read["machine"],
        "tests/fixtures/machine/SETUP.ARC:INITIAL_INI"
    );
    assert_eq!(read["axes"][0]["name"], "X");
    assert_eq!(read["axes"][0]["limits"], serde_json::json!([-0.6, 800.6]));
    assert_eq!(
        read["definitions"],
        serde_json::json!({"gud": 2, "macros": 0})
    );
    // A record no solver can use is an error, as everywhere (K001).
    let broken = run(&["machine", "tests/fixtures/lint/K001_trigger.spf"], b"");
    assert_exit(&broken, 1);
}

/// A folder of the control's data files is one machine: INITIAL first, the
/// files after it winning where they assign a datum again; a finding is told
/// on its own file's line; the folder's definition files are counted; other
/// files are passed over. As `--machine`, the folder answers a program's reads.
#[test]
fn a_folder_of_data_files_is_one_machine() {
    let folder = "tests/fixtures/machine/folder";
    let json = run(&["machine", "--format", "json", folder], b"");
    assert_exit(&json, 0);
    let read: serde_json::Value = serde_json::from_str(&stdout(&json)).expect("JSON");
    assert_eq!(read["axes"][1]["name"], "Z");
    assert_eq!(read["axes"][1]["limits"], serde_json::json!([-450.0, 1.5]));
    assert_eq!(read["frames"]["G54"]["X"]["tr"], 250.5);
    assert_eq!(
        read["definitions"],
        serde_json::json!({"gud": 1, "macros": 0})
    );
    let unreadable = &read["unreadable"];
    assert_eq!(unreadable.as_array().map(Vec::len), Some(1), "{unreadable}");
    assert_eq!(unreadable[0]["code"], "K006");
    assert_eq!(unreadable[0]["line"], 4);
    assert!(
        unreadable[0]["file"]
            .as_str()
            .is_some_and(|f| f.ends_with("_N_UFR_INI")),
        "{unreadable}"
    );
    let human = stdout(&run(&["machine", folder], b""));
    assert!(human.contains("_N_UFR_INI:4:"), "{human}");

    let evaluated = limit_read_by_a_program("machine_folder", &["--machine", folder]);
    assert!(evaluated.contains("_CYC600_3=15 "), "{evaluated}");
}

/// A swivel record's value that names a GUD variable is named (K001) with
/// what would give it, and read from the value given with `--set`.
#[test]
fn a_variable_in_a_record_is_named_until_its_value_is_given() {
    let dir = scratch("record_variable");
    let machine = dir.join("MACHINE.SPF");
    std::fs::write(
        &machine,
        "$TC_CARR23[1]=\"T\" $TC_CARR34[1]=\"HEAD\"\n$TC_CARR7[1]=1 $TC_CARR11[1]=1\n\
$TC_CARR5[1]=_RT_HOEHE_Y\nM17\n",
    )
    .expect("write");
    let program = dir.join("P.MPF");
    std::fs::write(&program, "G0 X0\nM30\n").expect("write");
    let check = |set: &[&str]| {
        let mut args = vec![
            "check",
            "--format",
            "short",
            "--machine",
            machine.to_str().expect("utf-8"),
        ];
        args.extend(set);
        args.push(program.to_str().expect("utf-8"));
        run(&args, b"")
    };
    let without = check(&[]);
    let text = stdout(&without);
    assert!(
        text.contains("MACHINE.SPF:3:14: error[K001] `$TC_CARR5[1]` reads `_RT_HOEHE_Y`"),
        "{text}"
    );
    assert_exit(&without, 1);
    let with = check(&["--set", "_RT_HOEHE_Y=12.5"]);
    assert!(!stdout(&with).contains("K001"), "{}", stdout(&with));
    assert_exit(&with, 0);
}

/// Where no definition files are named, those a control would hold beside
/// the program are read: the `.DEF` files of its folder and a `_N_DEF_DIR`
/// beside it; one that cannot be read is passed over. A name they define is
/// no finding, one they lack is.
#[test]
fn definitions_beside_the_program_are_found() {
    let output = run(
        &[
            "check",
            "--format",
            "short",
            "tests/fixtures/beside/PART.MPF",
        ],
        b"",
    );
    let text = stdout(&output);
    assert!(
        !text.contains("ZONE_MAX") && !text.contains("TEMP_LIMIT"),
        "{text}"
    );
    assert!(
        text.contains("`NOT_DEFINED_ANYWHERE` is read before any DEF or assignment\n"),
        "{text}"
    );
    // Named definitions replace those found: the names are unknown again.
    let named = run(
        &[
            "check",
            "--format",
            "short",
            "--definitions",
            "tests/fixtures/beside/_N_DEF_DIR/_N_UMAC_DEF",
            "tests/fixtures/beside/PART.MPF",
        ],
        b"",
    );
    let text = stdout(&named);
    assert!(
        text.contains("`ZONE_MAX`") && !text.contains("TEMP_LIMIT"),
        "{text}"
    );
}

/// A program's read of a machine datum is known offline when the machine's
/// data are given: `$MA_POS_LIMIT_PLUS[Z]` by the channel axis's name.
#[test]
fn machine_data_a_program_reads_are_known_offline() {
    let without = limit_read_by_a_program("machine_reads", &[]);
    assert!(!without.contains("_CYC600_3=5"), "{without}");
    let machine = ["--machine", "tests/fixtures/machine/INITIAL.INI"];
    let with = limit_read_by_a_program("machine_reads_given", &machine);
    assert!(with.contains("_CYC600_3=5 "), "{with}");
}

/// `eval` (with `options`) of a program whose CYCLE600 turns by ten times
/// `$MA_POS_LIMIT_PLUS[Z]` (its third result), in the scratch folder `name`.
fn limit_read_by_a_program(name: &str, options: &[&str]) -> String {
    let dir = scratch(name);
    let program = dir.join("LIMIT.MPF");
    std::fs::write(
        &program,
        "DEF REAL _A\nN10 _A=$MA_POS_LIMIT_PLUS[Z]*10\n\
N20 CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, _A, 0, 0, 0, 0, 0, 1, 39, 0, 0, 0)\nM30\n",
    )
    .expect("write");
    let mut args = vec!["eval", "--heads", "samples/HEAD_DEF.SPF"];
    args.extend(options);
    args.push(program.to_str().expect("utf-8"));
    stdout(&run(&args, b""))
}
