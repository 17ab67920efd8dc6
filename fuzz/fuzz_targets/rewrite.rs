//! Rewriting never panics, in every form; its diagnostics render; its output
//! parses with no new syntax error; rewriting it again changes nothing; and
//! every line of the input that does not mention CYCLE600 is still there, in
//! order (lines as the tool splits them: LF, CRLF, or a lone CR).
#![no_main]

use libfuzzer_sys::fuzz_target;
use sinuprep::emit::apply;
use sinuprep::cli::render::{human, FileReport};
use sinuprep::emit::cycle600::{rewrite, Form, Options};
use sinuprep::semantic::{analyze, Heads, Model, Supplied};
use sinuprep::syntax::lines::raw_lines;
use sinuprep::syntax::parse;

fn run(source: &[u8], heads: &Heads, options: &Options) -> Vec<u8> {
    let model = Model::of(source);
    let analysis = analyze(&model, &Supplied::default(), Some(heads));
    let rewrite = rewrite(&model, &analysis, options);
    let report = FileReport {
        name: "FUZZ.MPF",
        source,
        diagnostics: &rewrite.diagnostics,
    };
    human(&report, false, &mut String::new());
    apply(source, &rewrite.edits)
}

fuzz_target!(|data: &[u8]| {
    let heads = Heads::read(
        "HEAD_DEF".into(),
        b"_HEAD_NAME=\"UFK600\"\n_HEAD_ALLOWED=1\n",
    );
    let forms = [Form::Cycle800, Form::Frames, Form::Traori];
    let options = forms.into_iter().flat_map(|form| {
        [
            Options {
                form,
                ..Options::default()
            },
            Options {
                form,
                runtime: Some(None),
                inline_results: true,
                ..Options::default()
            },
        ]
    });
    for options in options {
        let once = run(data, &heads, &options);
        assert!(
            parse(&once).diagnostics.len() <= parse(data).diagnostics.len(),
            "syntax error added"
        );
        assert!(run(&once, &heads, &options) == once, "not idempotent");
        // Lines as the tool sees them: LF, CRLF and a lone CR all end one.
        let output_lines: Vec<&[u8]> = raw_lines(&once).map(|l| l.content.of(&once)).collect();
        let mut at = 0;
        for line in raw_lines(data).map(|l| l.content.of(data)) {
            let mentions = line.windows(8).any(|w| w.eq_ignore_ascii_case(b"CYCLE600"));
            let inline = line.windows(8).any(|w| w.eq_ignore_ascii_case(b"_CYC600_"));
            if mentions || inline {
                continue;
            }
            match output_lines[at..].iter().position(|o| *o == line) {
                Some(found) => at += found + 1,
                None => panic!("line lost: {:?}", String::from_utf8_lossy(line)),
            }
        }
    }
});
