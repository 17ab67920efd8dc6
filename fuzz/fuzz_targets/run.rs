//! The dry run never panics and never runs for ever, whatever the program
//! holds (a block limit ends a loop offline), on the test machine's data:
//! every position it passes is a number, every finding and every unknown
//! points inside the input.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sinuprep::machine::MachineData;
use sinuprep::run::{run, Options, Programs, Setup};
use sinuprep::semantic::{Model, Supplied};

const MACHINE: &[u8] = include_bytes!("../../tests/fixtures/run/MACHINE.INI");

fuzz_target!(|data: &[u8]| {
    let setup = Setup::of(&MachineData::read(MACHINE));
    let options = Options {
        block_limit: 20_000,
        ..Options::default()
    };
    let model = Model::of(data);
    let programs = Programs::alone(&model);
    let report = run(&programs, &setup, &Supplied::default(), &options, |end| {
        assert!(end.mcs.iter().flatten().all(|v| v.is_finite()));
    });
    for violation in &report.violations {
        assert!(violation.span.end <= data.len());
        assert!(violation.value.is_finite());
    }
    for unknown in &report.unknown {
        assert!(unknown.span.end <= data.len());
    }
    assert!(report.time_s.is_finite() && report.time_s >= 0.0);
});
