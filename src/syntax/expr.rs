//! Expressions with Sinumerik operator priority (Siemens PM, "Priority of the
//! operations"): comparisons bind weakest, below `<<`, `OR`, `XOR`, `AND`, the
//! bit operators, `+ -`, and `* / DIV MOD`; `NOT` and `B_NOT` bind strongest.
//! `:` (frame chaining) sits below everything. Same priority: left to right.
//!
//! This module only builds the tree; evaluating it is the semantic layer's job.

use nom::Input as _;

use crate::span::Span;
use crate::syntax::lexer::{
    is_name_start, is_one_of, offset, parse_blank, parse_name, parse_number, parse_string, peek,
    peek_at, span_between, Input, PResult, SyntaxError, SyntaxErrorKind,
};
use crate::syntax::tree::{Argument, Arguments, BinaryOp, Call, Expr, ExprKind, UnaryOp, Variable};

/// Trees deeper than this (parentheses, unary operators and chained binary
/// operators together) are refused with a diagnostic instead of overflowing
/// the stack while parsing or dropping them. A block of the control's 512
/// characters cannot come near it.
pub const MAX_DEPTH: usize = 256;

/// `expr := chain`
pub fn parse_expr(input: Input) -> PResult<Expr> {
    parse_binary(input, 0, 0)
}

fn deeper(input: &Input, depth: usize) -> Result<usize, nom::Err<SyntaxError>> {
    if depth >= MAX_DEPTH {
        SyntaxError::fail(offset(input), SyntaxErrorKind::TooDeep)
    } else {
        Ok(depth + 1)
    }
}

/// Priority levels, weakest first.
const CHAIN: u8 = 0;
const COMPARISON: u8 = 1;
const CONCAT: u8 = 2;
const OR: u8 = 3;
const XOR: u8 = 4;
const AND: u8 = 5;
const BIT_OR: u8 = 6;
const BIT_XOR: u8 = 7;
const BIT_AND: u8 = 8;
const ADDITIVE: u8 = 9;
const MULTIPLICATIVE: u8 = 10;

/// The binary operator after optional blanks, its level and the input after it.
fn peek_binary_operator(input: Input) -> Option<(BinaryOp, u8, Input)> {
    let at = parse_blank(input);
    let bytes = at.fragment();
    // By the first byte: only `=`, `<` and `>` start a two-byte operator.
    let second = bytes.get(1).copied();
    let symbol = match *bytes.first()? {
        b'=' if second == Some(b'=') => Some((BinaryOp::Eq, COMPARISON, 2)),
        b'<' => Some(match second {
            Some(b'>') => (BinaryOp::Ne, COMPARISON, 2),
            Some(b'=') => (BinaryOp::Le, COMPARISON, 2),
            Some(b'<') => (BinaryOp::Concat, CONCAT, 2),
            _ => (BinaryOp::Lt, COMPARISON, 1),
        }),
        b'>' if second == Some(b'=') => Some((BinaryOp::Ge, COMPARISON, 2)),
        b'>' => Some((BinaryOp::Gt, COMPARISON, 1)),
        b'+' => Some((BinaryOp::Add, ADDITIVE, 1)),
        b'-' => Some((BinaryOp::Sub, ADDITIVE, 1)),
        b'*' => Some((BinaryOp::Mul, MULTIPLICATIVE, 1)),
        b'/' => Some((BinaryOp::Div, MULTIPLICATIVE, 1)),
        b':' => Some((BinaryOp::Chain, CHAIN, 1)),
        _ => None,
    };
    if let Some((op, level, len)) = symbol {
        return Some((op, level, at.take_from(len)));
    }
    // Only these letters start a word operator (DIV, MOD, B_..., AND, XOR,
    // OR): most names after an operand are the block's next word.
    if !matches!(peek(&at)? | 0x20, b'd' | b'm' | b'b' | b'a' | b'x' | b'o') {
        return None;
    }
    let (rest, name) = parse_name(at).ok()?;
    let word = name.span.of_fragment(&at);
    let (op, level) = WORD_OPERATORS
        .iter()
        .find(|(text, _, _)| word.eq_ignore_ascii_case(text.as_bytes()))
        .map(|&(_, op, level)| (op, level))?;
    Some((op, level, rest))
}

const WORD_OPERATORS: [(&str, BinaryOp, u8); 8] = [
    ("DIV", BinaryOp::IntDiv, MULTIPLICATIVE),
    ("MOD", BinaryOp::Mod, MULTIPLICATIVE),
    ("B_AND", BinaryOp::BitAnd, BIT_AND),
    ("B_XOR", BinaryOp::BitXor, BIT_XOR),
    ("B_OR", BinaryOp::BitOr, BIT_OR),
    ("AND", BinaryOp::And, AND),
    ("XOR", BinaryOp::Xor, XOR),
    ("OR", BinaryOp::Or, OR),
];

trait SpanOfFragment {
    fn of_fragment<'a>(self, input: &Input<'a>) -> &'a [u8];
}

impl SpanOfFragment for crate::span::Span {
    /// The bytes of a span that starts where `input` starts.
    fn of_fragment<'a>(self, input: &Input<'a>) -> &'a [u8] {
        &input.fragment()[..self.len()]
    }
}

/// `binary(level) := unary (operator(level' >= level) binary(level' + 1))*`
fn parse_binary(input: Input, min_level: u8, depth: usize) -> PResult<Expr> {
    let depth = deeper(&input, depth)?;
    let (mut input, mut lhs) = match simple_operand(input, depth) {
        Some(operand) => operand,
        None => parse_unary(input, depth)?,
    };
    // Each operator in a chain deepens the (left-leaning) tree by one.
    let mut chain_depth = depth;
    while let Some((op, level, after)) = peek_binary_operator(input) {
        if level < min_level {
            break;
        }
        // Where this chain took most of the depth, it is too long, not too deep.
        let chain = chain_depth - depth;
        let too_long = move |error: nom::Err<SyntaxError>| match error {
            nom::Err::Failure(SyntaxError {
                at,
                kind: SyntaxErrorKind::TooDeep,
                ..
            }) if chain + 1 >= MAX_DEPTH / 2 => {
                nom::Err::Failure(SyntaxError::new(at, SyntaxErrorKind::ChainTooLong))
            }
            other => other,
        };
        chain_depth = deeper(&input, chain_depth).map_err(too_long)?;
        let (rest, rhs) =
            parse_binary(parse_blank(after), level + 1, chain_depth).map_err(too_long)?;
        let span = lhs.span.to(rhs.span);
        lhs = Expr {
            span,
            kind: ExprKind::Binary {
                op,
                lhs: Box::new(lhs),
                rhs: Box::new(rhs),
            },
        };
        input = rest;
    }
    Ok((input, lhs))
}

/// The operands most expressions are made of, a number or a variable
/// without indices (`120`, `x_start`, `$P_GG`), read as [`parse_unary`] reads
/// them without its layers; `None` for anything else, which it reads.
#[inline]
fn simple_operand(input: Input, depth: usize) -> Option<(Input, Expr)> {
    // Where the general path refuses to go deeper, it says so.
    if depth >= MAX_DEPTH {
        return None;
    }
    match peek(&input)? {
        b'0'..=b'9' | b'.' => {
            let (rest, number) = parse_number(input).ok()?;
            let kind = ExprKind::Number(number);
            Some((
                rest,
                Expr {
                    span: number.span,
                    kind,
                },
            ))
        }
        byte if byte == b'$' || is_name_start(byte) => {
            let (rest, name) = parse_name(input).ok()?;
            let text = name.span.of_fragment(&input);
            // An operator written as a word, DO, a call or an index: the
            // general path.
            let is_word = text.len() <= 5
                && (is_one_of(text, &["NOT", "B_NOT", "DO"])
                    || WORD_OPERATORS
                        .iter()
                        .any(|(word, ..)| word.as_bytes().eq_ignore_ascii_case(text)));
            if is_word || matches!(peek(&parse_blank(rest)), Some(b'(' | b'[')) {
                return None;
            }
            let variable = Variable {
                span: name.span,
                name,
                indices: Vec::new(),
            };
            let kind = ExprKind::Variable(variable);
            Some((
                rest,
                Expr {
                    span: name.span,
                    kind,
                },
            ))
        }
        _ => None,
    }
}

/// `unary := ('-' | '+' | '<<' | 'NOT' | 'B_NOT') unary | primary`
fn parse_unary(input: Input, depth: usize) -> PResult<Expr> {
    let depth = deeper(&input, depth)?;
    let start = input;
    let symbol = match peek(&input) {
        Some(b'-') => Some((UnaryOp::Neg, 1)),
        Some(b'+') => Some((UnaryOp::Plus, 1)),
        Some(b'<') if peek_at(&input, 1) == Some(b'<') => Some((UnaryOp::Concat, 2)),
        _ => None,
    };
    let word = symbol.or_else(|| {
        // Only `N` and `B` start NOT and B_NOT.
        if !matches!(peek(&input)? | 0x20, b'n' | b'b') {
            return None;
        }
        let (_, name) = parse_name(input).ok()?;
        let text = name.span.of_fragment(&input);
        if text.eq_ignore_ascii_case(b"NOT") {
            Some((UnaryOp::Not, 3))
        } else if text.eq_ignore_ascii_case(b"B_NOT") {
            Some((UnaryOp::BitNot, 5))
        } else {
            None
        }
    });
    let Some((op, len)) = word else {
        return parse_primary(input, depth);
    };
    let (rest, operand) = parse_unary(parse_blank(input.take_from(len)), depth)?;
    if matches!(op, UnaryOp::Neg | UnaryOp::Plus) && is_string_literal(&operand) {
        return SyntaxError::fail(offset(&start), SyntaxErrorKind::SignedString);
    }
    Ok((
        rest,
        Expr {
            span: span_between(&start, &rest),
            kind: ExprKind::Unary {
                op,
                operand: Box::new(operand),
            },
        },
    ))
}

/// A string literal, in parentheses or not: a sign before one is refused,
/// since a STRING converts to no number (Siemens, Job Planning, "Type
/// conversion": to BOOL and CHAR only; `NUMBER("12.5")` reads a number
/// from a string).
fn is_string_literal(expr: &Expr) -> bool {
    match &expr.kind {
        ExprKind::String => true,
        ExprKind::Paren(inner) => is_string_literal(inner),
        _ => false,
    }
}

/// `primary := number | string | '(' expr ')' | variable | call`
fn parse_primary(input: Input, depth: usize) -> PResult<Expr> {
    let start = input;
    match peek(&input) {
        Some(b'0'..=b'9' | b'.' | b'\'') => {
            let (rest, number) = parse_number(input)?;
            Ok((
                rest,
                Expr {
                    span: number.span,
                    kind: ExprKind::Number(number),
                },
            ))
        }
        Some(b'"') => {
            let (rest, span) = parse_string(input)?;
            Ok((
                rest,
                Expr {
                    span,
                    kind: ExprKind::String,
                },
            ))
        }
        Some(b'(') => {
            let inner = parse_blank(input.take_from(1));
            let (rest, inner) = parse_binary(inner, 0, depth)?;
            let rest = parse_blank(rest);
            if peek(&rest) != Some(b')') {
                return close_error(&start, &rest, b'(');
            }
            let rest = rest.take_from(1);
            Ok((
                rest,
                Expr {
                    span: span_between(&start, &rest),
                    kind: ExprKind::Paren(Box::new(inner)),
                },
            ))
        }
        Some(b'$') => parse_variable_or_call(input, depth),
        Some(byte) if is_name_start(byte) => parse_variable_or_call(input, depth),
        Some(b')' | b']') => {
            SyntaxError::at(&input, SyntaxErrorKind::UnmatchedClose(input.fragment()[0]))
        }
        Some(byte) if !is_known_byte(byte) => {
            SyntaxError::at(&input, SyntaxErrorKind::UnknownCharacter)
        }
        _ => SyntaxError::at(&input, SyntaxErrorKind::Expected("an expression")),
    }
}

/// Bytes that can start or continue some token of the language.
pub fn is_known_byte(byte: u8) -> bool {
    byte.is_ascii_alphanumeric()
        || b"_$.'\"()[]+-*/<>=:,;%".contains(&byte)
        || crate::syntax::lexer::is_blank(byte)
}

/// The error for a `(` or `[` at `open` whose partner is missing at `at`.
fn close_error<T>(open: &Input, at: &Input, bracket: u8) -> PResult<'static, T> {
    match peek(at) {
        // Something unreadable inside: report that, it is the real cause.
        Some(byte) if !is_known_byte(byte) => {
            SyntaxError::fail(offset(at), SyntaxErrorKind::UnknownCharacter)
        }
        _ => SyntaxError::fail(offset(open), SyntaxErrorKind::UnclosedBracket(bracket)),
    }
}

/// `variable := name (blank '[' expr (',' expr)* ']')?` ;
/// `call := name blank arguments`: a blank may stand between a name and its
/// bracket (`ABS ( R1 )`, `_OVR [4]`, as machine builders' cycles write).
fn parse_variable_or_call(input: Input, depth: usize) -> PResult<Expr> {
    let start = input;
    let (rest, name) = parse_name(input)?;
    // An operator written as a word, or DO, where an operand belongs.
    let text = &input.fragment()[..name.span.len()];
    if text.eq_ignore_ascii_case(b"DO")
        || WORD_OPERATORS
            .iter()
            .any(|(word, ..)| word.as_bytes().eq_ignore_ascii_case(text))
    {
        return SyntaxError::fail(offset(&input), SyntaxErrorKind::Expected("an operand"));
    }
    let rest = bracket_after_blank(rest);
    if peek(&rest) == Some(b'(') {
        let (rest, arguments) = parse_arguments(rest, depth)?;
        return Ok((
            rest,
            Expr {
                span: span_between(&start, &rest),
                kind: ExprKind::Call(Call { name, arguments }),
            },
        ));
    }
    let (rest, indices) = parse_indices(rest, depth)?;
    let span = span_between(&start, &rest);
    Ok((
        rest,
        Expr {
            span,
            kind: ExprKind::Variable(Variable {
                span,
                name,
                indices,
            }),
        },
    ))
}

/// Where the `(` or `[` after a name stands, past blanks; `input` itself
/// when no bracket follows (the name ends there).
pub fn bracket_after_blank(input: Input) -> Input {
    let after = parse_blank(input);
    match peek(&after) {
        Some(b'(' | b'[') => after,
        _ => input,
    }
}

/// `indices := ('[' expr (',' expr)* ']')?`
pub fn parse_indices(input: Input, depth: usize) -> PResult<Vec<crate::syntax::tree::Expr>> {
    if peek(&input) != Some(b'[') {
        return Ok((input, Vec::new()));
    }
    // Read straight into the indices, not into a list of arguments first,
    // with room for as many as there are commas before the first `]`
    // (`$TC_DP1[1,1]`): growing from nothing took the allocator's slow
    // path on every indexed variable.
    let ahead = &input.fragment()[..input.input_len().min(64)];
    let end = memchr::memchr(b']', ahead).unwrap_or(ahead.len());
    let mut indices = Vec::with_capacity(1 + ahead[..end].iter().filter(|&&b| b == b',').count());
    let mut first_empty = None;
    let (rest, _) = parse_items(input, b'[', b']', depth, |span, value| match value {
        Some(value) => indices.push(value),
        None => {
            first_empty.get_or_insert(span.start);
        }
    })?;
    if let Some(at) = first_empty {
        return SyntaxError::fail(at, SyntaxErrorKind::Expected("an index"));
    }
    Ok((rest, indices))
}

/// `arguments := '(' blank ')' | '(' argument (',' argument)* ')'` ; `argument := expr?`
pub fn parse_arguments(input: Input, depth: usize) -> PResult<Arguments> {
    parse_list(input, b'(', b')', depth)
}

/// A bracketed, comma-separated list whose items may be empty.
pub fn parse_list(input: Input, open: u8, close: u8, depth: usize) -> PResult<Arguments> {
    // Frames and cycles take a dozen arguments (`CTRANS(X,0,Y,0,Z,0,...)`):
    // room for as many as there are commas before the first closing
    // bracket, within the next 256 bytes, instead of growing three times.
    let ahead = &input.fragment()[..input.input_len().min(256)];
    let end = memchr::memchr(close, ahead).unwrap_or(ahead.len());
    let commas = memchr::memchr_iter(b',', &ahead[..end]).count();
    let mut items = match commas {
        0..4 => Vec::new(),
        _ => Vec::with_capacity(commas + 1),
    };
    let (rest, span) = parse_items(input, open, close, depth, |span, value| {
        items.push(Argument { span, value })
    })?;
    Ok((rest, Arguments { span, items }))
}

/// The items of a bracketed, comma-separated list, each given to `item`
/// with its span (an empty one: where it stands) as it is read; the list's
/// span, brackets included.
fn parse_items<'a>(
    input: Input<'a>,
    open: u8,
    close: u8,
    depth: usize,
    mut item: impl FnMut(Span, Option<Expr>),
) -> PResult<'a, Span> {
    let start = input;
    if peek(&input) != Some(open) {
        return SyntaxError::at(&input, SyntaxErrorKind::Expected("an argument list"));
    }
    let depth = deeper(&input, depth)?;
    let mut input = input.take_from(1);
    // `CYCLE800()` has no arguments at all, not one empty one.
    let inside = parse_blank(input);
    if peek(&inside) == Some(close) {
        let rest = inside.take_from(1);
        return Ok((rest, span_between(&start, &rest)));
    }
    loop {
        input = parse_blank(input);
        let item_start = input;
        let value = match peek(&input) {
            Some(b',') => None,
            Some(b) if b == close => None,
            _ => match parse_binary(input, 0, depth) {
                Ok((rest, value)) => {
                    input = rest;
                    Some(value)
                }
                Err(nom::Err::Error(error)) => {
                    return Err(nom::Err::Failure(list_error(&start, &input, close, error)));
                }
                Err(other) => return Err(other),
            },
        };
        let span = match &value {
            Some(value) => value.span,
            None => span_between(&item_start, &item_start),
        };
        item(span, value);
        input = parse_blank(input);
        match peek(&input) {
            Some(b',') => input = input.take_from(1),
            Some(b) if b == close => {
                let rest = input.take_from(1);
                return Ok((rest, span_between(&start, &rest)));
            }
            _ => return close_error(&start, &input, open),
        }
    }
}

/// An item that failed inside a list: at the end of the line it is the list
/// that is unclosed; elsewhere the item itself is wrong.
fn list_error(open: &Input, at: &Input, _close: u8, error: SyntaxError) -> SyntaxError {
    if peek_at(at, 0).is_none() {
        SyntaxError::new(
            offset(open),
            SyntaxErrorKind::UnclosedBracket(open.fragment()[0]),
        )
    } else {
        error
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shape(text: &str) -> String {
        let (rest, expr) = parse_expr(Input::new(text.as_bytes(), 0)).expect("parses");
        assert!(
            rest.fragment().is_empty(),
            "left over: {:?}",
            String::from_utf8_lossy(rest.fragment())
        );
        render(text.as_bytes(), &expr)
    }

    fn render(source: &[u8], expr: &Expr) -> String {
        match &expr.kind {
            ExprKind::Binary { op, lhs, rhs } => {
                format!("({} {op:?} {})", render(source, lhs), render(source, rhs))
            }
            ExprKind::Unary { op, operand } => format!("({op:?} {})", render(source, operand)),
            ExprKind::Paren(inner) => render(source, inner),
            _ => String::from_utf8_lossy(expr.span.of(source)).into_owned(),
        }
    }

    #[test]
    fn comparison_binds_weaker_than_and() {
        assert_eq!(shape("A==1 AND B==2"), "((A Eq (1 And B)) Eq 2)");
    }

    #[test]
    fn arithmetic_priority_and_left_to_right() {
        assert_eq!(shape("2+3*4"), "(2 Add (3 Mul 4))");
        assert_eq!(shape("10-6/2"), "(10 Sub (6 Div 2))");
        assert_eq!(shape("7 DIV 3 MOD 2"), "((7 IntDiv 3) Mod 2)");
        assert_eq!(shape("2*-3"), "(2 Mul (Neg 3))");
        assert_eq!(shape("NOT A AND B"), "((Not A) And B)");
    }

    #[test]
    fn strings_concatenate_below_or() {
        assert_eq!(shape("\"R1=\" << R1 OR 1"), "(\"R1=\" Concat (R1 Or 1))");
    }

    #[test]
    fn frame_chain_is_the_weakest() {
        assert_eq!(
            shape("CTRANS(X,15):CROT(Z,45)"),
            "(CTRANS(X,15) Chain CROT(Z,45))"
        );
    }

    #[test]
    fn empty_arguments_are_kept() {
        let (_, expr) = parse_expr(Input::new(b"SET(0,,,9,)", 0)).expect("parses");
        let ExprKind::Call(call) = expr.kind else {
            panic!("not a call")
        };
        let present: Vec<bool> = call
            .arguments
            .items
            .iter()
            .map(|a| a.value.is_some())
            .collect();
        assert_eq!(present, [true, false, false, true, false]);
    }

    #[test]
    fn long_operator_chains_are_refused_not_overflowed() {
        let text = "1".to_string() + &"+1".repeat(100_000);
        let error = parse_expr(Input::new(text.as_bytes(), 0)).expect_err("too long");
        assert!(matches!(
            error,
            nom::Err::Failure(SyntaxError {
                kind: SyntaxErrorKind::ChainTooLong,
                ..
            })
        ));
        let fine = "1".to_string() + &"+1".repeat(200);
        assert!(parse_expr(Input::new(fine.as_bytes(), 0)).is_ok());
    }

    proptest::proptest! {
        /// The shortcut reads an operand exactly as the general path does,
        /// or leaves it to the general path.
        #[test]
        fn simple_operands_read_as_the_general_path_reads_them(
            text in "(NOT|b_not|Do|AND|mod|X|\\$?[A-Za-z_][A-Za-z0-9_]{0,5}|[0-9.]{1,8}([eE][xX][-+]?[0-9]?)?)( ?[-+*/,)\\](\\[=<>:]| AND| DO| X)?",
            depth in proptest::prop_oneof![proptest::strategy::Just(1usize), proptest::strategy::Just(MAX_DEPTH - 1), proptest::strategy::Just(MAX_DEPTH)],
        ) {
            let input = Input::new(text.as_bytes(), 40);
            if let Some((rest, operand)) = simple_operand(input, depth) {
                let (general_rest, general) = parse_unary(input, depth).expect("the general path reads it");
                proptest::prop_assert_eq!(rest, general_rest);
                proptest::prop_assert_eq!(operand, general);
            }
        }
    }

    #[test]
    fn indices_report_the_first_error_in_the_order_read() {
        let error = |text: &str| match parse_indices(Input::new(text.as_bytes(), 0), 0) {
            Err(nom::Err::Failure(error)) => (error.at, error.kind),
            other => panic!("{text}: {other:?}"),
        };
        // An empty index is reported once the list is read, after any
        // error inside it.
        assert_eq!(error("[,1]"), (1, SyntaxErrorKind::Expected("an index")));
        assert_eq!(error("[1,,2,]"), (3, SyntaxErrorKind::Expected("an index")));
        assert_eq!(error("[,1+]"), (4, SyntaxErrorKind::UnmatchedClose(b']')));
        let (_, indices) = parse_indices(Input::new(b"[1, R2+1]", 0), 0).expect("indices");
        assert_eq!(indices.len(), 2);
    }

    #[test]
    fn deep_nesting_is_refused_not_overflowed() {
        let text = "(".repeat(100_000) + "1" + &")".repeat(100_000);
        let error = parse_expr(Input::new(text.as_bytes(), 0)).expect_err("too deep");
        assert!(matches!(
            error,
            nom::Err::Failure(SyntaxError {
                kind: SyntaxErrorKind::TooDeep,
                ..
            })
        ));
    }
}
