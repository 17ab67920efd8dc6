//! The dry run (`sinuprep run`) of the document on the machine its
//! settings name: where a block's hover says the axes are, and the
//! software limits the program passes (K007) among its findings.

use crate::diagnostic::Diagnostic;
use crate::machine::MachineData;
use crate::run::{BlockEnd, Options, Programs, Report, Setup};

use super::Snapshot;

/// The largest document run on each change: past it (a CAM program of
/// millions of blocks takes seconds) the limits are `sinuprep run`'s to check.
pub const MOST_RUN_BYTES: usize = 10_000_000;

/// The most blocks one dry run passes (a loop the run cannot end stops there).
const MOST_RUN_BLOCKS: u64 = 1_000_000;

impl Snapshot<'_, '_> {
    /// The dry run of the program, each block's end handed to `each`, with
    /// the machine it ran on; `None` without a machine whose data describe
    /// its axes.
    pub(super) fn dry_run(&self, each: impl FnMut(BlockEnd)) -> Option<(Setup, Report)> {
        let machine = self.settings.machine.as_deref()?;
        let data = MachineData::read(&machine.source);
        let setup = Setup::of(&data).with_records(&machine.machine);
        if setup.axes.iter().all(|a| a.machine.is_none()) {
            return None;
        }
        let (values, from_data) =
            crate::run::setup::values_with_data(&self.settings.supplied, &data);
        let options = Options {
            block_limit: MOST_RUN_BLOCKS,
            values_from_data: from_data,
            ..Options::default()
        };
        let programs = Programs::alone(self.model);
        let report = crate::run::run(&programs, &setup, &values, &options, each);
        Some((setup, report))
    }

    /// The software limits the program's own blocks pass on the machine
    /// (K007), as `sinuprep run` reports them; none for a document larger
    /// than [`MOST_RUN_BYTES`].
    pub(super) fn limit_findings(&self) -> Vec<Diagnostic> {
        if self.text.bytes().len() > MOST_RUN_BYTES {
            return Vec::new();
        }
        let Some((_, report)) = self.dry_run(|_| {}) else {
            return Vec::new();
        };
        report
            .violations
            .iter()
            .filter(|v| v.program.is_none())
            .map(|v| v.diagnostic())
            .collect()
    }
}
