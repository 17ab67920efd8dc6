//! Walking a tree's expressions: what a statement reads, for the rules, the
//! walk and the rewrite alike.

use crate::syntax::tree::{
    Block, Expr, ExprKind, Goto, Initializer, Statement, StatementKind, Variable, WordValue,
};

/// Every expression directly in a statement, for collecting reads.
pub fn for_each_expression<'e>(kind: &'e StatementKind, visit: &mut dyn FnMut(&'e Expr)) {
    match kind {
        StatementKind::Word(word) => {
            if let WordValue::Expr(expr) = &word.value {
                visit(expr);
            }
        }
        StatementKind::Assign(assign) => {
            assign.target.indices.iter().for_each(&mut *visit);
            visit(&assign.value);
        }
        StatementKind::Call(call) => call
            .arguments
            .items
            .iter()
            .filter_map(|a| a.value.as_ref())
            .for_each(visit),
        StatementKind::If { condition }
        | StatementKind::While { condition }
        | StatementKind::Until { condition } => visit(condition),
        // What an action reads is read in the main run, yet read all the same.
        StatementKind::SyncAction(sync) => {
            if let Some((_, number)) = &sync.id {
                visit(number);
            }
            if let Some(condition) = &sync.condition {
                visit(&condition.expr);
            }
            let otherwise = sync.otherwise.iter().flat_map(|(_, actions)| actions);
            for action in sync.actions.iter().chain(otherwise) {
                for_each_expression(&action.kind, visit);
            }
        }
        StatementKind::For { start, end, .. } => {
            visit(start);
            visit(end);
        }
        StatementKind::Case(case) => visit(&case.selector),
        _ => {}
    }
}

/// Each variable read in `expr`, to `found` (iteratively: trees may be
/// deep).
pub fn each_variable<'e>(expr: &'e Expr, found: &mut dyn FnMut(&'e Variable)) {
    // Most expressions are a number or one variable: no stack for those.
    match &expr.kind {
        ExprKind::Number(_) | ExprKind::String => return,
        ExprKind::Variable(variable) if variable.indices.is_empty() => return found(variable),
        _ => {}
    }
    let mut stack = Stack::new(expr);
    while let Some(expr) = stack.pop() {
        match &expr.kind {
            ExprKind::Variable(variable) => {
                found(variable);
                variable.indices.iter().for_each(|e| stack.push(e));
            }
            ExprKind::Call(call) => (call.arguments.items.iter())
                .filter_map(|a| a.value.as_ref())
                .for_each(|e| stack.push(e)),
            ExprKind::Unary { operand, .. } => stack.push(operand),
            ExprKind::Binary { lhs, rhs, .. } => {
                stack.push(lhs);
                stack.push(rhs);
            }
            ExprKind::Paren(inner) => stack.push(inner),
            ExprKind::Tuple(items) => (items.items.iter())
                .filter_map(|a| a.value.as_ref())
                .for_each(|e| stack.push(e)),
            ExprKind::Number(_) | ExprKind::String => {}
        }
    }
}

/// The expressions still to visit: the usual expression's fit in the
/// function's own frame, a deeper one's go on onto the heap.
struct Stack<'e> {
    held: [&'e Expr; 16],
    len: usize,
    /// Only while `held` is full, so that the last pushed is popped first.
    spilled: Vec<&'e Expr>,
}

impl<'e> Stack<'e> {
    fn new(first: &'e Expr) -> Self {
        Self {
            held: [first; 16],
            len: 1,
            spilled: Vec::new(),
        }
    }

    fn push(&mut self, expr: &'e Expr) {
        match self.held.get_mut(self.len) {
            Some(slot) => {
                *slot = expr;
                self.len += 1;
            }
            None => self.spilled.push(expr),
        }
    }

    fn pop(&mut self) -> Option<&'e Expr> {
        self.spilled.pop().or_else(|| {
            self.len = self.len.checked_sub(1)?;
            Some(self.held[self.len])
        })
    }
}

/// Variables a statement reads (DEF initialisers and indices included).
pub fn reads(statement: &Statement) -> Vec<&Variable> {
    let mut out = Vec::new();
    each_read(statement, &mut |variable| out.push(variable));
    out
}

/// Each variable a statement reads, to `found`, in the order of [`reads`].
pub fn each_read<'e>(statement: &'e Statement, found: &mut dyn FnMut(&'e Variable)) {
    for_each_expression(&statement.kind, &mut |expr| each_variable(expr, found));
    if let StatementKind::Def(def) = &statement.kind {
        for declarator in &def.variables {
            if let Some(Initializer::Expr(expr)) = &declarator.init {
                each_variable(expr, found);
            }
            for dimension in declarator
                .dimensions
                .iter()
                .filter_map(|d| d.value.as_ref())
            {
                each_variable(dimension, found);
            }
        }
    }
}

/// Every jump of a block (GOTO statements and CASE branches).
pub fn gotos(block: &Block) -> Vec<&Goto> {
    let mut out = Vec::new();
    for statement in &block.statements {
        match &statement.kind {
            StatementKind::Goto(goto) => out.push(goto),
            StatementKind::Case(case) => {
                out.extend(case.branches.iter().map(|(_, g)| g).chain(&case.default))
            }
            _ => {}
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::lines::raw_lines;
    use crate::syntax::tree::LineKind;
    use crate::syntax::LineParser;

    /// The variables of `expr`, by plain recursion: the order the stack
    /// must give them in (the right operand's first, as it is popped first).
    fn recursively<'e>(expr: &'e Expr, out: &mut Vec<&'e Variable>) {
        let mut children: Vec<&Expr> = Vec::new();
        match &expr.kind {
            ExprKind::Variable(variable) => {
                out.push(variable);
                children.extend(variable.indices.iter());
            }
            ExprKind::Call(call) => {
                children.extend(call.arguments.items.iter().filter_map(|a| a.value.as_ref()))
            }
            ExprKind::Unary { operand, .. } => children.push(operand),
            ExprKind::Binary { lhs, rhs, .. } => children.extend([&**lhs, &**rhs]),
            ExprKind::Paren(inner) => children.push(inner),
            ExprKind::Tuple(items) => {
                children.extend(items.items.iter().filter_map(|a| a.value.as_ref()))
            }
            ExprKind::Number(_) | ExprKind::String => {}
        }
        for child in children.into_iter().rev() {
            recursively(child, out);
        }
    }

    /// Shallow and deep expressions (past the stack's own room of 16)
    /// give every variable, in the order of a recursive walk.
    #[test]
    fn each_variable_is_found_however_deep_the_expression() {
        for depth in [1, 3, 15, 16, 17, 40] {
            let mut value = String::from("A0");
            for i in 1..depth {
                value = format!("B{i}[C{i}, SIN(D{i})]*({value}-E{i})");
            }
            let line = format!("R1={value}\n");
            let source = line.as_bytes();
            let raw = raw_lines(source).next().expect("a line");
            let (parsed, error) = LineParser::default().parse_line(source, raw);
            assert!(error.is_none(), "{line}");
            let LineKind::Block(block) = &parsed.kind else {
                panic!("no block: {line}");
            };
            let StatementKind::Assign(assign) = &block.statements[0].kind else {
                panic!("no assignment: {line}");
            };
            let mut found = Vec::new();
            each_variable(&assign.value, &mut |v| found.push(v.name.text(source)));
            let mut expected = Vec::new();
            recursively(&assign.value, &mut expected);
            let expected: Vec<&[u8]> = expected.iter().map(|v| v.name.text(source)).collect();
            assert_eq!(found, expected, "depth {depth}");
            assert_eq!(found.len(), 1 + 4 * (depth - 1), "depth {depth}");
        }
    }
}
