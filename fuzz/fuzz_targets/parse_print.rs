//! Any bytes parse, and printing the parse gives them back.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let program = sinuprep::syntax::parse(data);
    assert!(program.print() == data, "printing the parse changed bytes");
    for diagnostic in &program.diagnostics {
        assert!(diagnostic.span.end <= data.len());
    }
});
