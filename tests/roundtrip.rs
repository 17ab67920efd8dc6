//! `print(parse(x)) == x`, byte for byte, for every input: samples, fixtures,
//! the outside corpus, hand-made edge cases and arbitrary bytes. Also that
//! spans stay inside their lines and in order.

mod support;

use proptest::prelude::*;
use sinuprep::syntax::parse;
use sinuprep::syntax::tree::LineKind;

fn assert_lossless(name: &str, source: &[u8]) {
    let program = parse(source);
    assert!(
        program.print() == source,
        "{name}: printing the parse changed bytes"
    );
    let mut at = 0;
    for line in &program.lines {
        assert_eq!(
            line.raw.content.start, at,
            "{name}: lines must tile the file"
        );
        at = line.raw.full().end;
        if let LineKind::Block(block) = &line.kind {
            let mut previous = line.raw.content.start;
            for statement in &block.statements {
                assert!(
                    statement.span.start >= previous && statement.span.end <= line.raw.content.end,
                    "{name}: span out of line"
                );
                previous = statement.span.end;
            }
        }
    }
    assert_eq!(at, source.len(), "{name}: lines must cover the file");
    assert_eq!(
        sinuprep::syntax::diagnostics(source),
        program.diagnostics,
        "{name}: both passes agree"
    );
    for diagnostic in &program.diagnostics {
        assert!(
            diagnostic.span.end <= source.len(),
            "{name}: diagnostic outside the input"
        );
    }
}

#[test]
fn samples_and_fixtures_round_trip() {
    for path in support::own_inputs() {
        assert_lossless(
            &path.display().to_string(),
            &std::fs::read(&path).expect("readable"),
        );
    }
}

#[test]
fn outside_corpus_round_trips_without_a_syntax_error() {
    let files = support::corpus_files();
    for path in &files {
        let source = std::fs::read(path).expect("readable");
        assert_lossless(&path.display().to_string(), &source);
        let diagnostics = parse(&source).diagnostics;
        assert!(
            diagnostics.is_empty(),
            "{}: {diagnostics:#?}",
            path.display()
        );
    }
    eprintln!("outside corpus: {} files round-tripped", files.len());
}

#[test]
fn edge_cases_round_trip() {
    let cases: &[&[u8]] = &[
        b"",
        b"\n",
        b"N10 X1",
        b"N10 X1\r\nN20 X2\r\n",
        b"N10 X1\rN20 X2\r",
        b"N10 X1\n\r\nN20\r\r\n",
        b"N10 X1   \t\n\t\n",
        b"N10 X1\0 Y2\n",
        b"\xff\xfe\x00garbage ( [ \" \n",
        b"N10 ; K\xfchlmittel\n",
        b"((((((((((((((((((((((((((((((((((((((((\n",
    ];
    for case in cases {
        assert_lossless(&format!("{:?}", String::from_utf8_lossy(case)), case);
    }
}

#[test]
fn a_ten_megabyte_line_round_trips() {
    let mut line = b"N10 X=1".to_vec();
    line.extend(std::iter::repeat_n(b"+1".as_slice(), 5_000_000).flatten());
    assert_lossless("10 MB line", &line);
    let codes: Vec<_> = parse(&line).diagnostics.iter().map(|d| d.code()).collect();
    // Past 64 KiB a block of code is not read into a tree at all (S009).
    assert_eq!(codes, ["S009"], "refused with one diagnostic, not a crash");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn arbitrary_bytes_round_trip(source in proptest::collection::vec(any::<u8>(), 0..400)) {
        assert_lossless("arbitrary bytes", &source);
    }

    #[test]
    fn nc_like_text_round_trips(source in "[NGXYZRF0-9 .=+*/()\\[\\],;\"'A-Z_$:<>\r\n\t-]{0,300}") {
        assert_lossless("nc-like text", source.as_bytes());
    }
}
