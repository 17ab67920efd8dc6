//! N014 `block-numbers-backwards`: Finds a block number lower than the one before it.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockAt, Check, FileContext, PlainLine, Sees};
use crate::semantic::environment::holds_machine_data;
use crate::syntax::plain::digits_value;
use crate::syntax::tree::{Block, BlockNumber, StatementKind};

pub static RULE: RuleInfo = RuleInfo {
    code: "N014",
    name: "block-numbers-backwards",
    severity: Severity::Info,
    docs: r#"## What it does
Finds a block number lower than the one before it.

## Why it matters
Block numbers are not executed in order, but a jump to a block number searches in a direction,
and readers expect them to grow: a number going backwards often marks blocks pasted from
elsewhere.

Machine data are not checked: an `.INI` file (`INITIAL.INI`, `TO_INI.INI`), a file of any name
that holds machine data (its first block assigns `$MN_`, `$MC_` or `$MA_`, and its other blocks
assign data, select a channel with `CHANDATA` or end it: a `.TEA`, machine data saved as `.TXT`,
an archive's member), and elsewhere a block that assigns machine or setting data
(`N10000 $MN_AXCONF_MACHAX_NAME_TAB[0]="X1"`) number their blocks by machine-data number, not in
the order they are written.

## Example
```
N100 G0 X0
N40 G1 X10
```

## Fix
Renumber the blocks."#,
};

#[derive(Default)]
pub struct Checker {
    previous: Option<u64>,
    /// Whether the file is machine data, read once from its name and its
    /// first block.
    machine_data: Option<bool>,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::BLOCKS | Sees::PLAIN_LINES
    }

    fn block(&mut self, file: &FileContext, at: &BlockAt, out: &mut Vec<Diagnostic>) {
        if !is_machine_data(file.source, at.block) {
            self.number(file, at.block.number, out);
        }
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], out: &mut Vec<Diagnostic>) {
        if self.machine_data(file) {
            return;
        }
        for line in lines {
            self.number(file, line.facts.number, out);
        }
    }
}

impl Checker {
    fn number(
        &mut self,
        file: &FileContext,
        number: Option<BlockNumber>,
        out: &mut Vec<Diagnostic>,
    ) {
        if self.machine_data(file) {
            return;
        }
        let Some(number) = number.filter(|n| !n.main) else {
            return;
        };
        let Some(value) = digits_value(number.digits.of(file.source)) else {
            return;
        };
        if let Some(previous) = self.previous.filter(|&p| value < p) {
            out.push(backwards(number, value, previous));
        }
        self.previous = Some(value);
    }
}

impl Checker {
    /// An `.INI` file, or a file of machine data whatever its name
    /// ([`holds_machine_data`]): numbered by machine-data number.
    fn machine_data(&mut self, file: &FileContext) -> bool {
        *self.machine_data.get_or_insert_with(|| {
            std::path::Path::new(file.name)
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("ini"))
                || holds_machine_data(file.source)
        })
    }
}

/// A block assigning machine or setting data (`$MN_`, `$MC_`, `$MA_`,
/// `$SN_`, `$SC_`, `$SA_`), whose block number is the datum's number.
fn is_machine_data(source: &[u8], block: &Block) -> bool {
    block.statements.iter().any(|s| match &s.kind {
        StatementKind::Assign(assign) => {
            let name = assign.target.name.span.of(source);
            name.len() > 4
                && name[0] == b'$'
                && matches!(name[1].to_ascii_uppercase(), b'M' | b'S')
                && matches!(name[2].to_ascii_uppercase(), b'N' | b'C' | b'A')
                && name[3] == b'_'
        }
        _ => false,
    })
}

/// Apart and cold, so that the path every line takes does not set up the
/// message's formatting (it was a 300-byte stack frame a line).
#[cold]
fn backwards(number: BlockNumber, value: u64, previous: u64) -> Diagnostic {
    RULE.at(number.span)
        .message(format!("block number N{value} after N{previous}"))
        .label("goes backwards")
        .help("renumber the blocks in ascending order")
}
