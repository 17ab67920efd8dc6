//! Frames on the way to a CYCLE600 call (spec section 8).
//!
//! Two facts decide what the rewrite may emit, and both are about frame
//! statements of the program's own, not the blocks sinuprep emitted for an
//! earlier CYCLE600:
//! - a frame statement between the last swivel and an additive call makes
//!   the rotation it adds to unknown (the programmable frame and the swivel
//!   are separate frames on the control);
//! - a frame statement active in the programmable frame forbids the frames
//!   and TRAORI forms, whose `TRANS` would replace it.
//!
//! The blocks sinuprep emitted are recognised by the `; sinuprep:` line that
//! keeps the original call above them, followed by exactly the blocks one of
//! the forms writes; the walk takes that call in their place, so a rewritten
//! program rewritten again gives the same result.

use std::fmt;

use crate::span::Span;
use crate::syntax::block::parse_block;
use crate::syntax::lexer::Input;
use crate::syntax::tree::{Block, FrameKind, Statement, StatementKind};

/// Frame statements of the program's own, as diagnostics name them.
#[derive(Clone, Debug, PartialEq)]
pub enum FrameSeen {
    /// One statement: its text and 1-based line.
    Statement { text: String, line: usize },
    /// Somewhere in a region the walk cannot follow (a loop, a jump).
    Region(String),
}

impl fmt::Display for FrameSeen {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FrameSeen::Statement { text, line } => {
                write!(f, "the frame statement `{text}` on line {line}")
            }
            FrameSeen::Region(where_) => write!(f, "a frame statement {where_}"),
        }
    }
}

/// What a block of the program's own does to the frames.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameEffect {
    /// `TRANS` or `ROT` without values: the programmable frame is cleared.
    ClearsProgrammable,
    /// A frame statement or an assignment to `$P_PFRAME`: the programmable
    /// frame holds something of the program's own.
    SetsProgrammable,
    /// Another frame changes (system or settable frames, `TOROT`, `PAROT`, ...).
    SetsOther,
}

/// What the block does to the frames, if anything.
pub fn frame_effect(source: &[u8], block: &Block) -> Option<FrameEffect> {
    let mut effect = None;
    for (index, statement) in block.statements.iter().enumerate() {
        let this = match &statement.kind {
            StatementKind::Frame(frame) => {
                let has_values = block.statements[index + 1..]
                    .iter()
                    .any(|s| !matches!(s.kind, StatementKind::Frame(_)));
                let clears = matches!(frame.kind, FrameKind::Trans | FrameKind::Rot) && !has_values;
                if clears {
                    FrameEffect::ClearsProgrammable
                } else {
                    FrameEffect::SetsProgrammable
                }
            }
            StatementKind::Assign(assign) => {
                match frame_variable(assign.target.name.text(source)) {
                    Some(effect) => effect,
                    None => continue,
                }
            }
            StatementKind::Command(name) if is_frame_command(name.text(source)) => {
                // TOFRAME writes the programmable frame unless the machine
                // data sends it to the tool frame: take the stronger effect.
                let text = name.text(source);
                if text.len() >= 7 && text[..7].eq_ignore_ascii_case(b"TOFRAME") {
                    FrameEffect::SetsProgrammable
                } else {
                    FrameEffect::SetsOther
                }
            }
            _ => continue,
        };
        effect = Some(match (effect, this) {
            (Some(FrameEffect::SetsProgrammable), _) | (_, FrameEffect::SetsProgrammable) => {
                FrameEffect::SetsProgrammable
            }
            (_, this) => this,
        });
    }
    effect
}

/// `$P_PFRAME` is the programmable frame; other `$P_...FRAME` and the
/// settable and basic frame arrays (`$P_UIFR`, `$P_CHBFR`, ...) are frames too.
fn frame_variable(name: &[u8]) -> Option<FrameEffect> {
    if name.eq_ignore_ascii_case(b"$P_PFRAME") {
        return Some(FrameEffect::SetsProgrammable);
    }
    let ends = |suffix: &[u8]| {
        name.len() >= suffix.len() && name[name.len() - suffix.len()..].eq_ignore_ascii_case(suffix)
    };
    let frame =
        name.len() > 3 && name[..3].eq_ignore_ascii_case(b"$P_") && (ends(b"FRAME") || ends(b"FR"));
    frame.then_some(FrameEffect::SetsOther)
}

/// Commands that align frames to the tool or the workpiece.
fn is_frame_command(name: &[u8]) -> bool {
    const COMMANDS: [&[u8]; 12] = [
        b"TOFRAME",
        b"TOFRAMEX",
        b"TOFRAMEY",
        b"TOFRAMEZ",
        b"TOROT",
        b"TOROTX",
        b"TOROTY",
        b"TOROTZ",
        b"TOROTOF",
        b"PAROT",
        b"PAROTOF",
        b"TOFRAMEOF",
    ];
    COMMANDS.iter().any(|c| c.eq_ignore_ascii_case(name))
}

/// The text of a block's statements, for naming it in a diagnostic.
pub fn statements_text(source: &[u8], block: &Block) -> String {
    match (block.statements.first(), block.statements.last()) {
        (Some(first), Some(last)) => {
            String::from_utf8_lossy(Span::new(first.span.start, last.span.end).of(source))
                .into_owned()
        }
        _ => String::new(),
    }
}

/// The marker sinuprep writes above the blocks it emitted.
pub const MARKER: &[u8] = b"; sinuprep: ";

/// The CYCLE600 call kept in a `; sinuprep:` line, parsed where it stands.
pub fn marked_call(source: &[u8], content: Span) -> Option<Statement> {
    let text = content.of(source);
    let indent = text
        .iter()
        .take_while(|&&b| b == b' ' || b == b'\t')
        .count();
    if !text[indent..].starts_with(MARKER) {
        return None;
    }
    let start = content.start + indent + MARKER.len();
    let (block, error) = parse_block(Input::new(&source[start..content.end], start));
    if error.is_some() || block.statements.len() != 1 {
        return None;
    }
    let statement = block.statements.into_iter().next()?;
    match &statement.kind {
        StatementKind::Call(call) if call.name.text(source).eq_ignore_ascii_case(b"CYCLE600") => {
            Some(statement)
        }
        _ => None,
    }
}

/// One block as the forms write it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shape {
    Cycle800,
    Traori,
    Oriwks,
    /// `TRANS X.. Y.. Z..`.
    Trans,
    /// `ATRANS X.. Y.. Z..`.
    Atrans,
    Arot,
    /// Address words only: the tool direction after TRAORI.
    Words,
}

fn shape(source: &[u8], block: &Block) -> Option<Shape> {
    if block.unparsed.is_some() || block.label.is_some() {
        return None;
    }
    let mut found = None;
    for statement in &block.statements {
        let this = match &statement.kind {
            StatementKind::Word(_) => continue,
            StatementKind::Call(call)
                if call.name.text(source).eq_ignore_ascii_case(b"CYCLE800") =>
            {
                Shape::Cycle800
            }
            StatementKind::Command(name) if name.is(source, "TRAORI") => Shape::Traori,
            StatementKind::Command(name) if name.is(source, "ORIWKS") => Shape::Oriwks,
            StatementKind::Frame(frame) => match frame.kind {
                FrameKind::Trans => Shape::Trans,
                FrameKind::ATrans => Shape::Atrans,
                FrameKind::ARot => Shape::Arot,
                _ => return None,
            },
            _ => return None,
        };
        if found.replace(this).is_some() {
            return None;
        }
    }
    match found {
        None if !block.statements.is_empty() => Some(Shape::Words),
        found => found,
    }
}

/// How many blocks after a `; sinuprep:` line sinuprep emitted with frames
/// or CYCLE800 in them (0 for the other forms, whose blocks are ordinary
/// assignments the walk follows as they are). `block(i)` parses the `i`-th
/// line after the marker, `None` past the end.
pub fn emitted_blocks(source: &[u8], mut block: impl FnMut(usize) -> Option<Block>) -> usize {
    use Shape::*;
    // Each block of a form, with the shapes it may take.
    const FRAMES: &[&[Shape]] = &[&[Trans, Atrans], &[Arot], &[Arot], &[Arot], &[Atrans]];
    const TRAORI: &[&[Shape]] = &[
        &[Traori],
        &[Oriwks],
        &[Trans, Atrans],
        &[Arot],
        &[Arot],
        &[Arot],
        &[Atrans],
        &[Words],
    ];
    let form = match block(0).and_then(|b| shape(source, &b)) {
        Some(Cycle800) => return 1,
        Some(Trans | Atrans) => FRAMES,
        Some(Traori) => TRAORI,
        _ => return 0,
    };
    let fits = form.iter().enumerate().all(|(i, shapes)| {
        block(i)
            .and_then(|b| shape(source, &b))
            .is_some_and(|s| shapes.contains(&s))
    });
    if fits {
        form.len()
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::{parse, tree::LineKind};

    fn blocks(source: &[u8]) -> Vec<Block> {
        parse(source)
            .lines
            .into_iter()
            .filter_map(|line| match line.kind {
                LineKind::Block(block) => Some(block),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn frame_statements_are_told_apart() {
        let source = b"TRANS\nROT\nTRANS X10\nAROT Z=5\n$P_PFRAME=CTRANS(X,1)\n$P_UIFR[1]=CROT(Z,5)\nTOROT\nTOFRAME\nG1 X10\nR1=5\n";
        let effects: Vec<_> = blocks(source)
            .iter()
            .map(|b| frame_effect(source, b))
            .collect();
        use FrameEffect::*;
        assert_eq!(
            effects,
            [
                Some(ClearsProgrammable),
                Some(ClearsProgrammable),
                Some(SetsProgrammable),
                Some(SetsProgrammable),
                Some(SetsProgrammable),
                Some(SetsOther),
                Some(SetsOther),
                Some(SetsProgrammable),
                None,
                None
            ]
        );
    }

    #[test]
    fn only_the_blocks_a_form_writes_count_as_emitted() {
        let count = |text: &[u8]| {
            let found = blocks(text);
            emitted_blocks(text, |i| found.get(i).cloned())
        };
        assert_eq!(
            count(b"N10 CYCLE800(0,\"H\",0,39,0,0,0,1,2,3,0,0,0,-1)\nAROT Z=5\n"),
            1
        );
        let frames =
            b"N10 TRANS X0 Y0 Z0\nAROT Z=1\nAROT X=2\nAROT Y=3\nATRANS X0 Y0 Z0\nAROT Z=5\n";
        assert_eq!(count(frames), 5);
        let traori = b"TRAORI\nORIWKS\nATRANS X0 Y0 Z0\nAROT Z=1\nAROT X=2\nAROT Y=3\nATRANS X0 Y0 Z0\nG0 A3=0 B3=0 C3=1\n";
        assert_eq!(count(traori), 8);
        // One block short, or a user's block in between: not sinuprep's.
        assert_eq!(
            count(b"TRANS X0 Y0 Z0\nAROT Z=1\nAROT X=2\nATRANS X0 Y0 Z0\n"),
            0
        );
        assert_eq!(count(b"_CYC600_1=\"H\" _CYC600_2=1\n"), 0);
    }

    #[test]
    fn the_marker_keeps_a_cycle600_call() {
        let source = b"  ; sinuprep: CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)";
        let call = marked_call(source, Span::new(0, source.len())).expect("a call");
        assert_eq!(&source[call.span.start..call.span.start + 8], b"CYCLE600");
        let other = b"; sinuprep: ignore N005";
        assert!(marked_call(other, Span::new(0, other.len())).is_none());
    }
}
