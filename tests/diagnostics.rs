//! Rendered syntax diagnostics of broken inputs (`tests/fixtures/invalid`):
//! the short lines and the human report, without colour.

use sinuprep::cli::render::{human, short, FileReport};
use sinuprep::syntax::parse;

#[test]
fn broken_inputs_are_reported_where_they_break() {
    insta::glob!("fixtures/invalid/*", |path| {
        let source = std::fs::read(path).expect("fixture");
        let program = parse(&source);
        assert!(
            !program.diagnostics.is_empty(),
            "{} should be reported",
            path.display()
        );
        assert_eq!(program.print(), source, "diagnostics must not cost a byte");
        let name = path.file_name().and_then(|n| n.to_str()).expect("name");
        let report = FileReport {
            name,
            source: &source,
            diagnostics: &program.diagnostics,
        };
        let mut text = String::new();
        short(&report, &mut text);
        text.push('\n');
        human(&report, false, &mut text);
        insta::assert_snapshot!(text);
    });
}
