//! [`scan_words`](super::scan_words) 64 bytes at a time: each byte's class
//! becomes one bit of a mask (AVX2 compares, 32 bytes at once), and the
//! grammar of a plain line is checked on the masks with a few dozen integer
//! operations instead of a branch per byte.
//!
//! Decides only lines whose words stop within the first 64 bytes, on a CPU
//! with AVX2 (x86-64 since 2013); longer lines, the file's last 63 bytes and
//! older CPUs go byte by byte. Property-tested to agree with the byte-by-byte
//! scan on every input.

use super::{bit, motion_bit, LetterCount, Words};

/// One bit per byte of the window (bit `i` = byte `i`), for each class the
/// grammar needs.
struct Classes {
    letters: u64,
    signs: u64,
    /// Digits and points: the bytes of a number.
    numbers: u64,
    points: u64,
    /// Letters, signs, numbers and blanks: anything else is not plain.
    allowed: u64,
    /// CR, LF and `;`: where the words stop.
    stops: u64,
    /// `G` and `g`: where a motion G function may stand.
    g: u64,
}

/// The words of `window` as [`scan_words`](super::scan_words) reads them;
/// `None` when they do not stop within the window (the caller then reads
/// byte by byte).
pub(super) fn scan_words(window: &[u8; 64]) -> Option<Option<Words>> {
    if !*HAS_FEATURES {
        return None;
    }
    // SAFETY: the CPU has AVX2 (HAS_FEATURES, checked above).
    #[allow(unsafe_code)]
    unsafe {
        scan_words_avx2(window)
    }
}

/// The CPU has AVX2, BMI1 and POPCNT: asked once, as three questions to
/// the standard library's cache on every line cost about ten instructions a
/// line, a twentieth of a CAM block's scan.
static HAS_FEATURES: std::sync::LazyLock<bool> = std::sync::LazyLock::new(|| {
    std::arch::is_x86_feature_detected!("avx2")
        && std::arch::is_x86_feature_detected!("bmi1")
        && std::arch::is_x86_feature_detected!("popcnt")
});

/// [`scan_words`] compiled for AVX2, so that [`classify`] is inlined.
///
/// # Safety
///
/// The CPU must have AVX2.
#[allow(unsafe_code)]
#[target_feature(enable = "avx2,bmi1,popcnt")]
unsafe fn scan_words_avx2(window: &[u8; 64]) -> Option<Option<Words>> {
    let classes = classify(window);
    if classes.stops == 0 {
        return None;
    }
    Some(words_before(
        window,
        &classes,
        classes.stops.trailing_zeros() as usize,
    ))
}

/// The grammar of a plain line, `blank* (letter sign? number blank*)*`, with
/// a number of 1 to 24 digits and points, at least one digit and at most one
/// point, read on the masks of the bytes before `stop` (below 64).
fn words_before(window: &[u8; 64], classes: &Classes, stop: usize) -> Option<Words> {
    let before_stop = (1u64 << stop) - 1;
    let letters = classes.letters & before_stop;
    let signs = classes.signs & before_stop;
    let numbers = classes.numbers & before_stop;
    let points = classes.points & before_stop;
    let numbers_or_signs = numbers | signs;

    let other = before_stop & !classes.allowed;
    // A letter is followed by a sign or a number; a sign follows a letter and
    // is followed by a number; a number starts after a letter or a sign.
    let bare_letter = letters & !(numbers_or_signs >> 1);
    let stray_sign = signs & !((letters << 1) & (numbers >> 1));
    let run_starts = numbers & !(numbers << 1);
    let stray_number = run_starts & !((letters | signs) << 1);
    if other | bare_letter | stray_sign | stray_number != 0 {
        return None;
    }

    // `in_run[k]`: this byte and the 2^k - 1 before it are number bytes.
    let in_run_2 = numbers & (numbers << 1);
    let in_run_4 = in_run_2 & (in_run_2 << 2);
    let in_run_8 = in_run_4 & (in_run_4 << 4);
    let in_run_16 = in_run_8 & (in_run_8 << 8);
    // A number of 25 bytes or more.
    let too_long = in_run_16 & (in_run_8 << 16) & (numbers << 24);
    // Bytes after a point in the same number (spread 1 + 2 + 4 + 8 + 16 = 31
    // bytes, more than a number may have): a point there is a second one.
    let mut after_point = (points << 1) & numbers;
    after_point |= (after_point << 1) & numbers;
    after_point |= (after_point << 2) & in_run_2;
    after_point |= (after_point << 4) & in_run_4;
    after_point |= (after_point << 8) & in_run_8;
    after_point |= (after_point << 16) & in_run_16;
    let second_point = points & after_point;
    // With one point at most, a number without digits is a lone point.
    let lone_point = points & !(numbers << 1) & !(numbers >> 1);
    if too_long | second_point | lone_point != 0 {
        return None;
    }

    let Some(first) = lowest_bit(letters) else {
        return Some(Words::new(stop, None, LetterCount::default()));
    };
    let number = block_number(window, first, numbers, signs, points);
    let words = if number.is_some() {
        letters & (letters - 1)
    } else {
        letters
    };
    let mut count = LetterCount {
        seen: 0,
        words: words.count_ones(),
        motions: 0,
    };
    let mut rest = words;
    while rest != 0 {
        count.seen |= bit(window[rest.trailing_zeros() as usize]);
        rest &= rest - 1;
    }
    // The G words apart: one in most CAM blocks, and no test on the others.
    let mut g_words = words & classes.g;
    while g_words != 0 {
        count.motions |= motion_bit(window, g_words.trailing_zeros() as usize);
        g_words &= g_words - 1;
    }
    Some(Words::new(stop, number, count))
}

/// The block number, as the parser reads one: the first word (its letter at
/// `first`) when it is N with digits alone; where its letter is and where
/// its digits end.
fn block_number(
    window: &[u8; 64],
    first: usize,
    numbers: u64,
    signs: u64,
    points: u64,
) -> Option<(usize, usize)> {
    let digits_from = first + 1;
    let digits_end = digits_from + (!(numbers >> digits_from)).trailing_zeros() as usize;
    let digits = ((1u64 << digits_end) - 1) & !((1u64 << digits_from) - 1);
    let signed = signs & (1u64 << digits_from) != 0;
    let is_number = window[first].eq_ignore_ascii_case(&b'N') && !signed && points & digits == 0;
    is_number.then_some((first, digits_end))
}

/// The words of a plain line whose first 64 bytes are `window`, the block
/// number left out: where each word's letter stands and where its number
/// ends, by the offsets of `window`; `None` when its words do not stop
/// within the window or the CPU lacks AVX2 (the caller then reads byte by
/// byte). The line must be plain: the grammar is not checked again.
pub(super) fn words(window: &[u8; 64], each: impl FnMut(usize, usize)) -> Option<()> {
    if !*HAS_FEATURES {
        return None;
    }
    // SAFETY: the CPU has AVX2 (HAS_FEATURES, checked above).
    #[allow(unsafe_code)]
    unsafe {
        words_avx2(window, each)
    }
}

/// [`words`] compiled for AVX2, so that [`classify`] is inlined.
///
/// # Safety
///
/// The CPU must have AVX2.
#[allow(unsafe_code)]
#[target_feature(enable = "avx2,bmi1,popcnt")]
unsafe fn words_avx2(window: &[u8; 64], mut each: impl FnMut(usize, usize)) -> Option<()> {
    let classes = classify(window);
    let stop = lowest_bit(classes.stops)?;
    let before_stop = (1u64 << stop) - 1;
    let letters = classes.letters & before_stop;
    let numbers = classes.numbers & before_stop;
    let signs = classes.signs & before_stop;
    let Some(first) = lowest_bit(letters) else {
        return Some(());
    };
    let mut words = letters;
    if block_number(window, first, numbers, signs, classes.points).is_some() {
        words &= words - 1;
    }
    // A word is its letter and the sign and number bytes after it; the
    // stop is neither, so every word ends before it (below 64).
    let value = numbers | signs;
    while words != 0 {
        let letter = words.trailing_zeros() as usize;
        let end = letter + 1 + (!(value >> (letter + 1))).trailing_zeros() as usize;
        each(letter, end);
        words &= words - 1;
    }
    Some(())
}

fn lowest_bit(mask: u64) -> Option<usize> {
    (mask != 0).then(|| mask.trailing_zeros() as usize)
}

/// The class masks of the 64 bytes, 32 at a time.
///
/// # Safety
///
/// The CPU must have AVX2.
#[allow(unsafe_code)]
#[inline]
#[target_feature(enable = "avx2")]
unsafe fn classify(window: &[u8; 64]) -> Classes {
    let (Some(low), Some(high)) = (window.first_chunk(), window.last_chunk()) else {
        unreachable!("64 bytes are two halves of 32");
    };
    let (low, high) = (classify_32(low), classify_32(high));
    let join = |class: usize| u64::from(low[class]) | u64::from(high[class]) << 32;
    Classes {
        letters: join(0),
        signs: join(1),
        numbers: join(2),
        points: join(3),
        allowed: join(4),
        stops: join(5),
        g: join(6),
    }
}

/// The class masks of 32 bytes, in the order of [`Classes`]' fields.
///
/// # Safety
///
/// The CPU must have AVX2.
#[allow(unsafe_code)]
#[inline]
#[target_feature(enable = "avx2")]
unsafe fn classify_32(bytes: &[u8; 32]) -> [u32; 7] {
    use std::arch::x86_64::*;

    // Reads the 32 bytes the type guarantees.
    let v = _mm256_loadu_si256(bytes.as_ptr().cast());
    let splat = |byte: u8| _mm256_set1_epi8(byte as i8);
    let eq = |byte: u8| _mm256_cmpeq_epi8(v, splat(byte));
    // x in [0, limit] as unsigned bytes: min(x, limit) == x.
    let at_most = |x: __m256i, limit: u8| _mm256_cmpeq_epi8(_mm256_min_epu8(x, splat(limit)), x);
    let letter = at_most(
        _mm256_sub_epi8(_mm256_or_si256(v, splat(0x20)), splat(b'a')),
        25,
    );
    let digit = at_most(_mm256_sub_epi8(v, splat(b'0')), 9);
    let point = eq(b'.');
    let sign = _mm256_or_si256(eq(b'+'), eq(b'-'));
    let number = _mm256_or_si256(digit, point);
    // Blanks as `lexer::is_blank`: CR and LF count too, but they are
    // stops, and only the bytes before the first stop are read.
    let blank = _mm256_or_si256(at_most(v, b' '), _mm256_or_si256(eq(b'&'), eq(0x7f)));
    let allowed = _mm256_or_si256(
        _mm256_or_si256(letter, sign),
        _mm256_or_si256(number, blank),
    );
    let stop = _mm256_or_si256(_mm256_or_si256(eq(b'\n'), eq(b'\r')), eq(b';'));
    let g = _mm256_cmpeq_epi8(_mm256_or_si256(v, splat(0x20)), splat(b'g'));
    [letter, sign, number, point, allowed, stop, g].map(|mask| _mm256_movemask_epi8(mask) as u32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::plain::scan_words_bytewise;
    use proptest::prelude::*;

    /// Lines near the grammar's edges: every class of byte, numbers up to
    /// and past 24 bytes, points far apart, lines up to and past the window.
    fn line() -> impl Strategy<Value = Vec<u8>> {
        let piece = prop_oneof![
            r"[NnGXYZBCF][-+]?[0-9.]{0,8}",
            r"[0-9]{20,26}",
            r"[0-9]{0,3}\.[0-9]{12,20}\.[0-9]{0,2}",
            r"[ \t&\x7f\x01]{1,2}",
            r"[;\r\n]",
            r"[-+.NX0-9a-z=(@\[`{\x{80}\x{ff}]",
        ];
        prop::collection::vec(piece, 0..16).prop_map(|pieces| pieces.concat().into_bytes())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]

        /// Where the window decides, it decides as the byte-by-byte scan.
        #[test]
        fn agrees_with_the_bytewise_scan(line in line(), tail in r"[X0-9 \n]{64}") {
            let mut bytes = line;
            bytes.extend_from_slice(tail.as_bytes());
            let window = bytes.first_chunk().expect("64 bytes at least");
            if let Some(words) = scan_words(window) {
                prop_assert_eq!(words, scan_words_bytewise(&bytes));
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]

        /// The words of a plain line read on the window are those read
        /// byte by byte.
        #[test]
        fn words_agree_with_the_bytewise_reading(
            line in r"([ \t&]{0,2}[NnGXYZBCFm][-+]?([0-9]{1,12}|[0-9]{0,6}\.[0-9]{1,6})){0,9}[ ]?(;[A-Z ]{0,8})?",
            tail in r"[X0-9 \n]{64}",
        ) {
            let mut bytes = line.into_bytes();
            if !crate::syntax::plain::is_plain(&bytes) {
                return Ok(()); // a number longer than a position's
            }
            let bytewise: Vec<_> = crate::syntax::plain::words_bytewise(&bytes).collect();
            bytes.push(b'\n');
            bytes.extend_from_slice(tail.as_bytes());
            let mut wide = Vec::new();
            let window = bytes.first_chunk().expect("64 bytes at least");
            if words(window, |letter, end| wide.push((letter, end))).is_some() {
                prop_assert_eq!(wide, bytewise);
            }
        }
    }

    #[test]
    fn decides_a_cam_block_and_leaves_long_lines() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return; // the byte-by-byte scan decides everything
        }
        let mut block = b"N120 G1 X471.229 Y369.075 Z57.232 B16.480 C60.352\n".to_vec();
        block.resize(64, b'X');
        let words = scan_words(block.first_chunk().expect("64")).expect("decided");
        assert_eq!(words, scan_words_bytewise(&block));
        assert_eq!(words.map(|w| w.number), Some(Some((0, 4))));
        let long = [b'X'; 64];
        assert!(scan_words(&long).is_none());
    }
}
