//! Where a jump lands: the label or block number it names, the lines that
//! hold it, and the one the control's search finds. The walk, the jump
//! rules, an editor's definition and the renumbering all read this one
//! answer. Computed targets (`GOTOF "L"<<I`) name nothing here.

use crate::hash::HashSet;
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

/// The line a search of `kind` from line `from` finds among `items` in the
/// order of their lines (`row`), of which those `holds` takes hold the
/// target (GOTOF the first after, GOTOB the last up to it, GOTO and GOTOC
/// forward first): split at `from` by a binary search,
/// so a jump costs no walk over every line holding its target (a program
/// may hold a label a hundred thousand times).
pub(crate) fn search_in<T>(
    items: &[T],
    row: impl Fn(&T) -> usize,
    holds: impl Fn(&T) -> bool,
    kind: GotoKind,
    from: usize,
) -> Option<usize> {
    let split = items.partition_point(|item| row(item) <= from);
    let (before, after) = items.split_at(split);
    let forward = || after.iter().find(|item| holds(item)).map(&row);
    let backward = || before.iter().rev().find(|item| holds(item)).map(&row);
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
        let search = |rows: &[usize], kind, from| search_in(rows, |&row| row, |_| true, kind, from);
        let rows = [2, 5, 9];
        assert_eq!(search(&rows, GotoKind::Forward, 5), Some(9));
        assert_eq!(search(&rows, GotoKind::Forward, 9), None);
        assert_eq!(search(&rows, GotoKind::Backward, 5), Some(5));
        assert_eq!(search(&rows, GotoKind::Backward, 1), None);
        assert_eq!(search(&rows, GotoKind::Both, 9), Some(9));
        assert_eq!(search(&rows, GotoKind::Conditional, 3), Some(5));
        assert_eq!(search(&[], GotoKind::Start, 3), Some(0));
        // Only the lines that hold the target count.
        let marked = [(1, true), (4, false), (6, true), (8, false)];
        let holds = |&(_, holds): &(usize, bool)| holds;
        let found = |kind, from| search_in(&marked, |&(row, _)| row, holds, kind, from);
        assert_eq!(found(GotoKind::Forward, 1), Some(6));
        assert_eq!(found(GotoKind::Forward, 6), None);
        assert_eq!(found(GotoKind::Backward, 5), Some(1));
        assert_eq!(found(GotoKind::Both, 7), Some(6));
    }
}
