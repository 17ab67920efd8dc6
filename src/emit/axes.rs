//! With the machine known, each rewritten swivel gets a comment above its
//! new code naming where the machine's rotary axes go (`; sinuprep: on
//! UFK600 the axes go to C=-180 A=-20`): the control still does the
//! kinematics, the comment tells the reader what it will do.

use crate::edit::Edit;
use crate::semantic::swivels::{self, OnMachine};
use crate::semantic::Analysis;
use crate::syntax::lines::dominant_ending;

/// The comments for the calls of `analysis` that `edits` rewrote.
pub fn comments(source: &[u8], analysis: &Analysis, edits: &[Edit], on: &OnMachine) -> Vec<Edit> {
    // Read only when a comment is written: it scans the whole program.
    let eol = std::cell::OnceCell::new();
    analysis
        .calls
        .iter()
        .filter(|site| edits.iter().any(|edit| edit.span == site.statement))
        .filter_map(|site| {
            let asked = swivels::of_cycle600(site)?;
            let mut comment = crate::emit::cycle600::indent(source, site).to_vec();
            comment.extend_from_slice(b"; sinuprep: ");
            comment.extend_from_slice(swivels::taken(&asked, on).as_bytes());
            comment.extend_from_slice(eol.get_or_init(|| dominant_ending(source)).as_bytes());
            Some(Edit::insert(site.content.start, comment))
        })
        .collect()
}
