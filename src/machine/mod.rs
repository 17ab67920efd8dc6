//! The machine as its own data describe it: the machine data of the files
//! the control writes, read by name and index ([`data`]), and what they say
//! of each axis ([`axes`]), of its tools ([`tools`]) and its settable frames
//! ([`frames`]). The swivel data records are read by
//! [`crate::semantic::machine`], the names a program may use (GUD, macros,
//! axes) by [`crate::semantic::environment`].

pub mod axes;
pub mod data;
pub mod frames;
pub mod tools;

pub use axes::{axes, Axis};
pub use data::{Datum, Index, MachineData};
pub use frames::{frames, Components};
pub use tools::{tools, Tool};
