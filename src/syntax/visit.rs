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

/// Variables read in `expr` (iteratively: trees may be deep).
pub fn collect_variables<'e>(expr: &'e Expr, out: &mut Vec<&'e Variable>) {
    // Most expressions are a number or one variable: no stack for those.
    match &expr.kind {
        ExprKind::Number(_) | ExprKind::String => return,
        ExprKind::Variable(variable) if variable.indices.is_empty() => return out.push(variable),
        _ => {}
    }
    let mut stack = vec![expr];
    while let Some(expr) = stack.pop() {
        match &expr.kind {
            ExprKind::Variable(variable) => {
                out.push(variable);
                stack.extend(variable.indices.iter());
            }
            ExprKind::Call(call) => {
                stack.extend(call.arguments.items.iter().filter_map(|a| a.value.as_ref()))
            }
            ExprKind::Unary { operand, .. } => stack.push(operand),
            ExprKind::Binary { lhs, rhs, .. } => {
                stack.push(lhs);
                stack.push(rhs);
            }
            ExprKind::Paren(inner) => stack.push(inner),
            ExprKind::Tuple(items) => {
                stack.extend(items.items.iter().filter_map(|a| a.value.as_ref()))
            }
            ExprKind::Number(_) | ExprKind::String => {}
        }
    }
}

/// Variables a statement reads (DEF initialisers and indices included).
pub fn reads(statement: &Statement) -> Vec<&Variable> {
    let mut out = Vec::new();
    for_each_expression(&statement.kind, &mut |expr| {
        collect_variables(expr, &mut out)
    });
    if let StatementKind::Def(def) = &statement.kind {
        for declarator in &def.variables {
            if let Some(Initializer::Expr(expr)) = &declarator.init {
                collect_variables(expr, &mut out);
            }
            for dimension in declarator
                .dimensions
                .iter()
                .filter_map(|d| d.value.as_ref())
            {
                collect_variables(dimension, &mut out);
            }
        }
    }
    out
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
