//! Small helpers the rules share: what a block jumps to, which names an
//! expression reads, whether a name is a user variable.

use crate::lint::rule::FileContext;
use crate::semantic::addresses::Address;
use crate::semantic::modal::{is_axis_letter, is_feed_motion, Modal};
use crate::span::Span;
use crate::syntax::tree::{Block, Goto, GotoTarget, Name, Statement, StatementKind};
pub use crate::syntax::visit::{gotos, reads};

/// The upper-case text of `span`.
pub fn upper(source: &[u8], span: Span) -> String {
    crate::syntax::tree::upper(span.of(source))
}

/// Where a jump can land: the model's.
pub use crate::semantic::jumps::Target;

/// The block's label (upper case), if it has one.
pub fn label(source: &[u8], block: &Block) -> Option<(String, Span)> {
    block.label.map(|l| (upper(source, l.span), l.span))
}

/// Where a jump goes, and the span that names it; `None` for computed
/// targets.
pub fn target(file: &FileContext, goto: &Goto) -> Option<(Target, Span)> {
    let named = goto.target.as_ref()?;
    let span = match named {
        GotoTarget::Label(name) => name.span,
        GotoTarget::Number(number) => number.span,
        GotoTarget::Computed(_) => return None,
    };
    Some((Target::of(file.source, named)?, span))
}

/// A name a user could have defined: two leading letters (or `_` after a
/// letter), not a system variable, not a cycle's reserved `_` name, and not a
/// frame component or constant.
pub fn is_user_name(name: &str) -> bool {
    let bytes = name.as_bytes();
    bytes.len() >= 2
        && bytes[0].is_ascii_alphabetic()
        && (bytes[1].is_ascii_alphabetic() || bytes[1] == b'_')
        && !matches!(name, "TRUE" | "FALSE" | "TR" | "RT" | "SC" | "MI" | "FI")
}

/// Files that hold declarations only, by their extension.
pub fn is_definition_file(name: &str) -> bool {
    let extension = std::path::Path::new(name)
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("");
    ["DEF", "INI", "GUD", "COM"]
        .iter()
        .any(|e| extension.eq_ignore_ascii_case(e))
}

/// Where the program ends in this block: its M2, M17, M30 or RET, or a
/// macro of the definition files given whose text ends it (`ENDE` with
/// `DEFINE ENDE AS M30`), which the control expands where it is written.
/// The statements read from an expansion span the macro's name, so the
/// name is what is looked up.
pub fn program_end(file: &FileContext, block: &Block, addresses: &[Address]) -> Option<Span> {
    crate::semantic::addresses::program_end(file.source, block, addresses).or_else(|| {
        if file.environment.macros.is_empty() {
            return None;
        }
        block.statements.iter().find_map(|statement| {
            let expanded = file
                .environment
                .macros
                .get(&upper(file.source, statement.span))?;
            expanded.ends_program.then_some(statement.span)
        })
    })
}

/// The feed motion a block makes, after `modal` has taken it in: the G
/// function in force (`G1`, `G2`, `G3`) and the span of the block's words,
/// when its words move an axis (an axis letter, a polar end point `AP`,
/// `RP`, or, `named`, an axis the machine names).
pub fn feed_move(
    source: &[u8],
    modal: &Modal,
    addresses: &[Address],
    named: bool,
) -> Option<(u32, Span)> {
    let motion = modal.motion.filter(|&m| is_feed_motion(m))?;
    let moves = named
        || addresses.iter().any(|a| {
            (a.name.len() == 1 && is_axis_letter(a.letter(source)))
                || a.is(source, "AP")
                || a.is(source, "RP")
        });
    let (first, last) = (addresses.first()?, addresses.last()?);
    moves.then(|| (motion, Span::new(first.span.start, last.span.end)))
}

/// The words of two addresses, for a message: `X10` and `X20`.
pub fn both(source: &[u8], first: &Address, second: &Address) -> (String, String) {
    let text = |a: &Address| String::from_utf8_lossy(a.span.of(source)).into_owned();
    (text(first), text(second))
}

/// The block assigns a position to an axis the machine names (`XC=10`, with
/// `axes = ["XC"]`): an axis word the one-letter addresses do not show.
pub fn moves_a_named_axis(file: &FileContext, block: &Block) -> bool {
    !file.environment.axes.is_empty()
        && block.statements.iter().any(|s| match &s.kind {
            StatementKind::Assign(assign) => file
                .environment
                .axes
                .contains(&upper(file.source, assign.target.name.span)),
            _ => false,
        })
}

/// Functions that exclude each other in one block: for each group (as
/// `grouped` gives a word's group and number), its first function and the
/// first later one with another number. Linear in the block's words.
pub fn group_conflicts<T, G: Copy + Eq + std::hash::Hash>(
    words: &[T],
    grouped: impl Fn(&T) -> Option<(G, u32)>,
) -> Vec<(G, &T, &T)> {
    // group -> its first function, and whether a conflict was found.
    let mut first_of: std::collections::HashMap<G, (&T, u32, bool)> = Default::default();
    let mut conflicts = Vec::new();
    for second in words {
        let Some((group, number)) = grouped(second) else {
            continue;
        };
        let (first, first_number, found) = first_of.entry(group).or_insert((second, number, false));
        if *first_number != number && !*found {
            *found = true;
            conflicts.push((group, *first, second));
        }
    }
    conflicts
}

/// The name a statement calls or commands (`TRAORI`, `TRAORI(1)`,
/// `CYCLE800(...)`), `None` for any other statement.
pub fn command_name(statement: &Statement) -> Option<&Name> {
    match &statement.kind {
        StatementKind::Command(name) => Some(name),
        StatementKind::Call(call) => Some(&call.name),
        _ => None,
    }
}
