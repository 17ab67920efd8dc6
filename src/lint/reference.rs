//! The rules as people read them: one rule's page (`sinuprep rule CODE`)
//! and the whole reference (`docs/rules.md`), made from the rules' own
//! documentation so that neither can fall behind the code.

use crate::diagnostic::RuleInfo;
use crate::lint::{off_by_default, rules, severity_in_check};

/// The severity `check` reports the rule at, with how it departs from the
/// rule's own: `info, off by default: --select N015`, `error, a warning for GOTOC`.
pub fn severity_text(info: &RuleInfo) -> String {
    let severity = info.severity.as_str();
    if off_by_default(info.code) {
        return format!("{severity}, off by default: --select {}", info.code);
    }
    match severity_in_check(info) {
        Some(note) => format!("{severity}, {note}"),
        None => severity.to_string(),
    }
}

/// One rule's page: its code, name and severity, then its documentation.
pub fn page(info: &RuleInfo) -> String {
    format!(
        "# {} {} ({})\n\n{}\n",
        info.code,
        info.name,
        severity_text(info),
        info.docs
    )
}

/// The anchor of the rule's section in `docs/rules.md`, as GitHub makes it
/// from the heading `## N001 undefined-label`: `n001-undefined-label`.
pub fn anchor(info: &RuleInfo) -> String {
    format!("{}-{}", info.code, info.name).to_ascii_lowercase()
}

/// The project's repository (`repository` in Cargo.toml): SARIF's
/// `informationUri`, and the base of the links to the rules' pages (SARIF's
/// `helpUri`, an editor's finding code); empty where Cargo.toml names none,
/// and then no such link is written.
pub const REPOSITORY: &str = env!("CARGO_PKG_REPOSITORY");

/// A rule's section of docs/rules.md in `repository`. The page is generated
/// from every rule (tests/lint.rs, `the_rule_reference`), so every rule has
/// its section.
pub fn help_uri(repository: &str, info: &RuleInfo) -> Option<String> {
    if repository.is_empty() {
        return None;
    }
    let base = repository.trim_end_matches('/');
    Some(format!("{base}/blob/HEAD/docs/rules.md#{}", anchor(info)))
}

/// Every rule in code order: a table of them, then each rule's page one
/// heading level down. Written to `docs/rules.md`; a test holds the file to it.
pub fn reference() -> String {
    let all = rules::all();
    let mut out = String::from(
        "# Rules\n\nEvery finding `sinuprep check` can report, made from the rules' own documentation \
         (`sinuprep rule CODE` prints one of them). `S...` are syntax errors, `N...` the general NC rules, \
         `C6..` the CYCLE600 walk's and the rewrite's, `K...` the machine's (swivel data, and swivels \
         solved on it with `--machine`).\n\n| code | name | severity | what it does |\n|---|---|---|---|\n",
    );
    for rule in &all {
        let info = rule.info;
        out.push_str(&format!(
            "| [{code}](#{anchor}) | {name} | {severity} | {what} |\n",
            code = info.code,
            anchor = anchor(info),
            name = info.name,
            severity = severity_text(info),
            what = first_sentence(info.docs).replace('|', "\\|"),
        ));
    }
    for rule in &all {
        let info = rule.info;
        out.push_str(&format!(
            "\n## {} {}\n\n*{}*\n\n",
            info.code,
            info.name,
            severity_text(info)
        ));
        for line in info.docs.lines() {
            // The docs' own sections sit under the rule's heading.
            if line.starts_with("## ") {
                out.push('#');
            }
            out.push_str(line);
            out.push('\n');
        }
    }
    out
}

/// The first sentence of a rule's "What it does", on one line.
fn first_sentence(docs: &str) -> String {
    let body = docs
        .split_once("## What it does")
        .map_or(docs, |(_, rest)| rest)
        .split("\n## ")
        .next()
        .unwrap_or_default();
    let text = body.split_whitespace().collect::<Vec<_>>().join(" ");
    // A sentence ends at a full stop before a space and a capital letter
    // (not inside `G1 X10.5` or an abbreviation in backquotes).
    let bytes = text.as_bytes();
    let end = (0..bytes.len().saturating_sub(2))
        .find(|&i| bytes[i] == b'.' && bytes[i + 1] == b' ' && bytes[i + 2].is_ascii_uppercase())
        .map_or(text.len(), |i| i + 1);
    text[..end].to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rules_help_is_its_section_of_the_reference_in_the_repository() {
        let info = crate::lint::rule("N001").expect("N001");
        assert_eq!(
            help_uri("https://example.org/shop/sinuprep/", info).as_deref(),
            Some("https://example.org/shop/sinuprep/blob/HEAD/docs/rules.md#n001-undefined-label")
        );
        // No repository in Cargo.toml: no link to a page that is nowhere.
        assert_eq!(help_uri("", info), None);
    }
}
