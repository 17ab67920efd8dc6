//! The rewrite: CYCLE600 calls replaced by native code, as text edits
//! ([`crate::edit`]). Everything outside an edit is copied from the source,
//! so bytes the rewrite does not touch cannot change.

pub mod axes;
pub mod cycle600;
pub(crate) mod diff;
pub(crate) mod runtime;
pub mod split;

pub use crate::edit::{apply, write_applied, Edit};
