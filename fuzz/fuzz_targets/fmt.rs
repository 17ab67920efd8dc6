//! Any bytes format without a panic; formatting the result again changes
//! nothing; a program with syntax errors is left as it is, and no
//! formatting changes which errors a program has.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sinuprep::edit::apply;
use sinuprep::format::{format, Case, Settings};
use sinuprep::semantic::Model;
use sinuprep::syntax::program_kind;

fuzz_target!(|data: &[u8]| {
    // The first byte picks the settings, so that every option is fuzzed.
    let (choice, source) = match data.split_first() {
        Some((&choice, rest)) => (choice, rest),
        None => (0, data),
    };
    let settings = Settings {
        indent: if choice & 1 == 0 { "  " } else { "\t" }.to_string(),
        case: [Case::Upper, Case::Lower, Case::Keep][usize::from(choice >> 1) % 3],
        max_blank_lines: usize::from(choice >> 3) % 3,
        indent_proc_body: choice & 0x20 == 0,
        renumber: (choice & 0x40 != 0).then_some((10, 10)),
        case_names: choice & 0x80 != 0,
    };
    let name = "FUZZ.MPF";
    let kind = program_kind(Some(name), source);
    let once = format(name, source, kind, &settings);
    for edit in &once.edits {
        assert!(edit.span.end <= source.len());
    }
    if !once.syntax.is_empty() {
        assert!(once.edits.is_empty(), "a program with syntax errors changed");
        return;
    }
    let formatted = apply(source, &once.edits);
    let errors = |bytes: &[u8]| Model::build(bytes, program_kind(Some(name), bytes)).syntax.len();
    assert_eq!(errors(&formatted), errors(source), "formatting changed the syntax errors");
    let twice = format(name, &formatted, program_kind(Some(name), &formatted), &settings);
    assert!(
        twice.edits.is_empty(),
        "formatting again changed it: {:?}",
        String::from_utf8_lossy(&formatted)
    );
});
