//! The parser's input: a slice of one line's bytes and the file offset where
//! it starts, so every token gets a file span without allocating.
//!
//! `nom_locate` does the same and also counts newlines on every slice, work
//! for nothing here since a line never contains one: line numbers come from
//! offsets, only when a diagnostic needs them.

use std::iter::{Copied, Enumerate};
use std::slice::Iter;

use nom::{Compare, CompareResult, Needed, Offset};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Input<'a> {
    bytes: &'a [u8],
    offset: usize,
}

impl<'a> Input<'a> {
    /// `bytes` found at file offset `offset`.
    pub fn new(bytes: &'a [u8], offset: usize) -> Self {
        Self { bytes, offset }
    }

    /// The bytes not consumed yet.
    pub fn fragment(&self) -> &'a [u8] {
        self.bytes
    }

    /// The file offset of the first byte not consumed yet.
    pub fn offset(&self) -> usize {
        self.offset
    }
}

impl<'a> nom::Input for Input<'a> {
    type Item = u8;
    type Iter = Copied<Iter<'a, u8>>;
    type IterIndices = Enumerate<Self::Iter>;

    #[inline]
    fn input_len(&self) -> usize {
        self.bytes.len()
    }

    #[inline]
    fn take(&self, index: usize) -> Self {
        Self::new(&self.bytes[..index], self.offset)
    }

    #[inline]
    fn take_from(&self, index: usize) -> Self {
        Self::new(&self.bytes[index..], self.offset + index)
    }

    #[inline]
    fn take_split(&self, index: usize) -> (Self, Self) {
        (self.take_from(index), self.take(index))
    }

    #[inline]
    fn position<P>(&self, predicate: P) -> Option<usize>
    where
        P: Fn(u8) -> bool,
    {
        self.bytes.iter().position(|&b| predicate(b))
    }

    #[inline]
    fn iter_elements(&self) -> Self::Iter {
        self.bytes.iter().copied()
    }

    #[inline]
    fn iter_indices(&self) -> Self::IterIndices {
        self.iter_elements().enumerate()
    }

    #[inline]
    fn slice_index(&self, count: usize) -> Result<usize, Needed> {
        if self.bytes.len() >= count {
            Ok(count)
        } else {
            Err(Needed::new(count - self.bytes.len()))
        }
    }
}

impl<'b> Compare<&'b [u8]> for Input<'_> {
    #[inline]
    fn compare(&self, t: &'b [u8]) -> CompareResult {
        self.bytes.compare(t)
    }

    #[inline]
    fn compare_no_case(&self, t: &'b [u8]) -> CompareResult {
        self.bytes.compare_no_case(t)
    }
}

impl Offset for Input<'_> {
    fn offset(&self, second: &Self) -> usize {
        second.offset - self.offset
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nom::Input as _;

    #[test]
    fn slices_keep_their_file_offset() {
        let input = Input::new(b"X12.5 Y3", 100);
        let (rest, taken) = input.take_split(5);
        assert_eq!((taken.fragment(), taken.offset()), (&b"X12.5"[..], 100));
        assert_eq!((rest.fragment(), rest.offset()), (&b" Y3"[..], 105));
        assert_eq!(input.slice_index(9), Err(Needed::new(1)));
    }
}
