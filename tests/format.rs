//! `sinuprep fmt`: snapshots of formatted fixtures and samples (input,
//! output, notes), and invariants over every sample, fixture and program of
//! the outside corpus that do not rely on the snapshots: formatting twice
//! equals formatting once; the formatted program parses to the same
//! statements modulo blanks and case (and, renumbered, block numbers);
//! strings and comments are byte for byte the same; every jump lands on the
//! same statement; a program with a syntax error is left as it is.

mod support;

use support::{assert_exit, run};

use sinuprep::edit::apply;
use sinuprep::format::{format, format_rows, Case, Settings};
use sinuprep::semantic::uses::{Role, Uses};
use sinuprep::semantic::Model;
use sinuprep::syntax::tree::{Block, LineKind};
use sinuprep::syntax::{parse, program_kind};

fn formatted(name: &str, source: &[u8], settings: &Settings) -> (Vec<u8>, Vec<String>) {
    let kind = program_kind(Some(name), source);
    let result = format(name, source, kind, settings);
    let notes = result.notes.iter().map(|n| n.message.clone()).collect();
    (apply(source, &result.edits), notes)
}

/// The bytes of a line's code with blanks outside strings left out, and
/// in upper case outside strings; its strings; its comment.
struct Shape {
    code: Vec<Vec<u8>>,
    kinds: Vec<String>,
    strings: Vec<Vec<u8>>,
    comments: Vec<Vec<u8>>,
}

fn shape(source: &[u8], renumbered: bool) -> Shape {
    let program = parse(source);
    let mut shape = Shape {
        code: Vec::new(),
        kinds: Vec::new(),
        strings: Vec::new(),
        comments: Vec::new(),
    };
    for line in &program.lines {
        let content = line.raw.content;
        let LineKind::Block(block) = &line.kind else {
            shape.code.push(content.of(source).to_vec());
            continue;
        };
        let code_end = block.comment.map_or(content.end, |c| c.start);
        if let Some(comment) = block.comment {
            shape.comments.push(comment.of(source).to_vec());
        }
        let mut code = Vec::new();
        let mut quote = None;
        let mut string = Vec::new();
        let start = match (renumbered, block.number) {
            (true, Some(number)) => number.span.end,
            _ => content.start,
        };
        for &byte in &source[start..code_end] {
            match quote {
                Some(q) => {
                    string.push(byte);
                    code.push(byte);
                    if byte == q {
                        quote = None;
                        shape.strings.push(std::mem::take(&mut string));
                    }
                }
                None if byte == b'"' || byte == b'\'' => {
                    quote = Some(byte);
                    string.push(byte);
                    code.push(byte);
                }
                None if byte == b' ' || byte == b'\t' => {}
                None => code.push(byte.to_ascii_uppercase()),
            }
        }
        if !is_blank_line(block) || !code.is_empty() {
            shape.kinds.push(kinds(block));
            if !renumbered {
                shape.code.push(code);
            }
        }
    }
    shape
}

fn is_blank_line(block: &Block) -> bool {
    block.is_empty() && block.comment.is_none() && block.number.is_none() && block.label.is_none()
}

fn kinds(block: &Block) -> String {
    block
        .statements
        .iter()
        .map(|s| {
            let debug = format!("{:?}", s.kind);
            debug
                .split(['(', ' ', '{'])
                .next()
                .unwrap_or_default()
                .to_string()
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// Where each jump lands, as the ordinal of its line among the lines that
/// are not blank (formatting removes blank lines only).
fn landings(name: &str, source: &[u8]) -> Vec<Option<usize>> {
    let model = Model::build(source, program_kind(Some(name), source));
    let uses = Uses::of(&model);
    let program = parse(source);
    let mut ordinal = Vec::with_capacity(program.lines.len());
    let mut count = 0;
    for line in &program.lines {
        ordinal.push(count);
        let blank = match &line.kind {
            LineKind::Block(block) => {
                is_blank_line(block) && line.raw.content.of(source).trim_ascii().is_empty()
            }
            _ => false,
        };
        if !blank {
            count += 1;
        }
    }
    uses.all()
        .iter()
        .filter(|u| u.role == Role::JumpsTo)
        .map(|u| {
            uses.definition(&model, u)
                .map(|definition| ordinal[definition.row])
        })
        .collect()
}

fn assert_formats_safely(name: &str, source: &[u8], settings: &Settings) {
    let renumbered = settings.renumber.is_some();
    let (once, _) = formatted(name, source, settings);
    let (twice, _) = formatted(name, &once, settings);
    let kind = program_kind(Some(name), source);
    let merged = sinuprep::format::format_merged(name, source, kind, settings);
    assert!(
        apply(source, &merged.edits) == once,
        "{name}: merged edits differ"
    );
    assert!(
        once == twice,
        "{name}: formatting again changed it:\n{}",
        String::from_utf8_lossy(&twice)
    );
    // The model's reading, with the program's own macros expanded, is the
    // one the formatter goes by.
    let errors = |bytes: &[u8]| {
        Model::build(bytes, program_kind(Some(name), bytes))
            .syntax
            .len()
    };
    if !format(name, source, kind, settings).syntax.is_empty() {
        assert!(errors(source) > 0, "{name}: refused without an error");
        assert_eq!(once, source, "{name}: a program with syntax errors changed");
        return;
    }
    // Errors after the program's end, which the control never reads, are
    // left where they are.
    assert_eq!(
        errors(&once),
        errors(source),
        "{name}: formatting changed the syntax errors:\n{}",
        String::from_utf8_lossy(&once)
    );
    let (before, after) = (shape(source, renumbered), shape(&once, renumbered));
    assert_eq!(before.kinds, after.kinds, "{name}: statements changed");
    assert!(
        before.code == after.code,
        "{name}: code changed beyond blanks and case"
    );
    assert!(before.strings == after.strings, "{name}: a string changed");
    assert!(
        before.comments == after.comments,
        "{name}: a comment changed"
    );
    assert_eq!(
        landings(name, source),
        landings(name, &once),
        "{name}: a jump lands elsewhere"
    );
}

fn every_program() -> Vec<(String, Vec<u8>)> {
    let mut files = support::own_inputs();
    files.extend(support::corpus_files());
    files
        .into_iter()
        .filter(|p| {
            // Archives are formatted member by member (tests below).
            !p.extension().is_some_and(|e| e.eq_ignore_ascii_case("arc"))
                && !p
                    .extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case("snap"))
        })
        .map(|p| {
            let bytes = std::fs::read(&p).expect("readable");
            (p.to_string_lossy().into_owned(), bytes)
        })
        .collect()
}

/// The settings every program is formatted under: the defaults, every
/// other layout and case, and renumbering with two steps.
fn settings_to_try() -> [Settings; 4] {
    [
        Settings::default(),
        Settings {
            indent: "\t".to_string(),
            case: Case::Lower,
            case_names: true,
            max_blank_lines: 0,
            indent_proc_body: false,
            ..Settings::default()
        },
        Settings {
            renumber: Some((10, 10)),
            ..Settings::default()
        },
        Settings {
            renumber: Some((1, 1)),
            case: Case::Keep,
            ..Settings::default()
        },
    ]
}

#[test]
fn every_program_formats_idempotently_and_means_what_it_meant() {
    let programs = every_program();
    assert!(programs.len() > 100, "{} programs", programs.len());
    let settings = settings_to_try();
    let mut changed = 0;
    for (name, source) in &programs {
        for settings in &settings {
            assert_formats_safely(name, source, settings);
        }
        changed += usize::from(formatted(name, source, &settings[0]).0 != *source);
    }
    // The test is worth something only if formatting changed programs.
    assert!(changed > 20, "only {changed} programs changed");
}

#[test]
fn random_programs_format_idempotently() {
    // Blocks of every kind, nested, in random case and spacing.
    let pieces = [
        "IF R1==1",
        "ENDIF",
        "ELSE",
        "WHILE R2<3",
        "ENDWHILE",
        "FOR R3=1 TO 3",
        "ENDFOR",
        "LOOP",
        "ENDLOOP",
        "REPEAT",
        "UNTIL R1>2",
        "g1 x10  y20",
        "GOTOF N30",
        "GOTOB LBL",
        "LBL:",
        "msg(\"a  b\")",
        "; a comment  ",
        "",
        "   ",
        "n30 m3",
        "CASE R1 OF 1 GOTOF N30 DEFAULT GOTOF LBL",
        "DEF REAL _X",
        "$p_uifr[1]=ctrans(x,1)",
        "REPEAT LBL N30 P=2",
        "M30",
        "G0 Z5 ;*RO*",
    ];
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = |n: usize| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % n as u64) as usize
    };
    let mut formatted_rounds = 0;
    for round in 0..400 {
        let mut text = String::new();
        for row in 0..(5 + next(30)) {
            let piece = pieces[next(pieces.len())];
            if next(3) == 0 {
                text.push_str(&format!("N{} ", 10 * (row + 1)));
            }
            text.push_str(&" ".repeat(next(3)));
            text.push_str(piece);
            text.push_str(["\n", "\r\n", "  \n"][next(3)]);
        }
        let settings = Settings {
            renumber: (round % 2 == 0).then_some((100, 5)),
            ..Settings::default()
        };
        let name = format!("random{round}.mpf");
        assert_formats_safely(&name, text.as_bytes(), &settings);
        formatted_rounds +=
            usize::from(formatted(&name, text.as_bytes(), &settings).0 != text.as_bytes());
    }
    assert!(formatted_rounds > 200, "{formatted_rounds} of 400 changed");
}

#[test]
fn formats() {
    insta::glob!("fixtures/format/*.mpf", |path| {
        let source = std::fs::read(path).expect("fixture");
        let relative = path
            .strip_prefix(env!("CARGO_MANIFEST_DIR"))
            .expect("inside the repo")
            .to_string_lossy()
            .into_owned();
        let first = String::from_utf8_lossy(&source)
            .lines()
            .next()
            .unwrap_or_default()
            .to_string();
        let extra: Vec<&str> = first
            .strip_prefix("; args:")
            .map(|a| a.split_whitespace().collect())
            .unwrap_or_default();
        let mut args = vec!["fmt", "-"];
        args.extend(extra.iter().copied());
        let output = run(&args, &source);
        let snapshot = format!(
            "## Arguments\n{}\n## Exit status\n{}\n## Notes\n{}\n## Formatted\n{}",
            extra.join(" "),
            output.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&output.stderr).replace("<stdin>", &relative),
            String::from_utf8_lossy(&output.stdout)
        );
        insta::assert_snapshot!(snapshot);
    });
}

#[test]
fn formatted_samples() {
    for sample in ["PROBE_ALIGN.MPF", "PAPER_EXAMPLE3.MPF", "HEAD_DEF.SPF"] {
        let path = format!("samples/{sample}");
        let output = run(&["fmt", "--diff", &path], b"");
        assert_exit(&output, 0);
        insta::assert_snapshot!(sample, String::from_utf8_lossy(&output.stdout));
    }
}

/// `case-names`: the user's names take the case too (the control ignores
/// it); by default they stay as written. Strings and comments never change.
#[test]
fn user_names_take_the_case_only_when_asked() {
    let source = b"def real _depth=1 ; _depth\nproc_a:\n_depth=_depth+1\nif _depth<3 gotob proc_a\nmy_sub(\"_depth\")\nm30\n";
    let (kept, _) = formatted("A.MPF", source, &Settings::default());
    assert_eq!(
        String::from_utf8_lossy(&kept),
        "DEF REAL _depth=1 ; _depth\nproc_a:\n_depth=_depth+1\nIF _depth<3 GOTOB proc_a\nmy_sub(\"_depth\")\nM30\n"
    );
    let names = Settings {
        case_names: true,
        ..Settings::default()
    };
    let (upper, _) = formatted("A.MPF", source, &names);
    assert_eq!(
        String::from_utf8_lossy(&upper),
        "DEF REAL _DEPTH=1 ; _depth\nPROC_A:\n_DEPTH=_DEPTH+1\nIF _DEPTH<3 GOTOB PROC_A\nMY_SUB(\"_depth\")\nM30\n"
    );
}

/// Indentation is bounded: 20,000 nested IFs come out about as large as
/// they went in, every line indented at most 16 levels.
#[test]
fn indentation_is_capped() {
    let depth = 20_000;
    let mut source = String::new();
    for _ in 0..depth {
        source.push_str("IF R1>0\n");
    }
    source.push_str("R2=1\n");
    for _ in 0..depth {
        source.push_str("ENDIF\n");
    }
    source.push_str("M30\n");
    let settings = Settings::default();
    let (out, _) = formatted("DEEP.MPF", source.as_bytes(), &settings);
    let widest = settings.indent.len() * 16;
    for line in out.split(|&b| b == b'\n') {
        let indent = line.iter().take_while(|&&b| b == b' ').count();
        assert!(indent <= widest, "{indent} blanks");
    }
    assert!(out.len() <= source.len() + (2 * depth + 2) * widest);
    let (twice, _) = formatted("DEEP.MPF", &out, &settings);
    assert_eq!(twice, out, "not idempotent");
}

/// A block the control takes (at most 512 characters) is never indented
/// past that: it is indented less, or left as it is.
#[test]
fn no_block_is_indented_past_the_control_s_length() {
    for length in [500, 508, 510, 512] {
        let start = if length % 2 == 1 { "R1=11" } else { "R1=1" };
        let long = format!("{start}{}", "+1".repeat((length - start.len()) / 2));
        assert_eq!(long.len(), length);
        let source = format!("IF R2>0\nIF R3>0\n{long}\nENDIF\nENDIF\nM30\n");
        let (out, _) = formatted("LONG.MPF", source.as_bytes(), &Settings::default());
        for line in String::from_utf8(out).expect("utf-8").lines() {
            assert!(line.chars().count() <= 512, "{} characters", line.len());
        }
    }
}

/// `--renumber` counts the numbers it changes, not the numbered blocks:
/// numbering a program as it is numbered changes nothing and says so.
#[test]
fn renumbering_counts_only_the_numbers_it_changes() {
    let source = b"N10 G1 X1 F100\nN20 GOTOB N10\nN30 M30\n";
    let settings = Settings {
        renumber: Some((10, 10)),
        ..Settings::default()
    };
    let kind = program_kind(Some("SAME.MPF"), source);
    let result = format("SAME.MPF", source, kind, &settings);
    assert!(result.edits.is_empty(), "{:?}", result.edits);
    assert_eq!(result.renumbered, 0);
    assert!(result.notes.is_empty(), "{:?}", result.notes);
    let settings = Settings {
        renumber: Some((10, 5)),
        ..settings
    };
    let result = format("SAME.MPF", source, kind, &settings);
    assert_eq!(result.renumbered, 2, "N20 and N30 change, N10 stays");
}

/// A block too long to read (S009) after the program's end keeps its
/// bytes: renumbering the others would leave its number out of order, so
/// the file is not renumbered, and says why.
#[test]
fn a_block_too_long_to_read_stops_renumbering() {
    let long = format!("N92581 R1={}1", "1+".repeat(40_000));
    let source = format!("N10 G1 X1 F100\nN20 M30\n{long}\n");
    let settings = Settings {
        renumber: Some((100, 10)),
        ..Settings::default()
    };
    let (out, notes) = formatted("LONG.MPF", source.as_bytes(), &settings);
    assert_eq!(out, source.as_bytes());
    assert!(
        notes.iter().any(|n| n.contains("too long to read (S009)")),
        "{notes:?}"
    );
}

/// Trailing comments aligned in a column stay aligned: the blanks before a
/// comment are kept as they were.
#[test]
fn aligned_trailing_comments_stay_aligned() {
    let source = b"G0 SUPA Z0        ; retract\nG0 X0 Y0          ; home\nM30\n";
    let (out, _) = formatted("ALIGNED.MPF", source, &Settings::default());
    assert_eq!(out, source);
}

/// The rows the HMI writes and reads back, as the Siemens HMI marks them:
/// a line holding one of its markers; a contour section from its dialog
/// tag `;#7__DlgK` to its `;#End` line, with the `E_LAB_A_`/`E_LAB_E_`
/// labels around it; a screen's generated code from `;NCG#` to `;#END#`
/// (either section running to the file's end when its last line is
/// missing).
fn hmi_rows(lines: &[&[u8]]) -> Vec<bool> {
    let has = |line: &[u8], marker: &[u8]| line.windows(marker.len()).any(|w| w == marker);
    let markers: [&[u8]; 7] = [
        b"*RO*",
        b"*GP*",
        b"*HD*",
        b";#SM",
        b";NCG#",
        b";CON,",
        b"Don't change",
    ];
    let label = |line: &[u8], prefix: &[u8]| {
        let line = line.trim_ascii();
        line.starts_with(prefix) && line.ends_with(b":")
    };
    let mut owned: Vec<bool> = lines
        .iter()
        .map(|line| line.contains(&b';') && markers.iter().any(|m| has(line, m)))
        .collect();
    let mut row = 0;
    while row < lines.len() {
        let sections: [(&[u8], &[u8]); 2] = [(b";#7__DlgK", b";#End"), (b";NCG#", b";#END#")];
        let Some(&(_, end)) = sections.iter().find(|(begin, _)| has(lines[row], begin)) else {
            row += 1;
            continue;
        };
        let contour = end != b";#END#";
        if contour && row > 0 && label(lines[row - 1], b"E_LAB_A_") {
            owned[row - 1] = true;
        }
        let last = (row + 1..lines.len())
            .find(|&r| has(lines[r], end))
            .unwrap_or(lines.len() - 1);
        owned[row..=last].fill(true);
        if contour && lines.get(last + 1).is_some_and(|l| label(l, b"E_LAB_E_")) {
            owned[last + 1] = true;
        }
        row = last + 1;
    }
    owned
}

/// No byte of a region the HMI generated and reads back changes, under any
/// settings, in any sample, fixture or program of the outside corpus: no
/// edit touches a line of one.
#[test]
fn no_byte_of_an_hmi_region_changes() {
    let settings = settings_to_try();
    let mut region_rows = 0;
    let mut changed_beside_regions = 0;
    for (name, source) in every_program() {
        let lines: Vec<_> = sinuprep::syntax::lines::raw_lines(&source).collect();
        let contents: Vec<&[u8]> = lines.iter().map(|l| l.content.of(&source)).collect();
        let owned = hmi_rows(&contents);
        let rows_owned = owned.iter().filter(|&&o| o).count();
        if rows_owned == 0 {
            continue;
        }
        region_rows += rows_owned;
        let starts: Vec<usize> = lines.iter().map(|l| l.content.start).collect();
        let row_of = |at: usize| starts.partition_point(|&s| s <= at).saturating_sub(1);
        let kind = program_kind(Some(&name), &source);
        for settings in &settings {
            let result = format(&name, &source, kind, settings);
            for edit in &result.edits {
                let last = edit.span.end.max(edit.span.start + 1) - 1;
                for row in row_of(edit.span.start)..=row_of(last) {
                    assert!(
                        !owned[row],
                        "{name}: line {} of an HMI region changed: {:?} -> {:?}",
                        row + 1,
                        String::from_utf8_lossy(contents[row]),
                        String::from_utf8_lossy(&edit.text)
                    );
                }
            }
            changed_beside_regions += usize::from(!result.edits.is_empty());
        }
    }
    // Worth something only where there are regions and lines beside them
    // that do change.
    assert!(region_rows > 20, "{region_rows} rows in HMI regions");
    assert!(changed_beside_regions > 3, "{changed_beside_regions}");
}

/// Formatting a range of lines gives exactly the edits formatting the whole
/// program gives on those lines, under several settings, for ranges of one
/// line and of a third of the program in every sample, fixture and corpus
/// program: the lines before a range carry their levels, the program's end
/// and the blank lines in a row over to it.
#[test]
fn a_range_is_formatted_as_the_whole_program_formats_it() {
    let settings = settings_to_try();
    let mut compared = 0;
    for (name, source) in every_program() {
        let starts: Vec<usize> = sinuprep::syntax::lines::raw_lines(&source)
            .map(|l| l.content.start)
            .collect();
        let row_of = |at: usize| starts.partition_point(|&s| s <= at).saturating_sub(1);
        let kind = program_kind(Some(&name), &source);
        let count = starts.len();
        for settings in &settings {
            let whole = format(&name, &source, kind, settings).edits;
            let step = (count / 40).max(1);
            let mut ranges: Vec<std::ops::Range<usize>> =
                (0..count).step_by(step).map(|row| row..row + 1).collect();
            ranges.push(count / 3..2 * count / 3);
            for rows in ranges {
                let expected: Vec<_> = whole
                    .iter()
                    .filter(|edit| rows.contains(&row_of(edit.span.start)))
                    .collect();
                let ranged = format_rows(&name, &source, kind, settings, rows.clone()).edits;
                assert_eq!(
                    ranged.iter().collect::<Vec<_>>(),
                    expected,
                    "{name}, lines {rows:?}"
                );
                compared += 1;
            }
        }
    }
    assert!(compared > 1000, "{compared}");
}
