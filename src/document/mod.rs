//! The library's front door: one program in, what sinuprep finds in it and
//! writes for it out. The command line and an editor's server call these,
//! so both report the same findings from the same analysis.

pub mod archive;
pub mod fixes;
pub mod held;
pub mod text;

use crate::diagnostic::{Diagnostic, Severity};
use crate::emit::cycle600::{rewrite_on, Form, Rewrite};
pub use crate::lint::Analyzed;
use crate::lint::{self, Settings};
use crate::semantic::swivels;
use crate::semantic::{analyze, Analysis, CallSite, Model};
use crate::syntax::{program_kind, ProgramKind};

/// A program: its name (a path, `<stdin>`, an editor's URI) and its bytes.
pub struct Document<'src> {
    pub name: &'src str,
    pub source: &'src [u8],
    pub kind: ProgramKind,
}

/// What a rewrite makes of a program.
pub struct Rewritten<'src> {
    /// The model the rewrite read, for other questions about the same
    /// program (`eval`'s CYCLE800 calls), its syntax errors moved to
    /// `diagnostics`; `None` for a program that never names CYCLE600, which
    /// only the streaming syntax pass reads.
    pub model: Option<Model<'src>>,
    /// How each CYCLE600 call evaluated.
    pub analysis: Analysis,
    /// The edits, and the calls rewritten and refused.
    pub rewrite: Rewrite,
    /// Syntax errors, the HEAD_DEF note, and every refusal or warning, in
    /// source order.
    pub diagnostics: Vec<Diagnostic>,
}

impl Rewritten<'_> {
    pub fn has_errors(&self) -> bool {
        self.diagnostics
            .iter()
            .any(|d| d.severity == Severity::Error)
    }
}

impl<'src> Document<'src> {
    /// The program `name` holds, its kind read from its name and first blocks.
    pub fn new(name: &'src str, source: &'src [u8]) -> Self {
        Self {
            name,
            source,
            kind: program_kind(Some(name), source),
        }
    }

    /// Everything `check` reports, in source order, with what could not be
    /// checked.
    pub fn check_outcome(&self, settings: &Settings) -> lint::Outcome {
        lint::check_outcome(self.source, self.name, self.kind, settings)
    }

    /// [`Self::check_outcome`], keeping what the analysis built: the model, the
    /// CYCLE600 walk's results and the findings with their fixes, for the
    /// questions an editor asks after the findings.
    pub fn analyze(&self, settings: &Settings) -> Analyzed<'src> {
        lint::analyze_program(self.source, self.name, self.kind, settings)
    }

    /// The model and the CYCLE600 walk's results (`None` for a program that
    /// never names CYCLE600), without the rules: what the questions about
    /// names and calls read (an editor's hover, definition, symbols).
    pub fn model_and_walk(&self, settings: &Settings) -> (Model<'src>, Option<Analysis>) {
        model_and_walk(self.source, self.kind, settings)
    }

    /// The CYCLE600 calls rewritten as `settings.emit` asks, with the
    /// measured values and HEAD_DEF of `settings`.
    pub fn rewrite(&self, settings: &Settings) -> Rewritten<'src> {
        // A program that never names CYCLE600 has nothing to rewrite: it
        // needs only the streaming syntax pass, not its trees in memory.
        let macros = &settings.environment.expansions;
        if !crate::semantic::mentions_cycle600(self.source) {
            // Macros (the machine's, or the program's own DEFINEs) change
            // what a line reads as: such a program is read with them.
            let diagnostics = if macros.is_empty() && !defines_macros(self.source) {
                crate::syntax::diagnostics(self.source)
            } else {
                let model = Model::build_with(self.source, self.kind, macros.clone());
                annotated(model.syntax, &model.macro_uses, self.source)
            };
            return Rewritten {
                model: None,
                analysis: Analysis::default(),
                rewrite: Rewrite::default(),
                diagnostics,
            };
        }
        // One parse for the syntax diagnostics, the walk and the rewrite.
        let (mut model, analysis) = self.model_and_walk(settings);
        let analysis = analysis.unwrap_or_default();
        let heads = settings.heads.as_ref();
        let machine = settings.machine.as_deref();
        let mut rewrite = rewrite_on(&model, &analysis, &settings.emit, machine);
        if let Some(on) = &settings.machine {
            let comments = crate::emit::axes::comments(self.source, &analysis, &rewrite.edits, on);
            rewrite.edits.extend(comments);
        }
        let mut diagnostics = std::mem::take(&mut model.syntax);
        if heads.is_none() && !analysis.calls.is_empty() {
            diagnostics.push(crate::semantic::head_def::not_found());
        }
        diagnostics.extend(rewrite.diagnostics.iter().cloned());
        if let Some(on) = settings
            .machine
            .as_deref()
            .filter(|_| settings.emit.form == Form::Cycle800)
        {
            // What the machine makes of each CYCLE800 written, as `check
            // --machine` says it of the call: a rewrite does not hand the
            // control a swivel its record cannot reach without saying so.
            let written = |site: &&CallSite| {
                rewrite.edits.iter().any(|edit| {
                    edit.span.start <= site.statement.start && site.statement.end <= edit.span.end
                })
            };
            let asked = analysis
                .calls
                .iter()
                .filter(written)
                .filter_map(swivels::of_cycle600);
            diagnostics.extend(asked.flat_map(|asked| swivels::findings(&asked, on)));
        }
        diagnostics.sort_by_key(|d| (d.span.start, d.code()));
        let diagnostics = annotated(diagnostics, &model.macro_uses, self.source);
        Rewritten {
            model: Some(model),
            analysis,
            rewrite,
            diagnostics,
        }
    }
}

/// A file's or member's name as text output prints it: its control
/// characters escaped as Rust writes them (`\n`, `\u{1b}`), so that a
/// name holding a line break cannot print a line of its own (which GitHub
/// Actions or a problem matcher would read as a finding) and one holding an
/// escape sequence cannot drive the terminal. Every text format and message
/// naming a file goes through it; JSON and SARIF escape them as JSON does.
pub fn printable(name: &str) -> std::borrow::Cow<'_, str> {
    if !name.chars().any(char::is_control) {
        return std::borrow::Cow::Borrowed(name);
    }
    let mut out = String::with_capacity(name.len() + 8);
    for c in name.chars() {
        if c.is_control() {
            out.extend(c.escape_debug());
        } else {
            out.push(c);
        }
    }
    std::borrow::Cow::Owned(out)
}

/// [`Document::model_and_walk`] of `source`, read as a program of `kind`.
pub(crate) fn model_and_walk<'src>(
    source: &'src [u8],
    kind: ProgramKind,
    settings: &Settings,
) -> (Model<'src>, Option<Analysis>) {
    let macros = settings.environment.expansions.clone();
    let model = Model::build_with(source, kind, macros);
    let walk = crate::semantic::mentions_cycle600(source)
        .then(|| analyze(&model, &settings.supplied, settings.heads.as_ref()));
    (model, walk)
}

/// Whether `source` may define a macro of its own (`DEFINE`, in capitals
/// or in lower case): a byte search.
fn defines_macros(source: &[u8]) -> bool {
    crate::syntax::WordFinder::new("DEFINE").in_line(source)
}

/// `diagnostics`, those at a macro's use saying what it expanded to.
fn annotated(
    mut diagnostics: Vec<Diagnostic>,
    uses: &[crate::syntax::macros::Use],
    source: &[u8],
) -> Vec<Diagnostic> {
    for diagnostic in &mut diagnostics {
        crate::syntax::macros::annotate(diagnostic, uses, source);
    }
    diagnostics
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An editor's server answers requests on several threads from one
    /// analysis: the model, its line table included, reads alike from each.
    #[test]
    fn one_analysis_answers_on_several_threads() {
        let mut text = String::from("DEF REAL _A\nSTART:\n");
        for n in 0..2_000 {
            text.push_str(&format!("IF R{n}>0\nG1 X{n} F100\nENDIF\n"));
        }
        text.push_str("GOTOB START\nM30\n");
        let document = Document::new("SHARED.MPF", text.as_bytes());
        let analyzed = document.analyze(&Settings::default());
        let expected: Vec<&str> = text.lines().collect();
        let lines = &analyzed.model.lines;
        assert_eq!(lines.len(), expected.len());
        std::thread::scope(|scope| {
            for (step, first) in [(1, 0), (7, 3), (13, 5)] {
                let (expected, text) = (&expected, &text);
                scope.spawn(move || {
                    // Each thread goes its own way, moving the shared
                    // cursor under the others' feet.
                    for round in 0..3 {
                        let mut row = (first + round) % expected.len();
                        for _ in 0..expected.len() {
                            let content = lines.raw(row).content;
                            assert_eq!(&text[content.start..content.end], expected[row]);
                            row = (row + step) % expected.len();
                        }
                    }
                });
            }
        });
        assert!(analyzed.model.labels.any_within(0..text.len()));
    }
}
