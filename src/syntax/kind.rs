//! Main program or subprogram: what the end-of-program rules and the walk
//! need to know of a file before reading it.

use crate::syntax::lines::raw_lines;
use crate::syntax::tree::{LineKind, StatementKind};
use crate::syntax::LineParser;

/// What kind of program a file holds, by its name or its content.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProgramKind {
    Main,
    Subprogram,
}

/// What kind of program a file holds: a file whose first statement is PROC
/// is a subprogram whatever its name; else its extension decides (`.SPF`,
/// `.MPF`), else a `%_N_..._SPF` header or a PROC line among its first blocks.
pub fn program_kind(file_name: Option<&str>, source: &[u8]) -> ProgramKind {
    let mut parser = LineParser::default();
    let mut first_statements = raw_lines(source).take(200).filter_map(|raw| {
        let (line, _) = parser.parse_line(source, raw);
        match line.kind {
            LineKind::Block(block) => block.statements.into_iter().next(),
            _ => None,
        }
    });
    if first_statements
        .next()
        .is_some_and(|s| matches!(s.kind, StatementKind::Proc(_)))
    {
        return ProgramKind::Subprogram;
    }
    if let Some(name) = file_name {
        let upper = name.to_ascii_uppercase();
        if upper.ends_with(".SPF") {
            return ProgramKind::Subprogram;
        }
        if upper.ends_with(".MPF") {
            return ProgramKind::Main;
        }
    }
    let mut parser = LineParser::default();
    for raw in raw_lines(source).take(200) {
        let (line, _) = parser.parse_line(source, raw);
        let is_sub = match &line.kind {
            LineKind::Header { name } => name.of(source).to_ascii_uppercase().ends_with(b"_SPF"),
            LineKind::Block(block) => block
                .statements
                .iter()
                .any(|s| matches!(s.kind, StatementKind::Proc(_))),
            LineKind::Path { .. } => false,
        };
        if is_sub {
            return ProgramKind::Subprogram;
        }
    }
    ProgramKind::Main
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_that_starts_with_proc_is_a_subprogram_whatever_its_name() {
        let proc_first = b"; drilling cycle\nPROC HOLES(REAL _D)\nG1 X10\nM17\n";
        assert_eq!(
            program_kind(Some("HOLES.MPF"), proc_first),
            ProgramKind::Subprogram
        );
        assert_eq!(
            program_kind(Some("HOLES.TXT"), proc_first),
            ProgramKind::Subprogram
        );
        let main = b"G0 X0\nM30\n";
        assert_eq!(
            program_kind(Some("PART.SPF"), main),
            ProgramKind::Subprogram
        );
        assert_eq!(program_kind(Some("PART.MPF"), main), ProgramKind::Main);
        assert_eq!(
            program_kind(None, b"%_N_PART_SPF\nG0 X0\n"),
            ProgramKind::Subprogram
        );
        assert_eq!(program_kind(None, main), ProgramKind::Main);
    }
}
