//! Parse-tree snapshots, one fixture per construct (`tests/fixtures/parse`).

mod support;

use sinuprep::syntax::parse;

#[test]
fn parse_trees() {
    insta::glob!("fixtures/parse/*", |path| {
        let source = std::fs::read(path).expect("fixture");
        let program = parse(&source);
        assert!(
            program.diagnostics.is_empty(),
            "{}: {:?}",
            path.display(),
            program.diagnostics
        );
        insta::assert_snapshot!(support::dump::dump(&program));
    });
}

#[test]
fn samples_parse_without_diagnostics() {
    insta::glob!("..", "samples/*", |path| {
        let source = std::fs::read(path).expect("sample");
        let program = parse(&source);
        assert!(
            program.diagnostics.is_empty(),
            "{}: {:?}",
            path.display(),
            program.diagnostics
        );
        insta::assert_snapshot!(support::dump::dump(&program));
    });
}
