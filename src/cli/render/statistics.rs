//! Findings counted per rule (`check --statistics`), as ruff counts them.

use super::emitter::{Emitter, Program};
use crate::diagnostic::{Applicability, Diagnostic};

/// `check --statistics`: the findings counted per rule, as JSON (`json`)
/// or as a table, written at the end.
pub struct StatisticsEmitter {
    pub json: bool,
    /// Whether `--fix --unsafe-fixes` is given: unsafe fixes count as fixes.
    pub unsafe_fixes: bool,
    /// The table is read at a terminal (the human and short formats).
    pub for_people: bool,
}

impl Emitter for StatisticsEmitter {
    type Part = Statistics;
    type Kept = Statistics;

    fn add(&self, part: &mut Statistics, program: Program) {
        part.add(&program.diagnostics, self.unsafe_fixes);
    }

    fn write(
        &self,
        total: &mut Statistics,
        part: Statistics,
        _: &mut dyn std::io::Write,
    ) -> std::io::Result<()> {
        total.extend(part);
        Ok(())
    }

    fn end(&self, total: Statistics, out: &mut dyn std::io::Write) -> std::io::Result<()> {
        let text = if self.json {
            total.json()
        } else {
            total.text()
        };
        out.write_all(text.as_bytes())
    }

    fn for_people(&self) -> bool {
        self.for_people
    }
}

/// Findings per rule (`check --statistics`), summed over a run.
#[derive(Default)]
pub struct Statistics {
    rules: std::collections::BTreeMap<&'static str, Statistic>,
}

#[derive(Clone, Copy)]
struct Statistic {
    name: &'static str,
    count: usize,
    /// Whether `--fix` (with `--unsafe-fixes`, where given) answers any of them.
    fixable: bool,
}

impl Statistics {
    /// Counts `diagnostics`; `unsafe_fixes`: whether unsafe fixes count as fixable.
    pub fn add(&mut self, diagnostics: &[Diagnostic], unsafe_fixes: bool) {
        for d in diagnostics {
            let fixable = d
                .fix
                .as_deref()
                .is_some_and(|fix| fix.applicability == Applicability::Safe || unsafe_fixes);
            let entry = self.rules.entry(d.code()).or_insert(Statistic {
                name: d.name(),
                count: 0,
                fixable: false,
            });
            entry.count += 1;
            entry.fixable |= fixable;
        }
    }

    pub fn extend(&mut self, other: Statistics) {
        for (code, theirs) in other.rules {
            let ours = self.rules.entry(code).or_insert(Statistic {
                count: 0,
                fixable: false,
                ..theirs
            });
            ours.count += theirs.count;
            ours.fixable |= theirs.fixable;
        }
    }

    /// The most frequent first, then by code.
    fn sorted(&self) -> Vec<(&'static str, Statistic)> {
        let mut rules: Vec<_> = self.rules.iter().map(|(&c, &s)| (c, s)).collect();
        rules.sort_by(|a, b| b.1.count.cmp(&a.1.count).then(a.0.cmp(b.0)));
        rules
    }

    /// One line a rule, as ruff prints them: the count, the code, `[*]`
    /// where `--fix` answers some of its findings (`[ ]` where it answers
    /// none; no column when no rule is fixable), the rule's name.
    pub fn text(&self) -> String {
        let rules = self.sorted();
        let count_width = rules
            .iter()
            .map(|(_, s)| s.count.to_string().len())
            .max()
            .unwrap_or(0);
        let code_width = rules.iter().map(|(c, _)| c.len()).max().unwrap_or(0);
        let any_fixable = rules.iter().any(|(_, s)| s.fixable);
        let mut out = String::new();
        for (code, s) in rules {
            let mark = match (any_fixable, s.fixable) {
                (false, _) => "",
                (true, true) => "[*] ",
                (true, false) => "[ ] ",
            };
            out.push_str(&format!(
                "{:>count_width$}\t{code:<code_width$}\t{mark}{}\n",
                s.count, s.name
            ));
        }
        out
    }

    /// A JSON array of `{code, name, count, fixable}`, as ruff's.
    pub fn json(&self) -> String {
        let rules: Vec<_> = self
            .sorted()
            .into_iter()
            .map(|(code, s)| {
                serde_json::json!({ "code": code, "name": s.name, "count": s.count, "fixable": s.fixable })
            })
            .collect();
        let mut text = serde_json::to_string_pretty(&rules).unwrap_or_default();
        text.push('\n');
        text
    }
}
