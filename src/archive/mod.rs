//! Archives: many files in one, as a Sinumerik control writes them when a
//! shop saves its programs or its whole setup.
//!
//! - The text form ([`text`]): sections that each begin with a header line
//!   `%_N_NAME_MPF` (often followed by `;$PATH=/_N_MPF_DIR`) and run to the
//!   next header.
//! - The binary form ([`binary`]) that Sinumerik Operate writes for series
//!   start-up (`.arc` beginning with `@@MMCIBN.002`): tar-like records of a
//!   512-byte header and the member's bytes padded to 512.
//!
//! Reading an archive finds its members (name, kind, where their bytes
//! lie); nothing is copied. A change to a member becomes edits of the
//! archive's own bytes ([`Archive::edits`]), the header fields that hold
//! its size and checksum included, so every other byte stays as it was.
//! No I/O and no NC syntax here: the members are handed on as byte ranges.

pub mod binary;
pub mod text;

use std::ops::Range;

use crate::diagnostic::Diagnostic;
use crate::edit::Edit;
use crate::syntax::ProgramKind;

/// An archive's members, in the order they stand.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Archive {
    pub form: Form,
    pub members: Vec<Member>,
    /// Where bytes other than NULs begin after the block of NULs that ends
    /// a binary archive: left as they are, and not read.
    pub unread: Option<usize>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    Text,
    Binary,
}

/// One file of an archive.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Member {
    /// The control's name without its `_N_` prefix: `PART_MPF`, `MGUD_DEF`.
    pub name: String,
    /// The name as a file of its own would have it: `PART.MPF`.
    pub file_name: String,
    pub kind: MemberKind,
    /// The member's bytes in the archive: from its header line on in the
    /// text form (a section saved alone is the same file), after its header
    /// record in the binary form.
    pub data: Range<usize>,
    /// The binary form's header record of the member.
    pub header: Option<Range<usize>>,
}

/// What a member holds, by the suffix of its name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MemberKind {
    /// `_MPF` and `_SPF`: checked, rewritten and evaluated as programs.
    Program(ProgramKind),
    /// `_DEF`: GUD and macro definitions, read as the programs' environment.
    Definitions,
    /// `_INI` and the other NC data (`_TOA` tool offsets, `_TEA` machine
    /// data, `_UFR` frames, `_RPA` R parameters, `_GUD` values): NC
    /// assignments, read for machine data and swivel data records.
    Data,
    /// Anything else (screen forms `_COM`, texts, logs, binary data): left
    /// alone.
    Other,
}

impl Member {
    fn new(name: String, data: Range<usize>, header: Option<Range<usize>>) -> Self {
        let file_name = match name.rfind('_') {
            Some(at) if !name.contains('.') => format!("{}.{}", &name[..at], &name[at + 1..]),
            _ => name.clone(),
        };
        Self {
            kind: MemberKind::of_name(&name),
            name,
            file_name,
            data,
            header,
        }
    }
}

impl MemberKind {
    /// The kind a control name (`PART_MPF`, `PART.MPF`) gives.
    pub fn of_name(name: &str) -> Self {
        let suffix = name
            .rsplit(['_', '.'])
            .next()
            .unwrap_or("")
            .to_ascii_uppercase();
        match suffix.as_str() {
            "MPF" => Self::Program(ProgramKind::Main),
            "SPF" => Self::Program(ProgramKind::Subprogram),
            "DEF" => Self::Definitions,
            "INI" | "TOA" | "TEA" | "UFR" | "RPA" | "GUD" | "TMA" | "CEC" | "EEC" | "QEC" => {
                Self::Data
            }
            _ => Self::Other,
        }
    }
}

/// What makes a file no readable archive: where (the member, the byte
/// offset in the archive) and why.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}at byte {offset}: {why}", member.as_ref().map(|m| format!("member `{m}`, ")).unwrap_or_default())]
pub struct ArchiveError {
    pub member: Option<String>,
    pub offset: usize,
    pub why: String,
}

/// The archive `bytes` hold, `None` when they hold a plain file. `name`
/// (the file's) lets a `.arc` file of one text section count as an
/// archive; two sections or more make one whatever the name.
pub fn read(bytes: &[u8], name: &str) -> Option<Result<Archive, ArchiveError>> {
    if binary::is_binary(bytes) {
        return Some(binary::read(bytes).map(|(members, unread)| Archive {
            form: Form::Binary,
            members,
            unread,
        }));
    }
    let named_archive = std::path::Path::new(name)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("arc"));
    let members = text::members(bytes)?;
    (members.len() >= 2 || named_archive).then_some(Ok(Archive {
        form: Form::Text,
        members,
        unread: None,
    }))
}

impl Archive {
    /// The edits of `bytes` (the archive's) that change member `index`'s
    /// bytes by `edits` (offsets into the member): shifted to where the
    /// member lies, and in the binary form the header's size and checksum
    /// and the padding made to match the new length. `None` when the new
    /// size cannot be written in the header's field.
    pub fn edits(&self, bytes: &[u8], index: usize, edits: &[Edit]) -> Option<Vec<Edit>> {
        let member = &self.members[index];
        let at = member.data.start;
        let mut out: Vec<Edit> = edits
            .iter()
            .map(|edit| {
                Edit::replace(
                    crate::span::Span::new(edit.span.start + at, edit.span.end + at),
                    edit.text.clone(),
                )
            })
            .collect();
        if let (Form::Binary, Some(header)) = (self.form, &member.header) {
            let grown: isize = edits
                .iter()
                .map(|e| e.text.len() as isize - e.span.len() as isize)
                .sum();
            let length = member.data.len().checked_add_signed(grown)?;
            out.extend(binary::resized(
                bytes,
                header.clone(),
                member.data.clone(),
                length,
            )?);
        }
        Some(out)
    }
}

/// Swivel data records and machine data, as a file, an archive or a
/// folder of the control's files holds them.
pub struct SetupData<'a> {
    /// A plain file whole; of an archive, its data members (`_INI`,
    /// `_TOA`, ...) one after the other, since programs hold no machine data.
    pub bytes: std::borrow::Cow<'a, [u8]>,
    /// What reports call them: the file, or `ARCH.arc:INITIAL_INI` when
    /// one member holds them all.
    pub name: String,
    /// The files or members `bytes` joins, in order: a finding is told on
    /// the line of its own file ([`Part::split`]).
    pub parts: Vec<Part>,
}

/// One file's or member's share of joined setup data.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Part {
    pub name: String,
    pub range: Range<usize>,
}

impl Part {
    /// `diagnostics`, whose spans point into the joined bytes, by the part
    /// each points into (in the parts' order, parts without one left out),
    /// their spans moved to point into the part.
    pub fn split(parts: &[Part], diagnostics: &[Diagnostic]) -> Vec<(usize, Vec<Diagnostic>)> {
        let mut split: Vec<(usize, Vec<Diagnostic>)> = Vec::new();
        for (i, part) in parts.iter().enumerate() {
            let inside: Vec<Diagnostic> = diagnostics
                .iter()
                .filter(|d| {
                    part.range.contains(&d.span.start)
                        || (d.span.start == part.range.end && i + 1 == parts.len())
                })
                .map(|d| d.moved_back(part.range.start))
                .collect();
            if !inside.is_empty() {
                split.push((i, inside));
            }
        }
        split
    }
}

/// The setup data of `bytes`, the file `name`.
pub fn setup_data<'a>(bytes: &'a [u8], name: &str) -> Result<SetupData<'a>, ArchiveError> {
    let Some(archive) = read(bytes, name) else {
        return Ok(SetupData {
            bytes: std::borrow::Cow::Borrowed(bytes),
            name: name.to_string(),
            parts: vec![Part {
                name: name.to_string(),
                range: 0..bytes.len(),
            }],
        });
    };
    let data: Vec<Member> = archive?
        .members
        .into_iter()
        .filter(|m| m.kind == MemberKind::Data)
        .collect();
    let mut joined = Vec::new();
    let mut parts = Vec::new();
    for member in &data {
        let part_name = format!("{name}:{}", member.name);
        parts.push(join(&mut joined, &bytes[member.data.clone()], part_name));
    }
    let name = match data.as_slice() {
        [one] => format!("{name}:{}", one.name),
        _ => name.to_string(),
    };
    Ok(SetupData {
        bytes: std::borrow::Cow::Owned(joined),
        name,
        parts,
    })
}

/// `bytes` appended to `joined` as the part `name`, ending with a line break.
fn join(joined: &mut Vec<u8>, bytes: &[u8], name: String) -> Part {
    let start = joined.len();
    joined.extend_from_slice(bytes);
    if joined.last().is_some_and(|&b| b != b'\n') {
        joined.push(b'\n');
    }
    Part {
        name,
        range: start..joined.len(),
    }
}

/// The setup data of a folder `name` holding `files` (name, bytes), in the
/// order given: each file's as [`setup_data`] reads it, one after the other.
pub fn setup_data_of_files(
    name: &str,
    files: &[(String, Vec<u8>)],
) -> Result<SetupData<'static>, ArchiveError> {
    let mut joined = Vec::new();
    let mut parts = Vec::new();
    for (file, bytes) in files {
        let data = setup_data(bytes, file).map_err(|error| ArchiveError {
            member: error.member.or_else(|| Some(file.clone())),
            ..error
        })?;
        for part in data.parts {
            parts.push(join(&mut joined, &data.bytes[part.range], part.name));
        }
    }
    Ok(SetupData {
        bytes: std::borrow::Cow::Owned(joined),
        name: name.to_string(),
        parts,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_come_from_the_suffix_in_either_spelling() {
        assert_eq!(
            MemberKind::of_name("PART_MPF"),
            MemberKind::Program(ProgramKind::Main)
        );
        assert_eq!(
            MemberKind::of_name("l_cycle.spf"),
            MemberKind::Program(ProgramKind::Subprogram)
        );
        assert_eq!(MemberKind::of_name("MGUD_DEF"), MemberKind::Definitions);
        assert_eq!(MemberKind::of_name("INITIAL_INI"), MemberKind::Data);
        assert_eq!(MemberKind::of_name("MASK_COM"), MemberKind::Other);
        assert_eq!(MemberKind::of_name("README"), MemberKind::Other);
    }

    #[test]
    fn one_section_is_a_program_unless_the_file_is_named_an_archive() {
        let one = b"%_N_PART_MPF\n;$PATH=/_N_MPF_DIR\nG0 X0\nM30\n";
        assert_eq!(read(one, "PART.MPF"), None);
        let archive = read(one, "SAVED.ARC").expect("readable").expect("readable");
        assert_eq!(archive.members.len(), 1);
        assert_eq!(archive.members[0].data, 0..one.len());
    }

    #[test]
    fn setup_data_of_an_archive_are_its_data_members() {
        let archive =
            b"%_N_PART_MPF\nM30\n%_N_INITIAL_INI\n$TC_CARR1[1]=0\n%_N_MGUD_DEF\nDEF NCK INT A\n";
        let data = setup_data(archive, "A.ARC").expect("readable");
        assert_eq!(&data.bytes[..], b"%_N_INITIAL_INI\n$TC_CARR1[1]=0\n");
        assert_eq!(data.name, "A.ARC:INITIAL_INI");
        assert_eq!(data.parts[0].range, 0..data.bytes.len());
        let plain = setup_data(b"G0 X0\n", "P.MPF").expect("readable");
        assert_eq!(
            (&plain.bytes[..], plain.name.as_str()),
            (&b"G0 X0\n"[..], "P.MPF")
        );
    }
}
