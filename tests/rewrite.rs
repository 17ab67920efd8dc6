//! The rewrite, end to end through the binary: snapshots of what it emits and
//! says for each fixture (`tests/fixtures/rewrite`, arguments on a first
//! `; args:` line), plus checks that do not rely on the snapshots: the
//! emitted swivel reproduces the CYCLE600 rotation (computed here
//! independently), the rewrite is idempotent, keeps every other byte, and
//! adds no syntax error.

mod support;

use support::{assert_exit, run};

use nalgebra::{Matrix3, Rotation3, Vector3};
use sinuprep::emit::apply;
use sinuprep::emit::cycle600::{rewrite, Form, Options};
use sinuprep::semantic::value::Value;
use sinuprep::semantic::{analyze, Heads, Model, Supplied};
use sinuprep::syntax::lines::raw_lines;

/// The arguments a fixture asks for on its first line.
fn fixture_args(source: &[u8]) -> Vec<String> {
    let first = String::from_utf8_lossy(source)
        .lines()
        .next()
        .unwrap_or_default()
        .to_string();
    first
        .strip_prefix("; args:")
        .map(|a| a.split_whitespace().map(String::from).collect())
        .unwrap_or_default()
}

#[test]
fn rewrites() {
    insta::glob!("fixtures/rewrite/*.mpf", |path| {
        let source = std::fs::read(path).expect("fixture");
        let relative = path
            .strip_prefix(env!("CARGO_MANIFEST_DIR"))
            .expect("inside the repo")
            .to_string_lossy()
            .into_owned();
        let extra = fixture_args(&source);
        let mut args: Vec<&str> = vec![
            "rewrite",
            &relative,
            "--heads",
            "samples/HEAD_DEF.SPF",
            "--message-format",
            "short",
        ];
        args.extend(extra.iter().map(String::as_str));
        let output = run(&args, b"");
        let mut diff_args = args.clone();
        diff_args.push("--diff");
        let diff = run(&diff_args, b"");

        assert_invariants(&relative, &source, &output.stdout, &args);
        let snapshot = format!(
            "## Arguments\n{}\n## Exit status\n{}\n## Diagnostics\n{}\n## Diff\n{}",
            extra.join(" "),
            output.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&output.stderr),
            String::from_utf8_lossy(&diff.stdout)
        );
        insta::assert_snapshot!(snapshot);
    });
}

fn assert_invariants(name: &str, source: &[u8], output: &[u8], args: &[&str]) {
    // Rewriting the output again changes nothing.
    let mut again_args: Vec<&str> = args.to_vec();
    again_args[1] = "-";
    let again = run(&again_args, output);
    assert_eq!(
        again.stdout, output,
        "{name}: a second rewrite changed the output"
    );
    // The syntax errors stay what they were.
    assert_eq!(
        support::syntax_errors(output),
        support::syntax_errors(source),
        "{name}: the rewrite changed the syntax errors"
    );
    // Added lines use the file's line ending.
    if !source.windows(2).any(|w| w[1] == b'\n' && w[0] != b'\r') && !source.starts_with(b"\n") {
        assert!(
            !output.windows(2).any(|w| w[1] == b'\n' && w[0] != b'\r'),
            "{name}: an added line ends in LF in a CRLF file"
        );
    }
    // Every line without CYCLE600 is kept, in order (with --inline-results,
    // lines reading its results change too); lines as the tool splits them.
    let inline = args.contains(&"--inline-results");
    let out_lines: Vec<&[u8]> = raw_lines(output).map(|l| l.content.of(output)).collect();
    let mut at = 0;
    for line in raw_lines(source).map(|l| l.content.of(source)) {
        if contains(line, b"CYCLE600") || (inline && contains(line, b"_CYC600_")) {
            continue;
        }
        match out_lines[at..].iter().position(|o| *o == line) {
            Some(found) => at += found + 1,
            None => panic!("{name}: line {:?} lost", String::from_utf8_lossy(line)),
        }
    }
    check_swivels_independently(name, output);
}

fn contains(haystack: &[u8], needle: &[u8]) -> bool {
    haystack.windows(needle.len()).any(|w| w == needle)
}

// ---- the independent check -------------------------------------------------

/// Right-handed rotation about X, Y or Z (0, 1, 2) by degrees, via nalgebra's
/// axis-angle constructor (not the engine's own elemental matrices).
fn elemental(axis: usize, degrees: f64) -> Matrix3<f64> {
    let unit = [Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis()][axis];
    *Rotation3::from_axis_angle(&unit, degrees.to_radians()).matrix()
}

/// The axes of a Siemens code, first rotation in bits 1-0.
fn axes(code: u32) -> [usize; 3] {
    [0, 2, 4].map(|shift| ((code >> shift) & 0b11) as usize - 1)
}

fn numbers(arguments: &str) -> Option<Vec<f64>> {
    arguments
        .split(',')
        .map(|a| {
            let a = a.trim();
            if a.is_empty() {
                Some(0.0)
            } else {
                a.parse().ok()
            }
        })
        .collect()
}

/// For each `; sinuprep: CYCLE600(...)` comment with literal arguments, the
/// rotation of the call must equal the rotation of what replaced it.
fn check_swivels_independently(name: &str, output: &[u8]) {
    let text = String::from_utf8_lossy(output);
    let lines: Vec<&str> = text.lines().collect();
    for (i, line) in lines.iter().enumerate() {
        let Some(call) = line.trim_start().strip_prefix("; sinuprep: ") else {
            continue;
        };
        let inside = &call[call.find('(').expect("call") + 1..call.rfind(')').expect("call")];
        let without_head: String = inside
            .split(',')
            .enumerate()
            .map(|(i, a)| if i == 1 { "0" } else { a })
            .collect::<Vec<_>>()
            .join(",");
        let Some(mut v) = numbers(&without_head) else {
            continue;
        };
        if v.len() == 19 {
            v.remove(13);
        }
        if v[2] == 1.0 || v[15] == 1.0 {
            continue; // recalculation only, or additive: depends on the active rotation
        }
        let [a, b, c] = axes(v[3] as u32);
        let [t1, t2, t3] = [v[7], v[8], v[9]];
        let expected = if v[0] == 1.0 {
            elemental(a, t1) * elemental(b, t2) * elemental(c, t3)
        } else {
            elemental(c, t3) * elemental(b, t2) * elemental(a, t1)
        };
        let next = lines[i + 1];
        let actual = if let Some(start) = next.find("CYCLE800(") {
            let args: Vec<&str> = next[start + 9..next.rfind(')').expect("call")]
                .split(',')
                .collect();
            let mode: u32 = args[3].trim().parse().expect("mode");
            let angle = |k: usize| args[k].trim().parse::<f64>().expect("angle");
            let [p, q, r] = axes(mode);
            elemental(p, angle(7)) * elemental(q, angle(8)) * elemental(r, angle(9))
        } else {
            // Frames: the AROT blocks that follow, in order (intrinsic).
            let mut product = Matrix3::identity();
            for block in lines[i + 1..].iter().take(8) {
                if let Some(rest) = block.trim_start().strip_prefix("AROT ") {
                    let (axis, angle) = rest.split_once('=').expect("AROT axis=angle");
                    let axis = "XYZ".find(axis.trim()).expect("axis");
                    product *= elemental(axis, angle.trim().parse().expect("angle"));
                }
            }
            product
        };
        let difference = (expected - actual).abs().max();
        // 6 decimals move an angle by at most 5e-7 degrees: about 1e-8 in the matrix.
        assert!(
            difference < 1e-7,
            "{name}: line {}: swivel differs from CYCLE600 by {difference:e}",
            i + 2
        );
    }
}

// ---- samples and the outside corpus ---------------------------------------

fn rewrite_bytes(source: &[u8], heads: Option<&Heads>) -> Vec<u8> {
    let model = Model::of(source);
    let analysis = analyze(&model, &Supplied::default(), heads);
    let rewritten = rewrite(&model, &analysis, &Options::default());
    apply(source, &rewritten.edits)
}

#[test]
fn samples_and_corpus_rewrite_idempotently_and_keep_every_other_byte() {
    let heads_source =
        std::fs::read(support::repo().join("samples/HEAD_DEF.SPF")).expect("HEAD_DEF");
    let heads = Heads::read("HEAD_DEF.SPF".into(), &heads_source);
    let mut files = support::files_below(&support::repo().join("samples"));
    files.extend(support::corpus_files());
    for path in files {
        let source = std::fs::read(&path).expect("readable");
        let once = rewrite_bytes(&source, Some(&heads));
        let twice = rewrite_bytes(&once, Some(&heads));
        let name = path.display().to_string();
        assert_eq!(once, twice, "{name}: not idempotent");
        if !contains(&source, b"CYCLE600") {
            assert_eq!(once, source, "{name}: changed without a CYCLE600");
        }
        assert_eq!(
            support::syntax_errors(&once),
            support::syntax_errors(&source),
            "{name}: the rewrite changed the syntax errors"
        );
        check_swivels_independently(&name, &once);
    }
}

#[test]
fn rewriting_in_place_keeps_a_backup_and_refuses_on_errors() {
    let dir = std::env::temp_dir().join(format!("sinuprep-in-place-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let good = dir.join("GOOD.MPF");
    let original = b"N10 CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\nN20 M30\n";
    std::fs::write(&good, original).expect("write");
    let heads = support::repo().join("samples/HEAD_DEF.SPF");
    let heads = heads.to_string_lossy();
    let output = run(
        &[
            "rewrite",
            "--in-place",
            good.to_str().expect("utf-8"),
            "--heads",
            &heads,
        ],
        b"",
    );
    assert_exit(&output, 0);
    let rewritten = std::fs::read(&good).expect("read");
    assert!(contains(&rewritten, b"CYCLE800(0,\"UFK600\",0,39,"));
    assert_eq!(
        std::fs::read(dir.join("GOOD.MPF.bak")).expect("backup"),
        original
    );

    let bad = dir.join("BAD.MPF");
    let refused =
        b"N10 CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, R20, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\n";
    std::fs::write(&bad, refused).expect("write");
    let output = run(
        &[
            "rewrite",
            "--in-place",
            bad.to_str().expect("utf-8"),
            "--heads",
            &heads,
        ],
        b"",
    );
    assert_exit(&output, 1);
    assert_eq!(
        std::fs::read(&bad).expect("read"),
        refused,
        "a file with errors is not touched"
    );
    assert!(!dir.join("BAD.MPF.bak").exists());
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .expect("dir")
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().ends_with(".tmp"))
        .collect();
    assert!(leftovers.is_empty(), "no temporary file is left behind");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_mode_exits_1_when_something_would_change() {
    let changes = run(&["rewrite", "--check", "samples/PAPER_EXAMPLE3.MPF"], b"");
    assert_exit(&changes, 1);
    assert!(changes.stdout.is_empty());
    let nothing = run(&["rewrite", "--check", "-"], b"N10 G0 X0\n");
    assert_exit(&nothing, 0);
}

// ---- random programs -------------------------------------------------------

const SNIPPETS: &[&str] = &[
    "IF R1>0",
    "IF R50>0",
    "ELSE",
    "ENDIF",
    "WHILE R2<3",
    "ENDWHILE",
    "FOR R3=0 TO 2",
    "ENDFOR",
    "LOOP",
    "ENDLOOP",
    "REPEAT",
    "UNTIL R4>1",
    "GOTOF L1",
    "GOTOB L1",
    "GOTO L2",
    "IF R1==1 GOTOF L2",
    "L1:",
    "L2: R1=1",
    "GOTOS",
    "CASE R1 OF 1 GOTOF L1 2 GOTOB L2 DEFAULT GOTOF L2",
    "R1=R1+1",
    "R1=30",
    "R2=45.5",
    "R4=$AA_MW[X]",
    "CYCLE998(100105,9000,6,1,1,0,,10,0.5,103,2,60,,,,,1,0,1,)",
    "R5=_OVR[16]",
    "DEF REAL ANG=10",
    "CYCLE800()",
    "CYCLE800(0,\"UFK600\",0,57,0,0,0,R1,0,30,0,0,0,-1)",
    "CYCLE800(0,\"UFK600\",1,39,0,0,0,10,20,30,0,0,0,1)",
    "CYCLE600(0, \"UFK600\", 1, 57, 0, 0, 0, R1, R2, 60, 0, 0, 0, 0, 1, 39, 0, 0, 0)",
    "CYCLE600(1, \"UFK600\", 0, 39, 1, 2, 3, R1, 90, R5, 0, 0, 5, 1, 27, 1, 0, 0)",
    "CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 10, 20, 30, 0, 0, 0, 0, 55, 1, 1, 1)",
    "CYCLE600(0, \"NOHEAD\", 0, 58, 0, 0, 0, ASIN(2), 20, 30, 0, 0, 0, 1, 39, 0, 0, 0)",
    "CYCLE600(0, \"UFK600\", 0, 57)",
    "MSG(\"x\" << _CYC600_2)",
    "N10 X=_CYC600_3 Y=-_CYC600_4",
    "SUBPROG",
    "M30",
    "CYCLE600(0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45,",
    "IF (",
    // Frames of the program's own (spec section 8), and swivels around them.
    "AROT Z=5",
    "TRANS X10",
    "TRANS",
    "ATRANS Y=R1",
    "$P_PFRAME=CTRANS(X,1)",
    "TOFRAME",
    "CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)",
    "CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 10, 0, 0, 0, 0, 0, 1, 57, 1, 0, 0)",
    "CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 0, 0, 0, 0, 15, 0, 1, 57, 1, 1, 0)",
    "CYCLE600(0, \"UFK600\", 0, 27, 1, 2, 3, 5, 6, 7, 0, 0, 0, 1, 39, 1, 0, 0)",
    "CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, R4, 0, 0, 0, 0, 0, 1, 57, 1, 0, 0)",
    "CYCLE600(0, \"UFK600\", 0, 39, 0, 0, 0, 0, R4, 0, 0, 0, 0, 1, 57, 1, 0, 0)",
];

/// A result inlined as a string after a sign would be a syntax error
/// (`+ "UFK600"`, S005): that read stays the variable, the others are
/// inlined (found by the rewrite fuzz target).
#[test]
fn a_string_result_after_a_sign_is_not_inlined() {
    let source = b"N10 CYCLE600(0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 0, 39, 0, 0, 0)\n\
N20 STOPRE\nN30 CYCLE800(0,+ _CYC600_1, 0, _CYC600_6, 0,0,0, _CYC600_2, _CYC600_3, _CYC600_4,0,0,0,-1)\nN40 M30\n";
    let heads = Heads::read(
        "HEAD_DEF.SPF".into(),
        b"_HEAD_NAME=\"UFK600\"\n_HEAD_ALLOWED=1\n",
    );
    let options = Options {
        inline_results: true,
        runtime: Some(None),
        ..Options::default()
    };
    let model = Model::of(source);
    let analysis = analyze(&model, &Supplied::default(), Some(&heads));
    let once = apply(source, &rewrite(&model, &analysis, &options).edits);
    assert_eq!(
        support::syntax_errors(&once),
        support::syntax_errors(source)
    );
    let text = String::from_utf8_lossy(&once);
    assert!(
        text.contains("CYCLE800(0,+ _CYC600_1, 0, 39, 0,0,0, 39.639272,"),
        "{text}"
    );
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(1000))]

    #[test]
    fn random_programs_never_panic_and_rewrite_idempotently(
        picks in proptest::collection::vec(0..SNIPPETS.len(), 0..40),
        inline in proptest::bool::ANY,
        form in proptest::sample::select(vec![Form::Cycle800, Form::Frames, Form::Traori]),
        at_run_time in proptest::bool::ANY,
    ) {
        let source: String = picks.iter().map(|&i| format!("{}\n", SNIPPETS[i])).collect();
        let source = source.as_bytes();
        let heads = Heads::read("HEAD_DEF.SPF".into(), b"_HEAD_NAME=\"UFK600\"\n_HEAD_ALLOWED=1\n");
        let options = Options {
            inline_results: inline,
            form,
            runtime: at_run_time.then_some(None),
            ..Options::default()
        };
        let run = |bytes: &[u8]| {
            let model = Model::of(bytes);
            let analysis = analyze(&model, &Supplied::default(), Some(&heads));
            apply(bytes, &rewrite(&model, &analysis, &options).edits)
        };
        let once = run(source);
        proptest::prop_assert_eq!(&run(&once), &once, "not idempotent");
        proptest::prop_assert_eq!(support::syntax_errors(&once), support::syntax_errors(source));
    }

    /// A program rewritten where its values are known, and again once the
    /// measured ones are supplied, ends as one rewrite with everything
    /// supplied: the blocks emitted first count as the calls they replace.
    #[test]
    fn rewriting_in_two_steps_equals_one(
        picks in proptest::collection::vec(0..SNIPPETS.len(), 0..40),
        form in proptest::sample::select(vec![Form::Cycle800, Form::Frames, Form::Traori]),
    ) {
        let source: String = picks.iter().map(|&i| format!("{}\n", SNIPPETS[i])).collect();
        let source = source.as_bytes();
        let heads = Heads::read("HEAD_DEF.SPF".into(), b"_HEAD_NAME=\"UFK600\"\n_HEAD_ALLOWED=1\n");
        let options = Options { form, ..Options::default() };
        let mut measured = Supplied::default();
        measured.insert("R4".into(), Value::Number(12.5), "--set R4=12.5".into());
        let run = |bytes: &[u8], supplied: &Supplied| {
            let model = Model::of(bytes);
            let analysis = analyze(&model, supplied, Some(&heads));
            apply(bytes, &rewrite(&model, &analysis, &options).edits)
        };
        let first = run(source, &Supplied::default());
        let (in_two, in_one) = (run(&first, &measured), run(source, &measured));
        proptest::prop_assert_eq!(
            String::from_utf8_lossy(&in_two),
            String::from_utf8_lossy(&in_one)
        );
    }
}
