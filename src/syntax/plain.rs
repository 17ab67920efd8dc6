//! Facts about lines that do not need their tree: whether a line is nothing
//! but address words with numbers (the millions of motion blocks of a CAM
//! program), what the rules ask of such a line, and the block numbers a
//! file's jumps name.
//!
//! `check`, the syntax pass and the CYCLE600 walk use them to skip the parser
//! where the tree could not tell them anything.

use crate::hash::HashSet;
use crate::span::Span;
use crate::syntax::block::{block_number_digits, parse_block_number, parse_skip};
use crate::syntax::lexer::{is_blank, parse_blank, Input};
use crate::syntax::lines::{line_at, line_from, RawLine};
use crate::syntax::tree::BlockNumber;
use crate::syntax::MAX_PARSED_LINE;

#[cfg(target_arch = "x86_64")]
mod wide;

/// The line's content (before any `;` comment) is nothing but address words
/// with plain decimal numbers, `N10 G1 X-12.5 Y.5 F2000.`: it parses without
/// error into such words (property-tested), so it assigns, calls, jumps and
/// reads nothing. Strict and conservative: `false` means "parse it to know".
/// A line longer than [`MAX_PARSED_LINE`] is never plain: it is not read.
pub fn is_plain(content: &[u8]) -> bool {
    content.len() <= MAX_PARSED_LINE && scan_words(content).is_some()
}

/// A line [`is_plain`] accepts, with its `;` comment if it has one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plain {
    pub raw: RawLine,
    pub comment: Option<Span>,
    /// The block number's letter and end (see [`Plain::facts`]): kept this
    /// small because the syntax pass and the walk copy every `Plain` and
    /// never ask.
    number: Option<(usize, usize)>,
    letters: Letters,
    repeats: bool,
    motions: Motions,
}

impl Plain {
    /// What the rules ask of the line, seen by the scan that found it.
    pub fn facts(&self) -> PlainFacts {
        PlainFacts {
            number: self.number.map(|(letter, end)| BlockNumber {
                span: Span::new(letter, end),
                main: false,
                digits: Span::new(letter + 1, end),
            }),
            letters: self.letters,
            repeats: self.repeats,
            motions: self.motions,
        }
    }
}

/// The plain line starting at `start` in `source`; `None` when the line is
/// not plain. The pass that reads the words also finds the line's end and
/// the facts the rules ask for, so a plain line costs one look at each byte.
#[inline]
pub fn scan_plain_line(source: &[u8], start: usize) -> Option<Plain> {
    let rest = &source[start..];
    let words = scan_words(rest)?;
    let stop = words.stop;
    let (end, comment) = if rest.get(stop) == Some(&b';') {
        let end = memchr::memchr2(b'\n', b'\r', &rest[stop..]).map_or(rest.len(), |n| stop + n);
        (end, Some(Span::new(start + stop, start + end)))
    } else {
        (stop, None)
    };
    // A line too long to read is no plain line but an error (S009).
    if end > MAX_PARSED_LINE {
        return None;
    }
    Some(Plain {
        raw: line_at(source, start, start + end),
        comment,
        number: words
            .number
            .map(|(letter, end)| (start + letter, start + end)),
        letters: words.letters,
        repeats: words.repeats,
        motions: words.motions,
    })
}

/// What the rules ask of every line, read from a plain line without its
/// tree (property-tested to agree with the tree).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlainFacts {
    /// The block number it starts with (`N10`).
    pub number: Option<BlockNumber>,
    /// The address letters of its words, the block number's not counted.
    pub letters: Letters,
    /// Some letter starts more than one of its words (`G90 G54`, `X1 X2`).
    pub repeats: bool,
    /// The motion G functions (G0 to G3) among its words.
    pub motions: Motions,
}

impl PlainFacts {
    /// It holds at least one word besides the block number.
    pub fn has_words(&self) -> bool {
        !self.letters.is_empty()
    }
}

/// A set of address letters, case folded (`x` is `X`): what the scan of a
/// plain line learns of its words at the cost of an OR per word, so that the
/// rules look closer only at the lines that hold the letters they ask about.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Letters(u32);

impl Letters {
    /// `letters`, each an ASCII letter; `const`, so that the rules' sets
    /// are made once, not per line.
    pub const fn of(letters: &[u8]) -> Self {
        let (mut set, mut at) = (0, 0);
        while at < letters.len() {
            set |= bit(letters[at]);
            at += 1;
        }
        Self(set)
    }

    pub fn contains(self, letter: u8) -> bool {
        self.0 & bit(letter) != 0
    }

    /// Whether any of `other` is in the set.
    pub fn meets(self, other: Letters) -> bool {
        self.0 & other.0 != 0
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }
}

/// An ASCII letter's bit: its low five bits, the same for either case.
#[inline(always)]
const fn bit(letter: u8) -> u32 {
    1 << (letter & 31)
}

/// The motion G functions G0 to G3 (group 1) a plain line writes, one bit
/// each, and whether it writes any other G function: what the modal state
/// and the circle rule ask of every CAM block, and what tells the rules of
/// the other G groups (compensation, planes) which few lines to read.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Motions(u8);

/// The bit of a G function other than G0 to G3.
const OTHER_G: u8 = 1 << 4;

impl Motions {
    /// `G<number>` is among them (`number` 0 to 3).
    pub fn contains(self, number: u32) -> bool {
        number < 4 && self.0 & (1 << number) != 0
    }

    /// A G function other than G0 to G3 (`G17`, `G41`, `G1.5`) is written.
    pub fn others(self) -> bool {
        self.0 & OTHER_G != 0
    }

    /// The one G function the line writes, when it is one of G0 to G3.
    pub fn only(self) -> Option<u32> {
        match self.0 {
            1 => Some(0),
            2 => Some(1),
            4 => Some(2),
            8 => Some(3),
            _ => None,
        }
    }
}

/// The bit of the motion G function (G0 to G3, `G01` alike) whose letter is
/// at `at`, [`OTHER_G`] for another G function, 0 for any other word.
#[inline(always)]
fn motion_bit(bytes: &[u8], at: usize) -> u8 {
    if bytes[at] | 0x20 != b'g' {
        return 0;
    }
    let mut next = at + 1;
    while bytes.get(next) == Some(&b'0') {
        next += 1;
    }
    let digit = match bytes.get(next) {
        Some(&d @ b'0'..=b'3') => d - b'0',
        // `G0`, `G00`: the last zero is the number.
        _ if next > at + 1 => {
            next -= 1;
            0
        }
        _ => return OTHER_G,
    };
    match bytes.get(next + 1) {
        Some(b'0'..=b'9' | b'.') => OTHER_G,
        _ => 1 << digit,
    }
}

/// The letters of the words read so far, how many words, and their motions.
#[derive(Clone, Copy, Default)]
struct LetterCount {
    seen: u32,
    words: u32,
    motions: u8,
}

impl LetterCount {
    /// The word whose letter is at `at` of `bytes`.
    #[inline(always)]
    fn add(&mut self, bytes: &[u8], at: usize) {
        self.seen |= bit(bytes[at]);
        self.motions |= motion_bit(bytes, at);
        self.words += 1;
    }

    /// Some letter starts more than one word: fewer letters than words. A
    /// count rather than a second set, since few lines repeat a letter and
    /// the rules read those again.
    fn repeats(self) -> bool {
        self.seen.count_ones() < self.words
    }
}

/// Whether [`scanned_lines_with`] looks for plain lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlainScanner {
    /// [`scan_plain_line`] on every line.
    Scan,
    /// Take no line for plain: every line is parsed, the reference the
    /// plain-line shortcut is tested against.
    ParseEveryLine,
}

/// A line of [`scanned_lines`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scanned {
    Plain(Plain),
    /// Not plain: parse it to know what it holds.
    Other(RawLine),
}

impl Scanned {
    pub fn raw(&self) -> RawLine {
        match self {
            Scanned::Plain(plain) => plain.raw,
            Scanned::Other(raw) => *raw,
        }
    }
}

/// Every line of `source`, plain or not: a plain line's words and its end
/// are found in one pass, other lines' ends by a search.
pub fn scanned_lines(source: &[u8]) -> ScannedLines<'_> {
    scanned_lines_with(source, PlainScanner::Scan)
}

/// [`scanned_lines`], or with [`PlainScanner::ParseEveryLine`] every line parsed.
pub fn scanned_lines_with(source: &[u8], scan: PlainScanner) -> ScannedLines<'_> {
    scanned_lines_from(source, 0, scan)
}

/// [`scanned_lines_with`], from the line that starts at `at`.
pub fn scanned_lines_from(source: &[u8], at: usize, scan: PlainScanner) -> ScannedLines<'_> {
    ScannedLines { source, at, scan }
}

pub struct ScannedLines<'a> {
    source: &'a [u8],
    at: usize,
    scan: PlainScanner,
}

impl Iterator for ScannedLines<'_> {
    type Item = Scanned;

    fn next(&mut self) -> Option<Scanned> {
        if self.at >= self.source.len() {
            return None;
        }
        // An enum rather than a function pointer, so that the scan is
        // inlined into this loop over millions of lines.
        let plain = match self.scan {
            PlainScanner::Scan => scan_plain_line(self.source, self.at),
            PlainScanner::ParseEveryLine => None,
        };
        let line = match plain {
            Some(plain) => Scanned::Plain(plain),
            None => Scanned::Other(line_from(self.source, self.at)),
        };
        self.at = line.raw().full().end;
        Some(line)
    }
}

/// What [`scan_words`] saw.
#[derive(Debug, PartialEq)]
struct Words {
    /// Where it stopped: a `;`, a line end or the end of the bytes.
    stop: usize,
    /// The block number, as the parser reads one: a first word N with
    /// digits alone (a sign or a point makes it an address word); where its
    /// letter is and where its digits end.
    number: Option<(usize, usize)>,
    /// The letters of the words other than the block number.
    letters: Letters,
    /// Some letter starts more than one of them.
    repeats: bool,
    motions: Motions,
}

impl Words {
    fn new(stop: usize, number: Option<(usize, usize)>, count: LetterCount) -> Self {
        Self {
            stop,
            number,
            letters: Letters(count.seen),
            repeats: count.repeats(),
            motions: Motions(count.motions),
        }
    }
}

/// Reads address words up to a `;`, a line end or the end of `bytes`; `None`
/// at anything else.
fn scan_words(bytes: &[u8]) -> Option<Words> {
    // A line that starts with anything but a letter, a blank, a comment or
    // its end is not plain, whatever follows: `$TC_DP1[1,1]=0`, `_X=1`,
    // `/N10`. Said at once, before the 64 bytes are classified: setup files
    // are made of such lines.
    if bytes.first().is_some_and(|&b| {
        matches!(
            CLASS[usize::from(b)],
            Class::Digit | Class::Point | Class::Sign | Class::Other
        )
    }) {
        return None;
    }
    // `;$PATH=` is an archive's line to the parser, not a comment.
    if bytes.first() == Some(&b';') && super::is_archive_path(bytes) {
        return None;
    }
    #[cfg(target_arch = "x86_64")]
    if let Some(words) = bytes.first_chunk().and_then(wide::scan_words) {
        return words;
    }
    scan_words_bytewise(bytes)
}

/// [`scan_words`] a byte at a time.
fn scan_words_bytewise(bytes: &[u8]) -> Option<Words> {
    // The first word is read apart because only it can be the block number:
    // a test per word inside the loop would be paid on every word.
    let mut count = LetterCount::default();
    let (number, mut at) = match next_word(bytes, 0)? {
        Step::Stop(stop) => return Some(Words::new(stop, None, count)),
        Step::Word {
            letter,
            end,
            digits_only,
        } => {
            let is_number = digits_only && bytes[letter].eq_ignore_ascii_case(&b'N');
            if !is_number {
                count.add(bytes, letter);
            }
            (is_number.then_some((letter, end)), end)
        }
    };
    loop {
        match next_word(bytes, at)? {
            Step::Stop(stop) => return Some(Words::new(stop, number, count)),
            Step::Word { letter, end, .. } => {
                count.add(bytes, letter);
                at = end;
            }
        }
    }
}

/// The address words of the plain line that starts at `start` (see
/// [`is_plain`]), the block number left out: where each word's letter
/// stands and where its number ends, as offsets into `source`, in order.
/// The words stop at the comment.
pub fn words(source: &[u8], start: usize, mut each: impl FnMut(usize, usize)) {
    let line = &source[start..];
    #[cfg(target_arch = "x86_64")]
    if let Some(window) = line.first_chunk() {
        if wide::words(window, |letter, end| each(start + letter, start + end)).is_some() {
            return;
        }
    }
    for (letter, end) in words_bytewise(line) {
        each(start + letter, start + end);
    }
}

/// [`words`] a byte at a time, by the scan's own steps; offsets into `content`.
fn words_bytewise(content: &[u8]) -> impl Iterator<Item = (usize, usize)> + '_ {
    let mut at = 0;
    let mut first = true;
    std::iter::from_fn(move || loop {
        let Step::Word {
            letter,
            end,
            digits_only,
        } = next_word(content, at)?
        else {
            return None;
        };
        at = end;
        // The parser's block number: a first word N with digits alone.
        let is_number = std::mem::take(&mut first)
            && digits_only
            && content[letter].eq_ignore_ascii_case(&b'N');
        if !is_number {
            return Some((letter, end));
        }
    })
}

enum Step {
    /// At a `;`, a line end or the end of the bytes.
    Stop(usize),
    Word {
        letter: usize,
        end: usize,
        /// No sign and no point: `N10`, not `N-10` or `N10.`.
        digits_only: bool,
    },
}

/// The address word after `at` (blanks skipped), or where the words stop;
/// `None` at anything else.
#[inline(always)]
fn next_word(bytes: &[u8], mut at: usize) -> Option<Step> {
    let class = |at: usize| bytes.get(at).map_or(Class::End, |&b| CLASS[usize::from(b)]);
    while class(at) == Class::Blank {
        at += 1;
    }
    match class(at) {
        Class::End | Class::Comment => return Some(Step::Stop(at)),
        Class::Letter => at += 1,
        _ => return None,
    }
    let letter = at - 1;
    let signed = class(at) == Class::Sign;
    if signed {
        at += 1;
    }
    let (start, mut digits, mut points) = (at, 0, 0);
    loop {
        match class(at) {
            Class::Digit => digits += 1,
            Class::Point => points += 1,
            _ => break,
        }
        at += 1;
    }
    // A number needs a digit, has one point at most, and is no longer than
    // machine positions get (`1` with 400 zeros is too large for a REAL: the
    // parser says so).
    if digits == 0 || points > 1 || at - start > 24 {
        return None;
    }
    Some(Step::Word {
        letter,
        end: at,
        digits_only: !signed && points == 0,
    })
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Class {
    /// A line end (CR, LF) or the end of the bytes.
    End,
    Letter,
    Digit,
    Point,
    Sign,
    Blank,
    Comment,
    Other,
}

/// Each byte's class, looked up rather than tested: this runs on every byte.
static CLASS: [Class; 256] = {
    let mut table = [Class::Other; 256];
    let mut byte = 0;
    while byte < 256 {
        let b = byte as u8;
        table[byte] = if b.is_ascii_alphabetic() {
            Class::Letter
        } else if b.is_ascii_digit() {
            Class::Digit
        } else if b == b'.' {
            Class::Point
        } else if b == b'-' || b == b'+' {
            Class::Sign
        } else if b == b';' {
            Class::Comment
        } else if b == b'\n' || b == b'\r' {
            Class::End
        } else if is_blank(b) {
            Class::Blank
        } else {
            Class::Other
        };
        byte += 1;
    }
    table
};

/// Every block number among `wanted` (`N100`; not the main block number
/// `:100`) with its 0-based line, sorted by number and then line.
pub fn block_numbers(source: &[u8], wanted: &HashSet<u64>) -> Vec<(u64, usize)> {
    let mut numbers = Vec::new();
    if wanted.is_empty() {
        return numbers;
    }
    // A few jump targets against every line: a binary search costs a
    // fraction of hashing the number.
    let mut targets: Vec<u64> = wanted.iter().copied().collect();
    targets.sort_unstable();
    let mut read = |row: usize, start: usize, end: usize| {
        let line = &source[start..end];
        let digits = if matches!(line.first(), Some(b'N' | b'n')) {
            // Most lines start with their number: no parser needed.
            block_number_digits(line).map(|digits| &line[1..1 + digits])
        } else {
            let input = parse_blank(Input::new(line, start));
            let input = parse_skip(input).map_or(input, |(rest, _)| parse_blank(rest));
            parse_block_number(input)
                .ok()
                .filter(|(_, number)| !number.main)
                .map(|(_, number)| number.digits.of(source))
        };
        let value = digits.and_then(digits_value);
        if let Some(value) = value.filter(|value| targets.binary_search(value).is_ok()) {
            numbers.push((value, row));
        }
    };
    // One search over the file for the line ends (LF, CRLF, lone CR): a
    // search per line costs more to start than to run on a 50-byte line.
    let (mut row, mut start) = (0, 0);
    for end in memchr::memchr2_iter(b'\n', b'\r', source) {
        if end < start {
            continue; // the LF of a CRLF
        }
        read(row, start, end);
        let crlf = source[end] == b'\r' && source.get(end + 1) == Some(&b'\n');
        (row, start) = (row + 1, end + 1 + usize::from(crlf));
    }
    if start < source.len() {
        read(row, start, source.len());
    }
    // Stable, so rows stay in order; and fast on the ascending runs that
    // block numbers come in.
    numbers.sort_by_key(|&(number, _)| number);
    numbers
}

/// The value of ASCII digits, `None` beyond `u64` (or for anything else).
pub fn digits_value(digits: &[u8]) -> Option<u64> {
    // Nineteen digits cannot overflow a `u64`: no checked arithmetic for the
    // block numbers of every line.
    if digits.len() <= 19 {
        return digits.iter().try_fold(0u64, |value, &digit| {
            let digit = digit.wrapping_sub(b'0');
            (digit < 10).then(|| value * 10 + u64::from(digit))
        });
    }
    digits.iter().try_fold(0u64, |value, &digit| {
        let digit = (digit as char).to_digit(10)?;
        value.checked_mul(10)?.checked_add(u64::from(digit))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::tree::{StatementKind, WordValue};
    use crate::syntax::Lines;

    #[test]
    fn plain_lines_are_address_words_with_numbers() {
        for plain in [
            "N10 G1 X-12.5 Y.5",
            "X1 Y2 ; TRAORI",
            "",
            "  N20",
            "G01X498.375Y82.325",
        ] {
            assert!(is_plain(plain.as_bytes()), "{plain}");
        }
        for not in [
            "TRAORI", "R1=5", "X=R1", "GOTOF L1", "X 5", "X", "L1: X5", "/1 X5", "X1EX3", "T\"A\"",
        ] {
            assert!(!is_plain(not.as_bytes()), "{not}");
        }
    }

    proptest::proptest! {
        /// The block numbers found without trees are the trees' own, sorted
        /// by number and line, whatever the line endings.
        #[test]
        fn block_numbers_are_the_trees_numbers(
            lines in proptest::collection::vec("( ?/[0-9]? ?)?(N[0-9]{1,3}|n[0-9]|:[0-9]{1,2}|N9{20}|N1\\.5|N1=5|N2\\[1\\]=5)?( X1)?", 0..12),
            endings in proptest::collection::vec(proptest::prop_oneof!["\n", "\r\n", "\r"], 12),
            last in "(N[0-9])?",
        ) {
            let mut text: String = lines.iter().zip(&endings).map(|(l, e)| format!("{l}{e}")).collect();
            text.push_str(&last); // a last line without terminator
            let source = text.as_bytes();
            let lines = Lines::new(source);
            let mut expected: Vec<(u64, usize)> = (0..lines.len())
                .filter_map(|row| match lines.block(row) {
                    Some(block) => block
                        .number
                        .filter(|n| !n.main)
                        .and_then(|n| digits_value(n.digits.of(source)))
                        .map(|value| (value, row)),
                    _ => None,
                })
                .collect();
            expected.sort_unstable();
            let all: HashSet<u64> = expected.iter().map(|&(value, _)| value).collect();
            proptest::prop_assert_eq!(block_numbers(source, &all), expected.clone());
            // Only the wanted ones.
            let odd: HashSet<u64> = all.iter().copied().filter(|v| v % 2 == 1).collect();
            expected.retain(|(value, _)| value % 2 == 1);
            proptest::prop_assert_eq!(block_numbers(source, &odd), expected);
        }
    }

    proptest::proptest! {
        /// Digits read as `str::parse` reads them, up to and past `u64::MAX`
        /// (20 digits), and nothing else read as a number.
        #[test]
        fn digits_value_is_parse(text in "[0-9]{1,22}|[0-9]{0,3}[^0-9][0-9]{0,3}") {
            let parsed = text.parse::<u64>().ok().filter(|_| text.bytes().all(|b| b.is_ascii_digit()));
            proptest::prop_assert_eq!(digits_value(text.as_bytes()), parsed);
        }
    }

    proptest::proptest! {
        // Plain lines are a small share of random ones: many cases.
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(4000))]

        /// What `is_plain` calls plain parses without a diagnostic into
        /// address words with numbers only.
        #[test]
        fn a_plain_line_parses_into_number_words(text in proptest::prop_oneof![
            "[NGXYZEx0-9 .;+=:(-]{0,40}",
            "([NGXYZEx][-+]?[0-9.]{0,5} ?){0,8}(;[A-Z=]{0,3})?",
            "([Gg][-+]?0{0,2}[0-4]{1,2}\\.?[0-9]? ?|[Gg]4[0-2] |X1 ){1,5}",
        ]) {
            if is_plain(text.as_bytes()) {
                proptest::prop_assert!(crate::syntax::diagnostics(text.as_bytes()).is_empty());
                let lines = Lines::new(text.as_bytes());
                for index in 0..lines.len() {
                    let Some(block) = lines.block(index) else {
                        continue;
                    };
                    proptest::prop_assert!(block.label.is_none() && block.unparsed.is_none());
                    let plain = scan_plain_line(text.as_bytes(), lines.raw(index).content.start)
                        .expect("plain");
                    proptest::prop_assert_eq!(plain.raw, lines.raw(index));
                    proptest::prop_assert_eq!(plain.comment, block.comment);
                    proptest::prop_assert_eq!(plain.facts().number, block.number);
                    proptest::prop_assert_eq!(plain.facts().has_words(), !block.statements.is_empty());
                    let letters: Vec<u8> = block.statements.iter().filter_map(|s| match &s.kind {
                        StatementKind::Word(word) => Some(word.address.text(text.as_bytes())[0]),
                        _ => None,
                    }).collect();
                    proptest::prop_assert_eq!(plain.facts().letters, Letters::of(&letters));
                    let repeats = letters.iter().any(|l| letters.iter().filter(|o| o.eq_ignore_ascii_case(l)).count() > 1);
                    proptest::prop_assert_eq!(plain.facts().repeats, repeats);
                    let g: Vec<Option<u32>> = crate::semantic::addresses::of_block(text.as_bytes(), &block)
                        .iter()
                        .filter(|a| a.is(text.as_bytes(), "G"))
                        .map(|a| a.whole(text.as_bytes()))
                        .collect();
                    for n in 0..4 {
                        proptest::prop_assert_eq!(plain.facts().motions.contains(n), g.contains(&Some(n)), "G{}", n);
                    }
                    let others = g.iter().any(|n| !matches!(n, Some(0..=3)));
                    proptest::prop_assert_eq!(plain.facts().motions.others(), others);
                    for statement in &block.statements {
                        let number_word = matches!(
                            &statement.kind,
                            StatementKind::Word(word) if matches!(word.value, WordValue::Number(_))
                        );
                        proptest::prop_assert!(number_word, "{:?}", statement);
                    }
                }
            }
        }
    }
}
