//! What a program reads from the machine it runs on rather than from its
//! own text: the axis names of the machine data (`$MC_AXCONF_...`), the
//! global variables of GUD files, the macros of macro files and the
//! subprograms of the control's cycle directories (their PROC headers).
//! Given in sinuprep.toml; a program checked without it is checked on its
//! own text.

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::diagnostic::Diagnostic;
use crate::semantic::Model;
use crate::span::Span;
use crate::syntax::macros::Macros;
use crate::syntax::tree::{ExprKind, LineKind, StatementKind};

/// Names defined outside the program.
#[derive(Clone, Debug, Default)]
pub struct Environment {
    /// Axis names (upper case), as machine data names them: channel axes
    /// (`X`, `XC`), machine axes (`X1`, `AX1`), ...
    pub axes: HashSet<String>,
    /// Global variables of definition files (GUD: `DEF NCK REAL _ZERO`),
    /// upper case.
    pub variables: HashSet<String>,
    /// Macros of definition files (`DEFINE M_ON AS M3`) by name, upper
    /// case, with what they stand for.
    pub macros: HashMap<String, Macro>,
    /// The same macros' texts, as the parser expands them where a program
    /// writes their names. Shared: every program of a run reads them.
    pub expansions: Arc<Macros>,
    /// Subprograms of the program's folder and the cycle directories, by
    /// name (upper case). Shared: every program of a directory reaches the
    /// same ones.
    pub procedures: Arc<HashMap<String, Procedure>>,
    /// Where each variable and macro of the definition files is defined:
    /// the file (the archive, for a member of one) and the name's span in it.
    pub defined_in: HashMap<String, (PathBuf, Span)>,
    /// Whether any of it was given (definition files, axis names, cycle
    /// directories): without it, what a program takes from its machine
    /// cannot be checked, and `check` says so once.
    pub given: bool,
}

/// A subprogram a program can call without defining it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Procedure {
    /// The parameters its PROC declares, each as written (`REAL _X`,
    /// `VAR INT _N[3]`), for the editor's signature help.
    pub parameters: Vec<String>,
    /// Its file and the span of the PROC's name in it; `None` for a member
    /// of an archive.
    pub defined: Option<(PathBuf, Span)>,
}

/// What a macro stands for where a program writes its name: its text read
/// as a block once, when its file is read, for the rules that must see
/// through it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Macro {
    /// The text after `AS`, as written.
    pub text: String,
    /// It ends the program (`DEFINE ENDE AS M30`, `M17`, `M2`, `RET`).
    pub ends_program: bool,
}

impl Macro {
    pub(crate) fn of(text: &[u8]) -> Self {
        let lines = crate::syntax::Lines::new(text);
        let ends_program = lines.block(0).is_some_and(|block| {
            let addresses = crate::semantic::addresses::of_block(text, &block);
            crate::semantic::addresses::program_end(text, &block, &addresses).is_some()
        });
        Self {
            text: String::from_utf8_lossy(text).into_owned(),
            ends_program,
        }
    }
}

impl Environment {
    /// With the axis names `names` (any case).
    pub fn with_axes<S: AsRef<str>>(names: impl IntoIterator<Item = S>) -> Self {
        Self {
            axes: names
                .into_iter()
                .map(|n| n.as_ref().trim().to_ascii_uppercase())
                .collect(),
            ..Self::default()
        }
    }

    /// Whether the environment defines `name` (upper case): an axis, a
    /// global variable or a macro.
    pub fn defines(&self, name: &str) -> bool {
        self.axes.contains(name) || self.variables.contains(name) || self.macros.contains_key(name)
    }

    /// Learns the variables and macros of a definition file (GUD or macro
    /// `.DEF`), read with the project's own parser; its syntax errors, if
    /// any, are given back (nothing is learned from a broken file). `file`
    /// is the file `source` is read from and where in it `source` starts.
    pub fn read_definitions(
        &mut self,
        source: &[u8],
        file: Option<(&Path, usize)>,
    ) -> Result<(), Vec<Diagnostic>> {
        let model = Model::of(source);
        if !model.syntax.is_empty() {
            return Err(model.syntax);
        }
        let mut defined = Vec::new();
        for symbol in &model.symbols {
            self.variables.insert(symbol.name.clone());
            defined.push((symbol.name.clone(), symbol.span));
        }
        for (_, line) in model.lines.other_lines() {
            let LineKind::Block(block) = &line.kind else {
                continue;
            };
            for statement in &block.statements {
                if let StatementKind::Define { name, body } = &statement.kind {
                    // The control refuses it, and so does the file's own check.
                    if crate::semantic::model::is_reserved(name.text(source)) {
                        continue;
                    }
                    let upper = crate::syntax::tree::upper(name.text(source));
                    defined.push((upper.clone(), name.span));
                    self.macros.insert(upper, Macro::of(body.of(source)));
                    Arc::make_mut(&mut self.expansions).define(name.text(source), body.of(source));
                }
            }
        }
        if let Some((file, start)) = file {
            for (name, span) in defined {
                let span = Span::new(span.start + start, span.end + start);
                self.defined_in.insert(name, (file.to_path_buf(), span));
            }
        }
        Ok(())
    }
}

/// The machine data that name axes, and so the names a program may write
/// as axes: MD10000 (machine axes), MD20060 (geometry axes), MD20080
/// (channel axes).
const AXIS_NAME_TABLES: [&str; 3] = [
    "$MN_AXCONF_MACHAX_NAME_TAB",
    "$MC_AXCONF_GEOAX_NAME_TAB",
    "$MC_AXCONF_CHANAX_NAME_TAB",
];

/// Whether `source` holds machine data by its content, whatever its name
/// (`INITIAL.INI`, a `.TEA`, machine data saved as `.TXT`): its first block
/// assigns machine data, `$MN_` (NCK), `$MC_` (channel) or `$MA_` (axis),
/// and every other block assigns values (more machine data, setting data,
/// tool data, frames, R parameters, the values of GUD variables), selects
/// the channel the data after it are for (`CHANDATA(n)`, also before the
/// first) or ends the file
/// (`M17`, `M30`, `M2`). Block numbers, comments, a `%_N_` header and
/// `;$PATH=` lines are passed over. A setup program that writes machine
/// data and then runs blocks of its own (`NEWCONF`, `G0 X0`) is a program.
/// Read line by line up to the first block that says otherwise: a program
/// costs its first block.
pub fn holds_machine_data(source: &[u8]) -> bool {
    let mut first = true;
    for raw in crate::syntax::lines::raw_lines(source) {
        let line = raw.content.of(source).trim_ascii_start();
        if line.is_empty() || matches!(line[0], b';' | b'%') {
            continue;
        }
        let digits = |text: &[u8]| text.iter().take_while(|b| b.is_ascii_digit()).count();
        let line = match line.split_first() {
            Some((b'N' | b'n', rest)) if digits(rest) > 0 => {
                rest[digits(rest)..].trim_ascii_start()
            }
            _ => line,
        };
        let starts = |prefix: &[u8]| {
            line.len() > prefix.len() && line[..prefix.len()].eq_ignore_ascii_case(prefix)
        };
        if starts(b"CHANDATA") {
            continue;
        }
        let machine_data = starts(b"$MN_") || starts(b"$MC_") || starts(b"$MA_");
        if first {
            if !machine_data {
                return false;
            }
            first = false;
            continue;
        }
        if !(machine_data || is_end(line) || is_assignment(line)) {
            return false;
        }
    }
    !first
}

/// `M17`, `M30`, `M2` (or `M02`) alone in its block.
fn is_end(line: &[u8]) -> bool {
    let word = line
        .iter()
        .position(|b| b.is_ascii_whitespace() || *b == b';')
        .map_or(line, |end| &line[..end]);
    let rest = line[word.len()..].trim_ascii_start();
    (rest.is_empty() || rest[0] == b';')
        && ["M17", "M30", "M2", "M02"]
            .iter()
            .any(|end| word.eq_ignore_ascii_case(end.as_bytes()))
}

/// A block that begins by assigning a variable: a name (`$TC_DP1`, `R1`,
/// `_ZSFI`), its indices in brackets if any, and `=`.
fn is_assignment(line: &[u8]) -> bool {
    let name = line
        .iter()
        .skip_while(|&&b| b == b'$')
        .take_while(|&&b| b.is_ascii_alphanumeric() || b == b'_')
        .count();
    let dollars = line.iter().take_while(|&&b| b == b'$').count();
    if name == 0 {
        return false;
    }
    let mut rest = line[dollars + name..].trim_ascii_start();
    if rest.first() == Some(&b'[') {
        let Some(close) = memchr::memchr(b']', rest) else {
            return false;
        };
        rest = rest[close + 1..].trim_ascii_start();
    }
    rest.first() == Some(&b'=') && rest.get(1) != Some(&b'=')
}

impl Environment {
    /// Learns the axis names of a machine data file (an `.INI` of the
    /// control: `$MC_AXCONF_CHANAX_NAME_TAB[0]="X"`), of every channel it
    /// holds data for. Only the lines that name `AXCONF_` are parsed, so
    /// the thousands of other machine data of a setup file cost a byte
    /// search; a syntax error in one of them is given back (nothing is
    /// learned from the file then).
    pub fn read_machine_data(&mut self, source: &[u8]) -> Result<(), Vec<Diagnostic>> {
        let (names, errors) = axis_names(source);
        if !errors.is_empty() {
            return Err(errors);
        }
        self.axes.extend(names);
        Ok(())
    }

    /// Learns the axis names of the lines of `source` that read well: for a
    /// file read for something else first (the machine's swivel data,
    /// which reports its own errors).
    pub fn learn_axes(&mut self, source: &[u8]) {
        self.axes.extend(axis_names(source).0);
    }
}

/// The axis names the lines of `source` that name `AXCONF_` give, and the
/// syntax errors of those lines (a broken line gives none).
fn axis_names(source: &[u8]) -> (Vec<String>, Vec<Diagnostic>) {
    let mut names = Vec::new();
    let mut errors = Vec::new();
    for (line, error) in crate::syntax::lines_naming(source, "AXCONF_") {
        if let Some(error) = error {
            errors.push(error);
            continue;
        }
        let LineKind::Block(block) = &line.kind else {
            continue;
        };
        for statement in &block.statements {
            let StatementKind::Assign(assign) = &statement.kind else {
                continue;
            };
            let table = assign.target.name.upper(source);
            if !AXIS_NAME_TABLES.contains(&table.as_str()) {
                continue;
            }
            if let ExprKind::String = assign.value.kind {
                let quoted = assign.value.span.of(source);
                let name = quoted
                    .strip_prefix(b"\"")
                    .and_then(|q| q.strip_suffix(b"\""))
                    .unwrap_or(quoted);
                if !name.is_empty() {
                    names.push(crate::syntax::tree::upper(name));
                }
            }
        }
    }
    (names, errors)
}

/// Lines read for a subprogram's PROC before giving up: it is the first
/// statement of a subprogram (comments and blank lines may come before).
const PROC_WITHIN: usize = 200;

impl Environment {
    /// Learns a subprogram from its PROC header (its name and parameter
    /// count, and where the name stands in `file` when it has one); a file
    /// without one within its first lines (a main program, a text) teaches
    /// nothing.
    pub fn read_procedure(&mut self, source: &[u8], file: Option<&Path>) {
        let mut parser = crate::syntax::LineParser::default();
        for raw in crate::syntax::lines::raw_lines(source).take(PROC_WITHIN) {
            let (line, _) = parser.parse_line(source, raw);
            let LineKind::Block(block) = &line.kind else {
                continue;
            };
            for statement in &block.statements {
                if let StatementKind::Proc(proc) = &statement.kind {
                    let name = crate::syntax::tree::upper(proc.name.text(source));
                    let procedure = Procedure {
                        parameters: proc
                            .parameters
                            .iter()
                            .map(|p| String::from_utf8_lossy(p.span.of(source)).into_owned())
                            .collect(),
                        defined: file.map(|file| (file.to_path_buf(), proc.name.span)),
                    };
                    Arc::make_mut(&mut self.procedures).insert(name, procedure);
                    return;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn definition_files_give_variables_and_macros() {
        let mut environment = Environment::with_axes(["xc"]);
        let gud = b"%_N_MGUD_DEF\n;$PATH=/_N_DEF_DIR\nDEF NCK REAL _ZERO_X, _ZERO_Y\nDEF CHAN INT PART_COUNT\nM30\n";
        environment.read_definitions(gud, None).expect("valid");
        environment
            .read_definitions(b"DEFINE M_ON AS M3\n", None)
            .expect("valid");
        for name in ["XC", "_ZERO_Y", "PART_COUNT", "M_ON"] {
            assert!(environment.defines(name), "{name}");
        }
        environment
            .read_definitions(
                b"DEFINE ENDE AS M30\nDEFINE BACK AS RET\nDEFINE FAST AS G0 X0\n",
                None,
            )
            .expect("valid");
        let ends = |name: &str| environment.macros[name].ends_program;
        assert!(ends("ENDE") && ends("BACK") && !ends("FAST") && !ends("M_ON"));
        assert_eq!(environment.macros["M_ON"].text, "M3");
        assert!(!environment.defines("ZERO_X"));
        assert!(environment
            .read_definitions(b"DEF NCK REAL (\n", None)
            .is_err());
        // A member of an archive: spans count from the archive's start.
        let member = b"DEF NCK REAL _A\nDEFINE M_OFF AS M5\n";
        environment
            .read_definitions(member, Some((Path::new("GUD.ARC"), 100)))
            .expect("valid");
        let place = |name: &str| environment.defined_in[name].clone();
        assert_eq!(place("_A"), (PathBuf::from("GUD.ARC"), Span::new(113, 115)));
        assert_eq!(
            place("M_OFF"),
            (PathBuf::from("GUD.ARC"), Span::new(123, 128))
        );
    }

    #[test]
    fn machine_data_give_the_axis_names() {
        let mut environment = Environment::default();
        let ini = b"CHANDATA(1)\n$MC_AXCONF_GEOAX_NAME_TAB[0]=\"X\"\n$MC_AXCONF_CHANAX_NAME_TAB[3]=\"b\"\n\
$MN_AXCONF_MACHAX_NAME_TAB[0]=\"X1\"\n$MN_AXCONF_LOGIC_MACHAX_TAB[0]=\"NC1_AX1\"\n$MA_IS_ROT_AX[AX4]=1\n$TC_DP1[1,1]=120\nM17\n";
        environment.read_machine_data(ini).expect("valid");
        let mut axes: Vec<&str> = environment.axes.iter().map(String::as_str).collect();
        axes.sort_unstable();
        assert_eq!(axes, ["B", "X", "X1"]);
        assert!(environment
            .read_machine_data(b"$MC_AXCONF_CHANAX_NAME_TAB[0]=(\n")
            .is_err());
    }

    #[test]
    fn machine_data_are_known_by_their_blocks() {
        for data in [
            &b"%_N_NC_TEA\n; NCK\nN10000 $MN_AXCONF_MACHAX_NAME_TAB[0]=\"X1\"\n"[..],
            b"CHANDATA(2)\n$mc_axconf_chanax_name_tab[0]=\"XS\"\nM17\n",
            b"\n   N30130 $MA_CTRLOUT_TYPE[0,AX1]=1\n",
            b"$MN_X=1\nCHANDATA(1)\n$TC_DP1[1,1]=120\nR[0]=1 R1=2\n_ZSFI [2] = 3\n$SN_JOG=0\nM17 ; end\n",
        ] {
            assert!(holds_machine_data(data), "{}", String::from_utf8_lossy(data));
        }
        for other in [
            &b"N10 G0 X0\nN20 $MN_AXCONF_MACHAX_NAME_TAB[0]=\"X1\"\n"[..],
            b"N20070 $MC_AXCONF_MACHAX_USED[0]=1\nN20 NEWCONF\nN10 G0 X0\nN30 M30\n",
            b"$MN_X=1\nIF R1==1 GOTOF A\n",
            b"$TC_DP1[1,1]=120\n",
            b"; $MN_ in a comment\n",
            b"$MN_\n",
            b"",
        ] {
            assert!(
                !holds_machine_data(other),
                "{}",
                String::from_utf8_lossy(other)
            );
        }
    }

    #[test]
    fn a_broken_line_keeps_the_machine_files_other_axis_names() {
        let mut environment = Environment::default();
        environment
            .learn_axes(b"$MN_AXCONF_MACHAX_NAME_TAB[0]=(\n$MC_AXCONF_CHANAX_NAME_TAB[0]=\"XS\"\n");
        assert!(environment.defines("XS"));
    }

    #[test]
    fn a_cycle_directory_gives_procedures_with_their_parameters() {
        let mut environment = Environment::default();
        environment.read_procedure(
            b";cycle\n\nPROC Align(REAL _A, VAR REAL _B[3], INT _N) SAVE\nM17\n",
            Some(Path::new("ALIGN.SPF")),
        );
        environment.read_procedure(b"PROC NOARGS\nRET\n", None);
        environment.read_procedure(b"N10 G0 X0\nM30\n", None);
        let align = &environment.procedures["ALIGN"];
        assert_eq!(align.parameters, ["REAL _A", "VAR REAL _B[3]", "INT _N"]);
        assert_eq!(
            align.defined,
            Some((PathBuf::from("ALIGN.SPF"), Span::new(13, 18)))
        );
        assert!(environment.procedures["NOARGS"].parameters.is_empty());
        assert_eq!(environment.procedures.len(), 2);
    }
}
