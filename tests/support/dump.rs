//! A readable, indented dump of a parsed program: each node's kind and the
//! source text of its parts, so a snapshot can be checked by eye.

use sinuprep::span::Span;
use sinuprep::syntax::tree::*;
use sinuprep::syntax::Program;

pub fn dump(program: &Program) -> String {
    let source = program.source;
    let text = |span: Span| String::from_utf8_lossy(span.of(source)).into_owned();
    let mut out = String::new();
    for (row, line) in program.lines.iter().enumerate() {
        let row = row + 1;
        match &line.kind {
            LineKind::Header { name } => {
                out.push_str(&format!("{row}: header {:?}\n", text(*name)))
            }
            LineKind::Path { directory } => {
                out.push_str(&format!("{row}: path {:?}\n", text(*directory)))
            }
            LineKind::Block(block) => {
                let mut head = format!("{row}: block");
                if let Some(skip) = &block.skip {
                    head += &format!(" skip={:?}", text(skip.span));
                }
                if let Some(number) = &block.number {
                    head += &format!(" number={:?}", text(number.span));
                }
                if let Some(label) = &block.label {
                    head += &format!(" label={:?}", text(label.span));
                }
                if let Some(comment) = block.comment {
                    head += &format!(" comment={:?}", text(comment));
                }
                if let Some(unparsed) = block.unparsed {
                    head += &format!(" UNPARSED={:?}", text(unparsed));
                }
                out.push_str(&head);
                out.push('\n');
                for statement in &block.statements {
                    out.push_str(&format!(
                        "    {}\n",
                        statement_text(source, &statement.kind)
                    ));
                }
            }
        }
    }
    out
}

fn statement_text(source: &[u8], kind: &StatementKind) -> String {
    let t = |span: Span| String::from_utf8_lossy(span.of(source)).into_owned();
    let e = |expr: &Expr| expr_text(source, expr);
    match kind {
        StatementKind::Word(word) => {
            let ext = word.extension.map(t).unwrap_or_default();
            match &word.value {
                WordValue::Number(n) => format!(
                    "word {}{ext} {} ({})",
                    t(word.address.span),
                    t(n.span),
                    n.value
                ),
                WordValue::Expr(x) => format!("word {}{ext} = {}", t(word.address.span), e(x)),
            }
        }
        StatementKind::Assign(a) => format!(
            "assign {} = {}",
            variable_text(source, &a.target),
            e(&a.value)
        ),
        StatementKind::Call(c) => format!(
            "call {}({})",
            t(c.name.span),
            arguments_text(source, &c.arguments)
        ),
        StatementKind::Command(n) => format!("command {}", t(n.span)),
        StatementKind::Frame(f) => format!("frame {:?} ({})", f.kind, t(f.keyword.span)),
        StatementKind::Def(d) => {
            let scope = d
                .scope
                .map(|s| format!("{} ", t(s.span)))
                .unwrap_or_default();
            let attributes: Vec<String> = d
                .attributes
                .iter()
                .map(|a| match &a.value {
                    Some(v) => format!("{}={}", t(a.keyword.span), e(v)),
                    None => t(a.keyword.span),
                })
                .collect();
            let variables: Vec<String> = d
                .variables
                .iter()
                .map(|v| declarator_text(source, v))
                .collect();
            format!(
                "def {scope}{:?} attrs=[{}] vars=[{}]",
                d.data_type.kind,
                attributes.join(" "),
                variables.join("; ")
            )
        }
        StatementKind::Redef { name, attributes } => {
            let attributes: Vec<String> = attributes
                .iter()
                .map(|a| match &a.value {
                    Some(v) => format!("{}={}", t(a.keyword.span), e(v)),
                    None => t(a.keyword.span),
                })
                .collect();
            format!("redef {} attrs=[{}]", t(name.span), attributes.join(" "))
        }
        StatementKind::Proc(p) => {
            let params: Vec<String> = p
                .parameters
                .iter()
                .map(|p| {
                    format!(
                        "{}{:?} {}",
                        if p.by_reference { "VAR " } else { "" },
                        p.data_type.kind,
                        declarator_text(source, &p.declarator)
                    )
                })
                .collect();
            let attributes: Vec<String> = p.attributes.iter().map(|a| t(a.span)).collect();
            format!(
                "proc {} ({}) [{}]",
                t(p.name.span),
                params.join(", "),
                attributes.join(" ")
            )
        }
        StatementKind::Extern { name, parameters } => format!(
            "extern {} {}",
            t(name.span),
            parameters.map(t).unwrap_or_default()
        ),
        StatementKind::Define { name, body } => {
            format!("define {} as {:?}", t(name.span), t(*body))
        }
        StatementKind::If { condition } => format!("if {}", e(condition)),
        StatementKind::Else => "else".into(),
        StatementKind::EndIf => "endif".into(),
        StatementKind::While { condition } => format!("while {}", e(condition)),
        StatementKind::EndWhile => "endwhile".into(),
        StatementKind::For {
            variable,
            start,
            end,
        } => format!("for {} = {} to {}", t(variable.span), e(start), e(end)),
        StatementKind::EndFor => "endfor".into(),
        StatementKind::Loop => "loop".into(),
        StatementKind::EndLoop => "endloop".into(),
        StatementKind::Repeat { targets, count } => {
            format!(
                "repeat [{}]{}",
                targets
                    .iter()
                    .map(|n| t(n.span))
                    .collect::<Vec<_>>()
                    .join(" "),
                count
                    .as_ref()
                    .map(|n| format!(" P={}", e(n)))
                    .unwrap_or_default()
            )
        }
        StatementKind::Until { condition } => format!("until {}", e(condition)),
        StatementKind::Case(c) => {
            let branches: Vec<String> = c
                .branches
                .iter()
                .map(|(v, g)| format!("{} -> {}", e(v), goto_text(source, g)))
                .collect();
            let default = c
                .default
                .as_ref()
                .map(|g| format!(" default -> {}", goto_text(source, g)))
                .unwrap_or_default();
            format!(
                "case {} of {}{default}",
                e(&c.selector),
                branches.join(", ")
            )
        }
        StatementKind::Goto(g) => goto_text(source, g),
        StatementKind::IndirectCall { keyword, target } => format!(
            "indirect {} {:?}",
            t(keyword.span),
            target.map(t).unwrap_or_default()
        ),
        StatementKind::SyncAction(sync) => {
            let mut out = String::from("sync");
            if let Some((keyword, number)) = &sync.id {
                out += &format!(" {}={}", t(keyword.span), e(number));
            }
            if let Some(condition) = &sync.condition {
                out += &format!(" {}", t(condition.frequency.span));
                for g in &condition.g_functions {
                    out += &format!(" [{}]", statement_text(source, &g.kind));
                }
                out += &format!(" {}", e(&condition.expr));
            }
            let actions = |actions: &[Statement]| {
                actions
                    .iter()
                    .map(|a| format!("[{}]", statement_text(source, &a.kind)))
                    .collect::<Vec<_>>()
                    .join(" ")
            };
            out += &format!(" {} {}", t(sync.do_keyword.span), actions(&sync.actions));
            if let Some((keyword, otherwise)) = &sync.otherwise {
                out += &format!(" {} {}", t(keyword.span), actions(otherwise));
            }
            out
        }
        StatementKind::AccessLevels(attributes) => format!(
            "access levels {}",
            attributes
                .iter()
                .map(|a| format!(
                    "{}={}",
                    t(a.keyword.span),
                    a.value.as_ref().map(e).unwrap_or_default()
                ))
                .collect::<Vec<_>>()
                .join(" ")
        ),
    }
}

fn goto_text(source: &[u8], goto: &Goto) -> String {
    let t = |span: Span| String::from_utf8_lossy(span.of(source)).into_owned();
    let target = match &goto.target {
        None => String::new(),
        Some(GotoTarget::Label(name)) => format!(" label {}", t(name.span)),
        Some(GotoTarget::Number(n)) => format!(" number {}", t(n.span)),
        Some(GotoTarget::Computed(e)) => format!(" computed {}", expr_text(source, e)),
    };
    format!("goto {:?}{target}", goto.kind)
}

fn declarator_text(source: &[u8], d: &Declarator) -> String {
    let t = |span: Span| String::from_utf8_lossy(span.of(source)).into_owned();
    let dims = if d.dimensions.is_empty() {
        String::new()
    } else {
        let items: Vec<String> = d
            .dimensions
            .iter()
            .map(|a| {
                a.value
                    .as_ref()
                    .map(|v| expr_text(source, v))
                    .unwrap_or_default()
            })
            .collect();
        format!("[{}]", items.join(","))
    };
    let init = match &d.init {
        None => String::new(),
        Some(Initializer::Expr(x)) => format!(" = {}", expr_text(source, x)),
        Some(Initializer::List(list)) => format!(" = list({})", arguments_text(source, list)),
    };
    format!("{}{dims}{init}", t(d.name.span))
}

fn arguments_text(source: &[u8], arguments: &Arguments) -> String {
    let items: Vec<String> = arguments
        .items
        .iter()
        .map(|a| {
            a.value
                .as_ref()
                .map(|v| expr_text(source, v))
                .unwrap_or_else(|| "_".into())
        })
        .collect();
    items.join(", ")
}

fn list(source: &[u8], exprs: &[Expr]) -> String {
    exprs
        .iter()
        .map(|x| expr_text(source, x))
        .collect::<Vec<_>>()
        .join(", ")
}

fn variable_text(source: &[u8], v: &Variable) -> String {
    let name = String::from_utf8_lossy(v.name.span.of(source)).into_owned();
    if v.indices.is_empty() {
        name
    } else {
        format!("{name}[{}]", list(source, &v.indices))
    }
}

/// S-expressions for operators; literals and names as written.
fn expr_text(source: &[u8], expr: &Expr) -> String {
    match &expr.kind {
        ExprKind::Number(_) | ExprKind::String => {
            String::from_utf8_lossy(expr.span.of(source)).into_owned()
        }
        ExprKind::Variable(v) => variable_text(source, v),
        ExprKind::Call(c) => format!(
            "{}({})",
            String::from_utf8_lossy(c.name.span.of(source)),
            arguments_text(source, &c.arguments)
        ),
        ExprKind::Unary { op, operand } => format!("({op:?} {})", expr_text(source, operand)),
        ExprKind::Binary { op, lhs, rhs } => format!(
            "({op:?} {} {})",
            expr_text(source, lhs),
            expr_text(source, rhs)
        ),
        ExprKind::Paren(inner) => expr_text(source, inner),
        ExprKind::Tuple(items) => format!("(tuple {})", arguments_text(source, items)),
    }
}
