//! Parse-tree snapshots, one fixture per construct (`tests/fixtures/parse`),
//! and of the samples: none may have a syntax diagnostic.

mod support;

use std::path::Path;

use sinuprep::syntax::parse;

fn snapshot_tree(name: &str, path: &Path) {
    let source = std::fs::read(path).expect("input");
    let program = parse(&source);
    assert!(
        program.diagnostics.is_empty(),
        "{}: {:?}",
        path.display(),
        program.diagnostics
    );
    insta::assert_snapshot!(name, support::dump::dump(&program));
}

#[test]
fn parse_trees() {
    insta::glob!("fixtures/parse/*", |path| snapshot_tree(
        "parse_trees",
        path
    ));
}

#[test]
fn samples_parse_without_diagnostics() {
    insta::glob!("..", "samples/*", |path| snapshot_tree(
        "samples_parse_without_diagnostics",
        path
    ));
}
