//! Reading an archive never panics, its members lie inside it in order,
//! and a member changed through `Archive::edits` reads back changed while
//! every other member reads back byte for byte (headers and padding made
//! to match in the binary form).
#![no_main]

use libfuzzer_sys::fuzz_target;
use sinuprep::archive::{read, Form, MemberKind};
use sinuprep::edit::{apply, Edit};
use sinuprep::span::Span;

fuzz_target!(|data: &[u8]| {
    let Some(Ok(archive)) = read(data, "FUZZ.ARC") else {
        return;
    };
    let mut at = 0;
    for member in &archive.members {
        let start = member.header.as_ref().map_or(member.data.start, |h| h.start);
        assert!(at <= start && member.data.start <= member.data.end && member.data.end <= data.len());
        at = member.data.end;
    }
    let Some(index) = archive
        .members
        .iter()
        .position(|m| matches!(m.kind, MemberKind::Program(_)))
    else {
        return;
    };
    let member = &archive.members[index];
    let bytes = &data[member.data.clone()];
    let edit = match archive.form {
        // The second half replaced.
        Form::Binary => Edit::replace(
            Span::new(bytes.len() / 2, bytes.len()),
            b"G0 X1\nM30\n".to_vec(),
        ),
        // A line after the header line, which must stay a header.
        Form::Text => {
            let end = bytes.iter().position(|&b| b == b'\n').unwrap_or(bytes.len());
            Edit::insert(end, b"\nG0 X1".to_vec())
        }
    };
    let Some(edits) = archive.edits(data, index, std::slice::from_ref(&edit)) else {
        return;
    };
    let changed = apply(data, &edits);
    let again = match read(&changed, "FUZZ.ARC") {
        Some(Ok(again)) => again,
        other => panic!("the changed archive does not read: {other:?}"),
    };
    assert_eq!(again.members.len(), archive.members.len());
    for (i, (before, after)) in archive.members.iter().zip(&again.members).enumerate() {
        let expected = if i == index {
            apply(&data[before.data.clone()], std::slice::from_ref(&edit))
        } else {
            data[before.data.clone()].to_vec()
        };
        assert_eq!(changed[after.data.clone()], expected[..], "member {i}");
        assert_eq!(before.name, after.name);
    }
});
