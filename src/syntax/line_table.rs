//! A program's line table: where lines start, which are plain, and the
//! trees of the others, so that a pass (the CYCLE600 walk, the rewrite) can
//! go to any line and read its tree without parsing it again.

use std::borrow::Cow;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

use crate::syntax::lines::RawLine;
use crate::syntax::macros::Macros;
use crate::syntax::tree::{Block, Line, LineKind};
use crate::syntax::{lines, parse_line_kind, plain};

/// A program's lines: memory holds where every `STRIDE`th line starts, a
/// bit a line for whether it is plain (a quarter of a byte a line), and the
/// trees of the lines that are not plain up to `KEPT_TREES` bytes of their
/// source. A plain line, or one past that budget, is parsed when asked for:
/// it costs a byte scan, and a CAM program's millions of them would not fit.
pub struct Lines<'src> {
    pub source: &'src [u8],
    len: usize,
    /// Where lines 0, `STRIDE`, 2 `STRIDE`, ... start: another line is found
    /// by reading on from the one before it that is known.
    strided_starts: Vec<usize>,
    /// Bit `n % 64` of word `n / 64`: line `n` is plain ([`plain::is_plain`]),
    /// asked by every pass over the lines.
    plain: Vec<u64>,
    /// The line found last and where it starts ([`Cursor`]): the passes over
    /// the lines go forward, so the next line asked for is mostly read on
    /// from there. One atomic word, so that the table can be read from
    /// several threads (an editor's server); a reader that finds it moved
    /// by another only reads on from an earlier start.
    last: AtomicU64,
    /// (line, tree) of the lines not plain, in line order.
    trees: Vec<(usize, Line)>,
    /// The macros a line parsed again is read with (see [`crate::syntax::macros`]).
    macros: Option<Arc<Macros>>,
}

/// One line in this many has its start kept.
const STRIDE: usize = 32;

/// A line and how far past its stride's first line it starts, in one word:
/// 32 bits each. A line past the 2^32nd, or starting 4 GiB past its
/// stride's start, is not remembered (nothing a program holds).
struct Cursor {
    line: usize,
    past_stride: usize,
}

impl Cursor {
    const NONE: u64 = u64::MAX;

    fn pack(line: usize, past_stride: usize) -> u64 {
        match (u32::try_from(line), u32::try_from(past_stride)) {
            (Ok(line), Ok(past)) if line != u32::MAX => (u64::from(line) << 32) | u64::from(past),
            _ => Self::NONE,
        }
    }

    fn unpack(word: u64) -> Option<Self> {
        (word != Self::NONE).then(|| Self {
            line: (word >> 32) as usize,
            past_stride: (word & u64::from(u32::MAX)) as usize,
        })
    }
}

/// Source bytes of lines whose trees are kept: a tree costs about 50 bytes a
/// byte of source, so this is about 50 MiB, against 5 MiB for the largest
/// hand-written program met (93 KB). Past it, lines are parsed again when asked.
pub const KEPT_TREES: usize = 1 << 20;

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

    /// The line (0-based) `offset` is on, counted as [`crate::span::LineIndex`]
    /// counts rows: an offset on a line's ending is that line's, the end of
    /// a file that ends with a line break is on the line after.
    pub fn row_of(&self, offset: usize) -> usize {
        let offset = offset.min(self.source.len());
        let stride = self
            .strided_starts
            .partition_point(|&start| start <= offset)
            .saturating_sub(1);
        let start = self.strided_starts.get(stride).copied().unwrap_or(0);
        stride * STRIDE + crate::span::line_ends(self.source, start..offset)
    }

    /// Line `index` (0-based): its content and ending, read on from the
    /// nearest line before it whose start is known.
    pub fn raw(&self, index: usize) -> RawLine {
        assert!(index < self.len, "line {index} of {}", self.len);
        let strided = index / STRIDE * STRIDE;
        let strided_start = self.strided_starts[index / STRIDE];
        let (mut at, mut start) = match Cursor::unpack(self.last.load(Ordering::Relaxed)) {
            Some(Cursor { line, past_stride }) if (strided..=index).contains(&line) => {
                (line, strided_start + past_stride)
            }
            _ => (strided, strided_start),
        };
        while at < index {
            start = lines::line_from(self.source, start).full().end;
            at += 1;
        }
        let cursor = Cursor::pack(index, start - strided_start);
        self.last.store(cursor, Ordering::Relaxed);
        lines::line_from(self.source, start)
    }

    /// The tree of line `index` (0-based): kept, or parsed now.
    pub fn line(&self, index: usize) -> Cow<'_, Line> {
        if !self.is_plain(index) {
            if let Ok(at) = self.trees.binary_search_by_key(&index, |(row, _)| *row) {
                return Cow::Borrowed(&self.trees[at].1);
            }
        }
        let raw = self.raw(index);
        let expansion = self
            .macros
            .as_ref()
            .and_then(|m| m.expand(raw.content.of(self.source), raw.content.start));
        if let Some(expansion) = expansion {
            let (kind, _) = parse_line_kind(&expansion.text, 0, &mut Vec::new());
            let mut line = Line { raw, kind };
            expansion.map_line(&mut line);
            return Cow::Owned(line);
        }
        let (kind, _) = parse_line_kind(
            raw.content.of(self.source),
            raw.content.start,
            &mut Vec::new(),
        );
        Cow::Owned(Line { raw, kind })
    }

    /// Lines parsed again are read with `macros` expanded: those the
    /// program was read with (its own as defined at its end).
    pub fn read_with(&mut self, macros: Arc<Macros>) {
        self.macros = Some(macros);
    }

    /// The block of line `index`, if the line is one (not a `%` header or
    /// `;$PATH=` line); `None` past the last line.
    pub fn block(&self, index: usize) -> Option<Cow<'_, Block>> {
        if index >= self.len {
            return None;
        }
        match self.line(index) {
            Cow::Borrowed(Line {
                kind: LineKind::Block(block),
                ..
            }) => Some(Cow::Borrowed(block)),
            Cow::Owned(Line {
                kind: LineKind::Block(block),
                ..
            }) => Some(Cow::Owned(block)),
            _ => None,
        }
    }

    /// The lines that are not plain, in order, with their trees: the lines
    /// that can hold anything but address words with numbers.
    pub fn other_lines(&self) -> impl Iterator<Item = (usize, Cow<'_, Line>)> + '_ {
        (0..self.len)
            .filter(|&index| !self.is_plain(index))
            .map(|index| (index, self.line(index)))
    }
}

/// Builds a [`Lines`] table from a pass over the lines that another job
/// makes anyway (`check`'s rules), instead of scanning the file again.
#[derive(Default)]
pub struct LinesRecorder {
    len: usize,
    strided_starts: Vec<usize>,
    plain: Vec<u64>,
    trees: Vec<(usize, Line)>,
    /// Source bytes of the kept trees.
    kept: usize,
}

impl LinesRecorder {
    /// The next line, in order from the first.
    pub fn record(&mut self, line: &plain::Scanned) {
        let start = line.raw().content.start;
        match line {
            plain::Scanned::Plain(_) => self.record_plain_run(1, |_| start),
            plain::Scanned::Other(_) => self.record_other(start),
        }
    }

    /// The next line, one that is not plain, starting at `start`.
    pub fn record_other(&mut self, start: usize) {
        let index = self.len;
        if index.is_multiple_of(STRIDE) {
            self.strided_starts.push(start);
        }
        if index.is_multiple_of(64) {
            self.plain.push(0);
        }
        self.len += 1;
    }

    /// The next `count` lines, all plain, the start of the `n`th of them
    /// given by `start_of(n)`: a run is recorded at a cost of a few words,
    /// not of a few steps a line.
    pub fn record_plain_run(&mut self, count: usize, start_of: impl Fn(usize) -> usize) {
        let first = self.len;
        let end = first + count;
        let mut strided = first.next_multiple_of(STRIDE);
        while strided < end {
            self.strided_starts.push(start_of(strided - first));
            strided += STRIDE;
        }
        self.plain.resize(end.div_ceil(64), 0);
        let mut at = first;
        while at < end {
            let (word, bit) = (at / 64, at % 64);
            let bits = (64 - bit).min(end - at);
            let mask = if bits == 64 {
                u64::MAX
            } else {
                ((1 << bits) - 1) << bit
            };
            self.plain[word] |= mask;
            at += bits;
        }
        self.len = end;
    }

    /// Keeps the tree of the line recorded last, if it is not plain and the
    /// budget allows: the passes after this one read it instead of parsing.
    pub fn keep(&mut self, line: Line) {
        let Some(index) = self.len.checked_sub(1) else {
            return;
        };
        let plain = self.plain[index / 64] & (1 << (index % 64)) != 0;
        let len = line.raw.content.len();
        if !plain && self.kept + len <= KEPT_TREES {
            self.kept += len;
            self.trees.push((index, line));
        }
    }

    /// The table of the lines recorded, which must be all of `source`'s.
    pub fn finish(mut self, source: &[u8]) -> Lines<'_> {
        self.trees.shrink_to_fit();
        Lines {
            source,
            len: self.len,
            strided_starts: self.strided_starts,
            plain: self.plain,
            last: AtomicU64::new(Cursor::NONE),
            trees: self.trees,
            macros: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// The line an offset is on is the row the reports' line index
        /// gives, at every offset, line endings and the file's end included.
        #[test]
        fn an_offset_is_on_the_row_the_line_index_gives(
            text in "[a ;\r\n]{0,80}|([aN1 X;]{0,6}(\r\n|\n|\r)){0,120}[a ]{0,3}",
        ) {
            let source = text.as_bytes();
            let lines = Lines::new(source);
            let index = crate::span::LineIndex::new(source);
            for offset in 0..=source.len() + 1 {
                proptest::prop_assert_eq!(lines.row_of(offset), index.position(offset).row - 1);
            }
        }

        /// The line table keeps every 32nd line's start; the lines it gives
        /// back, in any order, are the ones splitting the source gives,
        /// endings included, and so are their plain bits.
        #[test]
        fn the_line_table_gives_back_every_line(
            text in "[aN1 ;\r\n]{0,60}|([aN1 X;]{0,6}(\r\n|\n|\r)){0,200}[aN1 ]{0,3}|(X1\n){60,140}a\n(X1\n){0,70}",
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
            // Plain lines recorded a run at a time make the same table.
            let mut runs = LinesRecorder::default();
            let mut run: Vec<usize> = Vec::new();
            for line in &expected {
                match line {
                    plain::Scanned::Plain(p) => run.push(p.raw.content.start),
                    other => {
                        runs.record_plain_run(run.len(), |n| run[n]);
                        run.clear();
                        runs.record(other);
                    }
                }
            }
            runs.record_plain_run(run.len(), |n| run[n]);
            let runs = runs.finish(source);
            proptest::prop_assert_eq!(&runs.strided_starts, &lines.strided_starts);
            proptest::prop_assert_eq!(&runs.plain, &lines.plain);
            proptest::prop_assert_eq!(runs.len(), lines.len());
        }
    }
}
