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
pub mod cycles;
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
pub mod vocabulary;
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
    // Searched by its `L`, which a CAM program's lines of coordinates never
    // hold: their digits would stop a search for the number on nearly
    // every line.
    memchr::memchr2_iter(b'L', b'l', bytes).any(|at| {
        at >= 3
            && bytes[at - 3..at].eq_ignore_ascii_case(b"CYC")
            && bytes
                .get(at + 1)
                .is_some_and(|e| e.eq_ignore_ascii_case(&b'E'))
            && bytes[at + 2..].starts_with(number)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A mention in any case and anywhere (the file's first bytes, a
    /// comment) counts; the digits alone, or CYCLE with others, do not.
    #[test]
    fn finds_a_cycle_named_in_any_case() {
        for text in [
            "CYCLE600(0)",
            "N10 cycle600",
            "; CyClE600 below",
            "X1 Y600 CYCLE600",
        ] {
            assert!(mentions_cycle600(text.as_bytes()), "{text}");
        }
        for text in [
            "X600 Y-600.600",
            "CYCLE800(1)",
            "CYCL600",
            "YCLE600",
            "L600 CYCLE60",
            "",
        ] {
            assert!(!mentions_cycle600(text.as_bytes()), "{text}");
        }
        assert!(mentions_cycle(b"G1 cycle800()", b"800"));
    }
}
