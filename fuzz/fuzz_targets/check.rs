//! Linting never panics, every finding points inside the input, and the
//! plain-line shortcut finds exactly what parsing every line finds.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sinuprep::lint::{check, check_with, Selection};
use sinuprep::semantic::{Heads, Supplied};
use sinuprep::syntax::plain::PlainScanner;
use sinuprep::syntax::program_kind;

fuzz_target!(|data: &[u8]| {
    let heads = Heads::read(
        "HEAD_DEF".into(),
        b"_HEAD_NAME=\"UFK600\"\n_HEAD_ALLOWED=1\n",
    );
    let kind = program_kind(None, data);
    let (selection, supplied) = (Selection::default(), Supplied::default());
    let findings = check(data, "FUZZ.MPF", kind, &selection, &supplied, Some(&heads));
    let every_line = PlainScanner::ParseEveryLine;
    let reference = check_with(
        every_line,
        data,
        "FUZZ.MPF",
        kind,
        &selection,
        &supplied,
        Some(&heads),
    );
    assert_eq!(findings, reference);
    for finding in &findings {
        assert!(
            finding.span.start <= finding.span.end && finding.span.end <= data.len(),
            "{}",
            finding.code
        );
    }
});
