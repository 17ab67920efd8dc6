//! The dry run of one program on the machine its settings name, as `check`
//! and the editor make it: the software limits its own blocks pass (K007)
//! among its findings, and where a block takes the axes (the editor's
//! hover). Its subprograms are not followed (`sinuprep run` follows them).

use super::{BlockEnd, Options, Programs, Report, Setup};
use crate::diagnostic::Diagnostic;
use crate::machine::MachineData;
use crate::semantic::env::Supplied;
use crate::semantic::model::Model;
use crate::semantic::swivels::OnMachine;

/// The largest program run with its analysis: past it (a CAM program of
/// millions of blocks takes seconds) the limits are `sinuprep run`'s to
/// check.
pub const MOST_RUN_BYTES: usize = 10_000_000;

/// The most blocks one such run passes (a loop the run cannot end stops
/// there).
const MOST_RUN_BLOCKS: u64 = 1_000_000;

/// The dry run of `model` alone on `on`, with the values `supplied`, each
/// block's end handed to `each`; `None` where the machine's data describe
/// none of its axes.
pub fn run_on(
    model: &Model,
    on: &OnMachine,
    supplied: &Supplied,
    each: impl FnMut(BlockEnd),
) -> Option<(Setup, Report)> {
    let data = MachineData::read(&on.source);
    let setup = Setup::of(&data).with_records(&on.machine);
    if setup.axes.iter().all(|a| a.machine.is_none()) {
        return None;
    }
    let (values, from_data) = super::setup::values_with_data(supplied, &data);
    let options = Options {
        block_limit: MOST_RUN_BLOCKS,
        values_from_data: from_data,
        ..Options::default()
    };
    let programs = Programs::alone(model);
    let report = super::run(&programs, &setup, &values, &options, each);
    Some((setup, report))
}

/// The software limits the program's own blocks pass on `on` (K007), as
/// `sinuprep run` reports them; none for a program larger than
/// [`MOST_RUN_BYTES`].
pub fn limit_findings(model: &Model, on: &OnMachine, supplied: &Supplied) -> Vec<Diagnostic> {
    if model.source.len() > MOST_RUN_BYTES {
        return Vec::new();
    }
    let Some((_, report)) = run_on(model, on, supplied, |_| {}) else {
        return Vec::new();
    };
    report
        .violations
        .iter()
        .filter(|v| v.program.is_none())
        .map(|v| v.diagnostic())
        .collect()
}
