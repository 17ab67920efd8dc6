//! `textDocument/foldingRange`: control blocks and runs of comment lines.

use lsp_types as lsp;

use super::Snapshot;

impl Snapshot<'_, '_> {
    /// IF ... ENDIF, WHILE, FOR, LOOP, REPEAT ... UNTIL.
    pub fn folding(&self) -> Vec<lsp::FoldingRange> {
        let mut ranges: Vec<lsp::FoldingRange> = self
            .model
            .blocks
            .closed()
            .iter()
            .map(|block| lsp::FoldingRange {
                start_line: block.row as u32,
                end_line: block.end as u32,
                ..lsp::FoldingRange::default()
            })
            .collect();
        ranges.extend(self.comment_runs().map(|(first, last)| lsp::FoldingRange {
            start_line: first as u32,
            end_line: last as u32,
            kind: Some(lsp::FoldingRangeKind::Comment),
            ..lsp::FoldingRange::default()
        }));
        ranges.sort_by_key(|r| (r.start_line, r.end_line));
        ranges
    }

    /// Runs of two or more lines that hold only a comment: their first and
    /// last line.
    fn comment_runs(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        let source = self.text.bytes();
        let lines = &self.model.lines;
        let is_comment = move |row: usize| {
            let content = lines.raw(row).content.of(source);
            let first = content.iter().position(|b| !b.is_ascii_whitespace());
            first.is_some_and(|at| content[at] == b';')
        };
        let mut row = 0;
        std::iter::from_fn(move || {
            while row < lines.len() {
                let first = row;
                while row < lines.len() && is_comment(row) {
                    row += 1;
                }
                if row - first >= 2 {
                    return Some((first, row - 1));
                }
                row += 1;
            }
            None
        })
    }
}
