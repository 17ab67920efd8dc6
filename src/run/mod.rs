//! `sinuprep run`: the dry run. The program executed offline on the
//! machine its own data describe ([`setup`]): its control flow and
//! variables, the modal state, the frames and the tool ([`frame`]), each
//! block's end point on every machine axis (MCS) and the travel inside it
//! (arcs' turning points, [`arc`]) against the software limits, and its
//! time from the feed and the axes' dynamics ([`profile`]).
//!
//! What cannot be known offline (a measured value, a condition on one, a
//! subprogram not followed, a function not modelled) is named with its
//! block in [`Report::unknown`]; the run goes on and says what it took.

pub mod arc;
pub mod contour;
mod execute;
pub mod frame;
pub mod on_machine;
pub mod plot;
pub mod profile;
pub(crate) mod programs;
pub mod setup;

pub use execute::run;
pub use programs::{subprogram_sources, Programs};
pub use setup::{RunAxis, Setup};

use crate::diagnostic::Diagnostic;
use crate::number::format;
use crate::registry::axis_beyond_limit::RULE;
use crate::span::Span;

/// At most this many excursions past a limit are listed (the rest are
/// counted): a program far off its machine passes them by the million.
pub const MOST_VIOLATIONS: usize = 10_000;

/// How to run.
#[derive(Clone, Debug)]
pub struct Options {
    /// MD32300/MD32431's dynamic response group (0 DYNNORM).
    pub dynamic_group: usize,
    /// The second pair of software limits (MD36120/36130), as the PLC may
    /// select them.
    pub second_limits: bool,
    /// At most this many blocks are executed: a loop that never ends is
    /// told, not followed for ever.
    pub block_limit: u64,
    /// Seconds a word (`M6`) or a call (`CYCLE800`) takes each time it
    /// runs, by its text in upper case (`[run] times` in sinuprep.toml).
    pub times: std::collections::BTreeMap<String, f64>,
    /// How many values of GUD variables and R parameters the machine's data
    /// gave ([`setup::values_with_data`]): said among the assumptions.
    pub values_from_data: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            dynamic_group: 0,
            second_limits: false,
            block_limit: 50_000_000,
            times: std::collections::BTreeMap::new(),
            values_from_data: 0,
        }
    }
}

/// Which limit a position passes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    Plus,
    Minus,
}

/// A machine axis beyond its software limit: from the block that takes it
/// there to the last block after which it is still beyond (a loop that
/// passes the first again adds to it), and the furthest point it reaches.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Violation {
    /// The subprogram the block is in (by name); `None` for the main program.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub program: Option<String>,
    /// 1-based.
    pub line: usize,
    pub last_line: usize,
    #[serde(skip)]
    pub span: Span,
    /// The machine axis (MD10000's name).
    pub axis: String,
    pub value: f64,
    pub limit: f64,
    pub side: Side,
}

impl Violation {
    /// The limit passed, as a finding (K007) on its block.
    pub fn diagnostic(&self) -> Diagnostic {
        let (side, datum) = match self.side {
            Side::Plus => ("plus", "MD36110 $MA_POS_LIMIT_PLUS"),
            Side::Minus => ("minus", "MD36100 $MA_POS_LIMIT_MINUS"),
        };
        let by = (self.value - self.limit).abs();
        let stays = match self.last_line {
            last if last > self.line => format!(" (beyond it up to line {last})"),
            _ => String::new(),
        };
        RULE.at(self.span)
            .message(format!(
                "machine axis {} reaches {}, {} past its {side} software limit {} ({datum}){stays}: the control stops here with alarm 10720",
                self.axis,
                format(self.value, 3),
                format(by, 3),
                format(self.limit, 3),
            ))
            .label("beyond the travel")
            .help("program the move within the travel, or check the zero offset, the tool and the machine data given")
    }
}

/// Something the run could not know, and what it did instead.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Unknown {
    /// The subprogram the block is in (by name); `None` for the main program.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub program: Option<String>,
    /// 1-based; 0 for what is said of the whole run (the machine's data).
    pub line: usize,
    #[serde(skip)]
    pub span: Span,
    pub why: String,
}

/// One block's end, as the run passes it.
#[derive(Debug)]
pub struct BlockEnd<'a> {
    /// The subprogram the block is in; `None` for the main program.
    pub program: Option<&'a str>,
    /// 1-based.
    pub line: usize,
    /// Each run axis's machine position, in [`Setup::axes`]'s order.
    pub mcs: &'a [Option<f64>],
    /// The time so far (seconds, as [`Report::time_s`]).
    pub t_s: f64,
    /// The arc the block moved along, in machine coordinates of the
    /// geometry axes.
    pub arc: Option<&'a arc::Arc>,
}

/// A machine axis's travel over the run.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Travel {
    /// The machine axis (MD10000's name), or the program's name where the
    /// data name none.
    pub axis: String,
    pub min: Option<f64>,
    pub max: Option<f64>,
    pub limits: [Option<f64>; 2],
}

/// The time spent with one tool.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct ToolTime {
    pub t: String,
    pub time_s: f64,
}

/// What a run found.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Report {
    /// The exact-stop blocks' time exact, the continuous-path blocks' at
    /// their feed without slowing down at their corners: the lower bound.
    pub time_s: f64,
    /// Continuous-path blocks at their feed (lower) and each block from
    /// rest to rest (upper).
    pub time_bounds_s: [f64; 2],
    /// Blocks whose time is not in the figures (a dynamic datum missing).
    pub blocks_without_time: u64,
    pub tools: Vec<ToolTime>,
    pub axes: Vec<Travel>,
    /// The first [`MOST_VIOLATIONS`] excursions past a limit.
    pub violations: Vec<Violation>,
    /// Excursions past a limit beyond those listed.
    pub violations_untold: u64,
    pub unknown: Vec<Unknown>,
    /// What the run took for granted, once each.
    pub assumptions: Vec<String>,
    /// Blocks executed.
    pub blocks: u64,
    /// The program came back to a state it was in: it runs until stopped,
    /// and the run ended there.
    pub endless: Option<Endless>,
}

/// A program that comes back to a state it was in, and so repeats from it
/// for ever: every block it runs later, it has run from the same state.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Endless {
    /// The subprogram it repeats in (by name); `None` for the main program.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub program: Option<String>,
    /// Where the repetition was found (1-based): the line the jump back
    /// goes to, and the line it jumps from.
    pub line: usize,
    pub from_line: usize,
    /// One pass: its blocks and its time (seconds, as [`Report::time_s`]).
    pub pass_blocks: u64,
    pub pass_s: f64,
    /// In the pass the run took something it could not know for a value
    /// (said in [`Report::unknown`]): with the true value the program may
    /// end.
    pub rests_on_unknown: bool,
    /// The variables that only count (nothing but themselves reads them)
    /// and counted on in the pass: left out of the state compared.
    pub counting: Vec<String>,
}
