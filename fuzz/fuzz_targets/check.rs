//! Linting never panics, and every finding points inside the input.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sinuprep::lint::{check, Selection};
use sinuprep::semantic::{Heads, Supplied};
use sinuprep::syntax::program_kind;

fuzz_target!(|data: &[u8]| {
    let heads = Heads::read(
        "HEAD_DEF".into(),
        b"_HEAD_NAME=\"UFK600\"\n_HEAD_ALLOWED=1\n",
    );
    let findings = check(
        data,
        "FUZZ.MPF",
        program_kind(None, data),
        &Selection::default(),
        &Supplied::default(),
        Some(&heads),
    );
    for finding in &findings {
        assert!(
            finding.span.start <= finding.span.end && finding.span.end <= data.len(),
            "{}",
            finding.code
        );
    }
});
