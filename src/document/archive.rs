//! The programs a file holds: the file itself, or each program of an
//! archive (`%_N_` sections, or a series start-up `.arc`) under the name
//! `ARCH.arc:PART_MPF`, with the archive's definitions, machine data and
//! subprograms as their environment.

use std::sync::Arc;

use crate::archive::{self, Archive, MemberKind};
use crate::diagnostic::{Diagnostic, Fix};
use crate::document::printable;
use crate::document::Document;
use crate::lint::Settings;
use crate::semantic::environment::{holds_machine_data, Environment};
use crate::semantic::head_def::Heads;
use crate::span::Span;
use crate::syntax::{program_kind, ProgramKind};

/// A file, read as an archive if it is one.
pub struct Opened {
    /// What reports call the file.
    pub name: String,
    pub archive: Option<Archive>,
    /// The file's kind when it is no archive (read once: it parses the
    /// first blocks).
    kind: ProgramKind,
}

/// One program to check, rewrite or evaluate.
pub struct Program<'a> {
    /// The file's name, or `ARCH.arc:PART_MPF` for an archive's member.
    pub name: String,
    /// Its bytes; named for its rules as a file of its own would be
    /// (`PART.MPF`), so that they read its kind and name alike.
    pub document: Document<'a>,
    /// The member's index in the archive.
    pub member: Option<usize>,
}

/// A member of the archive that could not be read for the environment:
/// its syntax errors, reported as its own findings.
pub struct Unreadable {
    /// The member's index in the archive.
    pub member: usize,
    pub diagnostics: Vec<Diagnostic>,
}

impl Opened {
    /// `bytes`, named `name`: an archive that cannot be read is an error
    /// naming the member and the offset, before anything is done with it.
    pub fn read(bytes: &[u8], name: &str) -> Result<Self, archive::ArchiveError> {
        let archive = archive::read(bytes, name).transpose()?;
        let kind = match archive {
            Some(_) => ProgramKind::Main,
            None => program_kind(Some(name), bytes),
        };
        Ok(Self {
            name: name.to_string(),
            archive,
            kind,
        })
    }

    /// The programs: the file, or the archive's `_MPF` and `_SPF` members.
    pub fn programs<'a>(&'a self, bytes: &'a [u8]) -> Vec<Program<'a>> {
        let Some(archive) = &self.archive else {
            return vec![Program {
                name: self.name.clone(),
                document: Document {
                    name: &self.name,
                    source: bytes,
                    kind: self.kind,
                },
                member: None,
            }];
        };
        archive
            .members
            .iter()
            .enumerate()
            .filter_map(|(index, member)| {
                let MemberKind::Program(kind) = member.kind else {
                    return None;
                };
                Some(Program {
                    name: self.member_name(index),
                    document: Document {
                        name: &member.file_name,
                        source: &bytes[member.data.clone()],
                        kind,
                    },
                    member: Some(index),
                })
            })
            .collect()
    }

    /// What of the archive (`bytes`) is left unchecked, as notes for stderr
    /// naming it: members that are no program, definitions or data (their
    /// NC path names no `_MPF` or `_SPF`, and they hold no machine data: a
    /// log, a screen form, a program saved without its suffix), and bytes after the block of NULs that ends a
    /// binary archive. `None` for a plain file, or an archive read whole.
    pub fn unchecked(&self, bytes: &[u8]) -> Option<String> {
        let archive = self.archive.as_ref()?;
        let name = printable(&self.name);
        let mut notes = String::new();
        let others: Vec<String> = archive
            .members
            .iter()
            .enumerate()
            // A binary archive's first record is the form's mark.
            .filter(|(index, member)| {
                member.kind == MemberKind::Other
                    && !(*index == 0 && member.name.as_bytes().starts_with(archive::binary::MARK))
                    && !holds_machine_data(&bytes[member.data.clone()])
            })
            .map(|(_, member)| printable(&member.name).into_owned())
            .collect();
        if !others.is_empty() {
            let mut names: Vec<&str> = others.iter().map(String::as_str).take(10).collect();
            if others.len() > names.len() {
                names.push("...");
            }
            let count = match others.len() {
                1 => "1 member".to_string(),
                n => format!("{n} members"),
            };
            notes.push_str(&format!(
                "note: {name}: {count} not checked, its NC path naming no program (_MPF, _SPF), definitions or data: {}\n",
                names.join(", ")
            ));
        }
        if let Some(offset) = archive.unread {
            let hidden = archive::binary::names_past_the_end(bytes, offset);
            let members = match hidden.len() {
                0 => "a member there is not checked".to_string(),
                1 => format!("the member there, {}, is not checked", hidden[0]),
                n => format!(
                    "the {n} members there, {}, are not checked",
                    hidden.join(", ")
                ),
            };
            notes.push_str(&format!(
                "note: {name}: the bytes from byte {offset} on, after the block of NULs that ends the archive, are not read: {members}\n"
            ));
        }
        (!notes.is_empty()).then_some(notes)
    }

    /// A member's bytes in `bytes` (the archive's).
    pub fn member_bytes<'a>(&self, bytes: &'a [u8], index: usize) -> &'a [u8] {
        match &self.archive {
            Some(archive) => &bytes[archive.members[index].data.clone()],
            None => bytes,
        }
    }

    /// Member `index`'s findings placed in the archive itself, for the
    /// formats whose readers open the file named (GitHub's annotations,
    /// SARIF's code scanning): `ARCH.arc:PART_MPF` is no file there. Each
    /// span is moved to where the member lies in `bytes` (the archive's),
    /// so that its line is the archive's; the message begins with the
    /// member's name; a fix becomes the archive's edits (a binary
    /// archive's header included), or is dropped where the new size does
    /// not fit the header.
    pub fn in_archive(
        &self,
        bytes: &[u8],
        index: usize,
        diagnostics: Vec<Diagnostic>,
    ) -> Vec<Diagnostic> {
        let Some(archive) = &self.archive else {
            return diagnostics;
        };
        let member = &archive.members[index];
        let at = member.data.start;
        let name = printable(&member.name);
        diagnostics
            .into_iter()
            .map(|mut d| {
                d.span = Span::new(d.span.start + at, d.span.end + at);
                if let Some(related) = &mut d.related {
                    related.span = Span::new(related.span.start + at, related.span.end + at);
                }
                d.message = format!("{name}: {}", d.message);
                d.fix = d.fix.and_then(|fix| {
                    let edits = archive.edits(bytes, index, &fix.edits)?;
                    Some(Box::new(Fix { edits, ..*fix }))
                });
                d
            })
            .collect()
    }

    /// `ARCH.arc:PART_MPF`.
    pub fn member_name(&self, index: usize) -> String {
        match &self.archive {
            Some(archive) => format!("{}:{}", self.name, archive.members[index].name),
            None => self.name.clone(),
        }
    }

    /// Adds to `settings` what the archive holds for its programs: the
    /// variables and macros of its definition members, the axis names of
    /// its data members, the subprograms its program members declare (found
    /// before the cycle directories', as the program's own directory is on
    /// the control), and its HEAD_DEF_SPF when no other is given. Gives
    /// back the members that could not be read.
    pub fn settings(&self, bytes: &[u8], settings: &mut Settings) -> Vec<Unreadable> {
        let mut unreadable = Vec::new();
        let Some(archive) = &self.archive else {
            return unreadable;
        };
        let environment = &mut settings.environment;
        let mut own = Environment::default();
        for (index, member) in archive.members.iter().enumerate() {
            let data = &bytes[member.data.clone()];
            let read = match member.kind {
                MemberKind::Data => environment.read_machine_data(data),
                // Machine data by their content, whatever the member's name.
                MemberKind::Definitions | MemberKind::Other if holds_machine_data(data) => {
                    environment.read_machine_data(data)
                }
                MemberKind::Definitions => environment.read_definitions(data, None),
                MemberKind::Program(_) => {
                    // A setup program that assigns machine data: its axis
                    // names are the machine's (its errors are its own
                    // findings, as a program's).
                    if holds_machine_data(data) {
                        environment.learn_axes(data);
                    }
                    own.read_procedure(data, None);
                    if settings.heads.is_none() && member.name.eq_ignore_ascii_case("HEAD_DEF_SPF")
                    {
                        settings.heads = Some(Heads::read(self.member_name(index), data));
                    }
                    continue;
                }
                MemberKind::Other => continue,
            };
            environment.given = true;
            if let Err(diagnostics) = read {
                unreadable.push(Unreadable {
                    member: index,
                    diagnostics,
                });
            }
        }
        if !own.procedures.is_empty() {
            let mut all = (*environment.procedures).clone();
            all.extend(Arc::unwrap_or_clone(own.procedures));
            environment.procedures = Arc::new(all);
        }
        unreadable
    }
}

/// The analysis of an archive (`name`, `source`) as an editor shows it: each
/// program checked as `check` checks it, with what the archive gives it,
/// its findings placed in the archive; the model and the walk of the whole
/// text answer the questions about names. `None` for a file that is no
/// archive, or one that cannot be read as one (it is a program then).
pub fn analyze<'src>(
    name: &str,
    source: &'src [u8],
    settings: &Settings,
) -> Option<crate::lint::Analyzed<'src>> {
    let opened = Opened::read(source, name).ok()?;
    opened.archive.as_ref()?;
    let mut settings = settings.clone();
    let mut findings = Vec::new();
    for unreadable in opened.settings(source, &mut settings) {
        findings.extend(opened.in_archive(source, unreadable.member, unreadable.diagnostics));
    }
    for program in opened.programs(source) {
        let analyzed = program.document.analyze(&settings);
        let member = program.member?;
        findings.extend(opened.in_archive(source, member, analyzed.findings));
    }
    findings.sort_by_key(|found| (found.span.start, found.code()));
    let (model, walk) = super::model_and_walk(source, ProgramKind::Main, &settings);
    Some(crate::lint::Analyzed {
        model,
        walk,
        findings,
        unresolved_calls: Vec::new(),
        names_as_operators: 0,
    })
}
