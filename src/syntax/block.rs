//! Blocks and statements: one physical line becomes one [`Block`].
//!
//! The first name of a statement decides what it is (`DEF`, `IF`, `GOTOF`, a
//! frame keyword, ...); anything else is an address word, an assignment, a
//! call or a bare command. A line is never rejected whole: what cannot be read
//! becomes the block's `unparsed` rest, and the caller reports the error.

use nom::Input as _;

use crate::syntax::expr::{
    bracket_after_blank, parse_arguments, parse_expr, parse_indices, parse_list,
};
use crate::syntax::lexer::{
    is_name_char, is_name_start, is_one_of, keyword, offset, parse_blank, parse_name, parse_number,
    peek, peek_at, span_between, Input, PResult, SyntaxError, SyntaxErrorKind, RESERVED,
};
use crate::syntax::tree::*;

/// The upper-case text of a name that starts `input`, for keyword dispatch.
fn upper<'a>(input: &Input<'a>, name: Name, buffer: &'a mut [u8; 16]) -> &'a [u8] {
    let text = &input.fragment()[..name.span.len()];
    if text.len() > buffer.len() {
        return b"";
    }
    let out = &mut buffer[..text.len()];
    out.copy_from_slice(text);
    out.make_ascii_uppercase();
    out
}

/// The text of `span`, which lies in `input` or after its start on the line.
fn text_in<'a>(input: &Input<'a>, span: crate::span::Span) -> &'a [u8] {
    &input.fragment()[span.start - input.offset()..span.end - input.offset()]
}

/// `block := blank skip? blank block_number? blank label? statement* comment?`
///
/// Returns the block and, if a statement could not be read, the error.
pub fn parse_block(input: Input) -> (Block, Option<SyntaxError>) {
    parse_block_with(input, &mut Vec::new())
}

/// [`parse_block`], gathering the statements in `scratch` (left empty) and
/// storing them in a vector of their number (see [`take_gathered`]).
#[inline]
pub fn parse_block_with(
    input: Input,
    scratch: &mut Vec<Statement>,
) -> (Block, Option<SyntaxError>) {
    let (mut block, error) = parse_block_gathered(input, scratch);
    block.statements = take_gathered(scratch);
    (block, error)
}

/// The block of `input` with its statements left in `scratch` (cleared
/// first), not moved into the block: for a reader that wants only the
/// error, moving them out would cost an allocation and a copy of every
/// statement per block.
#[inline]
pub(crate) fn parse_block_gathered(
    input: Input,
    scratch: &mut Vec<Statement>,
) -> (Block, Option<SyntaxError>) {
    scratch.clear();
    parse_statements(input, scratch)
}

/// The statements gathered in `scratch`, in a vector of their number (left
/// empty): a statement is large (about 150 bytes), and room for a CAM
/// block's eight, reserved on every block, would take the allocator's slow
/// path (about 500 instructions a block of code).
#[inline]
pub(crate) fn take_gathered(scratch: &mut Vec<Statement>) -> Vec<Statement> {
    if scratch.len() <= MANY_STATEMENTS {
        let mut statements = Vec::with_capacity(scratch.len());
        statements.append(scratch);
        statements
    } else {
        // A long block of address words keeps the gathered vector itself,
        // so that it is neither copied nor held on to for the next line.
        std::mem::take(scratch)
    }
}

/// More statements than a block of the control holds (512 characters).
pub(crate) const MANY_STATEMENTS: usize = 256;

/// The block of `input` without its statements, which go to `statements`.
fn parse_statements(input: Input, statements: &mut Vec<Statement>) -> (Block, Option<SyntaxError>) {
    let line = input;
    let mut block = Block::default();
    let mut input = parse_blank(input);
    if let Ok((rest, skip)) = parse_skip(input) {
        block.skip = Some(skip);
        input = parse_blank(rest);
    }
    if let Ok((rest, number)) = parse_block_number(input) {
        block.number = Some(number);
        input = parse_blank(rest);
    }
    if let Ok((rest, label)) = parse_label(input) {
        block.label = Some(label);
        input = parse_blank(rest);
    }
    loop {
        input = parse_blank(input);
        match peek(&input) {
            None => return (block, None),
            Some(b';') => {
                block.comment = Some(span_between(&input, &input.take_from(input.input_len())));
                return (block, None);
            }
            Some(_) => {}
        }
        if let Some(Err(error)) = statements.last().map(|p| may_follow(p, input)) {
            return unparsed(block, statements, line, input, error);
        }
        // Pushed where it is read: a statement is large, and every move of
        // it costs a copy.
        let rest = match plain_word(input) {
            Some((rest, word)) => {
                statements.push(word);
                rest
            }
            None => match parse_statement(input) {
                Ok((rest, statement)) => {
                    statements.push(statement);
                    rest
                }
                Err(nom::Err::Error(error) | nom::Err::Failure(error)) => {
                    return unparsed(block, statements, line, input, error)
                }
                // Complete parsers never ask for more input; should one, the
                // line is still kept and reported, not a panic.
                Err(nom::Err::Incomplete(_)) => {
                    let error = SyntaxError::new(
                        offset(&input),
                        SyntaxErrorKind::Expected("a complete statement"),
                    );
                    return unparsed(block, statements, line, input, error);
                }
            },
        };
        if let [_, .., last] = statements.as_slice() {
            if let Some(what) = stands_alone(&last.kind) {
                let error = SyntaxError::new(last.span.start, SyntaxErrorKind::NotAlone(what));
                statements.pop();
                return unparsed(block, statements, line, input, error);
            }
        }
        input = rest;
    }
}

/// The block read so far, with `rest` of the line unparsed and the error
/// that stopped it.
fn unparsed<'a>(
    mut block: Block,
    statements: &[Statement],
    line: Input<'a>,
    rest: Input<'a>,
    mut error: SyntaxError,
) -> (Block, Option<SyntaxError>) {
    error.meant = misspelt_keyword(&line, statements);
    let end = rest.take_from(rest.input_len());
    block.unparsed = Some(span_between(&rest, &end));
    (block, Some(error))
}

/// Keywords that take operands: misspelt, they leave a command followed by
/// operands that do not read as statements (`IFF R1==1`, `WHILEE R1<5`).
const KEYWORDS_WITH_OPERANDS: [&str; 20] = [
    "IF", "WHILE", "UNTIL", "FOR", "CASE", "GOTO", "GOTOF", "GOTOB", "GOTOC", "REPEAT", "REPEATB",
    "DEF", "REDEF", "PROC", "EXTERN", "DEFINE", "WHEN", "WHENEVER", "EVERY", "FROM",
];

/// The keyword a broken block's first word was probably meant to be.
fn misspelt_keyword(
    line: &Input,
    statements: &[Statement],
) -> Option<(&'static str, crate::span::Span)> {
    let StatementKind::Command(name) = &statements.first()?.kind else {
        return None;
    };
    let word = std::str::from_utf8(text_in(line, name.span)).ok()?;
    let most = if word.len() <= 4 { 1 } else { 2 };
    let keyword = crate::suggest::closest(word, &KEYWORDS_WITH_OPERANDS, most)?;
    Some((keyword, name.span))
}

/// Statements that stand alone in their block (Siemens, Job Planning,
/// "Control structures", "Definition of user variables", "Synchronized
/// actions"), by the name a message gives them.
fn stands_alone(kind: &StatementKind) -> Option<&'static str> {
    Some(match kind {
        StatementKind::Else => "ELSE",
        StatementKind::EndIf => "ENDIF",
        StatementKind::While { .. } => "WHILE",
        StatementKind::EndWhile => "ENDWHILE",
        StatementKind::For { .. } => "FOR",
        StatementKind::EndFor => "ENDFOR",
        StatementKind::Loop => "LOOP",
        StatementKind::EndLoop => "ENDLOOP",
        StatementKind::Repeat { .. } => "REPEAT",
        StatementKind::Until { .. } => "UNTIL",
        StatementKind::Def(_) => "DEF",
        StatementKind::Redef { .. } => "REDEF",
        StatementKind::AccessLevels(_) => "a line of access levels",
        StatementKind::Proc(_) => "PROC",
        StatementKind::Extern { .. } => "EXTERN",
        StatementKind::Define { .. } => "DEFINE",
        StatementKind::SyncAction(_) => "a synchronized action",
        _ => return None,
    })
}

/// Whether the statement at `next` may follow `previous` in one block.
/// `IF cond` is followed by its jump or by nothing; a jump by another
/// `IF … GOTO…` or nothing; the statements that stand alone, the calls by
/// `CALL`/`PCALL`/... and CASE by nothing.
fn may_follow(previous: &Statement, next: Input) -> Result<(), SyntaxError> {
    const GOTOS: [&str; 5] = ["GOTO", "GOTOF", "GOTOB", "GOTOC", "GOTOS"];
    const ELSEWHERE: &str = "write it in a block of its own, or after `;` as a comment";
    let (after, help) = match &previous.kind {
        StatementKind::If { .. } if keyword_of(next, &GOTOS).is_none() => (
            "the IF condition",
            "an IF either opens a block that ENDIF closes (nothing follows its condition) or jumps: `IF R1==1 GOTOF LABEL`",
        ),
        StatementKind::Goto(_) if keyword("IF")(next).is_err() => (
            "a jump",
            "a jump ends its block; only another `IF … GOTOF …` may follow it",
        ),
        StatementKind::Repeat { .. } => (
            "REPEAT",
            "REPEAT names its labels first, then the count: `REPEAT LBL1 LBL2 P=3`",
        ),
        StatementKind::Proc(_) => (
            "the PROC header",
            "after the parameters come only the attributes SAVE, SBLOF, SBLON, DISPLOF, DISPLON, ACTBLOCNO, ICYCOF, ICYCON, IPTRLOCK, IPTRUNLOCK, PREPRO",
        ),
        StatementKind::IndirectCall { .. } => ("the called program", ELSEWHERE),
        StatementKind::Case(_) => ("CASE", ELSEWHERE),
        kind => match stands_alone(kind) {
            Some(what) => (what, ELSEWHERE),
            None => return Ok(()),
        },
    };
    Err(SyntaxError::new(
        offset(&next),
        SyntaxErrorKind::Trailing { after, help },
    ))
}

/// `skip := '/' digit?`
pub fn parse_skip(input: Input) -> PResult<Skip> {
    if peek(&input) != Some(b'/') {
        return SyntaxError::at(&input, SyntaxErrorKind::Expected("`/`"));
    }
    let level = peek_at(&input, 1).filter(u8::is_ascii_digit);
    let rest = input.take_from(1 + usize::from(level.is_some()));
    Ok((
        rest,
        Skip {
            span: span_between(&input, &rest),
            level: level.map(|d| d - b'0'),
        },
    ))
}

/// `block_number := 'N' digit+ | ':' digit+`
pub fn parse_block_number(input: Input) -> PResult<BlockNumber> {
    let Some(digits) = block_number_digits(input.fragment()) else {
        return SyntaxError::at(&input, SyntaxErrorKind::Expected("a block number"));
    };
    let main = peek(&input) == Some(b':');
    let after_prefix = input.take_from(1);
    let rest = input.take_from(1 + digits);
    Ok((
        rest,
        BlockNumber {
            span: span_between(&input, &rest),
            main,
            digits: span_between(&after_prefix, &rest),
        },
    ))
}

/// How many digits follow the `N` or `:` that `bytes` starts with, if they
/// make a block number.
pub fn block_number_digits(bytes: &[u8]) -> Option<usize> {
    if !matches!(bytes.first(), Some(b'N' | b'n' | b':')) {
        return None;
    }
    let digits = bytes[1..].iter().take_while(|b| b.is_ascii_digit()).count();
    // `N10=5` would be an assignment, not a block number.
    let assigned = matches!(bytes.get(1 + digits), Some(b'=' | b'[' | b'.'));
    (digits > 0 && !assigned).then_some(digits)
}

/// `label := name ':'` (not `::`, which is not a label)
pub fn parse_label(input: Input) -> PResult<Name> {
    let (rest, name) = parse_name(input)?;
    if name.span.len() < 2 || peek(&rest) != Some(b':') || peek_at(&rest, 1) == Some(b':') {
        return SyntaxError::at(&input, SyntaxErrorKind::Expected("a label"));
    }
    Ok((rest.take_from(1), name))
}

/// `statement := keyword_statement | word | assignment | call | command`
#[inline]
pub fn parse_statement(input: Input) -> PResult<Statement> {
    let start = input;
    let (rest, kind) = parse_statement_kind(input)?;
    Ok((
        rest,
        Statement {
            span: span_between(&start, &rest),
            kind,
        },
    ))
}

fn parse_statement_kind(input: Input) -> PResult<StatementKind> {
    let Some(first) = peek(&input) else {
        return SyntaxError::at(&input, SyntaxErrorKind::Expected("a statement"));
    };
    // An identifier has two leading letters (or `_`); one letter followed by
    // anything else is an address: `X10`, `G01X5`, `R1=2`, `A3=0.5`.
    if first.is_ascii_alphabetic() && !peek_at(&input, 1).is_some_and(is_name_start) {
        return parse_word(input);
    }
    if first != b'$' && !is_name_start(first) {
        return SyntaxError::at(&input, stray_kind(first));
    }
    let (after_name, name) = parse_name(input)?;
    let next = parse_blank(after_name);
    let is_assignment_like = matches!(peek(&next), Some(b'=' | b'['));
    // `ID=1 WHEN ...`: the action's number, not an assignment.
    if peek(&next) == Some(b'=')
        && name.span.len() <= 3
        && peek_at(&next, 1) != Some(b'=')
        && is_one_of(&input.fragment()[..name.span.len()], &["ID", "IDS"])
    {
        return parse_sync_action(input);
    }
    // Only C and R start the multi-letter addresses.
    if !is_assignment_like && matches!(first | 0x20, b'c' | b'r') {
        if let Some(len) = multi_letter_address(&input.fragment()[..name.span.len()]) {
            return SyntaxError::fail(
                offset(&input) + len,
                SyntaxErrorKind::Expected(
                    "`=` between a multi-letter address and its value (`CR=25`)",
                ),
            );
        }
    }
    if !is_assignment_like && first != b'$' {
        let mut buffer = [0u8; 16];
        if let Some(parsed) =
            parse_keyword_statement(input, after_name, name, upper(&input, name, &mut buffer))
        {
            return parsed;
        }
    }
    parse_assignment_call_or_command(input, name, after_name)
}

/// Whether [`parse_statement_kind`] reads `name` (followed by neither `=`
/// nor `[`) as a call's or a command's: it runs no multi-letter address into
/// its digits (`CR25`) and is no keyword. The same tests, for
/// [`crate::syntax::clean`]; a keyword's statement is read from the name
/// alone, since only whether there is one counts.
pub(crate) fn names_call_or_command(name: Input) -> bool {
    let text = name.fragment();
    let first = text[0];
    if matches!(first | 0x20, b'c' | b'r') && multi_letter_address(text).is_some() {
        return false;
    }
    if first == b'$' {
        return true;
    }
    let after_name = name.take_from(text.len());
    let spanned = Name {
        span: span_between(&name, &after_name),
    };
    let mut buffer = [0u8; 16];
    let word = upper(&name, spanned, &mut buffer);
    parse_keyword_statement(name, after_name, spanned, word).is_none()
}

/// The length of the multi-letter address (radius, chamfer, rounding) that
/// `name` runs into its digits, as `CR25` for `CR=25`.
fn multi_letter_address(name: &[u8]) -> Option<usize> {
    ["RNDM", "CHF", "CHR", "RND", "CR"]
        .iter()
        .find_map(|address| {
            let len = address.len();
            let starts = name.len() > len && name[..len].eq_ignore_ascii_case(address.as_bytes());
            (starts && name[len..].iter().all(u8::is_ascii_digit)).then_some(len)
        })
}

fn stray_kind(byte: u8) -> SyntaxErrorKind {
    match byte {
        b')' | b']' => SyntaxErrorKind::UnmatchedClose(byte),
        b'0'..=b'9'
        | b'.'
        | b','
        | b'('
        | b'+'
        | b'-'
        | b'*'
        | b'/'
        | b'='
        | b'<'
        | b'>'
        | b':'
        | b'"'
        | b'\'' => SyntaxErrorKind::Expected("a word, an assignment or a statement"),
        _ => SyntaxErrorKind::UnknownCharacter,
    }
}

/// Statements introduced by a keyword; `None` when `word` is no keyword.
fn parse_keyword_statement<'a>(
    start: Input<'a>,
    after: Input<'a>,
    name: Name,
    word: &[u8],
) -> Option<PResult<'a, StatementKind>> {
    let simple = |kind: StatementKind| Some(Ok((after, kind)));
    let expr =
        |make: fn(Expr) -> StatementKind| Some(parse_condition(after).map(|(r, e)| (r, make(e))));
    match word {
        b"WHEN" | b"WHENEVER" | b"FROM" | b"EVERY" | b"DO" => Some(parse_sync_action(start)),
        b"REDEF" if !starts_typed_def(after) => Some(parse_redef(after)),
        b"DEF" | b"REDEF" => {
            Some(parse_def(after).map(|(r, d)| (r, StatementKind::Def(Box::new(d)))))
        }
        b"PROC" => Some(parse_proc(after).map(|(r, p)| (r, StatementKind::Proc(p)))),
        b"EXTERN" => Some(parse_extern(after)),
        _ if is_one_of(word, &ACCESS_ATTRIBUTES) => Some(
            parse_attributes(start)
                .map(|(r, attributes)| (r, StatementKind::AccessLevels(attributes))),
        ),
        b"DEFINE" => Some(parse_define(after)),
        b"IF" => expr(|condition| StatementKind::If { condition }),
        b"ELSE" => simple(StatementKind::Else),
        b"ENDIF" => simple(StatementKind::EndIf),
        b"WHILE" => expr(|condition| StatementKind::While { condition }),
        b"ENDWHILE" => simple(StatementKind::EndWhile),
        b"FOR" => Some(parse_for(after)),
        b"ENDFOR" => simple(StatementKind::EndFor),
        b"LOOP" => simple(StatementKind::Loop),
        b"ENDLOOP" => simple(StatementKind::EndLoop),
        b"REPEAT" | b"REPEATB" => Some(parse_repeat(after, word == b"REPEATB")),
        b"UNTIL" => expr(|condition| StatementKind::Until { condition }),
        b"CASE" => Some(parse_case(after).map(|(r, c)| (r, StatementKind::Case(Box::new(c))))),
        b"GOTO" | b"GOTOF" | b"GOTOB" | b"GOTOC" | b"GOTOS" => {
            Some(parse_goto(start).map(|(r, g)| (r, StatementKind::Goto(g))))
        }
        b"CALL" | b"PCALL" | b"MCALL" | b"EXTCALL" | b"ISOCALL" | b"CALLPATH" => {
            Some(parse_indirect_call(after, name, word))
        }
        _ => FrameKind::ALL
            .iter()
            .find(|(text, _)| text.as_bytes() == word)
            .and_then(|&(_, kind)| {
                simple(StatementKind::Frame(FrameStatement {
                    keyword: name,
                    kind,
                }))
            }),
    }
}

/// `condition := expr`; a condition followed by a lone `=` was meant as a
/// comparison.
fn parse_condition(input: Input) -> PResult<Expr> {
    let input = parse_blank(input);
    if matches!(peek(&input), None | Some(b';')) {
        return SyntaxError::fail(offset(&input), SyntaxErrorKind::Expected("a condition"));
    }
    let (rest, condition) = parse_expr(input)?;
    let next = parse_blank(rest);
    if peek(&next) == Some(b'=') && peek_at(&next, 1) != Some(b'=') {
        return SyntaxError::fail(
            offset(&next),
            SyntaxErrorKind::Expected("`==` to compare (one `=` assigns: `IF R1==5`)"),
        );
    }
    Ok((rest, condition))
}

const SYNC_FREQUENCIES: [&str; 4] = ["WHEN", "WHENEVER", "FROM", "EVERY"];

/// The keyword at `input` if it is one of `words`.
fn keyword_of<'a>(input: Input<'a>, words: &[&str]) -> Option<(Input<'a>, Name)> {
    let (rest, name) = parse_name(input).ok()?;
    is_one_of(&input.fragment()[..name.span.len()], words).then_some((rest, name))
}

/// `sync_action := (('ID' | 'IDS') '=' expr)? (frequency g_word* condition)?
/// 'DO' actions ('ELSE' actions)?` (Siemens, Function Manual Synchronized
/// actions, "Definition of a synchronized action": the action is the whole
/// block; without a frequency there is no condition and the actions run in
/// every interpolation cycle).
pub fn parse_sync_action(input: Input) -> PResult<StatementKind> {
    let mut at = input;
    let mut id = None;
    if let Some((rest, id_keyword)) = keyword_of(at, &["ID", "IDS"]) {
        let equals = parse_blank(rest);
        let (rest, number) = parse_expr(parse_blank(equals.take_from(1)))?;
        id = Some((id_keyword, number));
        at = parse_blank(rest);
    }
    let mut condition = None;
    if let Some((rest, frequency)) = keyword_of(at, &SYNC_FREQUENCIES) {
        let mut next = parse_blank(rest);
        let mut g_functions = Vec::new();
        while let Some((rest, g)) = g_function(next) {
            g_functions.push(g);
            next = parse_blank(rest);
        }
        if matches!(peek(&next), None | Some(b';')) || keyword("DO")(next).is_ok() {
            return SyntaxError::fail(
                offset(&next),
                SyntaxErrorKind::Expected("the condition the synchronized action tests"),
            );
        }
        let (rest, expr) = parse_condition(next)?;
        condition = Some(SyncCondition {
            frequency,
            g_functions,
            expr,
        });
        at = parse_blank(rest);
    }
    let Ok((rest, do_keyword)) = keyword("DO")(at) else {
        return SyntaxError::fail(
            offset(&at),
            SyntaxErrorKind::Expected("`DO` and the actions of the synchronized action"),
        );
    };
    let (mut rest, actions) = parse_actions(rest)?;
    let mut otherwise = None;
    if let Ok((after, else_keyword)) = keyword("ELSE")(parse_blank(rest)) {
        if condition.is_none() {
            return SyntaxError::fail(
                else_keyword.span.start,
                SyntaxErrorKind::Trailing {
                    after: "the actions of a synchronized action without a condition",
                    help:
                        "ELSE runs while a condition is not met: `WHEN $A_IN[1]==1 DO M3 ELSE M5`",
                },
            );
        }
        let (after, actions) = parse_actions(after)?;
        if let Ok((_, second)) = keyword("ELSE")(parse_blank(after)) {
            return SyntaxError::fail(
                second.span.start,
                SyntaxErrorKind::Trailing {
                    after: "the ELSE actions",
                    help: "a synchronized action has one ELSE at most",
                },
            );
        }
        otherwise = Some((else_keyword, actions));
        rest = after;
    }
    Ok((
        rest,
        StatementKind::SyncAction(Box::new(SyncAction {
            id,
            condition,
            do_keyword,
            actions,
            otherwise,
        })),
    ))
}

/// A G function such as `G710`, as a synchronized action's condition may start with.
fn g_function(input: Input) -> Option<(Input, Statement)> {
    let bytes = input.fragment();
    let is_g = bytes.first()?.eq_ignore_ascii_case(&b'G') && bytes.get(1)?.is_ascii_digit();
    is_g.then(|| plain_word(input)).flatten()
}

/// The actions after `DO` or `ELSE`, up to the comment, the end of the
/// line or an `ELSE`: address words, assignments, calls (technology
/// cycles, `CANCEL(n)`, `LOCK(n)`, ...) and commands (`DELDTG`, `STOPREOF`).
fn parse_actions(mut input: Input) -> PResult<Vec<Statement>> {
    let mut actions = Vec::new();
    loop {
        let at = parse_blank(input);
        if matches!(peek(&at), None | Some(b';')) || keyword("ELSE")(at).is_ok() {
            break;
        }
        let (rest, action) = match plain_word(at) {
            Some(word) => word,
            None => parse_statement(at)?,
        };
        if !matches!(
            action.kind,
            StatementKind::Word(_)
                | StatementKind::Assign(_)
                | StatementKind::Call(_)
                | StatementKind::Command(_)
        ) {
            return SyntaxError::fail(
                action.span.start,
                SyntaxErrorKind::Expected(
                    "an action: an assignment, an address word, a call or a command",
                ),
            );
        }
        actions.push(action);
        input = rest;
    }
    if actions.is_empty() {
        return SyntaxError::fail(
            offset(&parse_blank(input)),
            SyntaxErrorKind::Expected("an action after DO or ELSE"),
        );
    }
    Ok((input, actions))
}

/// `word := letter (extension? blank '=' blank expr | sign? number)`
///
/// `R<n>=` is an assignment to an R parameter, and `letter[..]=` one to an
/// indexed variable (`R[1]`, `A[1,2]`).
pub fn parse_word(input: Input) -> PResult<StatementKind> {
    let address = Name {
        span: span_between(&input, &input.take_from(1)),
    };
    let is_r = input.fragment()[0].eq_ignore_ascii_case(&b'R');
    let after_letter = input.take_from(1);
    let digits = after_letter
        .fragment()
        .iter()
        .take_while(|b| b.is_ascii_digit())
        .count();
    let after_digits = after_letter.take_from(digits);
    let equals = parse_blank(after_digits);

    // `X1=100`, `A3=0.5`, `R1 = 2`: digits then `=` make an extension.
    if peek(&equals) == Some(b'=') && peek_at(&equals, 1) != Some(b'=') {
        // A G function is written alone (`G0`); `G[8]=2` is the indexed form.
        if digits > 0 && input.fragment()[0].eq_ignore_ascii_case(&b'G') {
            return SyntaxError::fail(
                offset(&equals),
                SyntaxErrorKind::Expected("no value after a G function (`G0`, not `G0=10`)"),
            );
        }
        let (rest, value) = parse_expr(parse_blank(equals.take_from(1)))?;
        if is_r && digits > 0 {
            let name = Name {
                span: span_between(&input, &after_digits),
            };
            let target = Variable {
                span: name.span,
                name,
                indices: Vec::new(),
            };
            return Ok((rest, StatementKind::Assign(Assign { target, value })));
        }
        let extension = (digits > 0).then(|| span_between(&after_letter, &after_digits));
        return Ok((
            rest,
            StatementKind::Word(Word {
                address,
                extension,
                value: WordValue::Expr(value),
            }),
        ));
    }
    // `R[1]=`, `A[1,2]=`: a letter with an index is an indexed variable.
    if digits == 0 && peek(&after_letter) == Some(b'[') {
        let (after_index, indices) = parse_indices(after_letter, 0)?;
        let equals = parse_blank(after_index);
        if peek(&equals) != Some(b'=') {
            return SyntaxError::fail(
                offset(&equals),
                SyntaxErrorKind::Expected("`=` after an indexed variable"),
            );
        }
        let (rest, value) = parse_expr(parse_blank(equals.take_from(1)))?;
        let target = Variable {
            span: span_between(&input, &after_index),
            name: address,
            indices,
        };
        return Ok((rest, StatementKind::Assign(Assign { target, value })));
    }
    // `L6(TNR)`: a subprogram named L and digits, called with arguments.
    if digits > 0 && input.fragment()[0].eq_ignore_ascii_case(&b'L') {
        let open = bracket_after_blank(after_digits);
        if peek(&open) == Some(b'(') {
            let name = Name {
                span: span_between(&input, &after_digits),
            };
            let (rest, arguments) = parse_arguments(open, 0)?;
            return Ok((rest, StatementKind::Call(Call { name, arguments })));
        }
    }
    // `X-12.5`, `F.02`, `G01`: the number directly after the letter.
    let mut number_start = after_letter;
    let negative = match peek(&number_start) {
        Some(sign @ (b'-' | b'+')) => {
            number_start = number_start.take_from(1);
            sign == b'-'
        }
        _ => false,
    };
    match peek(&number_start) {
        Some(b'0'..=b'9' | b'.' | b'\'') => {}
        Some(byte) if !crate::syntax::expr::is_known_byte(byte) => {
            return SyntaxError::fail(offset(&number_start), SyntaxErrorKind::UnknownCharacter);
        }
        _ => return SyntaxError::fail(address.span.start, SyntaxErrorKind::MissingValue),
    }
    let (rest, mut number) = parse_number(number_start)?;
    number.span = span_between(&after_letter, &rest);
    if negative {
        number.value = -number.value;
    }
    Ok((
        rest,
        StatementKind::Word(Word {
            address,
            extension: None,
            value: WordValue::Number(number),
        }),
    ))
}

/// The word most blocks are made of, `X-12.5` or `G1`, read without the
/// general machinery; `None` for anything else (`X1=5`, `X=R1`, `X'H1F'`),
/// which [`parse_word`] reads into the same tree.
#[inline]
fn plain_word(input: Input) -> Option<(Input, Statement)> {
    let bytes = input.fragment();
    let letter = *bytes.first()?;
    let signed = matches!(bytes.get(1), Some(b'-' | b'+'));
    let number_start = 1 + usize::from(signed);
    if !letter.is_ascii_alphabetic() || !matches!(bytes.get(number_start), Some(b'0'..=b'9' | b'.'))
    {
        return None;
    }
    let (rest, mut number) = parse_number(input.take_from(number_start)).ok()?;
    // An extension (`X1 =5`), a call (`L6(TNR)`), a broken exponent or a
    // second point: the general path, which knows what to say.
    if matches!(peek(&rest), Some(b'E' | b'e' | b'.'))
        || matches!(peek(&parse_blank(rest)), Some(b'=' | b'('))
    {
        return None;
    }
    let after_letter = input.take_from(1);
    number.span = span_between(&after_letter, &rest);
    if bytes[1] == b'-' {
        number.value = -number.value;
    }
    let statement = Statement {
        span: span_between(&input, &rest),
        kind: StatementKind::Word(Word {
            address: Name {
                span: span_between(&input, &after_letter),
            },
            extension: None,
            value: WordValue::Number(number),
        }),
    };
    Some((rest, statement))
}

/// `assignment := variable blank '=' blank expr` ;
/// `call := name blank arguments` ; `command := name`
fn parse_assignment_call_or_command<'a>(
    start: Input<'a>,
    name: Name,
    after_name: Input<'a>,
) -> PResult<'a, StatementKind> {
    let (after_index, indices) = parse_indices(bracket_after_blank(after_name), 0)?;
    let after_index = if indices.is_empty() {
        after_name
    } else {
        after_index
    };
    let next = parse_blank(after_index);
    match peek(&next) {
        Some(b'=') if peek_at(&next, 1) != Some(b'=') => {
            let value_start = parse_blank(next.take_from(1));
            let tuple = (!indices.is_empty()).then(|| tuple(value_start)).flatten();
            let (rest, value) = match tuple {
                Some(tuple) => tuple,
                None => parse_expr(value_start)?,
            };
            let target = Variable {
                span: span_between(&start, &after_index),
                name,
                indices,
            };
            Ok((rest, StatementKind::Assign(Assign { target, value })))
        }
        Some(b'(') if indices.is_empty() => {
            let (rest, arguments) = parse_arguments(next, 0)?;
            Ok((rest, StatementKind::Call(Call { name, arguments })))
        }
        _ if !indices.is_empty() => SyntaxError::fail(
            offset(&next),
            SyntaxErrorKind::Expected("`=` after an indexed variable"),
        ),
        // SETINT(n) names the interrupt it assigns.
        _ if start.fragment()[..name.span.len()].eq_ignore_ascii_case(b"SETINT") => {
            SyntaxError::fail(
                offset(&next),
                SyntaxErrorKind::Expected("`(` and the interrupt number: SETINT(n)"),
            )
        }
        _ => Ok((after_name, StatementKind::Command(name))),
    }
}

/// `tuple := '(' expr (',' expr)+ ')'`: the several values of an indexed
/// assignment (`OSCTRL[Z]=(1+2,16+32+64)`, `POSP[X]=(END,PART,MODE)`);
/// `None` for one value in parentheses, which is an expression.
fn tuple(input: Input) -> Option<(Input, Expr)> {
    if peek(&input) != Some(b'(') {
        return None;
    }
    let (rest, items) = parse_list(input, b'(', b')', 0).ok()?;
    (items.items.len() > 1).then(|| {
        let span = span_between(&input, &rest);
        (
            rest,
            Expr {
                span,
                kind: ExprKind::Tuple(items),
            },
        )
    })
}

/// `def := ('DEF' | 'REDEF') scope? attribute* data_type attribute* declarator (',' declarator)*`
pub fn parse_def(input: Input) -> PResult<Def> {
    let mut input = parse_blank(input);
    let mut scope = None;
    if let Ok((rest, name)) = keyword("NCK")(input).or_else(|_| keyword("CHAN")(input)) {
        scope = Some(name);
        input = parse_blank(rest);
    }
    let (rest, mut attributes) = parse_attributes(input)?;
    let (rest, data_type) = parse_data_type(parse_blank(rest))?;
    let (rest, more) = parse_attributes(parse_blank(rest))?;
    attributes.extend(more);
    let mut input = parse_blank(rest);
    let mut variables = Vec::new();
    loop {
        let (rest, declarator) = parse_declarator(input)?;
        variables.push(declarator);
        let rest = parse_blank(rest);
        if peek(&rest) == Some(b',') {
            input = parse_blank(rest.take_from(1));
        } else {
            return Ok((
                rest,
                Def {
                    scope,
                    attributes,
                    data_type,
                    variables,
                },
            ));
        }
    }
}

/// Whether what follows `DEF`/`REDEF` starts as a definition with a type
/// does (a scope, an attribute or a data type first).
fn starts_typed_def(input: Input) -> bool {
    let input = parse_blank(input);
    let Ok((_, name)) = parse_name(input) else {
        return false;
    };
    let text = &input.fragment()[..name.span.len()];
    is_one_of(text, &["NCK", "CHAN"])
        || is_one_of(text, &VALUED_ATTRIBUTES)
        || is_one_of(text, &FLAG_ATTRIBUTES)
        || TYPES
            .iter()
            .any(|(t, _)| text.eq_ignore_ascii_case(t.as_bytes()))
}

/// The name at `input`, or an error that says what was `expected` there.
fn expect_name<'a>(input: Input<'a>, expected: &'static str) -> PResult<'a, Name> {
    parse_name(input)
        .or_else(|_| SyntaxError::fail(offset(&input), SyntaxErrorKind::Expected(expected)))
}

/// `redef := 'REDEF' name attribute+ ('='? expr)?`: new attributes (access
/// levels, initialisation) for a variable defined elsewhere; a new
/// initialisation value follows its time, `REDEF _VAR INIRE ""` (Siemens,
/// Job Planning, "Redefinition of system data, user data, and NC language
/// commands (REDEF)"). The value is kept as the time's.
pub fn parse_redef(input: Input) -> PResult<StatementKind> {
    let input = parse_blank(input);
    let (rest, name) = expect_name(input, "the name of the variable to redefine")?;
    let after = parse_blank(rest);
    let (mut rest, mut attributes) = parse_attributes(after)?;
    let Some(last) = attributes.last_mut() else {
        return SyntaxError::fail(
            offset(&after),
            SyntaxErrorKind::Expected("its new attributes (APR, APW, APX, INIRE, SYNR, ...)"),
        );
    };
    let value_start = parse_blank(rest);
    let is_init_time = is_one_of(text_in(&after, last.keyword.span), &INIT_TIMES);
    if is_init_time && !matches!(peek(&value_start), None | Some(b';')) {
        let value_start = match peek(&value_start) {
            Some(b'=') => parse_blank(value_start.take_from(1)),
            _ => value_start,
        };
        let (after_value, value) = parse_expr(value_start)?;
        last.value = Some(value);
        rest = after_value;
    }
    Ok((rest, StatementKind::Redef { name, attributes }))
}

/// Access levels for reading, writing and executing (Siemens, Job
/// Planning, "Attribute: Access rights").
const ACCESS_ATTRIBUTES: [&str; 7] = ["APR", "APW", "APX", "APRP", "APWP", "APRB", "APWB"];
pub(crate) const VALUED_ATTRIBUTES: [&str; 10] = [
    "APR", "APW", "APX", "APRP", "APWP", "APRB", "APWB", "PHU", "LLI", "ULI",
];
/// When a variable is initialised again (Siemens, Job Planning, "Attribute:
/// Initialization value").
const INIT_TIMES: [&str; 4] = ["INIPO", "INIRE", "INICF", "PRLOC"];
pub(crate) const FLAG_ATTRIBUTES: [&str; 7] =
    ["SYNR", "SYNW", "SYNRW", "INIPO", "INIRE", "INICF", "PRLOC"];

/// `attribute := ('APR' | 'APW' | ... | 'LLI' | 'ULI') expr | 'SYNR' | ... | 'PRLOC'`
pub fn parse_attributes(mut input: Input) -> PResult<Vec<Attribute>> {
    let mut attributes = Vec::new();
    loop {
        let Ok((rest, keyword)) = parse_name(input) else {
            return Ok((input, attributes));
        };
        let text = &input.fragment()[..keyword.span.len()];
        if is_one_of(text, &VALUED_ATTRIBUTES) {
            let (rest, value) = parse_expr(parse_blank(rest))?;
            attributes.push(Attribute {
                keyword,
                value: Some(value),
            });
            input = parse_blank(rest);
        } else if is_one_of(text, &FLAG_ATTRIBUTES) {
            attributes.push(Attribute {
                keyword,
                value: None,
            });
            input = parse_blank(rest);
        } else {
            return Ok((input, attributes));
        }
    }
}

const TYPES: [(&str, TypeKind); 7] = [
    ("INT", TypeKind::Int),
    ("REAL", TypeKind::Real),
    ("BOOL", TypeKind::Bool),
    ("CHAR", TypeKind::Char),
    ("STRING", TypeKind::String),
    ("AXIS", TypeKind::Axis),
    ("FRAME", TypeKind::Frame),
];

/// `data_type := 'INT' | 'REAL' | 'BOOL' | 'CHAR' | 'STRING' '[' expr ']' | 'AXIS' | 'FRAME'`
pub fn parse_data_type(input: Input) -> PResult<DataType> {
    let expected =
        SyntaxErrorKind::Expected("a data type: INT, REAL, BOOL, CHAR, STRING[n], AXIS or FRAME");
    let Ok((rest, name)) = parse_name(input) else {
        return SyntaxError::fail(offset(&input), expected);
    };
    let text = &input.fragment()[..name.span.len()];
    let Some(&(_, kind)) = TYPES
        .iter()
        .find(|(t, _)| text.eq_ignore_ascii_case(t.as_bytes()))
    else {
        return SyntaxError::fail(offset(&input), expected);
    };
    let mut rest = rest;
    let mut length = None;
    if kind == TypeKind::String {
        let (after, mut list) = parse_indices(bracket_after_blank(rest), 0)?;
        if list.len() > 1 {
            return SyntaxError::fail(
                offset(&rest),
                SyntaxErrorKind::Expected("one length, `STRING[n]`"),
            );
        }
        length = list.pop();
        rest = after;
    }
    Ok((
        rest,
        DataType {
            span: span_between(&input, &rest),
            kind,
            length,
        },
    ))
}

/// `declarator := name dimensions? (blank '=' blank initializer)?`
pub fn parse_declarator(input: Input) -> PResult<Declarator> {
    let (rest, name) = expect_name(input, "a variable name")?;
    let text = &input.fragment()[..name.span.len()];
    if text.len() == 1 {
        return SyntaxError::fail(
            offset(&input),
            SyntaxErrorKind::Expected(
                "a variable name of two characters or more (one letter is an address)",
            ),
        );
    }
    if is_one_of(text, RESERVED) {
        return SyntaxError::fail(
            offset(&input),
            SyntaxErrorKind::Expected("a variable name that is not a reserved word"),
        );
    }
    let open = bracket_after_blank(rest);
    let (rest, dimensions) = if peek(&open) == Some(b'[') {
        let (rest, list) = parse_list(open, b'[', b']', 0)?;
        (rest, list.items)
    } else {
        (rest, Vec::new())
    };
    let equals = parse_blank(rest);
    if peek(&equals) != Some(b'=') {
        return Ok((
            rest,
            Declarator {
                name,
                dimensions,
                init: None,
            },
        ));
    }
    let (rest, init) = parse_initializer(parse_blank(equals.take_from(1)))?;
    Ok((
        rest,
        Declarator {
            name,
            dimensions,
            init: Some(init),
        },
    ))
}

/// `initializer := '(' argument (',' argument)+ ')' | expr`
pub fn parse_initializer(input: Input) -> PResult<Initializer> {
    if peek(&input) == Some(b'(') {
        if let Ok((rest, list)) = parse_arguments(input, 0) {
            if list.items.len() > 1 {
                return Ok((rest, Initializer::List(list)));
            }
        }
    }
    parse_expr(input).map(|(rest, expr)| (rest, Initializer::Expr(expr)))
}

/// What may follow a PROC's parameters (Siemens, Job Planning, "Subprogram
/// with SAVE mechanism", "Suppress single block execution", ...).
const PROC_ATTRIBUTES: [&str; 11] = [
    "SAVE",
    "SBLOF",
    "SBLON",
    "DISPLOF",
    "DISPLON",
    "ACTBLOCNO",
    "ICYCOF",
    "ICYCON",
    "IPTRLOCK",
    "IPTRUNLOCK",
    "PREPRO",
];

/// `proc := 'PROC' name (blank '(' (parameter (',' parameter)*)? ')')? proc_attribute*`
pub fn parse_proc(input: Input) -> PResult<Proc> {
    let input = parse_blank(input);
    let (rest, name) = expect_name(input, "the procedure's name")?;
    let mut input = parse_blank(rest);
    let mut parameters = Vec::new();
    if peek(&input) == Some(b'(') {
        let open = input;
        input = parse_blank(input.take_from(1));
        if peek(&input) != Some(b')') {
            loop {
                let (rest, parameter) = parse_parameter(input)?;
                parameters.push(parameter);
                input = parse_blank(rest);
                match peek(&input) {
                    Some(b',') => input = parse_blank(input.take_from(1)),
                    Some(b')') => break,
                    None => {
                        return SyntaxError::fail(
                            offset(&open),
                            SyntaxErrorKind::UnclosedBracket(b'('),
                        )
                    }
                    Some(_) => {
                        return SyntaxError::fail(
                            offset(&input),
                            SyntaxErrorKind::Expected("`,` or `)` in the parameter list"),
                        )
                    }
                }
            }
        }
        input = input.take_from(1);
    }
    let mut attributes = Vec::new();
    loop {
        let at = parse_blank(input);
        match keyword_of(at, &PROC_ATTRIBUTES) {
            Some((rest, attribute)) => {
                attributes.push(attribute);
                input = rest;
            }
            None => {
                return Ok((
                    input,
                    Proc {
                        name,
                        parameters,
                        attributes,
                    },
                ))
            }
        }
    }
}

/// `parameter := 'VAR'? data_type blank declarator`
pub fn parse_parameter(input: Input) -> PResult<Parameter> {
    let start = input;
    let (rest, by_reference) = match keyword("VAR")(input) {
        Ok((rest, _)) => (parse_blank(rest), true),
        Err(_) => (input, false),
    };
    let (rest, data_type) = parse_data_type(rest)?;
    let (rest, declarator) = parse_declarator(parse_blank(rest))?;
    Ok((
        rest,
        Parameter {
            span: span_between(&start, &rest),
            by_reference,
            data_type,
            declarator,
        },
    ))
}

/// `extern := 'EXTERN' name ('(' any ')')?`
pub fn parse_extern(input: Input) -> PResult<StatementKind> {
    let input = parse_blank(input);
    let (rest, name) = expect_name(input, "the subprogram's name")?;
    let next = parse_blank(rest);
    if peek(&next) != Some(b'(') {
        return Ok((
            rest,
            StatementKind::Extern {
                name,
                parameters: None,
            },
        ));
    }
    match memchr::memchr(b')', next.fragment()) {
        Some(close) => {
            let after = next.take_from(close + 1);
            Ok((
                after,
                StatementKind::Extern {
                    name,
                    parameters: Some(span_between(&next, &after)),
                },
            ))
        }
        None => SyntaxError::fail(offset(&next), SyntaxErrorKind::UnclosedBracket(b'(')),
    }
}

/// `define := 'DEFINE' name 'AS' any` (the macro text runs to the comment)
pub fn parse_define(input: Input) -> PResult<StatementKind> {
    let input = parse_blank(input);
    let (rest, name) = expect_name(input, "the macro's name")?;
    let Ok((rest, _)) = keyword("AS")(parse_blank(rest)) else {
        return SyntaxError::fail(
            offset(&parse_blank(rest)),
            SyntaxErrorKind::Expected("`AS` after the macro's name"),
        );
    };
    let body_start = parse_blank(rest);
    let len = memchr::memchr(b';', body_start.fragment()).unwrap_or(body_start.input_len());
    let len = target_len(&body_start.fragment()[..len]);
    let end = body_start.take_from(len);
    Ok((
        end,
        StatementKind::Define {
            name,
            body: span_between(&body_start, &end),
        },
    ))
}

/// `for := 'FOR' name blank '=' expr 'TO' expr`
pub fn parse_for(input: Input) -> PResult<StatementKind> {
    let input = parse_blank(input);
    let (rest, variable) = expect_name(input, "the loop variable")?;
    let equals = parse_blank(rest);
    if peek(&equals) != Some(b'=') {
        return SyntaxError::fail(
            offset(&equals),
            SyntaxErrorKind::Expected("`=` after the loop variable"),
        );
    }
    let (rest, start) = parse_expr(parse_blank(equals.take_from(1)))?;
    let Ok((rest, _)) = keyword("TO")(parse_blank(rest)) else {
        return SyntaxError::fail(
            offset(&parse_blank(rest)),
            SyntaxErrorKind::Expected("`TO` and the end value"),
        );
    };
    let (rest, end) = parse_expr(parse_blank(rest))?;
    Ok((
        rest,
        StatementKind::For {
            variable,
            start: Box::new(start),
            end: Box::new(end),
        },
    ))
}

/// `repeat := 'REPEAT' (label label? ('P' '=' expr)?)? | 'REPEATB' label ('P' '=' expr)?`
/// (Siemens, Job Planning, "Program section repetition": the labels first,
/// then the count).
pub fn parse_repeat(mut input: Input, block_only: bool) -> PResult<StatementKind> {
    let mut targets = Vec::new();
    let mut count = None;
    loop {
        let at = parse_blank(input);
        let Ok((rest, name)) = parse_name(at) else {
            break;
        };
        let equals = parse_blank(rest);
        if peek(&equals) == Some(b'=') {
            if at.fragment()[..name.span.len()].eq_ignore_ascii_case(b"P") && !targets.is_empty() {
                let (rest, n) = parse_expr(parse_blank(equals.take_from(1)))?;
                count = Some(Box::new(n));
                input = rest;
            }
            break;
        }
        if !is_label_name(&at.fragment()[..name.span.len()]) {
            return SyntaxError::fail(
                name.span.start,
                SyntaxErrorKind::Expected("a label: two letters or `_` first (`LBL1`, `_MARK`)"),
            );
        }
        let most = if block_only { 1 } else { 2 };
        if targets.len() == most {
            return SyntaxError::fail(
                name.span.start,
                SyntaxErrorKind::Expected(if block_only {
                    "one label after REPEATB, then `P=n` or nothing"
                } else {
                    "two labels at most after REPEAT, then `P=n` or nothing"
                }),
            );
        }
        targets.push(name);
        input = rest;
    }
    if block_only && targets.is_empty() {
        return SyntaxError::fail(
            offset(&parse_blank(input)),
            SyntaxErrorKind::Expected("the label of the block REPEATB repeats"),
        );
    }
    Ok((input, StatementKind::Repeat { targets, count }))
}

/// A label's name: two letters or underscores first (Siemens,
/// Fundamentals, "Labels"), then letters, digits and underscores.
pub fn is_label_name(text: &[u8]) -> bool {
    text.len() >= 2
        && text[..2]
            .iter()
            .all(|b| b.is_ascii_alphabetic() || *b == b'_')
}

/// `case := 'CASE' expr 'OF' (expr goto)* ('DEFAULT' goto)?`
pub fn parse_case(input: Input) -> PResult<Case> {
    let (rest, selector) = parse_expr(parse_blank(input))?;
    let Ok((mut input, _)) = keyword("OF")(parse_blank(rest)) else {
        return SyntaxError::fail(
            offset(&parse_blank(rest)),
            SyntaxErrorKind::Expected("`OF` after the CASE expression"),
        );
    };
    let mut branches = Vec::new();
    let mut default = None;
    loop {
        let at = parse_blank(input);
        if matches!(peek(&at), None | Some(b';')) {
            return Ok((
                input,
                Case {
                    selector,
                    branches,
                    default,
                },
            ));
        }
        if let Ok((rest, _)) = keyword("DEFAULT")(at) {
            let (rest, goto) = parse_goto(parse_blank(rest))?;
            default = Some(goto);
            input = rest;
            continue;
        }
        let (rest, value) = parse_expr(at)?;
        let (rest, goto) = parse_goto(parse_blank(rest))?;
        branches.push((value, goto));
        input = rest;
    }
}

/// `goto := ('GOTO' | 'GOTOF' | 'GOTOB' | 'GOTOC') goto_target | 'GOTOS'`
/// `goto_target := name | number | expr`
pub fn parse_goto(input: Input) -> PResult<Goto> {
    let (rest, keyword_name) = expect_name(input, "GOTOF, GOTOB, GOTO or GOTOC")?;
    let text = &input.fragment()[..keyword_name.span.len()];
    let kind = match text.to_ascii_uppercase().as_slice() {
        b"GOTOF" => GotoKind::Forward,
        b"GOTOB" => GotoKind::Backward,
        b"GOTO" => GotoKind::Both,
        b"GOTOC" => GotoKind::Conditional,
        b"GOTOS" => {
            return Ok((
                rest,
                Goto {
                    keyword: keyword_name,
                    kind: GotoKind::Start,
                    target: None,
                },
            ))
        }
        _ => {
            return SyntaxError::fail(
                offset(&input),
                SyntaxErrorKind::Expected("GOTOF, GOTOB, GOTO or GOTOC"),
            )
        }
    };
    let at = parse_blank(rest);
    let target = match peek(&at) {
        Some(byte) if is_name_start(byte) && !is_operator_after_name(at) => {
            let (rest, label) = parse_name(at)?;
            (rest, GotoTarget::Label(label))
        }
        Some(b'0'..=b'9') if !is_operator_after_number(at) => {
            let (rest, number) = parse_number(at)?;
            (rest, GotoTarget::Number(number))
        }
        Some(b';') | None => {
            return SyntaxError::fail(
                offset(&at),
                SyntaxErrorKind::Expected("a label or block number to jump to"),
            );
        }
        _ => {
            let (rest, expr) = parse_expr(at)?;
            (rest, GotoTarget::Computed(expr))
        }
    };
    Ok((
        target.0,
        Goto {
            keyword: keyword_name,
            kind,
            target: Some(target.1),
        },
    ))
}

/// `GOTOF "L"<<I` and `GOTOF LBL<<I` are computed targets, not labels.
fn is_operator_after_name(input: Input) -> bool {
    let len = input
        .fragment()
        .iter()
        .take_while(|&&b| is_name_char(b))
        .count();
    input.fragment()[len..].starts_with(b"<<")
}

fn is_operator_after_number(input: Input) -> bool {
    let len = input
        .fragment()
        .iter()
        .take_while(|b| b.is_ascii_digit())
        .count();
    input.fragment()[len..].starts_with(b"<<")
}

/// `indirect_call := 'CALL' (named block_range? | block_range) | 'ISOCALL' named
/// | ('PCALL' | 'MCALL') program | ('EXTCALL' | 'CALLPATH') expr`, with
/// `program := path arguments? | expr` and `block_range := 'BLOCK' expr 'TO' expr`
/// (Siemens, Job Planning, "Indirect program call", "Program call with path
/// specification and parameters", "Modal subprogram call", "Execute external
/// subprogram", "Search path for subprogram calls"). `MCALL` alone ends a modal
/// call and `CALLPATH` alone resets the search path.
pub fn parse_indirect_call<'a>(
    input: Input<'a>,
    keyword_name: Name,
    word: &[u8],
) -> PResult<'a, StatementKind> {
    let at = parse_blank(input);
    if matches!(peek(&at), None | Some(b';')) {
        if !matches!(word, b"MCALL" | b"CALLPATH") {
            return SyntaxError::fail(
                offset(&at),
                SyntaxErrorKind::Expected("the program to call: its name, or its path in quotes"),
            );
        }
        return Ok((
            input,
            StatementKind::IndirectCall {
                keyword: keyword_name,
                target: None,
            },
        ));
    }
    let end = match word {
        b"CALL" if keyword("BLOCK")(at).is_ok() => block_range(at)?,
        b"CALL" => {
            let end = named(at, "CALL")?;
            match keyword("BLOCK")(parse_blank(end)) {
                Ok(_) => block_range(parse_blank(end))?,
                Err(_) => end,
            }
        }
        b"EXTCALL" | b"CALLPATH" => parse_expr(at)?.0,
        b"ISOCALL" => named(at, "ISOCALL")?,
        _ => program(at)?,
    };
    Ok((
        end,
        StatementKind::IndirectCall {
            keyword: keyword_name,
            target: Some(span_between(&at, &end)),
        },
    ))
}

/// `program := ('/' name)+ arguments? | expr`: `/_N_MPF_DIR/WELLE(1,2)`,
/// `WELLE(1,2)`, `"/_N_CUS_DIR/_N_L320_SPF"`, `"L"<<NR`.
fn program(input: Input) -> Result<Input, nom::Err<SyntaxError>> {
    if peek(&input) != Some(b'/') {
        return Ok(parse_expr(input)?.0);
    }
    let mut rest = input;
    while peek(&rest) == Some(b'/') {
        rest = expect_name(rest.take_from(1), "a directory or program name after `/`")?.0;
    }
    let open = bracket_after_blank(rest);
    if peek(&open) == Some(b'(') {
        rest = parse_arguments(open, 0)?.0;
    }
    Ok(rest)
}

/// The functions whose value is a STRING: `CALL SPRINT("L%D", _NR)` names
/// the program by its value (Siemens, Job Planning, "String operations").
const STRING_FUNCTIONS: &[&str] = &["AXSTRING", "SPRINT", "SUBSTR", "TOLOWER", "TOUPPER"];

/// `named := '/' name ('/' name)* | expr`: the program of CALL and ISOCALL,
/// which name the program to run and pass it nothing: the manual writes them `CALL <program name>` and `ISOCALL
/// <program name>`, the name a STRING, and passes arguments with PCALL
/// (`PCALL <path/program name>(<parameter 1>,...)`) or a call by name
/// (Siemens, Job Planning, "Indirect subprogram call (CALL)", "Indirect call
/// of a program programmed in an ISO language (ISOCALL)", "Subprogram call
/// with path specification and parameters (PCALL)"). An argument list after
/// the name (`CALL _PNAME(10,20)`) is refused at its `(`; a string
/// function's call is the name's value, not arguments.
fn named<'a>(input: Input<'a>, keyword: &'static str) -> Result<Input<'a>, nom::Err<SyntaxError>> {
    let refuse = |at: usize| SyntaxError::fail(at, SyntaxErrorKind::IndirectCallArguments(keyword));
    if peek(&input) == Some(b'/') {
        let mut rest = input;
        while peek(&rest) == Some(b'/') {
            rest = expect_name(rest.take_from(1), "a directory or program name after `/`")?.0;
        }
        let open = bracket_after_blank(rest);
        if peek(&open) == Some(b'(') {
            return refuse(offset(&open));
        }
        return Ok(rest);
    }
    let (rest, expr) = parse_expr(input)?;
    if let ExprKind::Call(call) = &expr.kind {
        let name = call
            .name
            .span
            .start
            .checked_sub(offset(&input))
            .and_then(|from| input.fragment().get(from..from + call.name.span.len()))
            .unwrap_or_default();
        if !is_one_of(name, STRING_FUNCTIONS) {
            return refuse(call.arguments.span.start);
        }
    }
    Ok(rest)
}

/// `block_range := 'BLOCK' expr 'TO' expr`: the labels or block numbers of
/// the section to run.
fn block_range(input: Input) -> Result<Input, nom::Err<SyntaxError>> {
    let (rest, _) = keyword("BLOCK")(input)?;
    let (rest, _) = parse_expr(parse_blank(rest))?;
    let Ok((rest, _)) = keyword("TO")(parse_blank(rest)) else {
        return SyntaxError::fail(
            offset(&parse_blank(rest)),
            SyntaxErrorKind::Expected("`TO` and the end of the section (`BLOCK L1 TO L2`)"),
        );
    };
    Ok(parse_expr(parse_blank(rest))?.0)
}

/// Up to the comment (outside strings), without trailing blanks.
fn target_len(bytes: &[u8]) -> usize {
    let mut in_string = false;
    let mut end = bytes.len();
    for (i, &b) in bytes.iter().enumerate() {
        match b {
            b'"' => in_string = !in_string,
            b';' if !in_string => {
                end = i;
                break;
            }
            _ => {}
        }
    }
    bytes[..end]
        .iter()
        .rposition(|&b| !crate::syntax::lexer::is_blank(b))
        .map_or(0, |p| p + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// The shortcut reads a word exactly as the general path does, or
        /// leaves it to the general path.
        #[test]
        fn plain_words_read_as_the_general_path_reads_them(
            text in "[A-Za-z][-+]?[0-9.]{0,12}([eE][xX]?[-+]?[0-9]{0,3})?[ =.;A-Z]{0,3}[0-9]{0,2}",
        ) {
            let input = Input::new(text.as_bytes(), 40);
            if let Some((rest, statement)) = plain_word(input) {
                let (general_rest, general) = parse_statement(input).expect("the general path reads it");
                proptest::prop_assert_eq!(rest, general_rest);
                proptest::prop_assert_eq!(statement, general);
            }
        }
    }

    #[test]
    fn the_shortcut_takes_cam_words_and_leaves_the_rest() {
        for word in [
            "X-12.5", "G1", "F.02", "Y+3", "N440G01", "C-.5 Y1", "X1.5EX3",
        ] {
            assert!(
                plain_word(Input::new(word.as_bytes(), 0)).is_some(),
                "{word}"
            );
        }
        for word in [
            "X1=5", "X1 = 5", "X=R1", "X1.5E", "R1=2", "X.", "X-", "AB1", "X'H1F'",
        ] {
            assert!(
                plain_word(Input::new(word.as_bytes(), 0)).is_none(),
                "{word}"
            );
        }
    }
}
