//! The variables that only count: read by nothing but assignments to
//! themselves or to other such variables (`_PASS=_PASS+1` in a run-in
//! program's loop), and by `MSG`, which only shows text. Their values
//! never reach a condition, a position, a call or any other variable, so
//! what a program does next does not depend on them: two states that differ
//! only in them run the same blocks the same way, and a program that counts
//! its passes and otherwise comes back to a state repeats for ever all the
//! same.
//!
//! A counter is an R parameter or a variable the programs define (DEF): not
//! an address written as an assignment (`CR=5`), not a system variable. Its
//! assignments add numbers to it (`_PASS=_PASS+1`, `R1=0`), and MSG shows it
//! with `<<` alone: nothing that can fail at some later pass (a square root,
//! a division, an index, a value that doubles until it overflows) and stop
//! the program with an alarm. (An INT counted up by one overflows after
//! 2^31 passes: not in a machine's life.)
//!
//! Every use of a name must be seen to be one of those. Uses are read from
//! the trees and counted against the name's occurrences in the text (every
//! word of the sources, comments and strings included): a use the trees
//! miss (a jump to a computed label, a REPEAT's count) leaves more in the
//! text than was seen, and the name is no counter. Arrays are never
//! counters, nor R parameters where one is reached by number (`R[R2]`,
//! `$R1`), nor anything where a macro is used (its body's text is not
//! where its uses stand).

use std::collections::{HashMap, HashSet};

use crate::run::Programs;
use crate::semantic::eval::key;
use crate::semantic::model::Model;
use crate::semantic::vocabulary::is_r_parameter;
use crate::syntax::tree::{
    upper, BinaryOp, Expr, ExprKind, Initializer, LineKind, Name, StatementKind, UnaryOp,
};
use crate::syntax::visit::{each_read, each_variable};

/// The counters of the programs the run may enter, by their variables' keys
/// (`R1`, `_PASS`).
pub(super) fn counters(programs: &Programs) -> HashSet<String> {
    let models: Vec<&Model> = std::iter::once(programs.main)
        .chain(programs.subprograms.values())
        .collect();
    if models.iter().any(|model| !model.macro_uses.is_empty()) {
        return HashSet::new();
    }
    let mut uses = Uses::default();
    for model in &models {
        uses.read(model);
    }
    let words = words_of(&models, &uses.seen);
    let mut counters: HashSet<String> = uses
        .assigned
        .iter()
        .filter(|name| is_r_parameter(name.as_bytes()) || uses.defined.contains(*name))
        .filter(|name| !uses.read_elsewhere.contains(*name))
        .filter(|name| words.get(name) == uses.seen.get(*name))
        .filter(|name| !(words.r_by_number && is_r_parameter(name.as_bytes())))
        .cloned()
        .collect();
    // A counter's value may feed only counters.
    loop {
        let feeding: Vec<String> = uses
            .feeds
            .iter()
            .filter(|(read, target)| counters.contains(read) && !counters.contains(target))
            .map(|(read, _)| read.clone())
            .collect();
        if feeding.is_empty() {
            return counters;
        }
        for name in feeding {
            counters.remove(&name);
        }
    }
}

/// What the trees say of each name.
#[derive(Default)]
struct Uses {
    /// Assigned as a whole (`NAME=...`), not as an array's element.
    assigned: HashSet<String>,
    /// Defined by a DEF.
    defined: HashSet<String>,
    /// Read where a value can go anywhere but into an assignment or MSG,
    /// or used as an array.
    read_elsewhere: HashSet<String>,
    /// `(read, target)`: a value read in an assignment to a variable.
    feeds: HashSet<(String, String)>,
    /// The uses seen, by name: assignments, definitions, reads.
    seen: HashMap<String, usize>,
}

impl Uses {
    fn read(&mut self, model: &Model) {
        let source = model.source;
        for row in 0..model.lines.len() {
            if model.lines.is_plain(row) {
                continue;
            }
            let line = model.lines.line(row);
            let LineKind::Block(block) = &line.kind else {
                continue;
            };
            for statement in &block.statements {
                match &statement.kind {
                    StatementKind::Assign(assign) => {
                        let target = key_of(source, assign.target.name);
                        self.see(&target);
                        if assign.target.indices.is_empty()
                            && counts_safely(source, &assign.value, &target, &mut false)
                        {
                            self.assigned.insert(target.clone());
                        } else {
                            self.read_elsewhere.insert(target.clone());
                            assign
                                .target
                                .indices
                                .iter()
                                .for_each(|i| self.elsewhere(source, i));
                        }
                        each_variable(&assign.value, &mut |variable| {
                            let read = key_of(source, variable.name);
                            self.see(&read);
                            if !variable.indices.is_empty() {
                                self.read_elsewhere.insert(read.clone());
                            }
                            self.feeds.insert((read, target.clone()));
                        });
                    }
                    StatementKind::Call(call) if upper(call.name.text(source)) == "MSG" => {
                        let arguments = call.arguments.items.iter();
                        for argument in arguments.filter_map(|a| a.value.as_ref()) {
                            let shown = shows_safely(argument);
                            each_variable(argument, &mut |variable| {
                                let read = key_of(source, variable.name);
                                self.see(&read);
                                if !shown {
                                    self.read_elsewhere.insert(read);
                                }
                            });
                        }
                    }
                    StatementKind::Def(def) => {
                        for declarator in &def.variables {
                            let name = key_of(source, declarator.name);
                            self.see(&name);
                            self.defined.insert(name.clone());
                            if !declarator.dimensions.is_empty()
                                || matches!(declarator.init, Some(Initializer::List(_)))
                            {
                                self.read_elsewhere.insert(name);
                            }
                        }
                        each_read(statement, &mut |variable| {
                            let read = key_of(source, variable.name);
                            self.see(&read);
                            self.read_elsewhere.insert(read);
                        });
                    }
                    _ => each_read(statement, &mut |variable| {
                        let read = key_of(source, variable.name);
                        self.see(&read);
                        self.read_elsewhere.insert(read);
                    }),
                }
            }
        }
    }

    fn see(&mut self, name: &str) {
        match self.seen.get_mut(name) {
            Some(count) => *count += 1,
            None => {
                self.seen.insert(name.to_string(), 1);
            }
        }
    }

    /// Every variable `expr` reads, read where its value can go anywhere.
    fn elsewhere(&mut self, source: &[u8], expr: &Expr) {
        each_variable(expr, &mut |variable| {
            let read = key_of(source, variable.name);
            self.see(&read);
            self.read_elsewhere.insert(read);
        });
    }
}

/// A name as the run keys its variable: `R01` is `R1`.
fn name_key(name: &str) -> String {
    key(name, &[])
}

/// The key of the variable `name` stands for in `source`.
fn key_of(source: &[u8], name: Name) -> String {
    name_key(&upper(name.text(source)))
}

/// A counter's new value: numbers added to or taken from `target`, which
/// appears at most once (`seen`): it never more than adds.
fn counts_safely(source: &[u8], expr: &Expr, target: &str, seen: &mut bool) -> bool {
    match &expr.kind {
        ExprKind::Number(_) => true,
        ExprKind::Variable(variable) => {
            let once = !*seen && variable.indices.is_empty();
            *seen = true;
            once && key_of(source, variable.name) == target
        }
        ExprKind::Paren(inner) => counts_safely(source, inner, target, seen),
        ExprKind::Unary { op, operand } => {
            matches!(op, UnaryOp::Neg | UnaryOp::Plus)
                && counts_safely(source, operand, target, seen)
        }
        ExprKind::Binary { op, lhs, rhs } => {
            matches!(op, BinaryOp::Add | BinaryOp::Sub)
                && counts_safely(source, lhs, target, seen)
                && counts_safely(source, rhs, target, seen)
        }
        _ => false,
    }
}

/// What MSG shows: text, numbers and scalar variables joined with `<<`.
fn shows_safely(expr: &Expr) -> bool {
    match &expr.kind {
        ExprKind::Number(_) | ExprKind::String => true,
        ExprKind::Variable(variable) => variable.indices.is_empty(),
        ExprKind::Paren(inner) => shows_safely(inner),
        ExprKind::Unary { op, operand } => *op == UnaryOp::Concat && shows_safely(operand),
        ExprKind::Binary { op, lhs, rhs } => {
            *op == BinaryOp::Concat && shows_safely(lhs) && shows_safely(rhs)
        }
        _ => false,
    }
}

/// The words of the sources, counted for the names in `wanted`.
struct Words {
    counts: HashMap<String, usize>,
    /// An R parameter is reached by its number somewhere (`R[...]`, `$R`).
    r_by_number: bool,
}

impl Words {
    fn get(&self, name: &str) -> Option<&usize> {
        self.counts.get(name)
    }
}

/// Each word of the sources, made of letters, digits, `_` and `$`, cut
/// where a letter follows a digit (`N10R1`: `N10`, `R1`), as a name key.
fn words_of(models: &[&Model], wanted: &HashMap<String, usize>) -> Words {
    let mut words = Words {
        counts: HashMap::new(),
        r_by_number: false,
    };
    let mut name = String::new();
    for model in models {
        let source = model.source;
        let mut at = 0;
        while at < source.len() {
            if !is_word_byte(source[at]) {
                at += 1;
                continue;
            }
            let start = at;
            at += 1;
            while at < source.len() && continues_word(source[at - 1], source[at]) {
                at += 1;
            }
            let word = &source[start..at];
            let after = source[at..].iter().find(|b| !b.is_ascii_whitespace());
            if word.eq_ignore_ascii_case(b"R") && after == Some(&b'[')
                || word.len() > 1 && word[0] == b'$' && word[1].eq_ignore_ascii_case(&b'R')
            {
                words.r_by_number = true;
            }
            name.clear();
            name.push_str(&upper(word));
            let key = name_key(&name);
            if wanted.contains_key(&key) {
                *words.counts.entry(key).or_insert(0) += 1;
            }
        }
    }
    words
}

/// Whether `byte` after `previous` is of the same word: not after a digit
/// unless a digit itself.
fn continues_word(previous: u8, byte: u8) -> bool {
    is_word_byte(byte) && (byte.is_ascii_digit() || !previous.is_ascii_digit())
}

fn is_word_byte(byte: u8) -> bool {
    byte.is_ascii_alphanumeric() || byte == b'_' || byte == b'$'
}

#[cfg(test)]
mod tests {
    use super::*;

    fn of(source: &str) -> Vec<String> {
        let model = Model::of(source.as_bytes());
        let mut found: Vec<String> = counters(&Programs::alone(&model)).into_iter().collect();
        found.sort();
        found
    }

    #[test]
    fn a_variable_read_only_by_its_own_count_and_msg_is_a_counter() {
        let counting =
            "DEF INT _PASS=0\nLOOP\n_PASS=_PASS+1\nMSG(\"pass \"<<_PASS)\nG0 X10\nENDLOOP\n";
        assert_eq!(of(counting), ["_PASS"]);
        // R01 is R1; a count down, a reset.
        let down = "DEF REAL _LEFT\nLOOP\nR01=R1+1\n_LEFT=-(1-_LEFT)\nIF R1>9 R1=0\nENDLOOP\n";
        assert_eq!(of(down), ["_LEFT"]);
        assert_eq!(of("LOOP\nR01=R1+1\nR1=0\nENDLOOP\n"), ["R1"]);
    }

    #[test]
    fn a_variable_whose_value_goes_anywhere_else_is_no_counter() {
        let def = "DEF INT _A, _B, _C, _P\n";
        let of = |program: &str| of(&format!("{def}{program}"));
        // A position, a condition (as R01), a variable that is read.
        assert!(of("LOOP\n_P=_P+1\nG0 X=_P\nENDLOOP\n").is_empty());
        assert!(of("LOOP\nR1=R1+1\nIF R01>5 GOTOF OUT\nENDLOOP\nOUT:\nM30\n").is_empty());
        assert_eq!(
            of("LOOP\n_A=_A+1\n_B=_B+_A\nIF _B>3 GOTOF OUT\n_C=_C+1\nENDLOOP\nOUT:\n"),
            ["_C"]
        );
        // Reads the trees do not show are in the text: a REPEAT's count, a
        // comment (taken for a read), an R parameter reached by number.
        assert!(of("LOOP\nR5=R5+1\nSEC: G0 X1\nREPEAT SEC P=R5\nENDLOOP\n").is_empty());
        assert!(of("LOOP\n_C=_C+1 ; _C\nENDLOOP\n").is_empty());
        assert_eq!(of("LOOP\nR1=R1+1\n_C=_C+1\nG0 X=R[2]\nENDLOOP\n"), ["_C"]);
        // An element assigned.
        assert!(of("DEF INT _ARR[2]\nLOOP\n_ARR[0]=_ARR[0]+1\nENDLOOP\n").is_empty());
        // A block number glued to the name is cut off it.
        assert!(of("LOOP\n_C=_C+1\nN10X=_C\nENDLOOP\n").is_empty());
        // An address written as an assignment is no variable: what feeds it
        // moves the axes.
        assert!(of("R1=20\nLOOP\nR1=R1-1\nG2 X10 Y0 CR=R1\nENDLOOP\n").is_empty());
        assert!(of("LOOP\nR1=R1+1\n$P_PFRAME=CTRANS(X,R1)\nENDLOOP\n").is_empty());
        // What may fail at a later pass (an alarm that ends the program).
        assert!(of("LOOP\nR1=R1+1\nR2=SQRT(10-R1)\nENDLOOP\n").is_empty());
        assert!(of("LOOP\nR1=R1+1\nR2=R2+1/(5-R1)\nENDLOOP\n").is_empty());
        assert!(of("LOOP\nR1=R1+1\nMSG(\"x\"<<SQRT(-R1))\nENDLOOP\n").is_empty());
        // What grows faster than a count: it overflows at last.
        assert!(of("R1=2\nLOOP\nR1=R1*R1\nENDLOOP\n").is_empty());
        assert!(of("R1=2\nLOOP\nR1=R1+R1\nENDLOOP\n").is_empty());
        assert!(of("LOOP\n_A=_A+_B\n_B=_B+_A\nENDLOOP\n").is_empty());
        // A value that feeds another counter is read elsewhere.
        assert!(of("LOOP\nR1=R1+1\n_C=_C+R1\nENDLOOP\n").is_empty());
    }

    #[test]
    fn a_name_no_def_defines_is_not_known_to_count() {
        // A GUD variable, say, which the control may read elsewhere.
        assert!(of("LOOP\n_GUD=_GUD+1\nENDLOOP\n").is_empty());
        assert_eq!(of("DEF INT _OWN\nLOOP\n_OWN=_OWN+1\nENDLOOP\n"), ["_OWN"]);
    }
}
