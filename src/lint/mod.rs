//! The linter: syntax errors, CYCLE600 findings from the walk, and the
//! general NC rules, each rule in its own file under `rules/`.
//!
//! One pass over the lines builds the program's model
//! ([`crate::semantic::model`]) and shows each line to the rules: a plain
//! line (address words with numbers, most of a CAM program) is read by a byte
//! scan and shown only to the few rules that learn from it; every other line
//! is parsed once and handed to every selected rule. The rules finish on the
//! complete model, and the CYCLE600 walk, for programs that mention CYCLE600,
//! runs on it without parsing again. It reports diagnostics; printing them is the CLI's job.

pub(crate) mod codes;
mod dispatch;
pub mod fix;
pub mod readers;
pub mod reference;
pub mod rule;
pub mod rules;
pub(crate) mod suppression;

use crate::diagnostic::{Applicability, Diagnostic, Fix, RuleInfo, Severity};
use crate::edit::Edit;
use crate::emit::cycle600::{call_edits, Form, Options};
use crate::lint::dispatch::Checkers;
use crate::lint::rule::{Check, Checking, FileContext, InLineOrder, LineView, PlainLine};
use crate::lint::rules::{undefined_variable, unused_suppression};
use crate::lint::suppression::Suppressions;
use crate::registry::{
    axis_beyond_limit, cycle600_rewritable, invalid_swivel_data, unreadable_machine_data,
};
use crate::semantic::environment::holds_machine_data;
use crate::semantic::machine::{Machine, Reading};
use crate::semantic::model::ModelBuilder;
use crate::semantic::swivels::{self, OnMachine};
pub use crate::semantic::walk::Stop;
use crate::semantic::{analyze, Analysis, CallSite, Environment, Heads, Model, Supplied};
use crate::syntax::ahead::{self, Read, ReadLines};
use crate::syntax::plain::PlainScanner;
use crate::syntax::tree::LineKind;
use crate::syntax::ProgramKind;

/// Which findings to report.
#[derive(Clone, Debug)]
pub struct Selection {
    /// Codes or code prefixes (`N`, `C6`, `N005`); empty selects all.
    pub select: Vec<String>,
    pub ignore: Vec<String>,
    pub severity_min: Severity,
}

impl Default for Selection {
    fn default() -> Self {
        Self {
            select: Vec::new(),
            ignore: Vec::new(),
            severity_min: Severity::Info,
        }
    }
}

/// Rules that run only when `--select` (or `select` in sinuprep.toml) names
/// their code in full: N015, since the control ignores case and users of
/// other Sinumerik tools do not want case findings unasked; C619, since a
/// program that keeps CYCLE600 for the control is not wrong.
pub static OFF_BY_DEFAULT: [&RuleInfo; 2] =
    [&rules::inconsistent_case::RULE, &cycle600_rewritable::RULE];

/// Whether `code` is a rule that runs only when selected by its full code.
pub fn off_by_default(code: &str) -> bool {
    OFF_BY_DEFAULT
        .iter()
        .any(|rule| rule.code.eq_ignore_ascii_case(code))
}

impl Selection {
    pub fn enables(&self, code: &str) -> bool {
        let matches = |list: &[String]| list.iter().any(|p| code.starts_with(p.as_str()));
        let selected = if off_by_default(code) {
            self.select.iter().any(|p| p.eq_ignore_ascii_case(code))
        } else {
            self.select.is_empty() || matches(&self.select)
        };
        selected && !matches(&self.ignore)
    }
}

/// What a program is checked with besides its text.
#[derive(Clone, Debug, Default)]
pub struct Settings {
    pub selection: Selection,
    /// Measured values, for the CYCLE600 walk.
    pub supplied: Supplied,
    /// HEAD_DEF, for the CYCLE600 walk.
    pub heads: Option<Heads>,
    /// Names the machine defines: axes, GUD globals, macros.
    pub environment: Environment,
    /// How rewritten code is written: by `rewrite`, and by C619's fix.
    pub emit: Options,
    /// The machine the swivels are solved on (K002-K005); shared by the
    /// programs of a run.
    pub machine: Option<std::sync::Arc<OnMachine>>,
    /// The file is swivel data, not a program: the machine file (`--machine`,
    /// `machine =`) or an archive's data member. Its `$TC_CARR` assignments
    /// are then the records the control holds, checked as such (K001); in a
    /// program they are run-time writes, whose values may be anything.
    pub swivel_data: bool,
}

/// Where `check` reports a rule at another severity than its own, how: a
/// CYCLE600 argument known only on the machine is no error for the linter
/// (the rewrite computes it on the control), and GOTOC goes on without an
/// alarm where its label is missing.
pub fn severity_in_check(rule: &RuleInfo) -> Option<&'static str> {
    if rule == &crate::registry::cycle600_unknown_argument::RULE {
        Some("info in check; rewrite refuses the call unless --emit-runtime")
    } else if rule == &rules::undefined_label::RULE {
        Some("a warning for GOTOC")
    } else {
        None
    }
}

/// The documentation of `code`, if it is one.
/// The documentation of the rule `code` names: its code or its name
/// (`N005`, `undefined-variable`), in any case.
pub fn rule(code: &str) -> Option<&'static RuleInfo> {
    rules::all()
        .into_iter()
        .map(|r| r.info)
        .find(|info| info.code.eq_ignore_ascii_case(code) || info.name.eq_ignore_ascii_case(code))
}

/// The code or name of a rule nearest `word`, for a did-you-mean.
pub fn nearest_rule(word: &str) -> Option<&'static str> {
    let infos: Vec<&'static RuleInfo> = rules::all().into_iter().map(|r| r.info).collect();
    let names = infos.iter().flat_map(|info| [info.code, info.name]);
    crate::suggest::closest(word, names.collect::<Vec<_>>().iter().copied(), 3)
}

/// Everything `check` reports for one program, in source order.
pub fn check(source: &[u8], name: &str, kind: ProgramKind, settings: &Settings) -> Vec<Diagnostic> {
    check_with(PlainScanner::Scan, source, name, kind, settings)
}

/// What `check` found in one program, and what it could not check there.
#[derive(Debug, Default)]
pub struct Outcome {
    /// In source order.
    pub diagnostics: Vec<Diagnostic>,
    /// Subprograms called that neither the program nor the environment
    /// declares (upper case, each once, sorted): their calls are unchecked.
    pub unresolved_calls: Vec<String>,
    /// Syntax errors on lines that write a name where an operator belongs
    /// (`(R1 _DEC2)`): read without the machine's macros, that name may be
    /// one.
    pub names_as_operators: usize,
}

/// One analysis of a program, everything it built kept: the model (lines,
/// labels, definitions, block structure), the CYCLE600 walk's results and
/// the findings with their fixes. The command line reports the findings and
/// drops the rest; an editor's server answers its questions from the rest.
pub struct Analyzed<'src> {
    pub model: Model<'src>,
    /// How each CYCLE600 call evaluated; `None` for a program that never
    /// names CYCLE600 (no walk runs).
    pub walk: Option<Analysis>,
    /// What `check` reports, in source order.
    pub findings: Vec<Diagnostic>,
    /// As [`Outcome::unresolved_calls`].
    pub unresolved_calls: Vec<String>,
    /// As [`Outcome::names_as_operators`].
    pub names_as_operators: usize,
}

impl From<Analyzed<'_>> for Outcome {
    fn from(analyzed: Analyzed) -> Self {
        Self {
            diagnostics: analyzed.findings,
            unresolved_calls: analyzed.unresolved_calls,
            names_as_operators: analyzed.names_as_operators,
        }
    }
}

/// [`check`], with what it could not check.
pub fn check_outcome(source: &[u8], name: &str, kind: ProgramKind, settings: &Settings) -> Outcome {
    analyze_with(LinePass::USUAL, source, name, kind, settings).into()
}

/// [`check`], keeping the model and the walk it built.
pub fn analyze_program<'src>(
    source: &'src [u8],
    name: &str,
    kind: ProgramKind,
    settings: &Settings,
) -> Analyzed<'src> {
    analyze_with(LinePass::USUAL, source, name, kind, settings)
}

/// [`analyze_program`], stopped as soon as `stop` says so: `None` then. It
/// is asked every few thousand lines, between the rules' last steps and
/// during the CYCLE600 walk; an editor's server stops the analysis of a
/// version of a document the user has changed since.
///
/// For one document the user waits on, the CYCLE600 walk is made on a
/// thread of its own while the line pass runs, on a model of its own
/// built from the same text: the walk needs the whole model, and would
/// otherwise wait for the rules' pass to end (a fifth of the analysis of
/// 75,000 hand-written lines). The command line does not: its files keep
/// every core busy already.
pub fn analyze_program_until<'src>(
    source: &'src [u8],
    name: &str,
    kind: ProgramKind,
    settings: &Settings,
    stop: Stop,
) -> Option<Analyzed<'src>> {
    let pass = LinePass::USUAL;
    let analyze =
        |walk: Walk| analyze_stopping(pass, source, name, kind, settings, Some(stop), walk);
    if !crate::semantic::mentions_cycle600(source) {
        return analyze(Walk::No);
    }
    std::thread::scope(|scope| {
        let aside = scope.spawn(|| {
            let macros = settings.environment.expansions.clone();
            let model = Model::build_with(source, kind, macros);
            walk_model(&model, settings, Some(stop))
        });
        analyze(Walk::Aside(aside))
    })
}

/// Where the line pass takes the CYCLE600 walk's analysis from.
enum Walk<'scope> {
    /// The program names no CYCLE600: no walk.
    No,
    /// The walk follows the line pass, on its model.
    Here,
    /// Made beside the line pass ([`analyze_program_until`]); `None` if stopped.
    Aside(std::thread::ScopedJoinHandle<'scope, Option<Analysis>>),
}

/// The CYCLE600 walk of `model`; `None` once `stop` says so.
fn walk_model(model: &Model, settings: &Settings, stop: Option<Stop>) -> Option<Analysis> {
    let (supplied, heads) = (&settings.supplied, settings.heads.as_ref());
    match stop {
        None => Some(analyze(model, supplied, heads)),
        Some(stop) => crate::semantic::walk::analyze_until(model, supplied, heads, stop),
    }
}

/// [`check`] with the plain-line scanner given: [`PlainScanner::ParseEveryLine`]
/// builds every line's tree, the reference the shortcut is tested against
/// (`tests/lint.rs`, the `check` fuzz target).
#[doc(hidden)]
pub fn check_with(
    scan_plain_line: PlainScanner,
    source: &[u8],
    name: &str,
    kind: ProgramKind,
    settings: &Settings,
) -> Vec<Diagnostic> {
    // The reference parses every line here, on the analysis's thread.
    let ahead = match scan_plain_line {
        PlainScanner::Scan => ReadAhead::WhenItPays,
        PlainScanner::ParseEveryLine => ReadAhead::Never,
    };
    let pass = LinePass {
        scan: scan_plain_line,
        ahead,
    };
    analyze_with(pass, source, name, kind, settings).findings
}

/// [`check`] with the lines read ahead on a thread of their own whatever
/// the program's size: tested against [`check_with`]'s reference
/// (`tests/lint.rs`, the `check` fuzz target).
#[doc(hidden)]
pub fn check_read_ahead(
    source: &[u8],
    name: &str,
    kind: ProgramKind,
    settings: &Settings,
) -> Vec<Diagnostic> {
    let pass = LinePass {
        scan: PlainScanner::Scan,
        ahead: ReadAhead::Always,
    };
    analyze_with(pass, source, name, kind, settings).findings
}

/// How the line pass reads the lines: which it parses, and where.
#[derive(Clone, Copy)]
struct LinePass {
    scan: PlainScanner,
    ahead: ReadAhead,
}

impl LinePass {
    /// Plain lines scanned, the lines read ahead where it pays.
    const USUAL: Self = Self {
        scan: PlainScanner::Scan,
        ahead: ReadAhead::WhenItPays,
    };
}

/// Whether the line pass reads the lines ahead, on a thread of its own
/// (see [`crate::syntax::ahead`]).
#[derive(Clone, Copy)]
enum ReadAhead {
    /// Where it [pays](ahead::pays).
    WhenItPays,
    Always,
    Never,
}

fn analyze_with<'src>(
    pass: LinePass,
    source: &'src [u8],
    name: &str,
    kind: ProgramKind,
    settings: &Settings,
) -> Analyzed<'src> {
    let walk = match crate::semantic::mentions_cycle600(source) {
        true => Walk::Here,
        false => Walk::No,
    };
    analyze_stopping(pass, source, name, kind, settings, None, walk)
        .expect("only a stop ends an analysis early")
}

/// Lines parsed between two questions to a [`Stop`] (plain lines: see
/// [`PlainRun::LINES`]).
const LINES_BETWEEN_STOPS: usize = 4096;

/// The checkers of the rules `selection` enables: each its own, the modal
/// rules one walk together.
fn checkers_of(selection: &Selection) -> Vec<Box<dyn Check>> {
    let mut own = Vec::new();
    let mut modal = Vec::new();
    for rule in rules::all() {
        if !selection.enables(rule.info.code) {
            continue;
        }
        match rule.checking {
            Checking::Own(make) => own.push(make()),
            Checking::InLineOrder(make) => modal.push(make()),
            Checking::Elsewhere => {}
        }
    }
    if !modal.is_empty() {
        own.push(Box::new(InLineOrder::new(modal)));
    }
    own
}

fn analyze_stopping<'src>(
    pass: LinePass,
    source: &'src [u8],
    name: &str,
    kind: ProgramKind,
    settings: &Settings,
    stop: Option<Stop>,
    walk: Walk,
) -> Option<Analyzed<'src>> {
    let stopped = || stop.is_some_and(|stop| stop());
    let Settings {
        selection,
        environment,
        ..
    } = settings;
    let file = FileContext::new(source, name, kind, environment);
    let mut checkers = Checkers::new(checkers_of(selection));
    let mut plain_run = PlainRun {
        lines: Vec::with_capacity(PlainRun::LINES),
    };
    let mut found = Vec::new();
    let mut suppressions = Suppressions::default();
    let keep_trees = !matches!(walk, Walk::No);
    let mut model =
        ModelBuilder::new(source, keep_trees).with_macros(environment.expansions.clone());
    // Asked again only after a line that is not plain (a DEFINE is none):
    // a CAM program's millions of plain lines pay a test of a local.
    let mut macros_reach_plain_lines = model.macros_reach_plain_lines();
    // The stop is asked where the line pass already branches: at each run
    // of plain lines given to the rules, and at a parsed line at least
    // LINES_BETWEEN_STOPS after the last question. A plain line pays nothing.
    // Read ahead: on a thread of its own, without macros (a DEFINE ends it),
    // and not where the trees are kept for the walk: those never go back to
    // the thread that made them, which then makes each in fresh memory, and
    // the pass reads each from the other core's cache (1 MB of hand-written
    // cycles with a CYCLE600: 1.19 times the wall time, 1.44 times the CPU).
    let ahead = match pass.ahead {
        ReadAhead::Never => false,
        ReadAhead::Always => true,
        ReadAhead::WhenItPays => !keep_trees && ahead::pays(source),
    } && environment.expansions.is_empty();
    let read = std::thread::scope(|scope| {
        let mut lines = match ahead {
            true => ReadLines::ahead(scope, source, pass.scan),
            false => ReadLines::here(source, pass.scan),
        };
        let mut row = 0;
        let mut next_stop = 0;
        while let Some(read) = lines.next() {
            let parsed = match read {
                Read::Handover(parser) => {
                    model.parse_on_with(parser);
                    continue;
                }
                Read::Plain(plain) if !(macros_reach_plain_lines && model.expands(plain.raw)) => {
                    // No syntax error, and only a few rules care: no tree to build.
                    let facts = plain.facts();
                    if let Some(comment) = plain.comment {
                        suppressions.read(source, row, comment);
                    }
                    plain_run.lines.push(PlainLine {
                        row,
                        raw: plain.raw,
                        facts,
                    });
                    row += 1;
                    if plain_run.lines.len() == PlainRun::LINES {
                        plain_run.give(&file, &mut model, &mut checkers, &mut found);
                        if stopped() {
                            return None;
                        }
                    }
                    continue;
                }
                Read::Plain(plain) => Err(plain.raw),
                Read::Other(raw) => Err(raw),
                Read::Parsed(tree, error) => Ok((tree, error)),
            };
            if row >= next_stop {
                if stopped() {
                    return None;
                }
                next_stop = row + LINES_BETWEEN_STOPS;
            }
            plain_run.give(&file, &mut model, &mut checkers, &mut found);
            let tree = match parsed {
                Ok((tree, error)) => model.parsed(tree, error),
                Err(raw) => model.parse(raw),
            };
            if let LineKind::Block(block) = &tree.kind {
                if let Some(comment) = block.comment {
                    suppressions.read(source, row, comment);
                }
            }
            let view = LineView::new(&tree);
            model.learn(&view);
            macros_reach_plain_lines = model.macros_reach_plain_lines();
            checkers.line(&file, row, &view, &mut found);
            if let Some(spent) = model.keep(tree) {
                lines.spent(spent);
            }
            row += 1;
        }
        Some(())
    });
    read?;
    plain_run.give(&file, &mut model, &mut checkers, &mut found);
    file.complete(model.finish(kind));
    let model = file.model();
    found.extend(model.syntax.iter().cloned());
    if !checkers.finish(&file, &mut found, stopped) {
        return None;
    }
    let analysis = match walk {
        Walk::No => None,
        Walk::Here => Some(walk_model(model, settings, stop)?),
        Walk::Aside(walked) => {
            let walked = walked.join();
            Some(walked.unwrap_or_else(|panic| std::panic::resume_unwind(panic))?)
        }
    };
    if stopped() {
        return None;
    }
    if let Some(analysis) = &analysis {
        found.extend(cycle600_findings(model, analysis, settings));
    }
    if let Some(on) = &settings.machine {
        found.extend(swivel_findings(model, analysis.as_ref(), on));
        // The dry run on the machine: the software limits the program's own
        // blocks pass, as `sinuprep run` finds them.
        if selection.enables(axis_beyond_limit::RULE.code) && !file.definition_file {
            if stopped() {
                return None;
            }
            found.extend(crate::run::on_machine::limit_findings(
                model,
                on,
                &settings.supplied,
            ));
        }
    }
    if selection.enables(unreadable_machine_data::RULE.code)
        && (file.definition_file || holds_machine_data(source))
    {
        // The syntax errors of its lines are the model's, reported above.
        let data = crate::machine::MachineData::read(source).diagnostics;
        found.extend(
            data.into_iter()
                .filter(|d| d.is(&unreadable_machine_data::RULE)),
        );
    }
    if settings.swivel_data && selection.enables(invalid_swivel_data::RULE.code) {
        // The syntax errors of its lines are the model's, reported above.
        let records = Machine::read(source, Reading::default()).diagnostics;
        found.extend(
            records
                .into_iter()
                .filter(|d| d.is(&invalid_swivel_data::RULE)),
        );
    }

    let mut kept: Vec<Diagnostic> = found
        .into_iter()
        .filter(|d| selection.enables(d.code()) && d.severity >= selection.severity_min)
        .filter(|d| !suppressions.covers(d, || model.lines.row_of(d.span.start)))
        .collect();
    if selection.enables(unused_suppression::RULE.code)
        && unused_suppression::RULE.severity >= selection.severity_min
    {
        kept.extend(suppressions.unused(source, |code| selection.enables(code)));
    }
    kept.sort_by_key(|d| (d.span.start, d.code()));
    one_finding_per_cause(&mut kept, &model.labels);
    if !model.macro_uses.is_empty() {
        // An undefined name (N005) on exactly a macro's name: the spans of an
        // expansion map to the macro's name, which the rule took for a
        // variable. Findings on what an expansion is (an ENDIF too many,
        // N004) stay.
        kept.retain(|d| {
            !(d.is(&undefined_variable::RULE)
                && crate::syntax::macros::is_a_macro_name(d.span, &model.macro_uses))
        });
        for diagnostic in &mut kept {
            crate::syntax::macros::annotate(diagnostic, &model.macro_uses, source);
        }
    }
    let names_as_operators = name_the_operators(&mut kept, source);
    if names_as_operators > 0 {
        kept.sort_by_key(|d| (d.span.start, d.code()));
    }
    let unresolved_calls = file.take_unresolved().into_iter().collect();
    Some(Analyzed {
        model: file.into_model(),
        walk: analysis,
        findings: kept,
        unresolved_calls,
        names_as_operators,
    })
}

/// A syntax error on a line that writes a name where an operator belongs
/// (`(R1 _DEC2)`) names it: read without the machine's macros, it may be
/// one. Gives how many lines do.
fn name_the_operators(found: &mut [Diagnostic], source: &[u8]) -> usize {
    let mut lines = 0;
    let mut last = None;
    for diagnostic in found.iter_mut().filter(|d| d.code().starts_with('S')) {
        let start = crate::span::line_start(source, diagnostic.span.start.min(source.len()));
        let end = crate::span::line_end(source, start);
        let Some(name) = crate::syntax::macros::name_in_operator_position(&source[start..end])
        else {
            continue;
        };
        if last.replace(start) != Some(start) {
            lines += 1;
        }
        let span = crate::span::Span::new(start + name.start, start + name.end);
        let text = String::from_utf8_lossy(span.of(source));
        diagnostic.message = format!(
            "`{text}` stands where an operator belongs ({}): it may be a macro of the machine, which sinuprep reads only from its definition files",
            diagnostic.message
        );
        diagnostic.span = span;
        diagnostic.label = "a name where an operator belongs".into();
        diagnostic.help = Some(format!("give the machine's macro definition files (`definitions`, --definitions MMAC.DEF), which define `{text}`; or write an operator here").into());
    }
    lines
}

/// The swivels of the program solved on the machine: its CYCLE800 calls
/// with constant arguments, and the CYCLE600 calls the walk evaluated.
fn swivel_findings(model: &Model, analysis: Option<&Analysis>, on: &OnMachine) -> Vec<Diagnostic> {
    let mut asked = swivels::cycle800_calls(model);
    if let Some(analysis) = analysis {
        asked.extend(analysis.calls.iter().filter_map(swivels::of_cycle600));
    }
    asked
        .iter()
        .flat_map(|asked| swivels::findings(asked, on))
        .collect()
}

/// Drops what another finding already says. Blocks after the program's
/// end that run on to the file's end (N027) leave the last block without
/// an end (N010): one cause, reported once, by N027, which points at the
/// first of them. A label after N027's block starts code a jump may reach,
/// whose missing end is N010's again.
fn one_finding_per_cause(kept: &mut Vec<Diagnostic>, labels: &crate::semantic::labels::Labels) {
    let after_end = &crate::lint::rules::block_after_program_end::RULE;
    let no_end = &crate::lint::rules::missing_program_end::RULE;
    let Some(first_after) = kept
        .iter()
        .rev()
        .find(|d| d.is(after_end))
        .map(|d| d.span.start)
    else {
        return;
    };
    kept.retain(|d| {
        !d.is(no_end) || d.span.end <= first_after || labels.any_within(first_after..d.span.end)
    });
}

/// Plain lines waiting to be given to the rules that watch them: a call per
/// run of lines, not per line (five calls a line were a sixth of `check`'s
/// work on a CAM program).
struct PlainRun {
    lines: Vec<PlainLine>,
}

impl PlainRun {
    /// Lines given at once, at most.
    const LINES: usize = crate::semantic::model::PLAIN_RUN;

    fn give(
        &mut self,
        file: &FileContext,
        model: &mut ModelBuilder,
        checkers: &mut Checkers,
        found: &mut Vec<Diagnostic>,
    ) {
        if self.lines.is_empty() {
            return;
        }
        model.plain_lines(&self.lines);
        checkers.plain_lines(file, &self.lines, found);
        self.lines.clear();
    }
}

/// The CYCLE600 walk's findings, as `check` reports them: an argument only
/// the machine knows is information here (the rewrite can compute it on the
/// control), not an error. When C619 is selected, each call the rewrite can
/// replace offline says so, with the rewrite's own edits as its fix.
fn cycle600_findings(model: &Model, analysis: &Analysis, settings: &Settings) -> Vec<Diagnostic> {
    let heads = settings.heads.as_ref();
    let mut out: Vec<Diagnostic> = analysis
        .calls
        .iter()
        .flat_map(|site| site.diagnostics.iter().cloned())
        .collect();
    for diagnostic in &mut out {
        if diagnostic.is(&crate::registry::cycle600_unknown_argument::RULE) {
            diagnostic.severity = Severity::Info;
        }
    }
    if heads.is_none() && !analysis.calls.is_empty() {
        out.push(crate::semantic::head_def::not_found());
    }
    if settings.selection.enables(cycle600_rewritable::RULE.code) {
        for site in &analysis.calls {
            if let Some(edits) =
                call_edits(model, site, &settings.emit, settings.machine.as_deref())
            {
                out.push(rewritable(site, edits, settings.emit.form));
            }
        }
    }
    out
}

/// C619 on a call the rewrite replaces with `edits`.
fn rewritable(site: &CallSite, edits: Vec<Edit>, form: Form) -> Diagnostic {
    let native = form.native();
    let title = format!("Rewrite as {native}");
    cycle600_rewritable::RULE
        .at(site.statement)
        .message(format!(
            "all arguments are known offline: this call can be written as {native} (`sinuprep rewrite`)"
        ))
        .label("rewritable")
        .fix(Fix {
            title,
            applicability: Applicability::Safe,
            edits,
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};

    /// An analysis told to stop stops at once, wherever it is: in the
    /// lines, between the rules' last steps, in the CYCLE600 walk. Counted,
    /// not timed: the n-th question answered `stop` is the last one asked
    /// (the walk made after the line pass, as the command line makes it; an
    /// editor's, made beside it, stops too).
    #[test]
    fn an_analysis_stops_when_told() {
        let mut text = String::from("DEF REAL _A=30\n");
        for n in 0..600 {
            text.push_str(&format!("G1 X{n} Y1\n"));
        }
        for n in 0..9_000 {
            text.push_str(&format!("IF R{n}>0\nR1=_A+{n}\nENDIF\n"));
        }
        text.push_str("CYCLE600(0,\"TC1\",0,57,0,0,0,_A,0,0,0,0,0,1,0,57)\nM30\n");
        let source = text.as_bytes();
        let settings = Settings::default();
        let kind = ProgramKind::Main;
        // The lines read here and ahead: the same questions at the same lines.
        let mut questions_here = None;
        for ahead in [ReadAhead::Never, ReadAhead::Always] {
            let until = |stop: Stop| {
                let walk = Walk::Here;
                let pass = LinePass {
                    scan: PlainScanner::Scan,
                    ahead,
                };
                analyze_stopping(pass, source, "BIG.MPF", kind, &settings, Some(stop), walk)
            };
            let asked = AtomicUsize::new(0);
            let never = || {
                asked.fetch_add(1, Relaxed);
                false
            };
            let whole = until(&never).expect("never told to stop");
            let questions = asked.load(Relaxed);
            assert_eq!(*questions_here.get_or_insert(questions), questions);
            let complete = analyze_program(source, "BIG.MPF", kind, &settings);
            assert_eq!(whole.findings, complete.findings);
            assert_eq!(whole.walk.map(|w| w.calls.len()), Some(1));
            // 27,603 lines: 9 questions in the lines (the first, after each of
            // two runs of 256 plain lines, then every 4,096 parsed lines), one
            // before each rule's last step, 5 in the walk (18,600 lines
            // walked), one after it.
            assert!(questions > 20, "{questions}");
            let walked = questions - 5..questions;
            let lines = [1, 2, 3, 4, 9, 10];
            for stop_at in
                lines
                    .into_iter()
                    .chain([questions / 2, walked.start, walked.end - 1, questions])
            {
                asked.store(0, Relaxed);
                let told = || asked.fetch_add(1, Relaxed) + 1 == stop_at;
                assert!(until(&told).is_none(), "told at question {stop_at}");
                assert_eq!(asked.load(Relaxed), stop_at, "no question after the stop");
                // Beside the line pass, the walk stops as well: a stop once
                // said holds, as a stale version stays stale.
                asked.store(0, Relaxed);
                let from_then = || asked.fetch_add(1, Relaxed) + 1 >= stop_at;
                let stopped = analyze_program_until(source, "BIG.MPF", kind, &settings, &from_then);
                assert!(stopped.is_none(), "told at question {stop_at}");
            }
        }
    }
}
