//! The text form of an archive (punched-tape format): each file begins
//! with a header line, `%` and the control's name (`%_N_PART_MPF`,
//! `%Flange3_MPF`), usually followed by the directory it goes to
//! (`;$PATH=/_N_MPF_DIR`), and runs to the next header line.
//!
//! The first line of such a file is a header (the form has no preamble):
//! a file that begins otherwise is no text archive, so a program that is
//! not one costs one line's look.

use super::Member;

/// The sections of `bytes`, `None` when its first line is no header.
pub fn members(bytes: &[u8]) -> Option<Vec<Member>> {
    header_name(first_line(bytes))?;
    let mut starts = vec![0];
    for newline in memchr::memmem::find_iter(bytes, b"\n%") {
        let start = newline + 1;
        if header_name(first_line(&bytes[start..])).is_some() {
            starts.push(start);
        }
    }
    let ends = starts.iter().skip(1).copied().chain([bytes.len()]);
    Some(
        starts
            .iter()
            .zip(ends)
            .map(|(&start, end)| {
                let name = header_name(first_line(&bytes[start..])).unwrap_or_default();
                Member::new(name, start..end, None)
            })
            .collect(),
    )
}

fn first_line(bytes: &[u8]) -> &[u8] {
    let end = memchr::memchr(b'\n', bytes).unwrap_or(bytes.len());
    &bytes[..end]
}

/// The name a header line gives (`%_N_PART_MPF` -> `PART_MPF`): `%`, a
/// name of letters, digits and `_` that ends in `_` and a suffix, and
/// nothing after it but blanks.
fn header_name(line: &[u8]) -> Option<String> {
    let rest = line.strip_prefix(b"%")?;
    let end = rest
        .iter()
        .position(|&b| !(b.is_ascii_alphanumeric() || b == b'_'))
        .unwrap_or(rest.len());
    let (name, after) = rest.split_at(end);
    if !after.iter().all(|b| b.is_ascii_whitespace()) {
        return None;
    }
    let name = name.strip_prefix(b"_N_").unwrap_or(name);
    let underscore = name.iter().rposition(|&b| b == b'_')?;
    let suffix = &name[underscore + 1..];
    if underscore == 0 || suffix.is_empty() || !suffix.iter().all(u8::is_ascii_alphabetic) {
        return None;
    }
    Some(String::from_utf8_lossy(name).into_owned())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::archive::MemberKind;
    use crate::syntax::ProgramKind;

    #[test]
    fn sections_run_from_their_header_to_the_next() {
        let archive = b"%_N_PART_MPF\r\n;$PATH=/_N_MPF_DIR\r\nG0 X0\r\n%_N_L1_SPF\n;$PATH=/_N_SPF_DIR\nPROC L1\nM17\n%Flange3_MPF\nM30";
        let members = members(archive).expect("readable");
        let names: Vec<&str> = members.iter().map(|m| m.name.as_str()).collect();
        assert_eq!(names, ["PART_MPF", "L1_SPF", "Flange3_MPF"]);
        assert_eq!(members[0].kind, MemberKind::Program(ProgramKind::Main));
        assert_eq!(
            members[1].kind,
            MemberKind::Program(ProgramKind::Subprogram)
        );
        assert_eq!(
            &archive[members[1].data.clone()],
            b"%_N_L1_SPF\n;$PATH=/_N_SPF_DIR\nPROC L1\nM17\n"
        );
        assert_eq!(members[2].data.end, archive.len());
    }

    #[test]
    fn a_percent_that_is_no_header_stays_in_its_section() {
        let archive = b"%_N_A_MPF\nMSG(\"x\")\n%\n% not a header\n%_N_B_MPF\nM30\n";
        let members = members(archive).expect("readable");
        assert_eq!(members.len(), 2);
        assert_eq!(
            &archive[members[0].data.clone()],
            b"%_N_A_MPF\nMSG(\"x\")\n%\n% not a header\n"
        );
    }

    #[test]
    fn a_file_that_begins_otherwise_is_no_archive() {
        assert_eq!(members(b"G0 X0\n%_N_A_MPF\n"), None);
        assert_eq!(members(b"%MPF\n"), None);
        assert_eq!(members(b""), None);
    }
}
