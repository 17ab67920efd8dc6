//! Machine kinematics: where a machine's rotary axes go for a requested
//! frame rotation, from its swivel data record. Pure math beside
//! [`crate::rotation`] (no syntax, no I/O): the record, Paden-Kahan's
//! subproblems, and the swivel with its two solutions, limits, `_DIR`,
//! Hirth grid, residual rotation and zero-point shift; a table under a
//! two-axis head, three rotary axes, split between them; a table's setup in
//! another control's words (Aerotech A3200). The model and its sources:
//! `reference/kinematics.md`.

pub mod a3200;
pub mod carrier;
pub mod record;
pub mod split;
pub(crate) mod subproblem;
pub mod swivel;

pub use carrier::Carrier;
pub use record::{Hirth, Kinematics, Record, RecordError, RotaryAxis};
pub use split::{
    split, split_nearest_either_way, Preference, Split, SplitError, TableAngle, TableAsk,
};
pub use swivel::{orientation, solve, Direction, Request, Solution, Swivel};
