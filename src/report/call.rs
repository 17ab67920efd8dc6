//! A CYCLE600 call as `eval` reports it: its arguments with their values
//! and where each came from, the conversion, the results and the code the
//! rewrite emits; as a table for people (an editor's hover shows it) and as
//! JSON.

use crate::emit::cycle600::{code_on, Options};
use crate::number::format;
use crate::semantic::cycle600::{Argument, Provenance};
use crate::semantic::swivels::OnMachine;
use crate::semantic::value::Value;
use crate::semantic::CallSite;
use crate::span::LineIndex;

/// A value as `eval` prints it (an editor's hover on a variable too).
pub fn value_text(value: &Result<Value, crate::semantic::value::Unknown>) -> String {
    match value {
        Ok(Value::Number(n)) => format(*n, 9),
        Ok(Value::Text(t)) => format!("\"{t}\""),
        Err(_) => "unknown".to_string(),
    }
}

/// The arguments in the order they stand in the call (the 19-value form's
/// reserved value is the 14th).
fn in_call_order(bound: &crate::semantic::cycle600::Bound) -> Vec<&Argument> {
    let mut arguments: Vec<&Argument> = bound.reserved.iter().chain(&bound.arguments).collect();
    arguments.sort_by_key(|a| a.span.start);
    arguments
}

fn provenance_text(argument: &Argument) -> String {
    match (&argument.provenance, &argument.value) {
        (_, Err(why)) => why.to_string(),
        (Provenance::Empty, _) => "empty: 0".to_string(),
        (Provenance::Literal, _) => "literal".to_string(),
        (Provenance::Expression, _) => "expression".to_string(),
        (
            Provenance::Variable {
                key,
                origin: Some(origin),
            },
            _,
        ) => format!("{key}: {origin}"),
        (Provenance::Variable { key, origin: None }, _) => key.clone(),
    }
}

/// The table `eval` prints for one call (an editor's hover shows it).
pub fn call_table(
    site: &CallSite,
    name: &str,
    source: &[u8],
    options: &Options,
    machine: Option<&OnMachine>,
) -> String {
    let mut out = String::new();
    let index = LineIndex::new(source);
    table(site, name, source, &index, options, machine, &mut out);
    out
}

pub fn table(
    site: &CallSite,
    name: &str,
    source: &[u8],
    index: &LineIndex,
    options: &Options,
    machine: Option<&OnMachine>,
    out: &mut String,
) {
    let row = index.position(site.statement.start).row;
    out.push_str(&format!(
        "{name}:{row}: {}\n",
        String::from_utf8_lossy(site.statement.of(source))
    ));
    if let Some(bound) = &site.bound {
        out.push_str(&format!(
            "  {:<10} {:<14} {:<16} {}\n",
            "parameter", "argument", "value", "from"
        ));
        for argument in in_call_order(bound) {
            out.push_str(&format!(
                "  {:<10} {:<14} {:<16} {}\n",
                argument.name,
                argument.text,
                value_text(&argument.value),
                provenance_text(argument)
            ));
        }
    }
    match &site.evaluation {
        None => out.push_str("  not evaluated offline (see the diagnostics)\n"),
        Some(evaluation) => {
            let p = &evaluation.parameters;
            let n = |v: f64| format(v, options.precision);
            let angles = |a: [f64; 3]| a.map(n).join("  ");
            out.push_str(&format!(
                "  input    {} (code {})  {}\n",
                p.input,
                p.input.code(),
                angles(p.angles)
            ));
            out.push_str(&format!(
                "  output   {} (code {})  {}\n",
                p.output,
                p.output.code(),
                angles(evaluation.output.angles)
            ));
            out.push_str(&format!(
                "  other    {}\n",
                angles(evaluation.output.alternative)
            ));
            if p.additive {
                let how = if evaluation.additive_on_control {
                    "added on the control to the active rotation (unknown offline)"
                } else {
                    "composed with the active rotation"
                };
                out.push_str(&format!("  additive {how}\n"));
            }
            let m = evaluation.target.matrix();
            for r in 0..3 {
                let label = if r == 0 { "matrix" } else { "" };
                out.push_str(&format!(
                    "  {label:<8} {:>10.6} {:>10.6} {:>10.6}\n",
                    m[(r, 0)] + 0.0,
                    m[(r, 1)] + 0.0,
                    m[(r, 2)] + 0.0
                ));
            }
            let gud: Vec<String> = evaluation
                .gud()
                .iter()
                .enumerate()
                .map(|(i, v)| match v {
                    Value::Number(x) => format!("_CYC600_{}={}", i + 1, n(*x)),
                    Value::Text(t) => format!("_CYC600_{}=\"{t}\"", i + 1),
                })
                .collect();
            out.push_str(&format!("  results  {}\n", gud.join(" ")));
            match code_on(site, evaluation, options, machine) {
                Ok(blocks) => {
                    for (i, block) in blocks.iter().enumerate() {
                        out.push_str(&format!(
                            "  {:<8} {block}\n",
                            if i == 0 { "emits" } else { "" }
                        ));
                    }
                }
                Err(problem) => out.push_str(&format!("  emits    nothing: {}\n", problem.message)),
            }
        }
    }
    out.push('\n');
}

pub fn json(
    site: &CallSite,
    source: &[u8],
    options: &Options,
    machine: Option<&OnMachine>,
) -> serde_json::Value {
    let arguments: Vec<serde_json::Value> = site
        .bound
        .iter()
        .flat_map(in_call_order)
        .map(|a| {
            let value = match &a.value {
                Ok(Value::Number(n)) => serde_json::json!(n),
                Ok(Value::Text(t)) => serde_json::json!(t),
                Err(_) => serde_json::Value::Null,
            };
            serde_json::json!({ "name": a.name, "text": a.text, "value": value, "from": provenance_text(a), "offset": a.span.start, "length": a.span.len() })
        })
        .collect();
    let evaluation = site.evaluation.as_ref().map(|e| {
        let m = e.target.matrix();
        let matrix = [0, 1, 2].map(|r| [0, 1, 2].map(|c| m[(r, c)] + 0.0));
        let results: Vec<serde_json::Value> = e
            .gud()
            .iter()
            .map(|v| match v {
                Value::Number(n) => serde_json::json!(n),
                Value::Text(t) => serde_json::json!(t),
            })
            .collect();
        serde_json::json!({
            "input": { "sequence": e.parameters.input.to_string(), "code": e.parameters.input.code(), "angles": e.parameters.angles },
            "output": { "sequence": e.parameters.output.to_string(), "code": e.parameters.output.code(), "angles": e.output.angles, "alternative": e.output.alternative, "gimbal_lock": e.output.gimbal_lock },
            "matrix": matrix,
            "additive_on_control": e.additive_on_control,
            "results": results,
            "emits": code_on(site, e, options, machine).ok(),
        })
    });
    serde_json::json!({
        "line": site.line + 1,
        "call": String::from_utf8_lossy(site.statement.of(source)),
        "arguments": arguments,
        "evaluation": evaluation,
        "diagnostics": site.diagnostics.iter().map(|d| serde_json::json!({ "code": d.code(), "severity": d.severity, "message": d.message })).collect::<Vec<_>>(),
    })
}
