//! A unified diff of a rewrite, built from its edits: the changed lines are
//! known exactly, so no line matching is needed.

use crate::emit::{apply, Edit};
use crate::span::Span;
use crate::syntax::lines::{raw_lines, RawLine};

const CONTEXT: usize = 3;

pub fn unified(name: &str, source: &[u8], edits: &[Edit]) -> String {
    let lines: Vec<RawLine> = raw_lines(source).collect();
    if edits.is_empty() || lines.is_empty() {
        return String::new();
    }
    // The line each edit belongs to: the one its start falls in (an insertion
    // at the very end of the file belongs to the last line).
    let line_of = |offset: usize| {
        lines
            .partition_point(|l| l.full().end <= offset)
            .min(lines.len() - 1)
    };
    let mut by_line: Vec<Vec<&Edit>> = vec![Vec::new(); lines.len()];
    for edit in edits {
        by_line[line_of(edit.span.start)].push(edit);
    }
    let mut out = format!("--- {name}\n+++ {name}\n");
    // Lines added (or removed) by the hunks before, for the new side's numbers.
    let mut shift: isize = 0;
    let mut i = 0;
    while i < lines.len() {
        if by_line[i].is_empty() {
            i += 1;
            continue;
        }
        let start = i.saturating_sub(CONTEXT);
        // Extend over changes closer than 2 * CONTEXT lines to each other.
        let mut last = i;
        let mut j = i + 1;
        while j < lines.len() && j <= last + 2 * CONTEXT {
            if !by_line[j].is_empty() {
                last = j;
            }
            j += 1;
        }
        let stop = (last + 1 + CONTEXT).min(lines.len());
        let (mut body, mut old_count, mut new_count) = (String::new(), 0, 0);
        for index in start..stop {
            let full = lines[index].full();
            let old = full.of(source);
            if by_line[index].is_empty() {
                push_line(&mut body, ' ', old);
                old_count += 1;
                new_count += 1;
                continue;
            }
            push_line(&mut body, '-', old);
            old_count += 1;
            let local: Vec<Edit> = by_line[index]
                .iter()
                .map(|e| Edit {
                    span: Span::new(
                        e.span.start - full.start,
                        e.span.end.min(full.end) - full.start,
                    ),
                    text: e.text.clone(),
                })
                .collect();
            let new = apply(old, &local);
            for new_line in new.split_inclusive(|&b| b == b'\n') {
                push_line(&mut body, '+', new_line);
                new_count += 1;
            }
        }
        let new_start = (start + 1) as isize + shift;
        out.push_str(&format!(
            "@@ -{},{old_count} +{new_start},{new_count} @@\n",
            start + 1
        ));
        shift += new_count as isize - old_count as isize;
        out.push_str(&body);
        i = stop;
    }
    out
}

fn push_line(out: &mut String, tag: char, line: &[u8]) {
    out.push(tag);
    out.push_str(&String::from_utf8_lossy(line));
    if !line.ends_with(b"\n") && !line.ends_with(b"\r") {
        out.push_str("\n\\ No newline at end of file\n");
    } else if line.ends_with(b"\r") {
        out.push('\n');
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_changed_line_with_context() {
        let source = b"L1\nL2\nL3\nL4\nL5\nL6\nL7\nL8\n";
        let diff = unified(
            "P.MPF",
            source,
            &[Edit::replace(Span::new(9, 11), "X4\nY4")],
        );
        assert_eq!(
            diff,
            "--- P.MPF\n+++ P.MPF\n@@ -1,7 +1,8 @@\n L1\n L2\n L3\n-L4\n+X4\n+Y4\n L5\n L6\n L7\n"
        );
    }
}
