//! Which fixes `check --fix` applies: the safe ones (and the unsafe ones
//! with `--unsafe-fixes`), in source order, each whole or not at all.

use std::collections::BTreeMap;

use crate::diagnostic::{Applicability, Diagnostic};
use crate::edit::Edit;
use crate::span::Span;

/// The edits of the fixes to apply, and how many findings they answer.
///
/// A fix whose edits overlap those of a fix taken before it is left out (its
/// finding stays, and a second `--fix` run takes it up); a fix made of the
/// very edits already taken (several unused codes of one suppression
/// comment share one) answers its finding without adding anything.
pub fn applicable(diagnostics: &[Diagnostic], unsafe_fixes: bool) -> (Vec<Edit>, usize) {
    let allowed = |applicability| applicability == Applicability::Safe || unsafe_fixes;
    let mut taken: BTreeMap<usize, Edit> = BTreeMap::new();
    let mut answered = 0;
    for fix in diagnostics.iter().filter_map(|d| d.fix.as_deref()) {
        if !allowed(fix.applicability) {
            continue;
        }
        let known = |edit: &Edit| taken.get(&edit.span.start) == Some(edit);
        if fix.edits.iter().all(known) {
            answered += 1;
            continue;
        }
        if fix
            .edits
            .iter()
            .any(|edit| !known(edit) && clashes(&taken, edit.span))
        {
            continue;
        }
        for edit in &fix.edits {
            taken.insert(edit.span.start, edit.clone());
        }
        answered += 1;
    }
    (taken.into_values().collect(), answered)
}

/// Whether an edit at `span` would overlap one taken, or start where one
/// starts (two insertions at one place have no order).
fn clashes(taken: &BTreeMap<usize, Edit>, span: Span) -> bool {
    let before = taken.range(..=span.start).next_back();
    let after = taken.range(span.start..).next();
    before.is_some_and(|(_, e)| e.span.start == span.start || e.span.end > span.start)
        || after.is_some_and(|(_, e)| e.span.start < span.end || e.span.start == span.start)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::Fix;
    use crate::edit::apply;
    use crate::registry::syntax::UNEXPECTED_TOKEN as UNEXPECTED;

    fn finding(applicability: Applicability, edits: &[(usize, usize, &str)]) -> Diagnostic {
        UNEXPECTED.at(Span::new(0, 0)).fix(Fix {
            title: "fix".into(),
            applicability,
            edits: edits
                .iter()
                .map(|&(start, end, text)| Edit::replace(Span::new(start, end), text))
                .collect(),
        })
    }

    #[test]
    fn safe_fixes_apply_whole_and_clashing_ones_wait() {
        let source = b"GOTOF LBL1 X=Abc";
        let findings = [
            finding(Applicability::Safe, &[(13, 16, "ABC")]),
            finding(Applicability::Unsafe, &[(6, 10, "LBL2")]),
            // Overlaps the first: left for another run.
            finding(Applicability::Safe, &[(14, 15, "b")]),
            // The same edit as the first: answered, applied once.
            finding(Applicability::Safe, &[(13, 16, "ABC")]),
        ];
        let (edits, answered) = applicable(&findings, false);
        assert_eq!(answered, 2);
        assert_eq!(apply(source, &edits), b"GOTOF LBL1 X=ABC");
        let (edits, answered) = applicable(&findings, true);
        assert_eq!(answered, 3);
        assert_eq!(apply(source, &edits), b"GOTOF LBL2 X=ABC");
    }

    #[test]
    fn insertions_at_one_place_clash_and_touching_edits_do_not() {
        let findings = [
            finding(Applicability::Safe, &[(3, 3, "a")]),
            finding(Applicability::Safe, &[(3, 3, "b")]),
            finding(Applicability::Safe, &[(0, 3, "xyz")]),
            finding(Applicability::Safe, &[(3, 5, "")]),
        ];
        let (edits, answered) = applicable(&findings, false);
        assert_eq!(answered, 2);
        assert_eq!(apply(b"012345", &edits), b"xyza345");
        // Edits that touch both apply; one reaching into another waits.
        let findings = [
            finding(Applicability::Safe, &[(4, 6, "ab")]),
            finding(Applicability::Safe, &[(3, 5, "c")]),
            finding(Applicability::Safe, &[(0, 4, "d")]),
            finding(Applicability::Safe, &[(5, 6, "e")]),
            finding(Applicability::Safe, &[(6, 6, "f")]),
        ];
        let (edits, answered) = applicable(&findings, false);
        assert_eq!(answered, 3);
        assert_eq!(apply(b"012345", &edits), b"dabf");
    }
}
