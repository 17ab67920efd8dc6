//! Every label of a file, in one table the rules share: 32 bytes a label,
//! names read back from the source when asked (a program can have a million
//! labels, and three rules look them up).

use crate::span::Span;

#[derive(Clone, Copy, Debug)]
struct Entry {
    /// Of the upper-case name: equal names have equal hashes.
    hash: u64,
    span: Span,
    /// 0-based.
    row: usize,
}

/// The labels, sorted by name hash and row once the line pass is over.
#[derive(Default, Debug)]
pub struct Labels {
    entries: Vec<Entry>,
}

/// FNV-1a over the upper-case bytes (labels are not case-sensitive).
fn hash(name: &[u8]) -> u64 {
    name.iter().fold(0xcbf2_9ce4_8422_2325, |hash, &b| {
        (hash ^ u64::from(b.to_ascii_uppercase())).wrapping_mul(0x0100_0000_01b3)
    })
}

impl Labels {
    /// Records the label at `span` on line `row` (during the line pass).
    pub fn record(&mut self, source: &[u8], row: usize, span: Span) {
        self.entries.push(Entry {
            hash: hash(span.of(source)),
            span,
            row,
        });
    }

    /// Ready for look-ups.
    pub fn sorted(mut self) -> Self {
        self.entries.sort_unstable_by_key(|e| (e.hash, e.row));
        self.entries.shrink_to_fit();
        self
    }

    /// The rows where `name` (any case) stands, in order.
    pub fn rows<'s>(&'s self, source: &'s [u8], name: &'s str) -> impl Iterator<Item = usize> + 's {
        let wanted = hash(name.as_bytes());
        let first = self.entries.partition_point(|e| e.hash < wanted);
        self.entries[first..]
            .iter()
            .take_while(move |e| e.hash == wanted)
            .filter(move |e| e.span.of(source).eq_ignore_ascii_case(name.as_bytes()))
            .map(|e| e.row)
    }

    pub fn contains(&self, source: &[u8], name: &str) -> bool {
        self.rows(source, name).next().is_some()
    }

    /// Each name once, upper case.
    pub fn names<'s>(&'s self, source: &'s [u8]) -> impl Iterator<Item = String> + 's {
        self.with_first(source)
            .filter(|(_, first)| first.is_none())
            .map(move |(e, _)| String::from_utf8_lossy(e.span.of(source)).to_ascii_uppercase())
    }

    /// Every label that stands again after its first line: its span, its
    /// name (upper case) and the first line (0-based).
    pub fn repeated(&self, source: &[u8]) -> Vec<(Span, String, usize)> {
        self.with_first(source)
            .filter_map(|(e, first)| {
                let name = String::from_utf8_lossy(e.span.of(source)).to_ascii_uppercase();
                Some((e.span, name, first?.row))
            })
            .collect()
    }

    /// Each entry with the first entry of the same name before it, if any
    /// (looked for among the entries of the same hash only).
    fn with_first<'s>(
        &'s self,
        source: &'s [u8],
    ) -> impl Iterator<Item = (&'s Entry, Option<&'s Entry>)> + 's {
        self.entries
            .chunk_by(|a, b| a.hash == b.hash)
            .flat_map(move |group| {
                group.iter().enumerate().map(move |(i, e)| {
                    let text = e.span.of(source);
                    let first = group[..i]
                        .iter()
                        .find(|o| o.span.of(source).eq_ignore_ascii_case(text));
                    (e, first)
                })
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_found_in_any_case_and_repeats_name_the_first_line() {
        let source = b"START: X1\nloop: X2\nLOOP: X3\nEND:\nStart:\n";
        let mut labels = Labels::default();
        for (row, (start, len)) in [(0, 5), (10, 4), (19, 4), (28, 3), (33, 5)]
            .into_iter()
            .enumerate()
        {
            labels.record(source, row, Span::new(start, start + len));
        }
        let labels = labels.sorted();
        assert_eq!(labels.rows(source, "LOOP").collect::<Vec<_>>(), [1, 2]);
        assert!(labels.contains(source, "end"));
        assert!(!labels.contains(source, "ENDE"));
        let mut names: Vec<String> = labels.names(source).collect();
        names.sort();
        assert_eq!(names, ["END", "LOOP", "START"]);
        let mut repeated = labels.repeated(source);
        repeated.sort_by_key(|(span, ..)| span.start);
        assert_eq!(
            repeated,
            [
                (Span::new(19, 23), "LOOP".to_string(), 1),
                (Span::new(33, 38), "START".to_string(), 0)
            ]
        );
    }
}
