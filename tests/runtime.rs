//! Run-time arithmetic (`--emit-runtime`): the generated NC is executed with
//! the project's own evaluator for thousands of measured values, and must give
//! what the offline engine gives.

use proptest::prelude::*;
use sinuprep::emit::apply;
use sinuprep::emit::cycle600::{rewrite, Options};
use sinuprep::number::format;
use sinuprep::rotation::{convert, decompose, matrix, Kind, Sequence};
use sinuprep::semantic::value::Value;
use sinuprep::semantic::walk::run;
use sinuprep::semantic::{Heads, Model, Supplied};
use sinuprep::syntax::parse;

fn heads() -> Heads {
    Heads::read(
        "HEAD_DEF.SPF".into(),
        b"_HEAD_NAME=\"UFK600\"\n_HEAD_ALLOWED=1\n",
    )
}

/// A program with one CYCLE600 whose angles are R10..R12, never assigned.
fn program(from: Sequence, to: Sequence, recalculate: bool) -> String {
    format!(
        "; runtime\nN10 CYCLE600({}, \"UFK600\", {}, {}, 1, 2, 3, R10, R11, R12, 4, 5, 6, {}, {}, 0, 0, 0)\nN20 M30\n",
        u8::from(from.kind == Kind::Intrinsic),
        u8::from(recalculate),
        from.code(),
        u8::from(to.kind == Kind::Intrinsic),
        to.code()
    )
}

/// Rewrites with run-time arithmetic, then runs the result with the measured
/// angles assigned where the original call stood.
fn execute(
    source: &str,
    angles: [f64; 3],
    options: &Options,
) -> (String, sinuprep::semantic::env::Env) {
    let heads = heads();
    let model = Model::of(source.as_bytes());
    let analysis = sinuprep::semantic::analyze(&model, &Supplied::default(), Some(&heads));
    let rewritten = rewrite(&model, &analysis, options);
    assert!(rewritten.refused == 0, "{:?}", rewritten.diagnostics);
    let output = String::from_utf8(apply(source.as_bytes(), &rewritten.edits)).expect("ASCII");
    assert!(
        parse(output.as_bytes()).diagnostics.is_empty(),
        "generated code has syntax errors:\n{output}"
    );
    assert!(
        output.lines().all(|l| l.len() <= 512),
        "a block longer than the control accepts"
    );
    let values = format!("R10={} R11={} R12={}\n", angles[0], angles[1], angles[2]);
    let at = output.find("; sinuprep:").expect("original kept");
    let executed = format!("{}{values}{}", &output[..at], &output[at..]);
    let (_, env) = run(
        &Model::of(executed.as_bytes()),
        &Supplied::default(),
        Some(&heads),
    );
    (output, env)
}

fn number(env: &sinuprep::semantic::env::Env, key: &str) -> f64 {
    match env.value(key) {
        Some(Value::Number(n)) => *n,
        other => panic!("{key} is {other:?}"),
    }
}

fn sequences() -> Vec<Sequence> {
    Sequence::all().collect()
}

/// Angles of every kind, or ones whose output is at or near gimbal lock.
fn case() -> impl Strategy<Value = (usize, usize, [f64; 3])> {
    let angle = || -400.0..400.0f64;
    let near = prop_oneof![Just(0.0), -1e-7..1e-7f64, -1e-3..1e-3f64];
    (
        0usize..24,
        0usize..24,
        [angle(), angle(), angle()],
        any::<bool>(),
        near,
    )
        .prop_map(|(f, t, angles, gimbal, d)| {
            let all = sequences();
            if !gimbal {
                return (f, t, angles);
            }
            // Output angles at lock (+ d), read back as input angles.
            let to = all[t];
            let middle = if to.is_proper_euler() {
                180.0 - d.abs()
            } else {
                90.0 - d.abs()
            };
            let rotation = matrix(to, [angles[0] / 3.0, middle, angles[2] / 3.0]);
            (f, t, decompose(all[f], &rotation).angles)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    #[test]
    fn generated_results_equal_the_offline_engine((f, t, angles) in case()) {
        let all = sequences();
        let (from, to) = (all[f], all[t]);
        // What the control will read: the literals as printed.
        let angles = angles.map(|a| format(a, 12).parse::<f64>().unwrap_or(0.0));
        let options = Options { runtime: Some(None), ..Options::default() };
        let (output, env) = execute(&program(from, to, true), angles, &options);
        let got = [number(&env, "_CYC600_2"), number(&env, "_CYC600_3"), number(&env, "_CYC600_4")];
        let expected = convert(from, angles, to);
        let difference = (matrix(to, got).matrix() - expected.matrix.matrix()).abs().max();
        prop_assert!(difference < 1e-9, "matrix differs by {difference:e}\n{output}");
        // Away from gimbal lock the split into angles is well conditioned.
        let reproduced = expected.output;
        let conditioning = if to.is_proper_euler() { reproduced.angles[1].to_radians().sin() } else { reproduced.angles[1].to_radians().cos() };
        if conditioning.abs() > 1e-5 {
            for (g, e) in got.iter().zip(reproduced.angles) {
                let d = (g - e).rem_euclid(360.0);
                prop_assert!(d.min(360.0 - d) < 1e-9, "{got:?} vs {:?}\n{output}", reproduced.angles);
            }
        }
        prop_assert_eq!(number(&env, "_CYC600_6"), to.code() as f64);
    }

    #[test]
    fn run_time_cycle800_equals_the_offline_rewrite(f in 0usize..24, t in 0usize..12, angles in [-180.0..180.0f64, -180.0..180.0f64, -180.0..180.0f64], r_parameters in any::<bool>()) {
        let all = sequences();
        // CYCLE800 takes the Tait-Bryan orders only.
        let tait_bryan: Vec<Sequence> = all.iter().copied().filter(|s| !s.is_proper_euler()).collect();
        let (from, to) = (all[f], tait_bryan[t]);
        let angles = angles.map(|a| format(a, 12).parse::<f64>().unwrap_or(0.0));
        let source = program(from, to, false);
        let runtime = Options { runtime: Some(r_parameters.then_some(100)), ..Options::default() };
        let (output, env) = execute(&source, angles, &runtime);
        // Offline, with the same values supplied, at full precision.
        let mut supplied = Supplied::default();
        for (n, a) in angles.iter().enumerate() {
            supplied.insert(format!("R{}", 10 + n), Value::Number(*a), "test".into());
        }
        let model = Model::of(source.as_bytes());
        let analysis = sinuprep::semantic::analyze(&model, &supplied, Some(&heads()));
        let offline = rewrite(&model, &analysis, &Options { precision: 15, ..Options::default() });
        let offline = String::from_utf8(apply(source.as_bytes(), &offline.edits)).expect("ASCII");
        let args = |text: &str| -> Vec<String> {
            let line = text.lines().find(|l| l.contains("CYCLE800(")).expect("a CYCLE800").to_string();
            let inside = &line[line.find('(').expect("(") + 1..line.rfind(')').expect(")")];
            inside.split(',').map(str::to_string).collect()
        };
        let (generated, literal) = (args(&output), args(&offline));
        prop_assert_eq!(&generated[3], &literal[3], "_MODE");
        // A literal, or the variable the generated code computed.
        let value = |text: &str| -> f64 { text.parse().unwrap_or_else(|_| number(&env, text)) };
        let mode: i64 = literal[3].parse().expect("mode");
        let sequence = Sequence::from_code(mode, Kind::Intrinsic).expect("mode");
        let got = [value(&generated[7]), value(&generated[8]), value(&generated[9])];
        let expected = [value(&literal[7]), value(&literal[8]), value(&literal[9])];
        let difference = (matrix(sequence, got).matrix() - matrix(sequence, expected).matrix()).abs().max();
        prop_assert!(difference < 1e-9, "{got:?} vs {expected:?}\n{output}");
    }
}
