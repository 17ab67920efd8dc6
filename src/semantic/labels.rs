//! Every label of a file, in one table the rules share: about 40 bytes a
//! label plus its name (a program can have a million labels, and three rules
//! look them up). Names are kept here rather than read back from the source:
//! reads scattered over a large mapped program would map all of it again.

use crate::semantic::jumps;
use crate::span::Span;
use crate::syntax::tree::GotoKind;

#[derive(Clone, Copy, Debug)]
struct Entry {
    /// Of the upper-case name: equal names have equal hashes.
    hash: u64,
    start: usize,
    /// 0-based.
    row: usize,
    /// Where the upper-case name is in [`Labels::names`].
    name_at: usize,
    name_len: u32,
}

/// The labels, sorted by name hash and row once the line pass is over.
#[derive(Default, Debug)]
pub struct Labels {
    entries: Vec<Entry>,
    /// The upper-case names, one after another.
    names: Vec<u8>,
}

/// FNV-1a (labels are compared in upper case).
fn hash(upper: &[u8]) -> u64 {
    upper.iter().fold(0xcbf2_9ce4_8422_2325, |hash, &b| {
        (hash ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

impl Labels {
    /// Records the label at `span` on line `row` (during the line pass).
    pub fn record(&mut self, source: &[u8], row: usize, span: Span) {
        let name_at = self.names.len();
        self.names
            .extend(span.of(source).iter().map(u8::to_ascii_uppercase));
        let name_len = u32::try_from(span.len()).unwrap_or(u32::MAX);
        self.names.truncate(name_at + name_len as usize);
        self.entries.push(Entry {
            hash: hash(&self.names[name_at..]),
            start: span.start,
            row,
            name_at,
            name_len,
        });
    }

    /// Whether a label stands within the bytes `range`.
    pub fn any_within(&self, range: std::ops::Range<usize>) -> bool {
        self.entries.iter().any(|e| range.contains(&e.start))
    }

    /// Ready for look-ups.
    pub fn sorted(mut self) -> Self {
        self.entries.sort_unstable_by_key(|e| (e.hash, e.row));
        self.entries.shrink_to_fit();
        self.names.shrink_to_fit();
        self
    }

    fn name(&self, entry: &Entry) -> &[u8] {
        &self.names[entry.name_at..entry.name_at + entry.name_len as usize]
    }

    /// The rows where `name` (upper case) stands, in order.
    pub fn rows<'s>(&'s self, name: &'s str) -> impl Iterator<Item = usize> + 's {
        (self.of_hash(name).iter())
            .filter(move |e| self.name(e) == name.as_bytes())
            .map(|e| e.row)
    }

    /// The line a jump of `kind` from line `from` to label `name` (upper
    /// case) lands on, searched as the control does.
    pub fn landing(&self, name: &str, kind: GotoKind, from: usize) -> Option<usize> {
        let holds = |e: &Entry| self.name(e) == name.as_bytes();
        jumps::search_in(self.of_hash(name), |e| e.row, holds, kind, from)
    }

    /// The entries of names hashed as `name` is, in the order of their rows.
    fn of_hash(&self, name: &str) -> &[Entry] {
        let wanted = hash(name.as_bytes());
        let first = self.entries.partition_point(|e| e.hash < wanted);
        let count = self.entries[first..].partition_point(|e| e.hash == wanted);
        &self.entries[first..first + count]
    }

    /// Whether `name` (upper case) is a label.
    pub fn contains(&self, name: &str) -> bool {
        self.rows(name).next().is_some()
    }

    /// Each name once, upper case.
    pub fn names(&self) -> impl Iterator<Item = String> + '_ {
        self.with_first()
            .filter(|(_, first)| first.is_none())
            .map(|(e, _)| String::from_utf8_lossy(self.name(e)).into_owned())
    }

    /// Each entry with the first entry of the same name before it, if any
    /// (looked for among the entries of the same hash only).
    fn with_first(&self) -> impl Iterator<Item = (&Entry, Option<&Entry>)> + '_ {
        self.entries
            .chunk_by(|a, b| a.hash == b.hash)
            .flat_map(move |group| {
                group.iter().enumerate().map(move |(i, e)| {
                    let first = group[..i].iter().find(|o| self.name(o) == self.name(e));
                    (e, first)
                })
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_found_in_any_case_and_each_once() {
        let source = b"START: X1\nloop: X2\nLOOP: X3\nEND:\nStart:\n";
        let mut labels = Labels::default();
        for (row, (start, len)) in [(0, 5), (10, 4), (19, 4), (28, 3), (33, 5)]
            .into_iter()
            .enumerate()
        {
            labels.record(source, row, Span::new(start, start + len));
        }
        let labels = labels.sorted();
        assert_eq!(labels.rows("LOOP").collect::<Vec<_>>(), [1, 2]);
        assert!(labels.contains("END"));
        assert!(!labels.contains("ENDE"));
        let mut names: Vec<String> = labels.names().collect();
        names.sort();
        assert_eq!(names, ["END", "LOOP", "START"]);
    }
}
