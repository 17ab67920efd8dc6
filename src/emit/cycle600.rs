//! CYCLE600 calls rewritten as native code (spec section 7).
//!
//! `_SW_REC=1` becomes the GUD assignments of the results; `_SW_REC=0` a
//! swivel: a CYCLE800 call (default), programmable frames, or frames under
//! TRAORI. Only the call's own bytes are replaced, so the block number,
//! indentation, other words and trailing comment stay; the original call is
//! kept as a comment line above, and added lines use the file's line ending.

use crate::diagnostic::{Diagnostic, Severity};
use crate::emit::{runtime, Edit};
use crate::number::format;
use crate::registry;
use crate::rotation::Kind;
use crate::semantic::cycle600::{no_cycle800_form, Evaluation, Parameters};
use crate::semantic::frames::FrameSeen;
use crate::semantic::swivels::{self, OnMachine};
use crate::semantic::value::Value;
use crate::semantic::walk::{Analysis, CallSite};
use crate::semantic::Model;
use crate::span::Span;
use crate::syntax::lines::dominant_ending;

/// How a rotating CYCLE600 (`_SW_REC=0`) is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Form {
    /// One CYCLE800 call (swivel with the head).
    #[default]
    Cycle800,
    /// TRANS, one AROT per rotation, ATRANS.
    Frames,
    /// The frames under a 5-axis transformation, tool along the new Z (3+2 machining).
    Traori,
}

impl Form {
    /// What a call is rewritten as, in a sentence: "a CYCLE800 call".
    pub fn native(self) -> &'static str {
        match self {
            Form::Cycle800 => "a CYCLE800 call",
            Form::Frames => "programmable frames",
            Form::Traori => "frames under TRAORI",
        }
    }
}

#[derive(Clone, Debug)]
pub struct Options {
    pub form: Form,
    /// Decimals of emitted numbers.
    pub precision: usize,
    /// Keep the original call as a comment above the new code.
    pub keep_original: bool,
    /// Replace later reads of `_CYC600_n` by their values.
    pub inline_results: bool,
    /// Compute calls whose angles are measured at run time on the control;
    /// `Some(Some(n))` keeps the intermediate values in R parameters from Rn.
    pub runtime: Option<Option<u32>>,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            form: Form::Cycle800,
            precision: 6,
            keep_original: true,
            inline_results: false,
            runtime: None,
        }
    }
}

/// What a rewrite changes, and why some calls were left alone.
#[derive(Debug, Default)]
pub struct Rewrite {
    pub edits: Vec<Edit>,
    pub diagnostics: Vec<Diagnostic>,
    /// Calls replaced, calls left as they were.
    pub rewritten: usize,
    pub refused: usize,
}

pub fn rewrite(model: &Model, analysis: &Analysis, options: &Options) -> Rewrite {
    rewrite_on(model, analysis, options, None)
}

/// [`rewrite`] for the machine `on`: a swivel on a head with a rotary table
/// under it is refused (C620) in the CYCLE800 form.
pub fn rewrite_on(
    model: &Model,
    analysis: &Analysis,
    options: &Options,
    on: Option<&OnMachine>,
) -> Rewrite {
    let source = model.source;
    let eol = dominant_ending(source).as_bytes();
    let mut out = Rewrite::default();
    let mut names = runtime::Names::new(options.runtime.flatten());
    let mut at_run_time: Vec<(&CallSite, Vec<String>)> = Vec::new();
    for site in &analysis.calls {
        let refused = site
            .diagnostics
            .iter()
            .any(|d| d.severity == Severity::Error);
        if let (Some(evaluation), false) = (&site.evaluation, refused) {
            out.diagnostics.extend(site.diagnostics.iter().cloned());
            match code_on(site, evaluation, options, on) {
                Ok(blocks) => {
                    out.edits.extend(edits(source, site, &blocks, options, eol));
                    out.rewritten += 1;
                }
                Err(problem) => {
                    out.diagnostics.push(problem);
                    out.refused += 1;
                }
            }
            continue;
        }
        // What the run-time code answers is the unknown arguments (C605); any
        // other error still refuses the call.
        let refused_at_run_time = site.diagnostics.iter().any(|d| {
            d.severity == Severity::Error && !d.is(&registry::cycle600_unknown_argument::RULE)
        });
        if let (Some(_), Some(parameters), false) =
            (options.runtime, &site.runtime, refused_at_run_time)
        {
            match runtime::code(
                parameters,
                &site.active,
                site.needs_stopre,
                options,
                &mut names,
                site.statement,
            ) {
                Ok(blocks) => {
                    at_run_time.push((site, blocks));
                    continue;
                }
                Err(problem) => out.diagnostics.push(problem),
            }
        }
        out.diagnostics.extend(site.diagnostics.iter().cloned());
        out.refused += 1;
    }
    if !at_run_time.is_empty() {
        match runtime::collision(model, &names) {
            Some(problem) => {
                out.diagnostics.push(problem);
                for (site, _) in &at_run_time {
                    out.diagnostics.extend(site.diagnostics.iter().cloned());
                    out.refused += 1;
                }
            }
            None => {
                let locals = names.locals();
                if !locals.is_empty() {
                    let at = model.declarations_insertion();
                    // The DEF lines end as the line before them does: a lone CR
                    // in front of that line's LF would join them into one CRLF.
                    let eol = crate::span::ending_before(source, at).unwrap_or(eol);
                    let mut declarations = Vec::new();
                    for chunk in locals.chunks(8) {
                        declarations
                            .extend_from_slice(format!("DEF REAL {}", chunk.join(", ")).as_bytes());
                        declarations.extend_from_slice(eol);
                    }
                    out.edits.push(Edit::insert(at, declarations));
                }
                for (site, blocks) in &at_run_time {
                    // The unknown-argument errors are answered by the run-time code.
                    out.diagnostics.extend(
                        site.diagnostics
                            .iter()
                            .filter(|d| !d.is(&registry::cycle600_unknown_argument::RULE))
                            .cloned(),
                    );
                    out.diagnostics.push(
                        registry::cycle600_computed_at_run_time::RULE.at(site.statement)
                            .message("values known only at run time: the conversion is computed on the control in native arithmetic")
                            .label("computed at run time"),
                    );
                    out.edits.extend(edits(source, site, blocks, options, eol));
                    out.rewritten += 1;
                }
            }
        }
    }
    if options.inline_results {
        for read in &analysis.result_reads {
            // A string after a sign is a syntax error (S005): such a read
            // stays the variable it is.
            let before = source[..read.span.start].trim_ascii_end();
            if matches!(read.value, Value::Text(_))
                && before.ends_with(b"+") | before.ends_with(b"-")
            {
                continue;
            }
            let text = literal(&read.value, options.precision);
            // A read may follow an operator, and a sign right after one is
            // not accepted by every control: `<< (-16.28)`, not `<< -16.28`.
            let text = if text.starts_with('-') {
                format!("({text})")
            } else {
                text
            };
            out.edits.push(Edit::replace(read.span, text));
        }
    }
    out
}

/// C620 for a call `code` writes as CYCLE800 on a head record with a
/// rotary table under it on `on`: no native form of the split is known.
fn over_table(site: &CallSite, options: &Options, on: Option<&OnMachine>) -> Option<Diagnostic> {
    if options.form != Form::Cycle800 {
        return None;
    }
    let asked = swivels::of_cycle600(site)?;
    let over = swivels::split_on(&asked, on?)?;
    Some(crate::emit::split::refusal(&asked, &over))
}

/// The edits that rewrite one call evaluated offline, as [`rewrite_on`]
/// writes them on `on`; `None` for a call it would refuse or compute at run
/// time (whose code shares DEF lines with the program's other such calls).
pub fn call_edits(
    model: &Model,
    site: &CallSite,
    options: &Options,
    on: Option<&OnMachine>,
) -> Option<Vec<Edit>> {
    let evaluation = site.evaluation.as_ref()?;
    if site
        .diagnostics
        .iter()
        .any(|d| d.severity == Severity::Error)
    {
        return None;
    }
    let blocks = code_on(site, evaluation, options, on).ok()?;
    let eol = dominant_ending(model.source).as_bytes();
    Some(edits(model.source, site, &blocks, options, eol))
}

fn literal(value: &Value, precision: usize) -> String {
    match value {
        Value::Number(n) => format(*n, precision),
        Value::Text(t) => format!("\"{t}\""),
    }
}

/// The call's output as CYCLE800 and AROT take it: they turn about the
/// rotated axes, so intrinsic angles only (an extrinsic a, b, c is the
/// intrinsic c, b, a).
fn intrinsic(evaluation: &Evaluation) -> (crate::rotation::Sequence, [f64; 3]) {
    let output = evaluation.parameters.output;
    match output.kind {
        Kind::Intrinsic => (output, evaluation.output.angles),
        Kind::Extrinsic => {
            let [a, b, c] = evaluation.output.angles;
            (output.reversed(), [c, b, a])
        }
    }
}

/// The blocks that replace the call, first one in the call's place.
pub fn code(
    site: &CallSite,
    evaluation: &Evaluation,
    options: &Options,
) -> Result<Vec<String>, Diagnostic> {
    let span = site.statement;
    let p = &evaluation.parameters;
    let n = |v: f64| format(v, options.precision);
    if p.recalculate_only {
        let gud: Vec<String> = evaluation
            .gud()
            .iter()
            .enumerate()
            .map(|(i, value)| format!("_CYC600_{}={}", i + 1, literal(value, options.precision)))
            .collect();
        return Ok(vec![gud.join(" ")]);
    }
    let (sequence, angles) = intrinsic(evaluation);
    let [x0, y0, z0] = [p.before.x, p.before.y, p.before.z].map(n);
    let [x1, y1, z1] = [p.after.x, p.after.y, p.after.z].map(n);
    match options.form {
        Form::Cycle800 => cycle800(evaluation, options.precision)
            .map(|call| vec![call])
            .ok_or_else(|| no_cycle800_form(p.output, span)),
        Form::Frames | Form::Traori => {
            if let Some(seen) = &site.user_frame {
                return Err(over_programmable_frame(options.form, seen, span));
            }
            let mut blocks = Vec::new();
            if options.form == Form::Traori {
                blocks.push("TRAORI".to_string());
                blocks.push("ORIWKS".to_string());
            }
            // An additive rotation onto an unknown active one adds to the frame.
            let shift = if evaluation.additive_on_control {
                "ATRANS"
            } else {
                "TRANS"
            };
            blocks.push(format!("{shift} X{x0} Y{y0} Z{z0}"));
            for (axis, angle) in sequence.axes.iter().zip(angles) {
                blocks.push(format!("AROT {}={}", axis.letter(), n(angle)));
            }
            blocks.push(format!("ATRANS X{x1} Y{y1} Z{z1}"));
            if options.form == Form::Traori {
                blocks.push("G0 A3=0 B3=0 C3=1".to_string());
            }
            Ok(blocks)
        }
    }
}

/// [`code`] on the machine `on`: a swivel on a head with a rotary table
/// under it is refused in the CYCLE800 form (C620).
pub fn code_on(
    site: &CallSite,
    evaluation: &Evaluation,
    options: &Options,
    on: Option<&OnMachine>,
) -> Result<Vec<String>, Diagnostic> {
    let blocks = code(site, evaluation, options)?;
    over_table(site, options, on).map_or(Ok(blocks), Err)
}

/// The CYCLE800 call that swivels as `evaluation` does; `None` when its
/// output is a proper Euler sequence, which CYCLE800 has no `_MODE` for.
pub fn cycle800(evaluation: &Evaluation, precision: usize) -> Option<String> {
    let p = &evaluation.parameters;
    let (sequence, angles) = intrinsic(evaluation);
    if sequence.is_proper_euler() {
        return None;
    }
    let n = |v: f64| format(v, precision);
    let [x0, y0, z0] = [p.before.x, p.before.y, p.before.z].map(n);
    let [x1, y1, z1] = [p.after.x, p.after.y, p.after.z].map(n);
    let st = u8::from(evaluation.additive_on_control);
    let dir = if p.inverse { 1 } else { -1 };
    let [a, b, c] = angles.map(n);
    Some(format!(
        "CYCLE800({},\"{}\",{st},{},{x0},{y0},{z0},{a},{b},{c},{x1},{y1},{z1},{dir})",
        u8::from(p.retract),
        p.head,
        sequence.code()
    ))
}

/// The CYCLE600 call of `parameters`, in the canonical form of 18 values
/// (spec section 1).
pub fn cycle600(p: &Parameters, precision: usize) -> String {
    let n = |v: f64| format(v, precision);
    let flag = |kind: Kind| u8::from(kind == Kind::Intrinsic);
    let [x0, y0, z0] = [p.before.x, p.before.y, p.before.z].map(n);
    let [a, b, c] = p.angles.map(n);
    let [x1, y1, z1] = [p.after.x, p.after.y, p.after.z].map(n);
    format!(
        "CYCLE600({},\"{}\",{},{},{x0},{y0},{z0},{a},{b},{c},{x1},{y1},{z1},{},{},{},{},{})",
        flag(p.input.kind),
        p.head,
        u8::from(p.recalculate_only),
        p.input.code(),
        flag(p.output.kind),
        p.output.code(),
        u8::from(p.additive),
        u8::from(p.inverse),
        u8::from(p.retract),
    )
}

/// The blanks the call's line begins with, which the lines written for it
/// begin with too.
pub(crate) fn indent<'s>(source: &'s [u8], site: &CallSite) -> &'s [u8] {
    let content = site.content;
    let blanks = content
        .of(source)
        .iter()
        .take_while(|&&b| b == b' ' || b == b'\t')
        .count();
    &source[content.start..content.start + blanks]
}

fn edits(
    source: &[u8],
    site: &CallSite,
    blocks: &[String],
    options: &Options,
    eol: &[u8],
) -> Vec<Edit> {
    let content = site.content;
    let indent = indent(source, site);
    let mut edits = Vec::new();
    if options.keep_original {
        let mut comment = indent.to_vec();
        comment.extend_from_slice(b"; sinuprep: ");
        comment.extend_from_slice(site.statement.of(source));
        comment.extend_from_slice(eol);
        edits.push(Edit::insert(content.start, comment));
    }
    edits.push(Edit::replace(site.statement, blocks[0].as_bytes()));
    if blocks.len() > 1 {
        let mut rest = Vec::new();
        for block in &blocks[1..] {
            rest.extend_from_slice(eol);
            rest.extend_from_slice(indent);
            rest.extend_from_slice(block.as_bytes());
        }
        edits.push(Edit::insert(content.end, rest));
    }
    edits
}

/// C617: the frames and TRAORI forms set the programmable frame with
/// `TRANS`, which would drop the program's own frame statement.
fn over_programmable_frame(form: Form, seen: &FrameSeen, span: Span) -> Diagnostic {
    let form = match form {
        Form::Traori => "traori",
        _ => "frames",
    };
    registry::cycle600_frames_over_programmable_frame::RULE.at(span,
    )
    .message(format!(
        "the {form} form replaces the programmable frame with TRANS, and {seen} is active in it"
    ))
    .label("would drop the programmable frame")
    .help("rewrite with --emit cycle800 (CYCLE800 keeps the programmable frame), or clear the frame (TRANS) before the call")
}
