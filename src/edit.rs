//! Text edits: what a rewrite or a fix changes, as non-overlapping (span,
//! text) pairs. Everything outside an edit is copied from the source, so
//! bytes no edit touches cannot change. Emitters and rules build edits;
//! nothing here decides what to change.

use std::io::{self, Write};

use crate::span::Span;

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Edit {
    /// Replaced bytes; empty for an insertion.
    pub span: Span,
    pub text: Vec<u8>,
}

impl Edit {
    pub fn replace(span: Span, text: impl Into<Vec<u8>>) -> Edit {
        Edit {
            span,
            text: text.into(),
        }
    }

    pub fn insert(at: usize, text: impl Into<Vec<u8>>) -> Edit {
        Edit {
            span: Span::new(at, at),
            text: text.into(),
        }
    }
}

/// The source with `edits` applied. Edits are sorted here; overlapping ones
/// are a bug in an emitter, and the later one is dropped rather than
/// producing a corrupt file.
pub fn apply(source: &[u8], edits: &[Edit]) -> Vec<u8> {
    let mut out =
        Vec::with_capacity(source.len() + edits.iter().map(|e| e.text.len()).sum::<usize>());
    write_applied(source, edits, &mut out).expect("writing to memory cannot fail");
    out
}

/// [`apply`], written piece by piece to `out`: the rewritten program is never
/// held in memory beside the source.
pub fn write_applied(
    source: &[u8],
    edits: &[Edit],
    out: &mut (impl Write + ?Sized),
) -> io::Result<()> {
    let mut sorted: Vec<&Edit> = edits.iter().collect();
    sorted.sort_by_key(|e| (e.span.start, e.span.end));
    let mut at = 0;
    for edit in sorted {
        if edit.span.start < at {
            debug_assert!(false, "overlapping edits at {:?}", edit.span);
            continue;
        }
        copy(&source[at..edit.span.start], out)?;
        out.write_all(&edit.text)?;
        at = edit.span.end;
    }
    copy(&source[at..], out)
}

fn copy(bytes: &[u8], out: &mut (impl Write + ?Sized)) -> io::Result<()> {
    out.write_all(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edits_apply_in_order_and_leave_the_rest() {
        let source = b"N10 X1 Y2\nN20 Z3\n";
        let edits = [
            Edit::replace(Span::new(14, 16), "Z=4"),
            Edit::insert(0, "; top\n"),
            Edit::replace(Span::new(4, 6), "X5"),
        ];
        assert_eq!(apply(source, &edits), b"; top\nN10 X5 Y2\nN20 Z=4\n");
        assert_eq!(apply(source, &[]), source);
    }
}
