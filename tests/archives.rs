//! Archives as a control writes them: the text form (`%_N_` sections,
//! `tests/fixtures/archive/SHOP.ARC`, written by hand) and the binary form
//! of series start-up (`@@MMCIBN.002`, built by `support::binary_archive`).
//! Each program member is checked, rewritten and evaluated as a program of
//! its own; every other byte stays.

mod support;

use support::{assert_exit, binary_archive, binary_members, run, scratch, stdout};

fn shop() -> std::path::PathBuf {
    support::repo().join("tests/fixtures/archive/SHOP.ARC")
}

/// The sections of SHOP.ARC as (NC path, bytes without the header line).
fn shop_sections() -> Vec<(String, Vec<u8>)> {
    let text = std::fs::read_to_string(shop()).expect("fixture");
    text.split_inclusive('\n')
        .fold(Vec::<(String, Vec<u8>)>::new(), |mut sections, line| {
            if let Some(name) = line.strip_prefix("%_N_") {
                let name = name.trim_end();
                let dir = name.rsplit('_').next().unwrap_or("");
                sections.push((format!("/_N_{dir}_DIR/_N_{name}"), line.as_bytes().to_vec()));
            } else if let Some((_, data)) = sections.last_mut() {
                data.extend_from_slice(line.as_bytes());
            }
            sections
        })
}

fn shop_binary() -> Vec<u8> {
    let mut members: Vec<(String, Vec<u8>)> = shop_sections();
    // Members that are no NC: a log and binary data, left alone.
    members.push((
        "/_N_LOG_DIR/_N_SETUP_TXT".into(),
        b"saved 2026-12-02\r\n".to_vec(),
    ));
    members.push((
        "/_N_DRV_DIR/_N_DRIVE_ACX".into(),
        (0..=255u8).cycle().take(700).collect(),
    ));
    let borrowed: Vec<(&str, &[u8])> = members.iter().map(|(p, d)| (p.as_str(), &d[..])).collect();
    binary_archive(&borrowed)
}

#[test]
fn each_program_of_a_text_archive_is_checked_with_the_archive_as_its_environment() {
    let name = shop().display().to_string();
    let output = run(&["check", "--format", "short", &name], b"");
    assert_exit(&output, 1);
    // The member's own line (8 of PART_MPF, 19 of the file); the globals
    // of MGUD_DEF are defined and L_DRILL's PROC is known, so neither
    // N005 nor N018 speaks.
    assert_eq!(
        stdout(&output),
        format!("{name}:PART_MPF:8:8: error[N022] address X is programmed twice in this block (`X10` and `X20`): the control takes it once\n")
    );
    let summary = String::from_utf8_lossy(&output.stderr);
    assert!(summary.contains("1 error in 4 files"), "{summary}");
    assert!(
        !summary.contains("without the machine's environment"),
        "{summary}"
    );
}

#[test]
fn a_binary_archive_reads_as_its_text_form_does_and_its_other_members_are_left_alone() {
    let dir = scratch("arc-check");
    let path = dir.join("SETUP.ARC");
    std::fs::write(&path, shop_binary()).expect("write");
    let name = path.display().to_string();
    let output = run(&["check", "--format", "short", &name], b"");
    assert_exit(&output, 1);
    assert_eq!(
        stdout(&output),
        format!("{name}:PART_MPF:8:8: error[N022] address X is programmed twice in this block (`X10` and `X20`): the control takes it once\n")
    );
    let json = run(&["check", "--format", "json", &name], b"");
    let document: serde_json::Value = serde_json::from_slice(&json.stdout).expect("JSON");
    let paths: Vec<&str> = document["files"]
        .as_array()
        .expect("files")
        .iter()
        .filter_map(|f| f["path"].as_str())
        .collect();
    let member = |m: &str| format!("{name}:{m}");
    assert_eq!(
        paths,
        [
            member("L_DRILL_SPF"),
            member("HEAD_DEF_SPF"),
            member("PART_MPF"),
            member("FLANGE_MPF")
        ]
    );
    // A directory's walk takes archives.
    let output = run(
        &["check", "--format", "short", dir.to_str().expect("utf-8")],
        b"",
    );
    assert!(
        stdout(&output).contains(":PART_MPF:8:8:"),
        "{}",
        stdout(&output)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_rewrite_in_place_changes_the_rewritten_member_and_its_header_only() {
    let dir = scratch("arc-rewrite");
    let path = dir.join("SETUP.ARC");
    let before = shop_binary();
    std::fs::write(&path, &before).expect("write");
    let heads = support::repo().join("samples/HEAD_DEF.SPF");
    let heads = heads.to_str().expect("utf-8");
    // The archive's own HEAD_DEF_SPF names the heads.
    let output = run(
        &["rewrite", "--in-place", path.to_str().expect("utf-8")],
        b"",
    );
    assert_exit(&output, 0);
    let after = std::fs::read(&path).expect("read");
    let (old, new) = (binary_members(&before), binary_members(&after));
    assert_eq!(old.len(), new.len());
    // The flange program, rewritten alone, is what its member became.
    let flange = dir.join("FLANGE.MPF");
    let (_, flange_bytes) = old
        .iter()
        .find(|(p, _)| p.ends_with("FLANGE_MPF"))
        .expect("member");
    std::fs::write(&flange, flange_bytes).expect("write");
    let alone = run(
        &["rewrite", "--heads", heads, flange.to_str().expect("utf-8")],
        b"",
    );
    assert_exit(&alone, 0);
    for ((old_path, old_data), (new_path, new_data)) in old.iter().zip(&new) {
        assert_eq!(old_path, new_path);
        if old_path.ends_with("FLANGE_MPF") {
            assert_eq!(new_data, &alone.stdout, "the rewritten member");
            assert_ne!(new_data, old_data);
        } else {
            assert_eq!(new_data, old_data, "{old_path} unchanged");
        }
    }
    // Before the flange member, not a byte moved.
    let at = memchr_find(&before, b"/_N_MPF_DIR/_N_FLANGE_MPF") - 257;
    assert_eq!(before[..at], after[..at]);
    // The backup is the archive as it was.
    let backup = std::fs::read(dir.join("SETUP.ARC.bak"));
    assert_eq!(backup.expect("backup"), before);
    let _ = std::fs::remove_dir_all(&dir);
}

fn memchr_find(haystack: &[u8], needle: &[u8]) -> usize {
    haystack
        .windows(needle.len())
        .position(|w| w == needle)
        .expect("found")
}

#[test]
fn a_text_archive_is_rewritten_section_by_section() {
    let heads = support::repo().join("samples/HEAD_DEF.SPF");
    let heads = heads.to_str().expect("utf-8");
    let name = shop().display().to_string();
    let output = run(&["rewrite", &name], b"");
    assert_exit(&output, 0);
    let dir = scratch("arc-text");
    let mut expected = Vec::new();
    for (path, data) in shop_sections() {
        let file = dir.join("SECTION.MPF");
        std::fs::write(&file, &data).expect("write");
        if path.ends_with("_MPF") {
            let alone = run(
                &["rewrite", "--heads", heads, file.to_str().expect("utf-8")],
                b"",
            );
            expected.extend(alone.stdout);
        } else {
            expected.extend(data);
        }
    }
    assert_eq!(stdout(&output), String::from_utf8_lossy(&expected));
    // The diff is the archive's, with its lines.
    let diff = stdout(&run(&["rewrite", "--diff", &name], b""));
    assert!(
        diff.starts_with(&format!("--- {name}\n+++ {name}\n@@ -64,7 +64,8 @@")),
        "{diff}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_damaged_archive_names_the_member_and_the_offset_and_nothing_is_written() {
    let dir = scratch("arc-damaged");
    let path = dir.join("SETUP.ARC");
    let mut bytes = shop_binary();
    let part = memchr_find(&bytes, b"/_N_MPF_DIR/_N_PART_MPF") - 257;
    bytes[part + 130] ^= 0x20;
    std::fs::write(&path, &bytes).expect("write");
    let name = path.to_str().expect("utf-8");
    for command in ["check", "eval"] {
        let output = run(&[command, name], b"");
        assert_exit(&output, 2);
        let said = String::from_utf8_lossy(&output.stderr).replace('\n', " ");
        assert!(
            said.contains("member `PART_MPF`") && said.contains(&format!("at byte {part}")),
            "{said}"
        );
    }
    let output = run(&["rewrite", "--in-place", name], b"");
    assert_exit(&output, 2);
    assert_eq!(std::fs::read(&path).expect("read"), bytes);
    let truncated = &shop_binary()[..part + 600];
    std::fs::write(&path, truncated).expect("write");
    let output = run(&["check", name], b"");
    assert_exit(&output, 2);
    assert!(String::from_utf8_lossy(&output.stderr).contains("truncated"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The swivel data of a series start-up archive's `INITIAL.INI` are the
/// machine; its GUD members are definitions for programs outside it.
#[test]
fn an_archive_gives_the_machine_and_the_definitions() {
    let dir = scratch("arc-machine");
    let machine = std::fs::read(support::repo().join("samples/MACHINE.SPF")).expect("machine");
    let mut initial = b"CHANDATA(1)\n$TC_DP1[1,1]=120\n$TC_DP6[1,1]=4\n".to_vec();
    initial.extend(&machine);
    let mgud = b"%_N_MGUD_DEF\n;$PATH=/_N_DEF_DIR\nDEF NCK REAL _ZERO_X\n".to_vec();
    let archive = binary_archive(&[
        ("/_N_DEF_DIR/_N_MGUD_DEF", &mgud),
        ("/_N_INITIAL_INI", &initial),
    ]);
    let path = dir.join("SERIES.ARC");
    std::fs::write(&path, archive).expect("write");
    let path = path.to_str().expect("utf-8");
    let output = run(
        &[
            "axes",
            "--machine",
            path,
            "--record",
            "1",
            "--mode",
            "57",
            "0",
            "30",
            "0",
        ],
        b"",
    );
    assert_exit(&output, 0);
    let from_file = run(
        &[
            "axes",
            "--machine",
            "samples/MACHINE.SPF",
            "--record",
            "1",
            "--mode",
            "57",
            "0",
            "30",
            "0",
        ],
        b"",
    );
    assert_eq!(stdout(&output), stdout(&from_file));

    let program = dir.join("P.MPF");
    std::fs::write(
        &program,
        "G0 X=_ZERO_X\nCYCLE800(1,\"TABLE_AC\",0,57,0,0,0,60,0,0,0,0,0,1)\nM30\n",
    )
    .expect("program");
    let program = program.to_str().expect("utf-8");
    let output = run(
        &[
            "check",
            "--format",
            "short",
            "--definitions",
            path,
            "--machine",
            path,
            program,
        ],
        b"",
    );
    let report = stdout(&output);
    assert!(!report.contains("N005"), "{report}");
    // The table's A turns from -120° to 30° only as the archive's
    // INITIAL_INI says: the `_DIR` solution A=60 lies outside (K003).
    assert!(report.contains("K003"), "{report}");
    assert!(!report.contains("K005"), "{report}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn eval_names_each_program_of_an_archive() {
    let name = shop().display().to_string();
    let output = run(&["eval", "--json", &name], b"");
    assert_exit(&output, 0);
    let documents: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
    let documents = documents.as_array().expect("one document per program");
    assert_eq!(documents.len(), 4);
    let flange = &documents[3];
    assert_eq!(flange["path"], format!("{name}:FLANGE_MPF"));
    assert_eq!(flange["calls"].as_array().map(Vec::len), Some(2));
}

/// The committed series start-up archive, written byte by byte from the
/// form's description: its program is checked with its GUD member's names.
#[test]
fn the_series_start_up_fixture_reads_as_its_members() {
    let path = support::repo().join("tests/fixtures/archive/SERIES.ARC");
    let members = binary_members(&std::fs::read(&path).expect("fixture"));
    assert_eq!(members.len(), 4);
    let name = path.display().to_string();
    let output = run(&["check", "--format", "short", &name], b"");
    assert_exit(&output, 1);
    assert_eq!(
        stdout(&output),
        format!("{name}:PART_MPF:8:1: error[N025] the circle has an end point but neither a centre (I, J, K) nor a radius (CR)\n")
    );
}

#[test]
fn check_fix_fixes_a_member_and_keeps_the_archive_readable() {
    let dir = scratch("arc-fix");
    let path = dir.join("FIX.ARC");
    let fixable: &[u8] = b"DEF REAL Depth\nR1=DEPTH+1 ; sinuprep: ignore N005, N016\nM30\n";
    let other: &[u8] = b"PROC OTHER\nDEF REAL Depth\nR1=DEPTH\nM17\n";
    let before = binary_archive(&[
        ("/_N_MPF_DIR/_N_PART_MPF", fixable),
        ("/_N_SPF_DIR/_N_OTHER_SPF", other),
    ]);
    std::fs::write(&path, &before).expect("write");
    let name = path.to_str().expect("utf-8");
    let output = run(
        &[
            "check", "--fix", "--select", "N,N015", "--format", "short", name,
        ],
        b"",
    );
    assert_exit(&output, 0);
    let members = binary_members(&std::fs::read(&path).expect("read"));
    assert_eq!(members[1].1, b"DEF REAL Depth\nR1=Depth+1\nM30\n");
    assert_eq!(members[2].1, b"PROC OTHER\nDEF REAL Depth\nR1=Depth\nM17\n");
    let said = String::from_utf8_lossy(&output.stderr);
    assert!(
        said.contains(&format!("{name}: fixed 4 findings")),
        "{said}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A text archive rewritten in place: the rewritten section changes, every
/// other section stays byte for byte.
#[test]
fn a_text_archive_rewritten_in_place_keeps_its_other_sections() {
    let dir = scratch("arc-text-in-place");
    let path = dir.join("SHOP.ARC");
    std::fs::copy(shop(), &path).expect("copy");
    let output = run(
        &[
            "rewrite",
            "--in-place",
            "--no-backup",
            path.to_str().expect("utf-8"),
        ],
        b"",
    );
    assert_exit(&output, 0);
    let after = std::fs::read_to_string(&path).expect("read");
    let before = std::fs::read_to_string(shop()).expect("fixture");
    let flange = before.find("%_N_FLANGE_MPF").expect("section");
    let mask = before.find("%_N_MASK_COM").expect("section");
    assert_eq!(after[..flange], before[..flange]);
    assert!(after.ends_with(&before[mask..]));
    assert!(after[flange..].contains("_CYC600_2=37.792346"), "{after}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// An archive piped in reads as one given by name.
#[test]
fn an_archive_on_stdin_is_read_as_its_members() {
    let bytes =
        std::fs::read(support::repo().join("tests/fixtures/archive/SERIES.ARC")).expect("fixture");
    let output = run(&["check", "--format", "short", "-"], &bytes);
    assert_exit(&output, 1);
    assert!(
        stdout(&output).starts_with("<stdin>:PART_MPF:8:1: error[N025]"),
        "{}",
        stdout(&output)
    );
    let named = run(
        &[
            "check",
            "--format",
            "short",
            "--stdin-filename",
            "SAVED.ARC",
            "-",
        ],
        &bytes,
    );
    assert!(
        stdout(&named).starts_with("SAVED.ARC:PART_MPF:8:1:"),
        "{}",
        stdout(&named)
    );
}

#[test]
fn what_an_archive_holds_unchecked_is_named() {
    let dir = scratch("archives-unchecked");
    let program: &[u8] = b"GOTOF NOWHERE\nM30\n";
    let mut archive = binary_archive(&[
        ("/_N_MPF_DIR/_N_PART_MPF", b"M30\n"),
        // Saved without its suffix: a program nobody checks.
        ("/_N_MPF_DIR/_N_NOSUFFIX", program),
    ]);
    // A block of NULs ends the archive; a member written after it.
    archive.extend_from_slice(&[0; 512]);
    let hidden = binary_archive(&[("/_N_MPF_DIR/_N_HIDDEN_MPF", program)]);
    archive.extend_from_slice(&hidden[512..]);
    let path = dir.join("SAVED.ARC");
    std::fs::write(&path, &archive).expect("write");
    let path = path.to_str().expect("utf-8");
    for args in [
        vec!["check", path],
        vec!["rewrite", "--check", path],
        vec!["eval", path],
    ] {
        let output = run(&args, b"");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            stderr.contains("SAVED.ARC: 1 member not checked") && stderr.contains("NOSUFFIX"),
            "{args:?}: {stderr}"
        );
        let after = format!("from byte {} on, after the block of NULs", 3 * 1024 + 512);
        assert!(stderr.contains(&after), "{args:?}: {stderr}");
        // The member there is named.
        assert!(
            stderr.contains("the member there, HIDDEN_MPF, is not checked"),
            "{args:?}: {stderr}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// GitHub's annotations and SARIF's code scanning open the file a finding
/// names: a member's finding names the archive, at the archive's own line,
/// and the member in its message (`SHOP.ARC:PART_MPF` named no file).
#[test]
fn ci_formats_point_at_the_archive_and_name_the_member() {
    let dir = scratch("arc-ci");
    let binary = dir.join("SETUP.ARC");
    std::fs::write(&binary, shop_binary()).expect("write");
    for path in [shop(), binary] {
        let bytes = std::fs::read(&path).expect("archive");
        let line = bytes
            .split(|&b| b == b'\n')
            .position(|l| l.starts_with(b"G1 X10 X20"))
            .expect("the finding's line")
            + 1;
        let name = path.display().to_string();
        let output = run(&["check", "--format", "github", &name], b"");
        assert_exit(&output, 1);
        assert_eq!(
            stdout(&output),
            format!("::error file={},line={line},col=8,endLine={line},endColumn=11,title=N022 repeated-address::PART_MPF: address X is programmed twice in this block (`X10` and `X20`): the control takes it once\n", name.replace(':', "%3A").replace(',', "%2C"))
        );
        let output = run(&["check", "--format", "sarif", &name], b"");
        let sarif: serde_json::Value = serde_json::from_slice(&output.stdout).expect("SARIF");
        let result = &sarif["runs"][0]["results"][0];
        let location = &result["locations"][0]["physicalLocation"];
        let uri = location["artifactLocation"]["uri"].as_str().expect("uri");
        assert!(
            uri.starts_with("file:///")
                && uri.ends_with(path.file_name().and_then(|n| n.to_str()).expect("name")),
            "{uri}"
        );
        assert_eq!(location["region"]["startLine"], line);
        let offset = location["region"]["byteOffset"].as_u64().expect("offset") as usize;
        assert_eq!(&bytes[offset..offset + 3], b"X20");
        assert!(result["message"]["text"]
            .as_str()
            .expect("message")
            .starts_with("PART_MPF: address X"));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// An archive's macro file (`%_N_MMAC_DEF`) is the environment of its
/// programs: their macros expand as on the control, and nothing is found.
#[test]
fn an_archive_s_macro_member_expands_in_its_programs() {
    let name = support::repo()
        .join("tests/fixtures/archive/MACROS.ARC")
        .display()
        .to_string();
    let output = run(&["check", "--format", "short", &name], b"");
    assert_exit(&output, 0);
    assert_eq!(stdout(&output), "");
}

#[test]
fn fmt_formats_each_program_member_and_keeps_the_archive_readable() {
    let dir = scratch("arc-fmt");
    let path = dir.join("SETUP.ARC");
    let before = shop_binary();
    std::fs::write(&path, &before).expect("write");
    let output = run(&["fmt", path.to_str().expect("utf-8")], b"");
    assert_exit(&output, 0);
    let after = std::fs::read(&path).expect("read");
    assert_ne!(after, before, "nothing formatted");
    // Every header reads, with its size and checksum.
    let (old, new) = (binary_members(&before), binary_members(&after));
    assert_eq!(old.len(), new.len());
    let mut formatted = 0;
    for ((old_path, old_data), (new_path, new_data)) in old.iter().zip(&new) {
        assert_eq!(old_path, new_path);
        if old_path.ends_with("_MPF") || old_path.ends_with("_SPF") {
            // A member formats as the same program alone would.
            let alone = run(&["fmt", "-"], old_data);
            assert_eq!(new_data, &alone.stdout, "{old_path}");
            formatted += usize::from(new_data != old_data);
        } else {
            assert_eq!(new_data, old_data, "{old_path} unchanged");
        }
    }
    assert!(formatted > 0);
    let check = run(
        &["check", "--format", "short", path.to_str().expect("utf-8")],
        b"",
    );
    assert_ne!(check.status.code(), Some(2), "{}", stdout(&check));
    // Formatted once, it is formatted.
    let again = run(&["fmt", "--check", path.to_str().expect("utf-8")], b"");
    assert_exit(&again, 0);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--machine` naming a series start-up archive brings its definition
/// members (GUD variables, macros) along, as if given as definitions.
#[test]
fn a_machine_archive_brings_its_definitions() {
    let dir = scratch("archive_definitions");
    let program = dir.join("USE.MPF");
    std::fs::write(&program, "R1=MY_GUD\nM30\n").expect("write");
    let archive = binary_archive(&[
        (
            "/_N_DEF_DIR/_N_SGUD_DEF",
            b"%_N_SGUD_DEF\nDEF NCK REAL MY_GUD\nM30\n".as_slice(),
        ),
        ("/_N_INITIAL_INI", b"CHANDATA(1)\nM17\n".as_slice()),
    ]);
    let arc = dir.join("MACHINE.ARC");
    std::fs::write(&arc, archive).expect("write");
    let program = program.to_str().expect("utf-8");
    let alone = run(&["check", "--format", "short", program], b"");
    assert!(stdout(&alone).contains("N005"), "{}", stdout(&alone));
    let with = run(
        &[
            "check",
            "--format",
            "short",
            "--machine",
            arc.to_str().expect("utf-8"),
            program,
        ],
        b"",
    );
    assert_eq!(
        stdout(&with),
        "",
        "{}",
        String::from_utf8_lossy(&with.stderr)
    );
}
