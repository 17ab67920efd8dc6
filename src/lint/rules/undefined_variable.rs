//! N005 `undefined-variable`: Finds a user variable read before any DEF, PROC parameter or assignment defines it.

use crate::diagnostic::{Applicability, Diagnostic, Fix, RuleInfo, Severity};
use crate::hash::{HashMap, HashSet};
use crate::lint::rule::{Check, FileContext, Sees, StatementAt};
use crate::lint::rules::support::*;
use crate::span::Span;
use crate::suggest::Nearest;
use crate::syntax::tree::{
    upper_in, Expr, ExprKind, Initializer, Statement, StatementKind, TypeKind,
};

pub static RULE: RuleInfo = RuleInfo {
    code: "N005",
    name: "undefined-variable",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a user variable read before any DEF, PROC parameter or assignment defines it.

## Why it matters
The control stops with alarm 12550 ("name not defined") unless the name is a global (GUD) defined
in a definition file; a typo in a name reads as an undefined variable.

## Example
```
DEF REAL LAYER_HEIGHT
N10 Z=IC(LAYER_HIGHT)   ; typo
```

## Fix
Declare the variable with DEF (or correct its spelling). Names of R parameters, system variables
(`$...`), cycle data (`_...`), one-letter addresses, global R parameters (`RG1`), the
orientation names of `PO[...]` (`PHI`, `PSI`, `THT`, `XH`, `YH`, `ZH`), the machine's axis names
(`axes = ["XC", "AX1"]` in sinuprep.toml, or the `$MC_AXCONF_CHANAX_NAME_TAB`, `$MC_AXCONF_GEOAX_NAME_TAB`
and `$MN_AXCONF_MACHAX_NAME_TAB` lines of machine data, every channel's: an `.INI`, or a file of
any name whose blocks are machine data (the first assigns `$MN_`, `$MC_` or `$MA_`), given as a
definition file, as the machine (`--machine`) or as an archive's member), the
globals and macros of the definition files given (`--definitions MGUD.DEF`, `definitions =
[...]` in sinuprep.toml), a bare name given to an AXIS variable
(`DEF AXIS _AX` then `_AX=XC`), a machine axis by its number (`AX1` ... `AXn`, known on every
machine: `SPOS[AX4]`, `TRAILON(AX2,AX1)`, `$MA_IS_ROT_AX[AX4]`) and `NO_AXIS` are not checked. A name defined before it
within two edits (one for names of up to four letters) is offered as did-you-mean, and as an
unsafe fix (`check --fix --unsafe-fixes`). Checked without any of the machine's definitions, a
name no definition near it explains may be a GUD variable, macro or axis of the machine: the
finding says so and asks for the definition files, since a DEF written for a macro's name would
break the program."#,
};

#[derive(Default)]
pub struct Checker {
    /// Names defined so far, with their type when a DEF or parameter gave one.
    defined: HashMap<String, Option<TypeKind>>,
    /// The same names, for the did-you-mean.
    nearest: Nearest,
    /// An AXIS variable is among them.
    axis_variables: bool,
    reported: HashSet<String>,
    /// Where a name is made upper case to be looked up.
    name_buffer: String,
}

/// Names that read like user variables but are the language's own: the
/// orientation angles and vector components of `PO[...]`, `ORIVECT` and
/// the like (Siemens, Job Planning, "Orientation programming").
const PREDEFINED: [&str; 6] = ["PHI", "PSI", "THT", "XH", "YH", "ZH"];

/// `RG<n>`: an NCK-global R parameter (MD18156), like `R<n>` no variable of
/// the program's own.
fn is_global_r_parameter(name: &str) -> bool {
    name.strip_prefix("RG")
        .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
}

/// The value of an assignment to an AXIS variable, or of its DEF, when it is
/// a bare name (`_AX=AX1`, `DEF AXIS _AX=XC`): an axis identifier, not a read.
/// `axis_variables`: whether any AXIS variable is defined (most programs
/// have none, and then no assignment's target is looked up).
fn axis_value(
    source: &[u8],
    statement: &Statement,
    defined: &HashMap<String, Option<TypeKind>>,
    axis_variables: bool,
) -> Vec<Span> {
    let bare = |expr: &Expr| match &expr.kind {
        ExprKind::Variable(v) if v.indices.is_empty() => Some(v.name.span),
        _ => None,
    };
    match &statement.kind {
        StatementKind::Assign(assign) if axis_variables => {
            let target = upper(source, assign.target.name.span);
            if defined.get(&target) == Some(&Some(TypeKind::Axis)) {
                return bare(&assign.value).into_iter().collect();
            }
            Vec::new()
        }
        StatementKind::Def(def) if def.data_type.kind == TypeKind::Axis => def
            .variables
            .iter()
            .filter_map(|d| match &d.init {
                Some(Initializer::Expr(expr)) => bare(expr),
                _ => None,
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// `AX<n>` (upper case): a machine axis by its number, which the language
/// knows on every machine (`SPOS[AX4]`, `TRAILON(AX2,AX1)`,
/// `$MA_IS_ROT_AX[AX4]`); `NO_AXIS`: no axis, the value of an empty AXIS
/// variable (Job Planning, "Axis types" and "Variable types").
fn is_axis_identifier(name: &str) -> bool {
    name == "NO_AXIS"
        || name
            .strip_prefix("AX")
            .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::STATEMENTS
    }

    fn statement(&mut self, file: &FileContext, at: &StatementAt, out: &mut Vec<Diagnostic>) {
        let statement = at.statement;
        let axes = axis_value(file.source, statement, &self.defined, self.axis_variables);
        // Names are made upper case in one buffer; a string is made only for
        // a name defined or reported.
        let mut buffer = std::mem::take(&mut self.name_buffer);
        for variable in at.reads() {
            if axes.contains(&variable.name.span) {
                continue;
            }
            let name = upper_in(variable.name.text(file.source), &mut buffer);
            if is_user_name(name)
                && !self.defined.contains_key(name)
                && !file.environment.defines(name)
                && !PREDEFINED.contains(&name)
                && !is_global_r_parameter(name)
                && !is_axis_identifier(name)
                && !self.reported.contains(name)
            {
                self.reported.insert(name.to_string());
                let given = file.environment.given;
                out.push(self.undefined(name.to_string(), variable.name.span, given));
            }
        }
        let text = |span: Span| span.of(file.source);
        match &statement.kind {
            StatementKind::Def(def) => {
                for d in &def.variables {
                    let name = upper_in(text(d.name.span), &mut buffer);
                    self.define(name, Some(def.data_type.kind));
                }
            }
            StatementKind::Proc(proc) => {
                for p in &proc.parameters {
                    let name = upper_in(text(p.declarator.name.span), &mut buffer);
                    self.define(name, Some(p.data_type.kind));
                }
            }
            StatementKind::Assign(assign) => {
                self.define(upper_in(text(assign.target.name.span), &mut buffer), None)
            }
            StatementKind::For { variable, .. } => {
                self.define(upper_in(text(variable.span), &mut buffer), None)
            }
            _ => {}
        }
        self.name_buffer = buffer;
    }
}

impl Checker {
    /// `name` is defined from here on; a type given later (a DEF after an
    /// assignment) is kept.
    fn define(&mut self, name: &str, data_type: Option<TypeKind>) {
        self.axis_variables |= data_type == Some(TypeKind::Axis);
        match self.defined.get_mut(name) {
            Some(known) => {
                if data_type.is_some() {
                    *known = data_type;
                }
            }
            None => {
                self.nearest.push(name);
                self.defined.insert(name.to_string(), data_type);
            }
        }
    }

    /// The finding for `name` at `span`, with the defined name it may have
    /// been meant as (`DEPTHH` for a defined `DEPTH`).
    /// The finding on `name`; `given` says whether the machine's
    /// definitions were given, without which the name may well be theirs.
    fn undefined(&mut self, name: String, span: Span, given: bool) -> Diagnostic {
        let most = if name.len() <= 4 { 1 } else { 2 };
        let diagnostic = RULE.at(span).label("not defined yet");
        if !given && self.nearest.closest(&name, most).is_none() {
            // A DEF added for a GUD variable or a macro of the machine would
            // break the program: the advice is to give the definitions.
            return diagnostic
                .message(format!("`{name}` is read before any DEF or assignment of this program, and no definitions of the machine were given: it may be one of its GUD variables, macros or axes"))
                .help(format!("give the machine's definition files (`definitions` in sinuprep.toml, --definitions FILE) or its axes; if `{name}` is the program's own, declare it before this block (`DEF REAL {name}`)"));
        }
        let diagnostic =
            diagnostic.message(format!("`{name}` is read before any DEF or assignment"));
        match self.nearest.closest(&name, most).map(str::to_string) {
            Some(meant) => diagnostic
                .help(format!("did you mean `{meant}`? Otherwise declare it, as `DEF REAL {name}`, before this block"))
                .fix(Fix::replace(
                    format!("write `{meant}`"),
                    Applicability::Unsafe,
                    span,
                    meant.as_bytes(),
                )),
            None => diagnostic.help(format!("declare it, as `DEF REAL {name}`, before this block (a global of a GUD file: name the file with --definitions or in sinuprep.toml)")),
        }
    }
}
