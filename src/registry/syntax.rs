//! Syntax errors (`S...`), found by the parser (`syntax`); this file
//! documents them for `sinuprep rule`.

use crate::diagnostic::{RuleInfo, Severity};

pub static UNCLOSED_STRING: RuleInfo = RuleInfo {
    code: "S001",
    name: "unclosed-string",
    severity: Severity::Error,
    docs: r#"## What it does
Reports a `"` without its closing `"` on the same line.

## Why it matters
The control refuses a block it cannot read. sinuprep keeps the line's bytes as they are and reads
the next line as usual.

## Example
```
N20 MSG("probe done
```

## Fix
Add the closing quote; strings cannot span lines."#,
};

pub static UNBALANCED_BRACKET: RuleInfo = RuleInfo {
    code: "S002",
    name: "unbalanced-bracket",
    severity: Severity::Error,
    docs: r#"## What it does
Reports a `(` or `[` not closed on its line, or a `)`/`]` with nothing to close.

## Why it matters
The control refuses a block it cannot read. sinuprep keeps the line's bytes as they are and reads
the next line as usual.

## Example
```
N120 CYCLE600 (0, "UFK600", 1, 57, 0, 0, 0, 30, 45, 60, 0,
```

## Fix
Add the missing bracket; join a call broken over two lines."#,
};

pub static INVALID_NUMBER: RuleInfo = RuleInfo {
    code: "S003",
    name: "invalid-number",
    severity: Severity::Error,
    docs: r#"## What it does
Reports a malformed number: two decimal points, `EX` without digits, a bad `'H..'`/`'B..'`, beyond REAL's range.

## Why it matters
The control refuses a block it cannot read. sinuprep keeps the line's bytes as they are and reads
the next line as usual.

## Example
```
N10 X1.2.3
```

## Fix
Write the number as the manual does: `1.5`, `1.5EX3`, `'H1F'`, `'B101'`."#,
};

pub static UNKNOWN_CHARACTER: RuleInfo = RuleInfo {
    code: "S004",
    name: "unknown-character",
    severity: Severity::Error,
    docs: r#"## What it does
Reports a character with no meaning outside comments and strings. A UTF-8 byte-order mark (U+FEFF,
the bytes EF BB BF) at the start of the file, which Windows editors write when saving as UTF-8, is
named as such, with a safe fix that removes it.

## Why it matters
The control refuses a block it cannot read. sinuprep keeps the line's bytes as they are and reads
the next line as usual.

## Example
```
N10 R1=2^3
```

## Fix
Remove it (Sinumerik has no `^`: use POT), or put it in a comment; `check --fix` removes a
byte-order mark."#,
};

pub static UNEXPECTED_TOKEN: RuleInfo = RuleInfo {
    code: "S005",
    name: "unexpected-token",
    severity: Severity::Error,
    docs: r#"## What it does
Reports something else than the statement needs at this place (the message says what), and
statements that cannot share a block:
- the control-structure keywords (ELSE, ENDIF, WHILE, ENDWHILE, FOR, ENDFOR, LOOP, ENDLOOP,
  REPEAT, REPEATB, UNTIL), DEF, REDEF, PROC, EXTERN, DEFINE and a synchronized action stand
  alone in their block (Siemens, Job Planning, "Control structures"; Function Manual
  Synchronized actions: no other commands in the action's block);
- nothing follows CASE, a call by CALL/PCALL/MCALL/EXTCALL/ISOCALL/CALLPATH, or the PROC
  header's attributes (SAVE, SBLOF, DISPLOF, ...);
- `IF cond` is followed by its jump (`IF R1==1 GOTOF LBL`) or by nothing, and a jump by another
  `IF … GOTO…` or by nothing;
- REPEAT names at most two labels (REPEATB one), then `P=n`;
- CALL and ISOCALL name the program to run and take no arguments (`CALL _PNAME(10,20)`): the
  manual writes them `CALL <program name>` and `ISOCALL <program name>`, the name a STRING, and
  passes arguments with PCALL (`PCALL <path/program name>(<parameter 1>,...)`) or a call by name
  (Siemens, Job Planning, "Indirect subprogram call (CALL)", "Indirect call of a program
  programmed in an ISO language (ISOCALL)", "Subprogram call with path specification and
  parameters (PCALL)"); a call of a string function (`CALL SPRINT("PART_%D",_NR)`) is the name;
- a sign before a string (`_STR=-"String 1"`): a STRING converts to no number (Job Planning,
  "Type conversion"; `NUMBER("12.5")` reads one);
- a header `%_N_<name>_<type>` whose name holds other characters than letters, digits and `_`
  (`%_N_CYCLE()_SPF`; Programming Manual NC programming, "Subprogram names": "Permissible
  characters"). Other headers (`%Flange3_MPF`, a lone `%`) are not read.
When the block's first word is one edit or two from a keyword that takes operands (`IFF R1==1`),
the help offers the keyword. The grammar, with the manual section of each choice, is
`grammar/sinumerik.ebnf`.

## Why it matters
The control refuses a block it cannot read. sinuprep keeps the line's bytes as they are and reads
the next line as usual.

## Example
```
N30 DEF WORD X
N40 ELSE invalid
N50 IF R1==1 ELSE ENDIF
N60 REPEAT P=10 START
```

## Fix
Correct the statement; move what shares a block with a statement that stands alone into a block
of its own."#,
};

pub static MISSING_VALUE: RuleInfo = RuleInfo {
    code: "S006",
    name: "missing-value",
    severity: Severity::Error,
    docs: r#"## What it does
Reports an address letter without a value.

## Why it matters
The control refuses a block it cannot read. sinuprep keeps the line's bytes as they are and reads
the next line as usual.

## Example
```
N10 G1 X Y10
```

## Fix
Write `X0`, not `X`, or `X=expression`."#,
};

pub static CONTINUED_BLOCK: RuleInfo = RuleInfo {
    code: "S007",
    name: "continued-block",
    severity: Severity::Error,
    docs: r#"## What it does
Reports a line that continues a call left open on the line before.

## Why it matters
The control refuses a block it cannot read. sinuprep keeps the line's bytes as they are and reads
the next line as usual.

## Example
```
0, 0, 0, 1, 39, 0, 0, 0)
```

## Fix
Join the line to the one before: a block is one line."#,
};

pub static TOO_LONG_TO_READ: RuleInfo = RuleInfo {
    code: "S009",
    name: "block-too-long-to-read",
    severity: Severity::Error,
    docs: r#"## What it does
Reports a block of more than 64 KiB, whatever it holds.

## Why it matters
512 characters is the block length commonly quoted for the control (not confirmed in a Siemens
manual available here, as N008 says); a block of more than 64 KiB is far past it and can never
run. sinuprep does not read it into a tree, which would cost about 50 bytes of memory a byte of
the line: its bytes stay as they are, no rule sees its statements, and the next line is read as
usual. (N008 warns from 512 characters on.)

## Example
```
N10 R1=MAX(1,1,1,1, ... 100,000 more ...,1)
```

## Fix
Split it into blocks of at most 512 characters."#,
};

pub static NESTING_TOO_DEEP: RuleInfo = RuleInfo {
    code: "S008",
    name: "nesting-too-deep",
    severity: Severity::Error,
    docs: r#"## What it does
Reports an expression deeper than 256 levels of parentheses and operators.

## Why it matters
The control refuses a block it cannot read. sinuprep keeps the line's bytes as they are and reads
the next line as usual.

## Example
```
N10 R1=((((((...))))))
```

## Fix
Split it into several assignments."#,
};

pub static RECURSIVE_MACRO: RuleInfo = RuleInfo {
    code: "S010",
    name: "recursive-macro",
    severity: Severity::Error,
    docs: r#"## What it does
Reports a macro written in a block whose text names the macro itself, directly or through other
macros (`DEFINE A AS B + 1` with `DEFINE B AS A * 2`).

## Why it matters
The control replaces a macro's name by its text before it reads the block (Siemens, Programming
Manual Job Planning, "Macro technique (DEFINE ... AS)"); a macro that names itself never ends
being replaced, and the block cannot run. sinuprep leaves the name as it is written there.

## Example
```
DEFINE FEED AS FEED*2
N10 G1 X10 F=FEED
```

## Fix
Define the macro without its own name."#,
};

pub static MACRO_REDEFINES_KEYWORD: RuleInfo = RuleInfo {
    code: "S011",
    name: "macro-redefines-keyword",
    severity: Severity::Error,
    docs: r#"## What it does
Reports a `DEFINE` whose name is a keyword or reserved word of the language (`IF`, `ENDIF`, `DEF`,
`MOD`, `TRANS`, ...).

## Why it matters
Keywords and reserved names may not be redefined with macros (Siemens, Programming Manual Job
Planning, "Macro technique (DEFINE ... AS)"); G, M and H functions and subprogram names may. The
control refuses the definition; sinuprep does not expand it.

## Example
```
DEFINE ENDIF AS M17
```

## Fix
Give the macro a name of its own."#,
};
