//! N022 `repeated-address`: Finds an address programmed twice in one block (`G1 X10 X20`).

use std::collections::HashMap;

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockWords, FileContext, Words};
use crate::lint::rules::support::both;
use crate::semantic::addresses::Address;
use crate::syntax::plain::{Letters, PlainFacts};

pub static RULE: RuleInfo = RuleInfo {
    code: "N022",
    name: "repeated-address",
    severity: Severity::Error,
    docs: r#"## What it does
Finds an address programmed twice in one block: an axis (`X Y Z A B C U V W`), a circle's centre
(`I J K`), its radius or aperture (`CR AR`), a polar end point (`AP RP`), `TURN`, a chamfer or
rounding (`CHF CHR RND RNDM`), the feed `F`, the tool `T`, the offset `D`, or a spindle's speed `S`
(the same spindle: `S1=` and `S2=` are two).

## Why it matters
Each of these addresses may appear once in a block; the control refuses a block with one of them
twice (alarm 12010, "address type programmed too often"). Usually one of the two words was meant
for another address or for the next block. G, M and H functions may appear several times (N023,
N024 and N021 check them); other letters are not checked.

## Example
```
N10 G1 X10 X20 F500
```

## Fix
Keep one word of the address, or move the other to the block it belongs to."#,
};

/// The one-letter addresses a block takes once.
const ONCE: &[u8] = b"XYZABCUVWIJKFTDS";
const ONCE_LETTERS: Letters = Letters::of(ONCE);

/// Every named address (see [`addresses::of_block`]) is taken once.
fn taken_once(source: &[u8], address: &Address) -> bool {
    address.name.len() > 1 || ONCE.contains(&address.letter(source))
}

pub struct Checker;

impl BlockWords for Checker {
    fn may_find(facts: &PlainFacts) -> bool {
        facts.repeats && facts.letters.meets(ONCE_LETTERS)
    }

    /// One finding per repeated address, at its second word (a third one is the
    /// same mistake). Linear in the block's words: a block may hold thousands.
    fn check(file: &FileContext, words: &Words, out: &mut Vec<Diagnostic>) {
        let addresses = words.addresses;
        let source = file.source;
        if !may_repeat(source, addresses) {
            return;
        }
        // The first word of each address, and whether it was reported.
        let mut seen: HashMap<Key, (&Address, bool)> = HashMap::new();
        for second in addresses.iter().filter(|a| taken_once(source, a)) {
            let key = (
                second.name.of(source).to_ascii_uppercase(),
                second.extension.map(|_| second.extension_value(source)),
            );
            let (first, reported) = seen.entry(key).or_insert((second, false));
            if std::ptr::eq(*first, second) || *reported {
                continue;
            }
            *reported = true;
            let (first_text, second_text) = both(source, first, second);
            let name = String::from_utf8_lossy(second.name.of(source)).to_ascii_uppercase();
            out.push(
                RULE.at(second.span)
                    .message(format!(
                        "address {name} is programmed twice in this block (`{first_text}` and `{second_text}`): the control takes it once"
                    ))
                    .label(format!("second {name}"))
                    .help(format!("keep one {name} word, or move `{second_text}` to the block it belongs to")),
            );
        }
    }
}

/// An address as the control tells addresses apart: its name in upper case
/// and its extension's value, if it has one.
type Key = (Vec<u8>, Option<Option<u32>>);

/// Whether some address taken once may appear twice: a set of letters for
/// the one-letter words without an extension (nearly all), a list for the
/// rest; `true` sends the block to the exact count above. Most blocks have
/// no repeat, and building the exact count's map for each cost a tenth of
/// `check` on real programs.
fn may_repeat(source: &[u8], addresses: &[Address]) -> bool {
    let mut letters = 0u32;
    let mut others: Vec<&Address> = Vec::new();
    for address in addresses.iter().filter(|a| taken_once(source, a)) {
        if address.name.len() == 1 && address.extension.is_none() {
            let bit = 1 << (address.letter(source) & 31);
            if letters & bit != 0 {
                return true;
            }
            letters |= bit;
        } else {
            let name = address.name.of(source);
            if others.len() > 16
                || others
                    .iter()
                    .any(|o| o.name.of(source).eq_ignore_ascii_case(name))
            {
                return true;
            }
            others.push(address);
        }
    }
    false
}
