//! Whether the control runs the lines of a program in their order: a jump,
//! a call or a block structure means the next line need not be the next
//! block run, nor the modal state the lines before it left the one in force.

use crate::semantic::addresses::Address;
use crate::semantic::calls::{call_kind, CallKind};
use crate::syntax::tree::{upper, Block, StatementKind};

/// The block makes the order of the lines no longer the order they run in
/// (a jump, CASE, PROC), or calls what may change the modal state (a
/// subprogram `L`, a cycle, a call or command that is not one of the
/// control's plain builtins, an indirect call).
pub fn leaves_line_order(source: &[u8], block: &Block, addresses: &[Address]) -> bool {
    addresses.iter().any(|a| a.is(source, "L"))
        || block.statements.iter().any(|s| match &s.kind {
            StatementKind::Call(call) => !is_plain_command(&upper(call.name.text(source))),
            StatementKind::Command(name) => !is_plain_command(&upper(name.text(source))),
            StatementKind::Proc(_)
            | StatementKind::Case(_)
            | StatementKind::Goto(_)
            | StatementKind::IndirectCall { .. } => true,
            _ => false,
        })
}

/// The block opens, continues or closes a block structure (IF, ELSE, loops):
/// the lines after it need not run after it.
pub fn is_block_structure(block: &Block) -> bool {
    block.statements.iter().any(|s| {
        matches!(
            s.kind,
            StatementKind::If { .. }
                | StatementKind::Else
                | StatementKind::EndIf
                | StatementKind::While { .. }
                | StatementKind::EndWhile
                | StatementKind::For { .. }
                | StatementKind::EndFor
                | StatementKind::Loop
                | StatementKind::EndLoop
                | StatementKind::Repeat { .. }
                | StatementKind::Until { .. }
        )
    })
}

/// A command of the control that neither jumps nor programs a feed rate.
fn is_plain_command(name: &str) -> bool {
    call_kind(name) == CallKind::Builtin && !name.starts_with("CYCLE")
}
