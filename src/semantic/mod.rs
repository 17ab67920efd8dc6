//! The semantic layer: what the program means offline.
//!
//! It evaluates expressions with Sinumerik semantics, walks the program
//! tracking variables (known, unknown, measured, supplied), reads HEAD_DEF,
//! and binds and evaluates each CYCLE600 call. It produces values and
//! diagnostics, never text: rewriting is `emit`'s job.

pub mod cycle600;
pub mod env;
pub mod eval;
pub mod head_def;
pub mod value;
pub mod walk;

pub use env::Supplied;
pub use head_def::Heads;
pub use walk::{analyze, Analysis, CallSite};
