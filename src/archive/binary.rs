//! The binary form of an archive, written by Sinumerik Operate for series
//! start-up (`.arc`, beginning with `@@MMCIBN.002`): tar-like records, each
//! a 512-byte header and the member's bytes padded with NULs to a multiple
//! of 512. The header's fields, as they stand in archives of real controls:
//!
//! | offset | field |
//! |---|---|
//! | 0 | member name, NUL-terminated |
//! | 50 | DOS name |
//! | 124 | size in bytes, decimal ASCII |
//! | 136 | time |
//! | 148 | checksum: the decimal sum of all 512 header bytes, the checksum field counted as zeros |
//! | 257 | NC path (`/_N_MPF_DIR/_N_PART_MPF`) |
//! | 384 | DOS path |
//!
//! The first record's name is the form's mark, `@@MMCIBN.002`. A block of
//! NULs, or the end of the file, ends the archive; whatever follows a block
//! of NULs is kept as it is, and where it begins told ([`read`]) so that
//! what it may hide is not passed over in silence.

use std::ops::Range;

use super::{ArchiveError, Member};
use crate::edit::Edit;
use crate::span::Span;

/// A header's length, and the unit the members' bytes are padded to.
pub const BLOCK: usize = 512;

const NAME: Range<usize> = 0..50;
const SIZE: Range<usize> = 124..136;
const CHECKSUM: Range<usize> = 148..156;
const NC_PATH: Range<usize> = 257..384;

/// The mark the form begins with.
pub const MARK: &[u8] = b"@@MMCIBN";

pub fn is_binary(bytes: &[u8]) -> bool {
    bytes.starts_with(MARK)
}

/// The members of a binary archive, each checked against its header's
/// checksum and its size against the bytes there are.
pub fn members(bytes: &[u8]) -> Result<Vec<Member>, ArchiveError> {
    Ok(read(bytes)?.0)
}

/// The members, and where data that is not all NULs begins after the
/// block of NULs that ends the archive: it is not read (a member written
/// there is neither checked nor rewritten).
pub fn read(bytes: &[u8]) -> Result<(Vec<Member>, Option<usize>), ArchiveError> {
    let mut members = Vec::new();
    let mut at = 0;
    while at < bytes.len() {
        let rest = &bytes[at..];
        if rest.iter().take(BLOCK).all(|&b| b == 0) {
            let after = at + BLOCK.min(rest.len());
            let unread = bytes[after..].iter().position(|&b| b != 0);
            return Ok((members, unread.map(|offset| after + offset)));
        }
        let fail = |member: Option<&str>, why: String| ArchiveError {
            member: member.map(str::to_string),
            offset: at,
            why,
        };
        if rest.len() < BLOCK {
            return Err(fail(
                None,
                format!(
                    "a header of {BLOCK} bytes begins here, and {} bytes are left: the archive is truncated",
                    rest.len()
                ),
            ));
        }
        let header = &rest[..BLOCK];
        let name = name(header);
        let recorded = decimal(&header[CHECKSUM]);
        let sum = checksum(header);
        if recorded != Some(sum) {
            let recorded = recorded.map_or("no number".to_string(), |n| n.to_string());
            return Err(fail(
                Some(&name),
                format!("the header is damaged: its checksum field holds {recorded}, its bytes sum to {sum}"),
            ));
        }
        let Some(size) = decimal(&header[SIZE]).and_then(|s| usize::try_from(s).ok()) else {
            return Err(fail(
                Some(&name),
                "the header's size field (offset 124) holds no decimal number".to_string(),
            ));
        };
        let start = at + BLOCK;
        let left = bytes.len() - start;
        if size > left {
            return Err(fail(
                Some(&name),
                format!("the member is {size} bytes long, and {left} bytes are left: the archive is truncated"),
            ));
        }
        members.push(Member::new(name, start..start + size, Some(at..start)));
        // A last member's padding may be missing; nothing else is lost.
        at = (start + padded(size)).min(bytes.len());
    }
    Ok((members, None))
}

/// The names of the members whose headers stand from `at` on, past the
/// block of NULs that ends the archive: every block there whose checksum
/// makes it a header (its member's bytes stepped over). What a report
/// names, since the archive's end leaves them unread.
pub fn names_past_the_end(bytes: &[u8], at: usize) -> Vec<String> {
    let mut names = Vec::new();
    let mut at = at - at % BLOCK;
    while at + BLOCK <= bytes.len() {
        let header = &bytes[at..at + BLOCK];
        let size = decimal(&header[SIZE]).and_then(|s| usize::try_from(s).ok());
        match size {
            Some(size)
                if header.iter().any(|&b| b != 0)
                    && decimal(&header[CHECKSUM]) == Some(checksum(header)) =>
            {
                names.push(name(header));
                at = at.saturating_add(BLOCK).saturating_add(padded(size));
            }
            _ => at += BLOCK,
        }
    }
    names
}

/// A member's name for reports: the last part of its NC path without
/// `_N_` (`PART_MPF`), else the name field as written.
fn name(header: &[u8]) -> String {
    let path = text(&header[NC_PATH]);
    let last = path.rsplit('/').next().unwrap_or("");
    match last.strip_prefix("_N_") {
        Some(name) if !name.is_empty() => name.to_string(),
        _ if !last.is_empty() => last.to_string(),
        _ => text(&header[NAME]),
    }
}

/// A NUL-terminated text field.
fn text(field: &[u8]) -> String {
    let end = field.iter().position(|&b| b == 0).unwrap_or(field.len());
    String::from_utf8_lossy(&field[..end]).trim().to_string()
}

/// A decimal field: digits, with blanks, NULs or leading zeros around them.
fn decimal(field: &[u8]) -> Option<u64> {
    let digits = field.iter().position(u8::is_ascii_digit)?;
    let end = field[digits..]
        .iter()
        .position(|b| !b.is_ascii_digit())
        .map_or(field.len(), |n| digits + n);
    let blank = |b: &u8| *b == 0 || *b == b' ';
    if !field[..digits].iter().all(blank) || !field[end..].iter().all(blank) {
        return None;
    }
    std::str::from_utf8(&field[digits..end]).ok()?.parse().ok()
}

/// The sum of a header's bytes, its checksum field counted as zeros.
fn checksum(header: &[u8]) -> u64 {
    let all: u64 = header.iter().map(|&b| u64::from(b)).sum();
    let field: u64 = header[CHECKSUM].iter().map(|&b| u64::from(b)).sum();
    all - field
}

/// `n` rounded up to whole blocks.
fn padded(n: usize) -> usize {
    n.div_ceil(BLOCK) * BLOCK
}

/// `value` written in `field`'s place as the field writes its number: at
/// the same place, right-aligned or zero-padded if it was, followed by the
/// same filler; `None` when it does not fit.
fn rewritten(field: &[u8], value: u64) -> Option<Vec<u8>> {
    let digits = value.to_string().into_bytes();
    let first = field.iter().position(u8::is_ascii_digit)?;
    let end = field[first..]
        .iter()
        .position(|b| !b.is_ascii_digit())
        .map_or(field.len(), |n| first + n);
    let mut out = field.to_vec();
    let zero_padded = field[first] == b'0' && end - first > 1;
    if first > 0 || zero_padded {
        // Right-aligned: the number ends where it ended.
        let pad = if zero_padded { b'0' } else { field[0] };
        let start = end.checked_sub(digits.len())?;
        out[..start].fill(pad);
        out[start..end].copy_from_slice(&digits);
    } else {
        if digits.len() > field.len() {
            return None;
        }
        let filler = field.get(end).copied().unwrap_or(0);
        out[..digits.len()].copy_from_slice(&digits);
        out[digits.len()..end.max(digits.len())].fill(filler);
    }
    Some(out)
}

/// The edits that make a member's header and padding fit its bytes'
/// new `length`: the size, the checksum of the header so changed, and NULs
/// to the next block.
pub fn resized(
    bytes: &[u8],
    header: Range<usize>,
    data: Range<usize>,
    length: usize,
) -> Option<Vec<Edit>> {
    let old = &bytes[header.clone()];
    let mut new = old.to_vec();
    new[SIZE].copy_from_slice(&rewritten(&old[SIZE], length as u64)?);
    let sum = checksum(&new);
    new[CHECKSUM].copy_from_slice(&rewritten(&old[CHECKSUM], sum)?);
    let mut edits = Vec::new();
    for field in [SIZE, CHECKSUM] {
        if new[field.clone()] != old[field.clone()] {
            let span = Span::new(header.start + field.start, header.start + field.end);
            edits.push(Edit::replace(span, new[field].to_vec()));
        }
    }
    let padding_end = (data.start + padded(data.len())).min(bytes.len());
    let padding = vec![0; padded(length) - length];
    if bytes[data.end..padding_end] != padding[..] {
        edits.push(Edit::replace(Span::new(data.end, padding_end), padding));
    }
    Some(edits)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::archive::MemberKind;
    use crate::edit::apply;

    /// A header record for `name` (NC path `path`) of `size` bytes, as a
    /// control writes it.
    fn header(name: &str, path: &str, size: usize) -> [u8; BLOCK] {
        let mut header = [0u8; BLOCK];
        let put = |header: &mut [u8; BLOCK], at: usize, text: &[u8]| {
            header[at..at + text.len()].copy_from_slice(text);
        };
        put(&mut header, NAME.start, name.as_bytes());
        put(&mut header, 50, name.to_ascii_uppercase().as_bytes());
        put(&mut header, SIZE.start, size.to_string().as_bytes());
        put(&mut header, 136, b"1733140800");
        put(&mut header, NC_PATH.start, path.as_bytes());
        let sum = checksum(&header);
        put(&mut header, CHECKSUM.start, sum.to_string().as_bytes());
        header
    }

    /// An archive of the mark and `files` (name, NC path, bytes).
    fn archive(files: &[(&str, &str, &[u8])]) -> Vec<u8> {
        let mut out = Vec::new();
        let mut add = |name: &str, path: &str, data: &[u8]| {
            out.extend_from_slice(&header(name, path, data.len()));
            out.extend_from_slice(data);
            out.resize(padded(out.len()), 0);
        };
        add("@@MMCIBN.002", "", b"series start-up\n");
        for (name, path, data) in files {
            add(name, path, data);
        }
        out
    }

    #[test]
    fn members_are_named_by_their_nc_path_and_found_whole() {
        let bytes = archive(&[
            ("PART.MPF", "/_N_MPF_DIR/_N_PART_MPF", b"G0 X0\nM30\n"),
            ("MGUD.DEF", "/_N_DEF_DIR/_N_MGUD_DEF", b"DEF NCK INT A\n"),
        ]);
        let members = members(&bytes).expect("readable");
        let names: Vec<&str> = members.iter().map(|m| m.name.as_str()).collect();
        assert_eq!(names, ["@@MMCIBN.002", "PART_MPF", "MGUD_DEF"]);
        assert_eq!(&bytes[members[1].data.clone()], b"G0 X0\nM30\n");
        assert_eq!(members[2].kind, MemberKind::Definitions);
        assert_eq!(members[0].kind, MemberKind::Other);
    }

    #[test]
    fn a_damaged_or_truncated_archive_names_the_member_and_the_offset() {
        let mut bytes = archive(&[("PART.MPF", "/_N_MPF_DIR/_N_PART_MPF", b"G0 X0\nM30\n")]);
        let whole = bytes.clone();
        bytes[1024 + 3] = b'X';
        let error = members(&bytes).expect_err("not readable");
        assert_eq!(error.member.as_deref(), Some("PART_MPF"));
        assert_eq!(error.offset, 1024);
        assert!(error.why.contains("checksum"), "{}", error.why);

        let cut = &whole[..1024 + BLOCK + 4];
        let error = members(cut).expect_err("not readable");
        assert!(error.why.contains("truncated"), "{}", error.why);
        let error = members(&whole[..1024 + 100]).expect_err("not readable");
        assert_eq!((error.member, error.offset), (None, 1024));
    }

    #[test]
    fn data_after_the_block_of_nuls_is_told() {
        let whole = archive(&[("PART.MPF", "/_N_MPF_DIR/_N_PART_MPF", b"M30\n")]);
        assert_eq!(read(&whole).expect("readable").1, None);
        let mut ended = whole.clone();
        ended.extend_from_slice(&[0; 2 * BLOCK]);
        assert_eq!(read(&ended).expect("readable").1, None);
        let hidden = archive(&[("HIDDEN.MPF", "/_N_MPF_DIR/_N_HIDDEN_MPF", b"M30\n")]);
        let mut with_more = whole.clone();
        with_more.extend_from_slice(&[0; BLOCK]);
        with_more.extend_from_slice(&hidden);
        assert_eq!(
            read(&with_more).expect("readable").1,
            Some(whole.len() + BLOCK)
        );
        assert_eq!(members(&with_more).expect("readable").len(), 2);
    }

    #[test]
    fn a_member_changed_gets_its_size_checksum_and_padding() {
        let bytes = archive(&[
            ("PART.MPF", "/_N_MPF_DIR/_N_PART_MPF", b"G0 X0\nM30\n"),
            ("NEXT.SPF", "/_N_SPF_DIR/_N_NEXT_SPF", b"PROC NEXT\nM17\n"),
        ]);
        let before = members(&bytes).expect("readable");
        let part = &before[1];
        let grown = vec![b'G'; 600];
        let edit = Edit::replace(Span::new(0, 5), grown.clone());
        let archive = super::super::Archive {
            form: super::super::Form::Binary,
            members: before.clone(),
            unread: None,
        };
        let edits = archive.edits(&bytes, 1, &[edit]).expect("readable");
        let changed = apply(&bytes, &edits);
        let after = members(&changed).expect("readable");
        let mut expected = grown;
        expected.extend_from_slice(b"\nM30\n");
        assert_eq!(&changed[after[1].data.clone()], &expected[..]);
        assert_eq!(&changed[after[2].data.clone()], b"PROC NEXT\nM17\n");
        assert_eq!(changed.len(), bytes.len() + BLOCK);
        // Nothing before the changed member moved.
        assert_eq!(
            changed[..part.header.clone().expect("readable").start],
            bytes[..part.header.clone().expect("readable").start]
        );
    }

    #[test]
    fn numbers_keep_their_field_s_layout() {
        assert_eq!(rewritten(b"10\0\0", 1234).expect("readable"), b"1234");
        assert_eq!(rewritten(b"1234\0\0", 7).expect("readable"), b"7\0\0\0\0\0");
        assert_eq!(rewritten(b"  12\0", 345).expect("readable"), b" 345\0");
        assert_eq!(rewritten(b"0012 ", 345).expect("readable"), b"0345 ");
        assert_eq!(rewritten(b"12", 12345), None);
        assert_eq!(decimal(b"  42\0 "), Some(42));
        assert_eq!(decimal(b"4 2"), None);
        assert_eq!(decimal(b"\0\0"), None);
    }
}
