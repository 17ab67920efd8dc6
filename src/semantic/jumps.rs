//! Where a jump lands: the label or block number it names, the lines that
//! hold it, and the one the control's search finds. The walk, the jump
//! rules, an editor's definition and the renumbering all read this one
//! answer. Computed targets (`GOTOF "L"<<I`) name nothing here.

use std::collections::HashSet;

use crate::syntax::tree::{upper, GotoKind, GotoTarget};

/// What a jump names: a label (upper case) or a block number (`N100` and
/// `N0100` name the same block; its value only, since a CAM program has
/// millions of numbers and no jump needs their text).
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Target {
    Label(String),
    Number(u64),
}

impl Target {
    /// What `target` names; `None` for a computed target.
    pub fn of(source: &[u8], target: &GotoTarget) -> Option<Self> {
        if let Some(number) = target.block_number(source) {
            return Some(Target::Number(number));
        }
        match target {
            GotoTarget::Label(name) => Some(Target::Label(upper(name.text(source)))),
            _ => None,
        }
    }
}

impl std::fmt::Display for Target {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Target::Label(name) => f.write_str(name),
            Target::Number(n) => write!(f, "N{n}"),
        }
    }
}

/// The block numbers some jump of the program names, learned as its lines
/// are read.
pub(crate) fn named_number(source: &[u8], target: Option<&GotoTarget>, named: &mut HashSet<u64>) {
    if let Some(number) = target.and_then(|t| t.block_number(source)) {
        named.insert(number);
    }
}

/// Whether a jump of `kind` on line `from` can land on line `row`: GOTOF
/// searches the lines after it, GOTOB its own and those before, GOTO and
/// GOTOC both ways.
pub(crate) fn reaches(kind: GotoKind, row: usize, from: usize) -> bool {
    match kind {
        GotoKind::Forward => row > from,
        GotoKind::Backward => row <= from,
        GotoKind::Both | GotoKind::Conditional => true,
        GotoKind::Start => row == 0,
    }
}

/// The line a search of `kind` from line `from` finds among `rows` (the
/// lines holding the target, in order).
pub(crate) fn search(rows: &[usize], kind: GotoKind, from: usize) -> Option<usize> {
    let forward = || (rows.iter().copied()).find(|&row| reaches(GotoKind::Forward, row, from));
    let backward =
        || (rows.iter().copied().rev()).find(|&row| reaches(GotoKind::Backward, row, from));
    match kind {
        GotoKind::Forward => forward(),
        GotoKind::Backward => backward(),
        GotoKind::Both | GotoKind::Conditional => forward().or_else(backward),
        GotoKind::Start => Some(0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_search_finds_as_the_control_does() {
        let rows = [2, 5, 9];
        assert_eq!(search(&rows, GotoKind::Forward, 5), Some(9));
        assert_eq!(search(&rows, GotoKind::Forward, 9), None);
        assert_eq!(search(&rows, GotoKind::Backward, 5), Some(5));
        assert_eq!(search(&rows, GotoKind::Backward, 1), None);
        assert_eq!(search(&rows, GotoKind::Both, 9), Some(9));
        assert_eq!(search(&rows, GotoKind::Conditional, 3), Some(5));
        assert_eq!(search(&[], GotoKind::Start, 3), Some(0));
    }
}
