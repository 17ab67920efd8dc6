//! Every rule on a fixture that triggers it and one that must not
//! (`tests/fixtures/lint/<CODE>_trigger|clean.*`), rendered as users see it;
//! the rule catalogue; configuration, suppression and every output format.

mod support;

use std::path::Path;

use sinuprep::cli::render::{human, short, FileReport};
use sinuprep::lint::{self, Selection};
use sinuprep::semantic::machine::{Machine, Reading};
use sinuprep::semantic::swivels::{self, OnMachine};
use sinuprep::semantic::Heads;
use sinuprep::syntax::{program_kind, ProgramKind};
use support::{assert_exit, run, stdout};

fn sample_heads() -> Heads {
    let source = std::fs::read(support::repo().join("samples/HEAD_DEF.SPF")).expect("HEAD_DEF");
    Heads::read("HEAD_DEF.SPF".into(), &source)
}

/// The sample machine (`samples/MACHINE.SPF`), for the swivel rules.
fn sample_machine() -> std::sync::Arc<OnMachine> {
    let path = support::repo().join("samples/MACHINE.SPF");
    let source = std::fs::read(&path).expect("MACHINE.SPF");
    std::sync::Arc::new(OnMachine {
        name: "MACHINE.SPF".into(),
        machine: Machine::read(&source, Reading::default()),
        values: Vec::new(),
        parts: vec![sinuprep::archive::Part {
            name: "MACHINE.SPF".into(),
            range: 0..source.len(),
        }],
        source,
        hirth_tolerance_deg: swivels::HIRTH_TOLERANCE_DEG,
        table: None,
    })
}

fn lint_fixture(path: &Path) {
    let source = std::fs::read(path).expect("fixture");
    let name = path.file_name().and_then(|n| n.to_str()).expect("name");
    let code = name.split('_').next().expect("code");
    let triggers = name.contains("_trigger");
    let heads = (!(code == "C610" && triggers)).then(sample_heads);
    // N099 is about the other rules' suppressions: it needs them enabled.
    let select = if code == "N099" {
        Vec::new()
    } else {
        vec![code.to_string()]
    };
    let settings = lint::Settings {
        selection: Selection {
            select,
            ..Selection::default()
        },
        heads,
        machine: code.starts_with('K').then(sample_machine),
        // K001's fixtures are machine files, but for those named as programs.
        swivel_data: code == "K001" && !name.contains("_program"),
        ..lint::Settings::default()
    };
    let diagnostics = lint::check(&source, name, program_kind(Some(name), &source), &settings);
    let fired = diagnostics.iter().any(|d| d.code() == code);
    let diagnostics: Vec<_> = diagnostics
        .into_iter()
        .filter(|d| d.code() == code)
        .collect();
    assert_eq!(fired, triggers, "{name}: {diagnostics:#?}");
    let report = FileReport {
        name,
        source: &source,
        diagnostics: &diagnostics,
    };
    let mut text = String::new();
    short(&report, &mut text);
    text.push('\n');
    human(&report, false, &mut text);
    insta::assert_snapshot!("lint", text);
}

#[test]
fn each_rule_fires_on_its_trigger_and_not_on_its_clean_fixture() {
    insta::glob!("fixtures/lint/*", lint_fixture);
}

#[test]
fn every_rule_is_documented_and_has_fixtures() {
    let fixtures: Vec<String> = support::files_below(&support::repo().join("tests/fixtures/lint"))
        .iter()
        .filter_map(|p| p.file_name().and_then(|n| n.to_str()).map(String::from))
        .collect();
    let mut codes = Vec::new();
    for rule in lint::rules::all() {
        let info = rule.info;
        for section in [
            "## What it does",
            "## Why it matters",
            "## Example",
            "## Fix",
        ] {
            assert!(info.docs.contains(section), "{} lacks {section}", info.code);
        }
        assert!(
            info.name
                .chars()
                .all(|c| c.is_ascii_lowercase() || c == '-' || c.is_ascii_digit()),
            "{}",
            info.name
        );
        codes.push(info.code);
        // Rules of the rewrite only (C611-C613, C617) are tested by tests/rewrite.rs (C620, which
        // needs a machine with a table, by tests/cli.rs), syntax codes by tests/diagnostics.rs,
        // the dry run's K007 by tests/run.rs.
        let elsewhere = info.code.starts_with('S')
            || ["C611", "C612", "C613", "C617", "C620", "K007"].contains(&info.code);
        if !elsewhere {
            for kind in ["trigger", "clean"] {
                assert!(
                    fixtures
                        .iter()
                        .any(|f| f.starts_with(&format!("{}_{kind}", info.code))),
                    "{} has no {kind} fixture",
                    info.code
                );
            }
        }
    }
    let mut sorted = codes.clone();
    sorted.dedup();
    assert_eq!(sorted.len(), codes.len(), "codes are unique");
}

/// Diagnostics can only be made from a rule (`RuleInfo::at`); every rule
/// defined anywhere in the source is one `sinuprep rule` lists, so every code
/// the parser, the walk, the rewrite or a checker raises is documented.
#[test]
fn every_rule_defined_is_registered() {
    let registered: Vec<&str> = lint::rules::all().iter().map(|r| r.info.code).collect();
    let mut defined = Vec::new();
    for path in support::files_below(&support::repo().join("src")) {
        let text = std::fs::read_to_string(&path).expect("source");
        for definition in text.split(": RuleInfo = RuleInfo {").skip(1) {
            let code = definition
                .split("code: \"")
                .nth(1)
                .and_then(|rest| rest.split('"').next())
                .expect("a rule's code");
            defined.push(code.to_string());
        }
    }
    assert!(defined.len() >= 40, "rules found: {}", defined.len());
    for code in &defined {
        assert!(
            registered.contains(&code.as_str()),
            "{code} is defined but not registered"
        );
    }
    assert_eq!(
        defined.len(),
        registered.len(),
        "every registered rule is defined once"
    );
}

#[test]
fn rule_command_prints_documentation_and_the_list() {
    let one = run(&["rule", "n001"], b"");
    assert_exit(&one, 0);
    insta::assert_snapshot!("rule_n001", stdout(&one));
    let all = run(&["rule", "--all"], b"");
    assert_exit(&all, 0);
    insta::assert_snapshot!("rule_all", stdout(&all));
    assert_exit(&run(&["rule", "X999"], b""), 2);
}

const FINDINGS: &[u8] = b"N20 X1\nN10 X=UNDEFINED_NAME\n";

#[test]
fn every_output_format_is_locked() {
    for format in ["short", "json", "github", "sarif"] {
        let output = run(
            &[
                "check",
                "--format",
                format,
                "--stdin-filename",
                "PART.MPF",
                "-",
            ],
            FINDINGS,
        );
        assert_exit(&output, 0);
        // The SARIF base URI is the directory the test runs in.
        let root = format!("file://{}/", env!("CARGO_MANIFEST_DIR").replace(' ', "%20"));
        let text = stdout(&output).replace(&root, "file:///CHECKOUT/");
        insta::assert_snapshot!(format!("format_{format}"), text);
    }
    let sarif: serde_json::Value =
        serde_json::from_slice(&run(&["check", "--format", "sarif", "-"], FINDINGS).stdout)
            .expect("json");
    assert_eq!(sarif["version"], "2.1.0");
    assert_eq!(
        sarif["runs"][0]["results"].as_array().map(Vec::len),
        Some(3)
    );
}

#[test]
fn selection_severity_and_deny_warnings_set_the_exit_status() {
    // Findings: N005 (warning), N010 (warning), N014 (info); no error.
    assert_exit(&run(&["check", "-"], FINDINGS), 0);
    assert_exit(&run(&["check", "--deny-warnings", "-"], FINDINGS), 1);
    assert_exit(
        &run(
            &["check", "--deny-warnings", "--ignore", "N005,N010", "-"],
            FINDINGS,
        ),
        0,
    );
    let only = run(
        &["check", "--format", "short", "--select", "N014", "-"],
        FINDINGS,
    );
    assert_eq!(stdout(&only).lines().count(), 1);
    let quiet = run(
        &[
            "check",
            "--format",
            "short",
            "--severity-min",
            "warning",
            "-",
        ],
        FINDINGS,
    );
    assert!(!stdout(&quiet).contains("info["));
}

#[test]
fn configuration_is_found_upward_and_unknown_keys_are_named() {
    let dir = std::env::temp_dir().join(format!("sinuprep-config-{}", std::process::id()));
    let nested = dir.join("programs/part");
    std::fs::create_dir_all(&nested).expect("dirs");
    std::fs::write(
        dir.join("sinuprep.toml"),
        "ignore = [\"N014\"]\ndeny-warnings = true\n",
    )
    .expect("config");
    let program = nested.join("PART.MPF");
    std::fs::write(&program, FINDINGS).expect("program");
    let output = run(
        &[
            "check",
            "--format",
            "short",
            program.to_str().expect("utf-8"),
        ],
        b"",
    );
    assert_exit(&output, 1);
    assert!(!stdout(&output).contains("N014"), "{}", stdout(&output));
    // --ignore replaces the file's list, as --select does.
    let replaced = run(
        &[
            "check",
            "--format",
            "short",
            "--ignore",
            "N016",
            program.to_str().expect("utf-8"),
        ],
        b"",
    );
    assert!(stdout(&replaced).contains("N014"), "{}", stdout(&replaced));
    // --stdin-filename finds the same configuration.
    let stdin_name = program.to_str().expect("utf-8");
    let output = run(
        &[
            "check",
            "--format",
            "short",
            "--stdin-filename",
            stdin_name,
            "-",
        ],
        FINDINGS,
    );
    assert_exit(&output, 1);
    assert!(stdout(&output).starts_with(stdin_name));
    // The machine's axis names are no undefined variables.
    std::fs::write(&program, "N10 POS[XC]=10 FA[AX1]=500\nN20 M30\n").expect("program");
    let args = [
        "check",
        "--format",
        "short",
        "--select",
        "N005",
        program.to_str().expect("utf-8"),
    ];
    assert!(stdout(&run(&args, b"")).contains("`XC` is read before any DEF"));
    std::fs::write(dir.join("sinuprep.toml"), "axes = [\"xc\", \"AX1\"]\n").expect("config");
    let output = run(&args, b"");
    assert_exit(&output, 0);
    std::fs::write(dir.join("sinuprep.toml"), "selct = [\"N\"]\n").expect("config");
    let output = run(&["check", program.to_str().expect("utf-8")], b"");
    assert_exit(&output, 2);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("sinuprep.toml:1:1: unknown field `selct`"),
        "{stderr}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `check` against `check` parsing every line, all rules on.
fn assert_shortcut_agrees(name: &str, source: &[u8]) {
    let (fast, reference) = on_both_paths(source, name);
    assert_eq!(fast, reference, "{name}");
}

/// The findings of `check` and of `check` parsing every line, all rules on;
/// `check` with the lines read ahead on a thread of their own must find
/// what parsing every line finds.
fn on_both_paths(
    source: impl AsRef<[u8]>,
    name: &str,
) -> (
    Vec<sinuprep::diagnostic::Diagnostic>,
    Vec<sinuprep::diagnostic::Diagnostic>,
) {
    let source = source.as_ref();
    let kind = program_kind(Some(name), source);
    let settings = lint::Settings {
        heads: Some(sample_heads()),
        ..lint::Settings::default()
    };
    let fast = lint::check(source, name, kind, &settings);
    let every_line = sinuprep::syntax::plain::PlainScanner::ParseEveryLine;
    let reference = lint::check_with(every_line, source, name, kind, &settings);
    let ahead = lint::check_read_ahead(source, name, kind, &settings);
    assert_eq!(ahead, reference, "{name}: the lines read ahead");
    (fast, reference)
}

/// The lines of a large program are read on a thread of their own, ahead
/// of the rules: the findings are those of every line parsed in turn, in a
/// program past the size that reads ahead, in batches whose boundaries fall
/// anywhere (a call left open across lines among them), and in one that
/// defines a macro halfway (the lines after it are read here, with it, by
/// the parser handed over: `syntax::ahead`'s own tests show the hand-over).
#[test]
fn reading_the_lines_ahead_changes_no_finding() {
    let cycles = "POCKET{n}:\n_Z=0\nWHILE _Z>-5\n_Z=_Z-0.5\nIF R{r}>_Z*2\n\
G1 X=R{r}+10 Y=R{r}*0.5 Z=_Z F800\nELSE\nG1 X10 Y20 Z=_Z F400\nENDIF\nENDWHILE\n\
CYCLE81(10, 0, 2, , -5\n, 1)\nIF _N<3 GOTOB POCKET{n}\nG1 X=UNDEFINED_{n} Y2 Y3\nL{sub}\n";
    let mut large = String::from("DEF REAL _Z\nDEF INT _N\n");
    let mut n = 0;
    while large.len() < 300 * 1024 {
        n += 1;
        let lines = cycles
            .replace("{n}", &n.to_string())
            .replace("{r}", &(n % 99 + 1).to_string())
            .replace("{sub}", &(n % 7 + 100).to_string());
        large.push_str(&lines);
        // A line more now and then: the batches' boundaries move.
        if n % 3 == 0 {
            large.push_str("N10 G1 X1\n");
        }
    }
    large.push_str("M30\n");
    let (fast, reference) = on_both_paths(&large, "LARGE.MPF");
    assert_eq!(fast, reference);
    assert!(reference.len() > 1000, "{}", reference.len());

    let mut with_macro = String::from("R1=_SPEED\n");
    with_macro.push_str(&"G1 X1 Y2\nR1=R2+1\n".repeat(400));
    // The parser handed over after the DEFINE counts the lines read ahead:
    // its message for a call left open names the call's line.
    with_macro.push_str("DEFINE _SPEED AS 1000\nCYCLE81(1,\n2)\n");
    with_macro.push_str(&"R1=_SPEED\nG1 X1 Y2\nR1=R2+1\n".repeat(400));
    with_macro.push_str("M30\n");
    let (fast, reference) = on_both_paths(&with_macro, "MACRO.MPF");
    assert_eq!(fast, reference);
}

/// Plain lines (`N10 G1 X5`) skip the parser and most rules: that must change
/// no finding, on every fixture and every program of the outside corpus.
#[test]
fn skipping_plain_lines_changes_no_finding() {
    let mut files = support::files_below(&support::repo().join("tests/fixtures"));
    files.extend(support::corpus_files());
    for path in &files {
        let source = std::fs::read(path).expect("readable");
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("?");
        assert_shortcut_agrees(name, &source);
    }
}

/// The modal rules (N028, N030, N031) walk the blocks together: their
/// findings together are those of each walking alone, on every fixture,
/// every program of the outside corpus and a file of several programs with
/// lines only one of them reads (an M alone, a G the others ignore), calls,
/// skippable blocks and structures.
#[test]
fn the_modal_rules_together_find_what_each_finds_alone() {
    const MODAL: [&str; 3] = ["N028", "N030", "N031"];
    let several = b"%_N_FIRST_MPF\nG17 G41 G1 X10 Y10 F100\nM3 S100\nTRAORI\nG18 X20\nM30\n\
%_N_SUB_SPF\nG42 G1 X0 F10\n/ G40 X1\nG19 X2\nL100\nG18 X3\nIF R1 == 1\nG17\nENDIF\nM2\n\
%_N_SECOND_MPF\nG91 G42 X1 F100\nM5\nTRANS X10\nN10 G1 X1\nG18 Y2\nM30\n";
    let mut sources: Vec<(String, Vec<u8>)> = vec![("SEVERAL.MPF".into(), several.to_vec())];
    let mut files = support::files_below(&support::repo().join("tests/fixtures"));
    files.extend(support::corpus_files());
    for path in &files {
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("?");
        sources.push((name.into(), std::fs::read(path).expect("readable")));
    }
    let findings = |name: &str, source: &[u8], select: &[&str]| -> Vec<(usize, &str, String)> {
        let settings = lint::Settings {
            selection: Selection {
                select: select.iter().map(|code| code.to_string()).collect(),
                ..Selection::default()
            },
            ..lint::Settings::default()
        };
        let kind = program_kind(Some(name), source);
        lint::check(source, name, kind, &settings)
            .into_iter()
            .filter(|d| MODAL.contains(&d.code()))
            .map(|d| (d.span.start, d.code(), d.message.clone()))
            .collect()
    };
    let mut found = 0;
    for (name, source) in &sources {
        let together = findings(name, source, &MODAL);
        let mut alone: Vec<(usize, &str, String)> = MODAL
            .iter()
            .flat_map(|code| findings(name, source, &[code]))
            .collect();
        alone.sort();
        let mut sorted = together.clone();
        sorted.sort();
        assert_eq!(sorted, alone, "{name}");
        found += together.len();
    }
    // The file of several programs finds each rule.
    let several = findings("SEVERAL.MPF", several, &MODAL);
    for code in MODAL {
        assert!(
            several.iter().any(|(_, c, _)| *c == code),
            "{code}: {several:?}"
        );
    }
    assert!(found >= 10, "{found}");
}

/// The editor's analysis makes the CYCLE600 walk beside the line pass, on a
/// model of its own: its findings are the command line's, on every fixture
/// and every program of the outside corpus.
#[test]
fn the_walk_beside_the_line_pass_changes_no_finding() {
    let mut files = support::files_below(&support::repo().join("tests/fixtures"));
    files.extend(support::corpus_files());
    let settings = lint::Settings {
        heads: Some(sample_heads()),
        ..lint::Settings::default()
    };
    let never = || false;
    let mut walked = 0;
    for path in &files {
        let source = std::fs::read(path).expect("readable");
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("?");
        let kind = program_kind(Some(name), &source);
        let here = lint::analyze_program(&source, name, kind, &settings);
        let aside = lint::analyze_program_until(&source, name, kind, &settings, &never);
        let aside = aside.expect("never stopped");
        assert_eq!(here.findings, aside.findings, "{name}");
        walked += usize::from(here.walk.is_some());
    }
    assert!(walked > 20, "{walked} programs walked");
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(400))]

    /// Random mixes of plain lines with the lines the plain-line rules watch
    /// (block numbers, STOPRE and main-run reads, DEF, program ends, long
    /// blocks, suppression comments).
    #[test]
    fn skipping_plain_lines_changes_no_finding_in_random_programs(
        lines in proptest::collection::vec(proptest::prop_oneof![
            "N[0-9]{1,4} G1 X[0-9.]{1,6} Y-[0-9]{1,3}",
            "N[0-9]{1,3}",
            "N[0-9]{1,2}\\.5 X1",
            "X1 ; sinuprep: ignore N0[0-9]{2}",
            "; sinuprep: ignore N014",
            "; sinuprep: ignore-file N01[0-9]",
            "STOPRE",
            "R1=\\$AA_IM\\[X\\]",
            "DEF REAL A[0-9]",
            "M30",
            "M17",
            "N[0-9]{1,2} X1(0){600}",
            "(M[0-9]{1,2} ?){4,7}( ; M M)?",
            "N[0-9]{1,2} (G[0-3] ?|G9[01] ?|G1[78] ?|[XYIJF]-?[0-9]{1,2} ?|M[0-5] ?|M30 ?){1,6}",
            "(G[23] |X[0-9] |Y=R1 |CR=5 |F=R2 |M2=[35] ){1,4}",
            "(IF R1==1|ENDIF|LBL:|GOTOF N[0-9]|SUB1|G0 X1|F100)",
            "/?(N[0-9] )?(G4[0-2] |G1 |X1 |L10 |D1 ){1,3}",
            "(TRAORI|TRAFOOF|TRACYL\\(40\\))",
            "/?(N[0-9] )?(G1[7-9] |G4[0-2] |G9[01] |X1 |Z1 |D1 ){1,3}(M30|M2)?",
            "(ATRANS X1|TRANS|AROT Z5|ROT|SCALE)",
            " *",
        ], 0..24),
        ending in proptest::prop_oneof!["\n", "\r\n"],
    ) {
        let source = lines.join(&ending);
        assert_shortcut_agrees("RANDOM.MPF", source.as_bytes());
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(300))]

    /// Random programs defining macros of every shape (words, keywords,
    /// operators, calls, labels, jumps, block numbers, broken text, macros
    /// naming macros or themselves) and using them anywhere: every rule
    /// reads the trees of their expansions without a panic, every finding
    /// points inside the program, and skipping plain lines (where `M6` may
    /// be a macro) changes nothing.
    #[test]
    fn macros_of_any_shape_are_read_without_harm(
        lines in proptest::collection::vec(proptest::prop_oneof![
            "DEFINE (_A|_B|M6|ENDE|L1) AS (G1 X10 F100|M30|ENDIF|IF R1==1|MOD 3|\\(1\\+|_A|_B \\+ 1|CYCLE800\\(1,\\\"T\\\",0,57\\)|GOTOF LBL|LBL:|N10 G0|X=|R1=_B|\\$AA_IM\\[X\\]|T1 M6|CR=5|\\)|;x|\\\"S\\\")",
            "(N[0-9] )?(_A|_B|M6|ENDE|L1|T1 M6|R2=_A|IF \\(R1 _A\\)==1|X=_B Y1|G1 X_A|M6\\(1,2\\)|_A:|GOTOF _A)( ; _A)?",
            "(IF R1==1|ENDIF|LBL:|G1 X1 F100|STOPRE|M30|DEF REAL R)",
        ], 0..16),
    ) {
        let source = lines.join("\n");
        let settings = lint::Settings {
            selection: Selection {
                select: ["C", "K", "N", "S", "N015", "C619"].map(String::from).to_vec(),
                ..Selection::default()
            },
            heads: Some(sample_heads()),
            ..lint::Settings::default()
        };
        let kind = program_kind(Some("RANDOM.MPF"), source.as_bytes());
        let found = lint::check(source.as_bytes(), "RANDOM.MPF", kind, &settings);
        for diagnostic in &found {
            proptest::prop_assert!(diagnostic.span.end <= source.len(), "{diagnostic:?}");
            proptest::prop_assert!(diagnostic.span.start <= diagnostic.span.end, "{diagnostic:?}");
        }
        let every_line = sinuprep::syntax::plain::PlainScanner::ParseEveryLine;
        let reference = lint::check_with(every_line, source.as_bytes(), "RANDOM.MPF", kind, &settings);
        let ahead = lint::check_read_ahead(source.as_bytes(), "RANDOM.MPF", kind, &settings);
        proptest::prop_assert_eq!(&found, &reference);
        proptest::prop_assert_eq!(ahead, reference);
    }

    /// Control bytes are blanks to the parser: a plain line's M words end
    /// at them as a parsed block's do (an input the check fuzz target found).
    #[test]
    fn control_bytes_end_a_plain_lines_words_as_they_end_a_parsed_blocks(gap in 0usize..70) {
        let source = format!("G1 \nX3 M103 M2 M3 M4{} M2 M3 M4 M5 M6\x05;\"x\n", "\0".repeat(gap));
        let (found, reference) = on_both_paths(&source, "CONTROL.MPF");
        proptest::prop_assert_eq!(found, reference);
    }

    /// An archive's `;$PATH=` line is no comment line to the plain scan
    /// either: a long one is no block too long (N008) on either path (an
    /// input the check fuzz target found).
    #[test]
    fn an_archive_path_line_is_read_alike_on_both_paths(
        case in "(;\\$PATH=|;\\$path=|; \\$PATH=|;\\$PAT)",
        fill in 500usize..700,
    ) {
        let source = format!("%_N_MGUD_DEF\r\n{case}/_N_{}\r\nDEF NCK REAL _X\r\nM30\r\n", "\0".repeat(fill));
        let (found, reference) = on_both_paths(&source, "GUD.DEF");
        proptest::prop_assert_eq!(found, reference);
    }

    /// Every fix, safe and unsafe, applied to random programs: the fixed
    /// program has no more syntax errors than the original, and after the
    /// safe fixes a second run finds nothing more to fix safely (safe fixes
    /// never overlap: names in the code, directives in comments).
    #[test]
    fn fixes_answer_their_findings_and_break_nothing(
        lines in proptest::collection::vec(proptest::prop_oneof![
            "DEF REAL (Depth|DEPTH|Count)",
            "R1=(DEPTH|depth|Count|COUNTT|DEPTHH)\\+1( ; sinuprep: ignore (N005|N016|N015)(, N00[0-9])?)?",
            "GOTOF (ENDE|END1|END2)",
            "(END1|ENDE):",
            "IFF R1==1",
            "; sinuprep: ignore-file N01[0-9]",
            "G1 X1",
            "M30",
        ], 0..16),
        ending in proptest::prop_oneof!["\n", "\r\n"],
    ) {
        let source = lines.join(&ending);
        let settings = lint::Settings {
            selection: Selection { select: vec!["N".into(), "S".into(), "N015".into()], ..Selection::default() },
            ..lint::Settings::default()
        };
        let run = |bytes: &[u8]| lint::check(bytes, "RANDOM.MPF", ProgramKind::Main, &settings);
        let before = run(source.as_bytes());
        for unsafe_fixes in [false, true] {
            let (edits, _) = lint::fix::applicable(&before, unsafe_fixes);
            let fixed = sinuprep::edit::apply(source.as_bytes(), &edits);
            proptest::prop_assert!(support::syntax_errors(&fixed).len() <= support::syntax_errors(source.as_bytes()).len());
            if !unsafe_fixes {
                let again = run(&fixed);
                let (more, _) = lint::fix::applicable(&again, false);
                proptest::prop_assert!(more.is_empty(), "{:?}", String::from_utf8_lossy(&fixed));
            }
        }
    }
}

/// Blocks after the end that run on to the file's end are one mistake:
/// N027 reports it, N010 does not say it again; after a label a jump may
/// reach, the missing end is N010's again.
#[test]
fn blocks_after_the_end_are_reported_once() {
    let codes = |source: &str| -> Vec<&'static str> {
        lint::check(
            source.as_bytes(),
            "P.MPF",
            ProgramKind::Main,
            &lint::Settings::default(),
        )
        .iter()
        .map(|d| d.code())
        .filter(|c| ["N010", "N027"].contains(c))
        .collect()
    };
    assert_eq!(
        codes("N10 G1 X10 F100\nN20 M30\nN30 G0 Z100\nN40 G0 X0\n"),
        ["N027"]
    );
    assert_eq!(
        codes("N10 G1 X10 F100\nN20 M30\nLBL:\nN30 G0 Z100\n"),
        ["N010"]
    );
    assert_eq!(
        codes("N10 G1 X10 F100\nN20 M30\nN30 G0 Z100\nLBL:\nN40 G0 X0\n"),
        ["N027", "N010"]
    );
    assert_eq!(codes("N10 G1 X10 F100\nN20 G0 Z100\n"), ["N010"]);
}

/// A broken `$TC_CARR` line is one syntax error, in a program and in swivel
/// data alike: the records are read from the same lines the rules parse
/// (a program's line was read again as swivel data, its S002 reported twice).
#[test]
fn a_syntax_error_in_a_swivel_data_line_is_reported_once() {
    let source = b"N10 $TC_CARR5[1=3\nN20 M30\n";
    for swivel_data in [false, true] {
        let settings = lint::Settings {
            swivel_data,
            ..lint::Settings::default()
        };
        let found = lint::check(source, "P.MPF", ProgramKind::Main, &settings);
        let s002 = found.iter().filter(|d| d.code() == "S002").count();
        assert_eq!(s002, 1, "swivel data: {swivel_data}: {found:#?}");
    }
}

/// `docs/rules.md` is the rules' own documentation: regenerate it with
/// `SINUPREP_WRITE_DOCS=1 cargo test --test lint the_rule_reference` after
/// changing a rule.
#[test]
fn the_rule_reference_is_the_rules_documentation() {
    let path = support::repo().join("docs/rules.md");
    let made = lint::reference::reference();
    if std::env::var_os("SINUPREP_WRITE_DOCS").is_some() {
        std::fs::write(&path, &made).expect("docs/rules.md");
    }
    let written = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        written == made,
        "docs/rules.md is stale: run SINUPREP_WRITE_DOCS=1 cargo test --test lint the_rule_reference"
    );
}

/// A machine's macro definition file given (`tests/fixtures/macros`): its
/// macros expand where the program writes them, so the IF with an operator
/// macro, the call through `M6` and the program end `ENDE` read as the
/// control reads them. Without it, they are syntax errors, and the note
/// says that a name where an operator belongs may be a macro.
#[test]
fn a_macro_definition_file_reads_the_program_as_the_control_does() {
    let program = "tests/fixtures/macros/TOOL_CHANGE.MPF";
    // Alone, away from the definition file beside it (which is found).
    let alone = support::scratch("macros_alone").join("TOOL_CHANGE.MPF");
    std::fs::copy(program, &alone).expect("copy");
    let alone = alone.to_str().expect("utf-8");
    let output = run(&["check", "--format", "short", alone], b"");
    assert_exit(&output, 1);
    let report = stdout(&output);
    for expected in [
        ":4:27: error[S002] `_DEC2` stands where an operator belongs",
        ":6:5: error[N004]",
        ":9:7: error[S005]",
    ] {
        assert!(report.contains(expected), "{expected} in {report}");
    }
    let note = String::from_utf8_lossy(&output.stderr);
    assert!(
        note.contains("2 lines with a syntax error have a name where an operator belongs"),
        "{note}"
    );
    let output = run(
        &[
            "check",
            "--format",
            "short",
            "--definitions",
            "tests/fixtures/macros/MMAC.DEF",
            program,
        ],
        b"",
    );
    assert_exit(&output, 0);
    assert_eq!(stdout(&output), "");
    let beside = run(&["check", "--format", "short", program], b"");
    assert_exit(&beside, 0);
    assert_eq!(stdout(&beside), "");
}

/// What the machine's definitions would answer is not told as the
/// program's fault: the control's own procedures are no subprograms to
/// look for, and a name read without the machine's definitions may be
/// theirs (no advice to DEF it, which would break a macro's use); given
/// the definitions, a name they lack is the program's own slip.
#[test]
fn what_the_machine_defines_is_not_the_programs_fault() {
    let source = b"N10 SETMS(2)\nN20 CTABDEF(Y,X,1,0)\nN30 MY_SUB(1)\nN40 R1=WT_ZONE\nM30\n";
    let unknown = |settings: &lint::Settings| {
        let outcome = lint::check_outcome(source, "PART.MPF", ProgramKind::Main, settings);
        let n005 = outcome
            .diagnostics
            .iter()
            .find(|d| d.code() == "N005")
            .cloned();
        (outcome.unresolved_calls, n005.expect("N005 on WT_ZONE"))
    };
    let (unresolved, without) = unknown(&lint::Settings::default());
    assert_eq!(unresolved, ["MY_SUB"]);
    assert!(without
        .message
        .contains("no definitions of the machine were given"));
    assert!(without
        .help
        .as_deref()
        .is_some_and(|h| h.contains("--definitions")));
    let mut settings = lint::Settings::default();
    settings
        .environment
        .read_definitions(b"DEF NCK REAL _OTHER\n", Some((Path::new("GUD.DEF"), 0)))
        .expect("a definition file");
    settings.environment.given = true;
    let (_, with) = unknown(&settings);
    assert_eq!(
        with.message,
        "`WT_ZONE` is read before any DEF or assignment"
    );
}

/// A macro the program defines itself is read as the control reads it:
/// its name is no variable read before its DEF (N005), and a macro that
/// stands for M30 ends the program (N010); a name the program never
/// defines is still N005.
#[test]
fn the_programs_own_macros_are_no_undefined_names() {
    let dir = support::scratch("own_macros");
    let program = dir.join("OWN.MPF");
    std::fs::write(
        &program,
        "DEFINE E_Y AS R1\nDEFINE M99 AS M30\nR2=E_Y+NOT_DEFINED\nG0 X1\nM99\n",
    )
    .expect("write");
    let output = run(
        &[
            "check",
            "--format",
            "short",
            program.to_str().expect("utf-8"),
        ],
        b"",
    );
    let report = stdout(&output);
    assert!(
        report.contains(":3:8: warning[N005] `NOT_DEFINED`"),
        "{report}"
    );
    assert!(
        !report.contains("E_Y") && !report.contains("N010"),
        "{report}"
    );
}
