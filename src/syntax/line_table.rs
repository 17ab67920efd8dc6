//! A program's line table: where lines start and which are plain, so that
//! a pass (the CYCLE600 walk, the rewrite) can go to any line and parse it
//! when it needs its tree.

use std::cell::Cell;

use crate::syntax::lines::RawLine;
use crate::syntax::tree::Line;
use crate::syntax::{lines, parse_line_kind, plain};

/// A program's lines, each parsed when asked for: memory holds where every
/// [`STRIDE`]th line starts and a bit a line for whether it is plain (a
/// quarter of a byte a line), never the whole tree nor every line's start,
/// however large the program.
pub struct Lines<'src> {
    pub source: &'src [u8],
    len: usize,
    /// Where lines 0, `STRIDE`, 2 `STRIDE`, ... start: another line is found
    /// by reading on from the one before it that is known.
    strided_starts: Vec<usize>,
    /// Bit `n % 64` of word `n / 64`: line `n` is plain ([`plain::is_plain`]),
    /// asked by every pass over the lines.
    plain: Vec<u64>,
    /// The line found last and where it starts: the passes over the lines go
    /// forward, so the next line asked for is mostly read on from there.
    last: Cell<(usize, usize)>,
}

/// One line in this many has its start kept.
const STRIDE: usize = 32;

impl<'src> Lines<'src> {
    pub fn new(source: &'src [u8]) -> Self {
        let mut recorder = LinesRecorder::default();
        plain::scanned_lines(source).for_each(|line| recorder.record(&line));
        recorder.finish(source)
    }

    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Line `index` holds only address words with numbers (see [`plain::is_plain`]).
    pub fn is_plain(&self, index: usize) -> bool {
        assert!(index < self.len, "line {index} of {}", self.len);
        self.plain[index / 64] & (1 << (index % 64)) != 0
    }

    /// Line `index` (0-based): its content and ending, read on from the
    /// nearest line before it whose start is known.
    pub fn raw(&self, index: usize) -> RawLine {
        assert!(index < self.len, "line {index} of {}", self.len);
        let strided = index / STRIDE * STRIDE;
        let (mut at, mut start) = match self.last.get() {
            (last, start) if (strided..=index).contains(&last) => (last, start),
            _ => (strided, self.strided_starts[index / STRIDE]),
        };
        while at < index {
            start = lines::line_from(self.source, start).full().end;
            at += 1;
        }
        self.last.set((index, start));
        lines::line_from(self.source, start)
    }

    /// The tree of line `index` (0-based).
    pub fn parse(&self, index: usize) -> Line {
        let raw = self.raw(index);
        let (kind, _) = parse_line_kind(raw.content.of(self.source), raw.content.start);
        Line { raw, kind }
    }
}

/// Builds a [`Lines`] table from a pass over the lines that another job
/// makes anyway (`check`'s rules), instead of scanning the file again.
#[derive(Default)]
pub struct LinesRecorder {
    len: usize,
    strided_starts: Vec<usize>,
    plain: Vec<u64>,
}

impl LinesRecorder {
    /// The next line, in order from the first.
    pub fn record(&mut self, line: &plain::Scanned) {
        let index = self.len;
        if index.is_multiple_of(STRIDE) {
            self.strided_starts.push(line.raw().content.start);
        }
        if index.is_multiple_of(64) {
            self.plain.push(0);
        }
        if let (plain::Scanned::Plain(_), Some(word)) = (line, self.plain.last_mut()) {
            *word |= 1 << (index % 64);
        }
        self.len += 1;
    }

    /// The table of the lines recorded, which must be all of `source`'s.
    pub fn finish(self, source: &[u8]) -> Lines<'_> {
        Lines {
            source,
            len: self.len,
            strided_starts: self.strided_starts,
            plain: self.plain,
            last: Cell::new((0, 0)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// The line table keeps every 32nd line's start; the lines it gives
        /// back, in any order, are the ones splitting the source gives,
        /// endings included, and so are their plain bits.
        #[test]
        fn the_line_table_gives_back_every_line(
            text in "[aN1 ;\r\n]{0,60}|([aN1 X;]{0,6}(\r\n|\n|\r)){0,200}[aN1 ]{0,3}",
            order in proptest::collection::vec(proptest::prelude::any::<usize>(), 0..300),
        ) {
            let source = text.as_bytes();
            let lines = Lines::new(source);
            let expected: Vec<plain::Scanned> = plain::scanned_lines(source).collect();
            proptest::prop_assert_eq!(lines.len(), expected.len());
            let forward = 0..expected.len();
            let shuffled = order.iter().map(|n| n % expected.len().max(1));
            for index in forward.chain(shuffled).filter(|&n| n < expected.len()) {
                proptest::prop_assert_eq!(lines.raw(index), expected[index].raw());
                let plain = matches!(expected[index], plain::Scanned::Plain(_));
                proptest::prop_assert_eq!(lines.is_plain(index), plain);
            }
        }
    }
}
