//! The semantic layer: what the program means offline.
//!
//! It evaluates expressions with Sinumerik semantics, walks the program
//! tracking variables (known, unknown, measured, supplied), reads HEAD_DEF,
//! and binds and evaluates each CYCLE600 call; it holds the facts the rules
//! share (the model, address words, the modal state). It produces values and
//! diagnostics, never text: rewriting is `emit`'s job.

pub(crate) mod addresses;
pub(crate) mod blocks;
pub(crate) mod calls;
pub mod cycle600;
pub mod cycle800;
pub mod env;
pub mod environment;
pub mod eval;
pub mod frame_statements;
pub(crate) mod frames;
pub mod functions;
pub mod head_def;
pub mod highlight;
pub mod jumps;
pub(crate) mod labels;
pub(crate) mod line_order;
pub mod machine;
pub(crate) mod modal;
pub mod model;
pub(crate) mod structure;
pub mod swivels;
pub mod uses;
pub mod value;
pub mod walk;
pub mod words;

pub use env::Supplied;
pub use environment::Environment;
pub use head_def::Heads;
pub use model::Model;
pub use walk::{analyze, Analysis, CallSite};

/// Whether `CYCLE600` (any case) occurs anywhere in the bytes: a program
/// without it needs no walk.
pub fn mentions_cycle600(bytes: &[u8]) -> bool {
    mentions_cycle(bytes, b"600")
}

/// Whether `CYCLE<number>` (any case) occurs anywhere in the bytes.
pub(crate) fn mentions_cycle(bytes: &[u8], number: &[u8]) -> bool {
    memchr::memmem::find_iter(bytes, number)
        .any(|at| at >= 5 && bytes[at - 5..at].eq_ignore_ascii_case(b"CYCLE"))
}
