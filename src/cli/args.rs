//! The command line, declared with clap's derive API.

use std::path::PathBuf;

use clap::{Parser, Subcommand, ValueEnum};

use crate::cli::notation::Notation;
use crate::emit::cycle600::Form;
use crate::rotation::Sequence;
use crate::workspace::SeverityName;

#[derive(Debug, Parser)]
#[command(
    name = "sinuprep",
    version,
    about = "Preprocessor and linter for Siemens Sinumerik part programs"
)]
pub struct Args {
    #[command(subcommand)]
    pub command: Command,
    /// Colour in reports and messages: `auto` on a terminal, unless NO_COLOR is set (CLICOLOR_FORCE forces it).
    #[arg(long, global = true, value_enum, default_value_t = ColorChoice::Auto, value_name = "WHEN")]
    pub color: ColorChoice,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ColorChoice {
    Auto,
    Always,
    Never,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Lint NC programs (files, directories, archives, or `-` for stdin): syntax errors,
    /// CYCLE600 findings and the general NC rules (`sinuprep rule --all`);
    /// `--fix` applies the safe fixes.
    Check(CheckArgs),
    /// Rewrite CYCLE600 calls as native CYCLE800 / frames / TRAORI code; every
    /// other byte stays as it is.
    Rewrite(RewriteArgs),
    /// Lay programs out (indent by block, blanks, case) and renumber them
    /// (`--renumber`), in place; strings, comments and HMI regions stay as they are.
    Fmt(FmtArgs),
    /// Show how each CYCLE600 call evaluates: parameters, provenance, matrix,
    /// angles, results and the code a rewrite emits.
    Eval(EvalArgs),
    /// Print a rule's documentation (`sinuprep rule N001`), or list every rule (`--all`).
    Rule(RuleArgs),
    /// Convert a rotation from one form to another: angles of any sequence, matrix,
    /// quaternion, axis and angle, Gibbs vector, Sinumerik frame statements, a
    /// post-processor's ROT_MAT (given, or one per line on stdin).
    #[command(allow_negative_numbers = true)]
    Convert(ConvertArgs),
    /// Convert a whole frame, translation and rotation, from one form to another, or
    /// give the tool-to-piece frame of a tool chain and a piece chain.
    #[command(allow_negative_numbers = true)]
    Frame(FrameArgs),
    /// Compute one swivel on a machine: the rotary axis positions its swivel
    /// data record gives a frame rotation (CYCLE800's axis-by-axis `_MODE` and
    /// angles), both solutions, the one the control takes, the rotation left
    /// in the frame and the zero-point shift.
    #[command(allow_negative_numbers = true)]
    Axes(AxesArgs),
    /// From points probed on an inclined face (two along X and two along Y,
    /// three anywhere, or its normal) to its two angles as CYCLE600 takes
    /// them (extrinsic X, Y), the CYCLE600 call and the CYCLE800 that turn
    /// the tool normal to the face.
    Probe(ProbeArgs),
    /// The axis of a rotary joint: from a point measured before and after a
    /// known turn (both solutions), or from two or three measured positions
    /// (the axis and a point on it); also as the `$TC_CARR` axis vector.
    #[command(allow_negative_numbers = true)]
    Axis(AxisArgs),
    /// Print what the machine's own data say: its axes with their names,
    /// software limits and dynamics, its swivel data records, and what could
    /// not be read (a machine-data file, an archive of a series start-up).
    Machine(MachineArgs),
    /// Run a program offline on the machine its own data describe (the dry
    /// run): each block's machine positions against the software limits
    /// (K007), and the time it takes from the feeds and the axes' dynamics.
    Run(RunArgs),
    /// Print the completion script of a shell (`sinuprep completions bash >
    /// /usr/share/bash-completion/completions/sinuprep`).
    Completions(CompletionsArgs),
    /// Print the man page, as roff (`sinuprep manpage > sinuprep.1`), a command's
    /// (`sinuprep manpage check > sinuprep-check.1`), or write them all to a directory (`--dir`).
    Manpage(ManpageArgs),
    /// Serve an editor as a language server over stdin and stdout (LSP):
    /// findings as you type, hover on CYCLE600 calls and names, definitions,
    /// references, symbols, folding and fixes.
    Lsp,
}

#[derive(Debug, clap::Args)]
pub struct ManpageArgs {
    /// The command whose page to print (`check`: sinuprep-check(1)) [default: sinuprep(1)].
    #[arg(value_name = "COMMAND")]
    pub command: Option<String>,
    /// Write every page to DIR instead: sinuprep.1 and one for each command (sinuprep-check.1, ...).
    #[arg(long, value_name = "DIR", conflicts_with = "command")]
    pub dir: Option<PathBuf>,
}

#[derive(Debug, clap::Args)]
pub struct CompletionsArgs {
    pub shell: clap_complete::Shell,
}

#[derive(Debug, clap::Args)]
pub struct AxesArgs {
    /// The machine's swivel data records: NC assignments `$TC_CARRn[m]=value`
    /// (a setup program, TO_INI.INI, INITIAL.INI) [default: `machine` in sinuprep.toml].
    #[arg(long, value_name = "FILE")]
    pub machine: Option<PathBuf>,
    /// The record, by its name (`$TC_CARR34`, CYCLE800's `_TC`) or number
    /// [default: the machine's only record with rotary axes].
    #[arg(long, value_name = "NAME")]
    pub record: Option<String>,
    /// A rotary table under the head: its record (kinematics "P", one axis), by
    /// name or number. The swivel is split over three rotary axes: the table's
    /// angle is chosen as `--prefer` says (or fixed with `--fix`), and the head
    /// (`--record`) is solved for the rest.
    #[arg(long, value_name = "NAME")]
    pub table: Option<String>,
    /// The table's angle, fixed instead of chosen: `--fix B=30` (the table
    /// axis's name, `$TC_CARR35`, and its position in degrees).
    #[arg(long, value_name = "AXIS=DEGREES", requires = "table")]
    pub fix: Option<String>,
    /// Which table angle to choose. `middle`: the head's axes nearest the
    /// middles of their limits (the default: the head keeps the most travel for
    /// the machining that follows, and the answer does not depend on where the
    /// axes stood, which offline is seldom known). `nearest`: the three axes
    /// moved least from their positions before (`--from`), the largest travel
    /// the smallest, as CAM systems choose.
    #[arg(long, value_enum, default_value_t = Prefer::Middle, requires = "table", conflicts_with = "fix")]
    pub prefer: Prefer,
    /// The rotary axes' positions before the swivel, by their names
    /// (`$TC_CARR35/36`): `--from B=10,C=90,A=0` or `--from B=10 --from A=0`.
    /// What `--prefer nearest` measures from, the turn a position is placed in
    /// and where an axis left free at a pole stays [default: each record's
    /// `$TC_CARR13/14`].
    #[arg(long, value_name = "AXIS=DEGREES", value_delimiter = ',')]
    pub from: Vec<String>,
    /// Where the work zero lies (machine coordinates, the table unturned), for how
    /// far it moves with the table: `--work-zero=X,Y,Z` [default: 0,0,0, where
    /// it moves as the end of the table's chain does].
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true, value_parser = point, requires = "table")]
    pub work_zero: Option<[f64; 3]>,
    /// CYCLE800's `_MODE` for axis-by-axis rotation: the sequence code of the
    /// three rotations about the turned axes (57 = X, Y', Z''; 27 = Z, Y', X'').
    #[arg(long, default_value_t = 57)]
    pub mode: i64,
    /// The three angles `_A`, `_B`, `_C` in degrees, in the order of the sequence.
    #[arg(value_parser = finite_angle, num_args = 3, required_unless_present_any = ["export", "from_a3200"], value_names = ["A", "B", "C"])]
    pub angles: Vec<f64>,
    /// Instead of a swivel, write the record's setup in another control's words:
    /// `a3200`, Aerotech's ROTATION / ANGLE / Displacement commands (a table, P).
    #[arg(long, value_enum, value_name = "CONTROL", conflicts_with_all = ["angles", "table"])]
    pub export: Option<Export>,
    /// Instead of a swivel, read an A3200 ROTATION setup and write the swivel data
    /// record it determines, as `$TC_CARRn[1]=value` assignments.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["angles", "table", "export", "machine"])]
    pub from_a3200: Option<PathBuf>,
    /// CYCLE800's `_DIR`: -1 takes the lower position of the direction-reference
    /// axis, 1 the higher (the other solution when the asked one is outside the limits)
    /// [default: -1; with --table and --prefer nearest, whichever travels least].
    #[arg(long, value_parser = direction)]
    pub dir: Option<i8>,
    /// The direction-reference axis of `_DIR` (1 or 2) [default: the axis that tilts the tool].
    #[arg(long, value_name = "1|2", value_parser = clap::value_parser!(u8).range(1..=2))]
    pub reference_axis: Option<u8>,
    /// Add the fine offsets ($TC_CARR41..65), as the control does with SD42974 = 1.
    #[arg(long)]
    pub fine_offsets: bool,
    /// The settings file (default: the nearest sinuprep.toml from the current directory upward).
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
}

/// Another control's words for a machine.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Export {
    /// Aerotech A3200: `ROTATION n InputAxes ... OutputAxes ...`, `ANGLE`, `Displacement`.
    A3200,
}

#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// Files or directories (walked for .mpf/.spf/.arc files, or what `include` takes, leaving out hidden names and what .gitignore ignores); an archive is read as its programs; `-` reads stdin. None: the current directory (stdin with --stdin-filename).
    pub paths: Vec<PathBuf>,
    /// How to print the diagnostics (`--output-format`, as ruff and `rewrite` name it).
    #[arg(long = "output-format", visible_alias = "format", value_enum, default_value_t = Format::Human)]
    pub format: Format,
    /// Write the report to FILE (atomically: the whole report or, should the run fail, nothing) instead of stdout; the summary stays on stderr.
    #[arg(long, short, value_name = "FILE")]
    pub output_file: Option<PathBuf>,
    /// Instead of the findings, how many each rule found: count, code, `[*]` where --fix answers some, name (JSON with --output-format json).
    #[arg(long)]
    pub statistics: bool,
    /// Report only these rules (codes or prefixes, comma-separated: `N,C6,S`).
    #[arg(long, value_delimiter = ',', value_name = "CODES")]
    pub select: Vec<String>,
    /// Do not report these rules (codes or prefixes, comma-separated).
    #[arg(long, value_delimiter = ',', value_name = "CODES")]
    pub ignore: Vec<String>,
    /// Report only findings of this severity or higher.
    #[arg(long, value_enum, value_name = "SEVERITY")]
    pub severity_min: Option<SeverityName>,
    /// Exit 1 on warnings too.
    #[arg(long)]
    pub deny_warnings: bool,
    /// Exit 0 whatever the findings (2 still when the tool fails), to report without failing.
    #[arg(long, conflicts_with = "deny_warnings")]
    pub exit_zero: bool,
    /// The name of the program read from stdin, for paths in reports, HEAD_DEF and sinuprep.toml lookup.
    #[arg(long, value_name = "NAME")]
    pub stdin_filename: Option<PathBuf>,
    /// Apply the safe fixes to the files, each rewritten atomically (a file with syntax errors is left alone), then report what remains.
    #[arg(long)]
    pub fix: bool,
    /// A definition file (GUD variables, macros) or machine data file (`.INI`: axis names) the programs use, as the control holds it (repeatable; also `definitions = [...]` in sinuprep.toml).
    #[arg(long = "definitions", value_name = "FILE")]
    pub definitions: Vec<PathBuf>,
    /// A cycle directory of the control (CUS, CMA, CST as copied from the machine), searched after the program's own directory for the subprograms it calls, whose PROC headers N018 checks calls against (repeatable, in search order; also `cycles = [...]` in sinuprep.toml).
    #[arg(long = "cycles", value_name = "DIR")]
    pub cycles: Vec<PathBuf>,
    /// The machine: its swivel data records (`$TC_CARRn[m]=value`), machine data, tool offsets and frames, as a setup program, an `.INI` the control writes, a series start-up archive or a folder of them; each swivel of the programs is solved on the record it names (K002-K005) and the machine data a program reads are known [default: `machine` in sinuprep.toml].
    #[arg(long, value_name = "PATH")]
    pub machine: Option<PathBuf>,
    /// Add the records' fine offsets ($TC_CARR41..65), as the control does with SD42974 = 1.
    #[arg(long)]
    pub fine_offsets: bool,
    #[command(flatten)]
    pub walk: WalkArgs,
    /// No summary line (`3 errors, 2 warnings in 5 files`) after the human and short reports.
    #[arg(long, short)]
    pub quiet: bool,
    /// With --fix, apply the unsafe fixes too (did-you-mean corrections of names, labels and keywords).
    #[arg(long, requires = "fix")]
    pub unsafe_fixes: bool,
    #[command(flatten)]
    pub input: InputArgs,
}

/// What every command that evaluates programs reads beside them.
#[derive(Debug, clap::Args)]
pub struct InputArgs {
    /// A measured value, as an NC assignment: `--set R10=0.215`, `--set _OVR[16]=-0.113` (repeatable).
    #[arg(long = "set", value_name = "NAME=VALUE")]
    pub set: Vec<String>,
    /// A file of measured values, one NC assignment per line (`R10=0.215`, `;` comments).
    #[arg(long, value_name = "FILE")]
    pub values: Option<PathBuf>,
    /// The HEAD_DEF subprogram defining the accessories (default: HEAD_DEF.SPF next to the program, any case).
    #[arg(long, value_name = "FILE")]
    pub heads: Option<PathBuf>,
    /// The settings file (default: the nearest sinuprep.toml from the program's directory upward).
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
}

/// Which files a directory walk takes (a file named is always taken).
#[derive(Debug, clap::Args)]
pub struct WalkArgs {
    /// A directory without programs is no error (by default it is: exit 2).
    #[arg(long)]
    pub allow_empty: bool,
    /// Follow symbolic links met while walking a directory (by default they are skipped, with a note; a link named on the command line is always followed).
    #[arg(long)]
    pub follow_links: bool,
    /// Leave out the files and folders these patterns match (`.gitignore` lines, relative to the current directory, any case; comma-separated, repeatable), in place of `exclude` in sinuprep.toml.
    #[arg(long, value_delimiter = ',', value_name = "PATTERNS")]
    pub exclude: Vec<String>,
    /// Leave out these too, besides `exclude` and `extend-exclude` in sinuprep.toml.
    #[arg(long, value_delimiter = ',', value_name = "PATTERNS")]
    pub extend_exclude: Vec<String>,
    /// Take only the files these patterns match (`*.nc`, `_N_*_MPF`; relative to the current directory, any case; comma-separated, repeatable), in place of `include` in sinuprep.toml and of the default `.mpf`, `.spf` and `.arc`.
    #[arg(long, value_delimiter = ',', value_name = "PATTERNS")]
    pub include: Vec<String>,
    /// Take the files these patterns match too (`*.nc`, `_N_*_MPF`), besides `.mpf`, `.spf` and `.arc` (`include`, `extend-include` in sinuprep.toml).
    #[arg(long, value_delimiter = ',', value_name = "PATTERNS")]
    pub extend_include: Vec<String>,
    /// Take what .gitignore, .ignore and git's exclude files ignore (by default it is left out; also `respect-gitignore = false` in sinuprep.toml).
    #[arg(long, overrides_with = "respect_gitignore")]
    pub no_respect_gitignore: bool,
    /// Leave out what .gitignore, .ignore and git's exclude files ignore, over `respect-gitignore = false` in sinuprep.toml.
    #[arg(long, overrides_with = "no_respect_gitignore", hide = true)]
    pub respect_gitignore: bool,
    /// Walk into hidden folders and take hidden files (names beginning with `.`).
    #[arg(long)]
    pub hidden: bool,
    /// Leave out a file named on the command line when the exclude patterns match it or a folder it lies in, as a walk does (for tools that pass every changed file, as pre-commit does; also `force-exclude = true` in sinuprep.toml).
    #[arg(long)]
    pub force_exclude: bool,
}

impl WalkArgs {
    /// The walk these options ask for, over the settings of `workspace`.
    pub fn walk<'w>(
        &self,
        workspace: &'w crate::workspace::Workspace,
    ) -> crate::cli::walk::Walk<'w> {
        crate::cli::walk::Walk {
            allow_empty: self.allow_empty,
            follow_links: self.follow_links,
            hidden: self.hidden,
            workspace,
        }
    }

    /// What the walk's options set over sinuprep.toml.
    pub fn given(&self) -> crate::workspace::WalkGiven {
        crate::workspace::WalkGiven {
            exclude: self.exclude.clone(),
            extend_exclude: self.extend_exclude.clone(),
            include: self.include.clone(),
            extend_include: self.extend_include.clone(),
            respect_gitignore: match (self.respect_gitignore, self.no_respect_gitignore) {
                (true, _) => Some(true),
                (_, true) => Some(false),
                _ => None,
            },
            force_exclude: self.force_exclude.then_some(true),
        }
    }
}

#[derive(Debug, clap::Args)]
pub struct RunArgs {
    /// The program to run (a main program; `-` reads stdin).
    pub path: PathBuf,
    /// The machine: its machine data (axes, limits, dynamics), tool offsets and
    /// settable frames, as an `.INI` the control writes, a series start-up
    /// archive or a folder of them [default: `machine` in sinuprep.toml].
    #[arg(long, value_name = "PATH")]
    pub machine: Option<PathBuf>,
    /// A definition file (GUD variables, macros) the program uses (repeatable; also `definitions = [...]` in sinuprep.toml).
    #[arg(long = "definitions", value_name = "FILE")]
    pub definitions: Vec<PathBuf>,
    /// A cycle directory of the control, searched after the program's own directory for the subprograms it calls (repeatable, in search order; also `cycles = [...]` in sinuprep.toml).
    #[arg(long = "cycles", value_name = "DIR")]
    pub cycles: Vec<PathBuf>,
    #[command(flatten)]
    pub input: InputArgs,
    /// How to print it: a summary for people, one JSON object (schema in
    /// docs/guide.md), or SARIF 2.1.0 of the limits passed (K007).
    #[arg(long = "output-format", visible_alias = "format", value_enum, default_value_t = RunFormat::Human)]
    pub format: RunFormat,
    /// With `--format json`: every block executed, its line, its machine
    /// positions and the time so far, written as the run goes.
    #[arg(long)]
    pub blocks: bool,
    /// Also write one self-contained HTML page (no script, nothing fetched)
    /// with each axis's position over time against its limits, the path
    /// from above and from the front, and the time per tool.
    #[arg(long, value_name = "FILE")]
    pub html: Option<PathBuf>,
    /// Check against the second software limits (MD36120/MD36130), as the PLC may select them.
    #[arg(long)]
    pub second_limits: bool,
    /// The dynamic response group whose MD32300/MD32431 apply: 0 DYNNORM, 1 DYNPOS, 2 DYNROUGH, 3 DYNSEMIFIN, 4 DYNFINISH.
    #[arg(long, value_name = "N", default_value_t = 0, value_parser = clap::value_parser!(u8).range(0..5))]
    pub dynamic_group: u8,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum RunFormat {
    Human,
    Json,
    Sarif,
}

#[derive(Debug, clap::Args)]
pub struct MachineArgs {
    /// The machine's data: an `.INI` the control writes (`INITIAL.INI`,
    /// `_N_AX1_TEA_INI`), an archive of a series start-up (`.arc`), a
    /// folder of them (`INITIAL` first, each finding on its own file's
    /// line), or a setup program with `$TC_CARR` records.
    pub path: PathBuf,
    /// How to print it: a table for people, or one JSON object (schema in
    /// docs/guide.md).
    #[arg(long = "output-format", visible_alias = "format", value_enum, default_value_t = MachineFormat::Human)]
    pub format: MachineFormat,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MachineFormat {
    /// A table of the axes, then the records and what could not be read.
    Human,
    /// One JSON object.
    Json,
}

#[derive(Debug, clap::Args)]
pub struct RuleArgs {
    /// The rule's code or name, as `N001`, `C605` or `undefined-variable`.
    #[arg(required_unless_present = "all")]
    pub code: Option<String>,
    /// List every rule: code, name, severity.
    #[arg(long, conflicts_with = "code")]
    pub all: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// miette's report with the source line and a label.
    Human,
    /// One line each: `path:line:col: severity[CODE] message`.
    Short,
    /// One JSON document (schema in docs/guide.md).
    Json,
    /// GitHub Actions workflow commands (`::error file=...::message`).
    Github,
    /// SARIF 2.1.0, for code-scanning tools.
    Sarif,
}

/// What the offline evaluation needs beyond the program.
#[derive(Debug, clap::Args)]
pub struct AnalysisArgs {
    #[command(flatten)]
    pub input: InputArgs,
    /// How a rotating CYCLE600 (_SW_REC=0) is written [default: cycle800].
    #[arg(long, value_enum)]
    pub emit: Option<Form>,
    /// Decimals of emitted numbers, trailing zeros trimmed, never an exponent [default: 6].
    #[arg(long, value_parser = clap::value_parser!(u8).range(0..=15))]
    pub precision: Option<u8>,
    /// Compute calls whose angles (or translations) are measured at run time on the
    /// control, in native arithmetic, instead of refusing them.
    #[arg(long)]
    pub emit_runtime: bool,
    /// With --emit-runtime, keep the intermediate values in R parameters from R N upward
    /// (instead of local variables declared with DEF), N from 0 to 99999.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(0..=i64::from(crate::emit::runtime::MAX_R_BASE)))]
    pub runtime_r: Option<u32>,
    /// How diagnostics are printed on stderr (`--output-format`, as `check` names it).
    #[arg(long = "output-format", visible_alias = "message-format", value_enum, default_value_t = MessageFormat::Human)]
    pub message_format: MessageFormat,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MessageFormat {
    /// miette's report with the source line.
    Human,
    /// One line each: `path:line:col: severity[CODE] message`.
    Short,
}

#[derive(Debug, clap::Args)]
pub struct RewriteArgs {
    /// Programs or directories (walked for .mpf/.spf/.arc files, or what `include` takes, leaving out hidden names and what .gitignore ignores); an archive is read as its programs; `-` reads stdin. None: the current directory with --check, --in-place, -o or --diff; stdin otherwise (when it is no terminal).
    /// Several programs need --in-place, -o DIR, --check or --diff.
    pub paths: Vec<PathBuf>,
    #[command(flatten)]
    pub walk: WalkArgs,
    #[command(flatten)]
    pub analysis: AnalysisArgs,
    /// Do not keep the original call as a `; sinuprep:` comment above the new code.
    #[arg(long)]
    pub no_original: bool,
    /// Replace later reads of `_CYC600_n` by their values, until the next CYCLE600.
    #[arg(long)]
    pub inline_results: bool,
    /// The machine's swivel data records: each rewritten swivel gets a comment naming
    /// the rotary axis positions its record takes [default: `machine` in sinuprep.toml].
    #[arg(long, value_name = "FILE")]
    pub machine: Option<PathBuf>,
    /// A rotary table under the machine's heads: its record (kinematics "P", one axis), by
    /// name or number. A swivel on a head record splits over the table and the head, which
    /// no native form is documented for: such a call is refused (C620) with the split's
    /// numbers [default: `table` in sinuprep.toml].
    #[arg(long, value_name = "NAME")]
    pub table: Option<String>,
    /// With the machine, add the fine offsets ($TC_CARR41..65), as the control does with SD42974 = 1.
    #[arg(long)]
    pub fine_offsets: bool,
    /// Write the result to FILE (atomically) instead of stdout; with several programs
    /// or a directory, to the directory DIR, mirroring the input tree.
    #[arg(short, long, value_name = "FILE|DIR", conflicts_with = "in_place")]
    pub output: Option<PathBuf>,
    /// Rewrite the file itself: a temporary file in its directory, synced, renamed over it; a `.bak` is kept.
    #[arg(long)]
    pub in_place: bool,
    /// With --in-place, keep no `.bak` copy.
    #[arg(long, requires = "in_place")]
    pub no_backup: bool,
    /// Write nothing; exit 1 when the rewrite would change the program (for CI).
    #[arg(long, conflicts_with_all = ["output", "in_place"])]
    pub check: bool,
    /// Print a unified diff instead of the program.
    #[arg(long, conflicts_with_all = ["output", "in_place"])]
    pub diff: bool,
}

#[derive(Debug, clap::Args)]
pub struct FmtArgs {
    /// Programs or directories (walked as `check` walks them); an archive's programs are formatted in it; `-` reads stdin and writes stdout. None: the current directory.
    pub paths: Vec<PathBuf>,
    #[command(flatten)]
    pub walk: WalkArgs,
    /// Write nothing; list the files that would change and exit 1 if any would.
    #[arg(long, conflicts_with = "diff")]
    pub check: bool,
    /// Print a unified diff instead of writing.
    #[arg(long)]
    pub diff: bool,
    /// Number the numbered blocks again from START in steps of STEP, and every jump, CASE,
    /// REPEAT and CALL BLOCK range that names them.
    #[arg(long, value_name = "START,STEP", value_parser = crate::cli::fmt::renumbering)]
    pub renumber: Option<(u64, u64)>,
    /// The settings file (default: the nearest sinuprep.toml from the program's directory upward).
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
}

#[derive(Debug, clap::Args)]
pub struct EvalArgs {
    /// Programs or directories (walked for .mpf/.spf/.arc files, or what `include` takes, leaving out hidden names and what .gitignore ignores); an archive is read as its programs; `-` reads stdin (also when none is named and stdin is no terminal).
    pub paths: Vec<PathBuf>,
    #[command(flatten)]
    pub walk: WalkArgs,
    #[command(flatten)]
    pub analysis: AnalysisArgs,
    /// The machine's swivel data records: each swivelling call shows the rotary axis
    /// positions its record gives [default: `machine` in sinuprep.toml].
    #[arg(long, value_name = "FILE")]
    pub machine: Option<PathBuf>,
    /// A rotary table under the machine's heads: its record (kinematics "P", one axis), by
    /// name or number. A swivel on a head record shows its split over the table and the head,
    /// as `axes --table` computes it [default: `table` in sinuprep.toml].
    #[arg(long, value_name = "NAME")]
    pub table: Option<String>,
    /// With the machine, add the fine offsets ($TC_CARR41..65), as the control does with SD42974 = 1.
    #[arg(long)]
    pub fine_offsets: bool,
    /// Print one JSON document instead of the tables.
    #[arg(long)]
    pub json: bool,
}

/// The unit of lengths a measurement is given in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Units {
    Mm,
    Inch,
}

#[derive(Debug, clap::Args)]
#[command(group(clap::ArgGroup::new("face").required(true).args(["along_x", "points", "normal"])))]
pub struct ProbeArgs {
    /// Two points probed on the face along X, `X,Y,Z X,Y,Z`: machine
    /// coordinates (or the active frame's, with --in-frame).
    #[arg(long, num_args = 2, value_names = ["X,Y,Z", "X,Y,Z"], value_parser = point, allow_hyphen_values = true, requires = "along_y")]
    pub along_x: Option<Vec<[f64; 3]>>,
    /// Two points probed on the face along Y.
    #[arg(long, num_args = 2, value_names = ["X,Y,Z", "X,Y,Z"], value_parser = point, allow_hyphen_values = true, requires = "along_x")]
    pub along_y: Option<Vec<[f64; 3]>>,
    /// Three points probed anywhere on the face, not on one line.
    #[arg(long, num_args = 3, value_names = ["X,Y,Z", "X,Y,Z", "X,Y,Z"], value_parser = point, allow_hyphen_values = true)]
    pub points: Option<Vec<[f64; 3]>>,
    /// The face's normal, on the tool's side (any length).
    #[arg(long, value_name = "NX,NY,NZ", value_parser = point, allow_hyphen_values = true)]
    pub normal: Option<[f64; 3]>,
    /// The rotation's centre, the new zero point (CYCLE800's `_X0 _Y0 _Z0`)
    /// [default: the first point; with --normal, the origin].
    #[arg(long, alias = "centre", value_name = "X,Y,Z", value_parser = point, allow_hyphen_values = true)]
    pub center: Option<[f64; 3]>,
    /// The rotation active while probing, three angles in --in-frame-sequence:
    /// the points (and --center) are in its coordinates, the result composes with it.
    #[arg(long, value_name = "A1,A2,A3", value_parser = point, allow_hyphen_values = true)]
    pub in_frame: Option<[f64; 3]>,
    /// The sequence of --in-frame's angles (`i:ZYX` for a CYCLE800's `_MODE` 27).
    #[arg(long, default_value = "e:XYZ", value_name = "SEQUENCE")]
    pub in_frame_sequence: Sequence,
    /// The active frame's zero point, in machine coordinates (a CYCLE800's `_X0 _Y0 _Z0`).
    #[arg(long, value_name = "X,Y,Z", value_parser = point, allow_hyphen_values = true)]
    pub in_frame_origin: Option<[f64; 3]>,
    /// The unit of the points (and of the centre and tolerance); the angles do not depend on it.
    #[arg(long, value_enum, default_value_t = Units::Mm)]
    pub units: Units,
    /// How far the points may lie from one plane, or be from coincident or
    /// collinear [default: 0.01 mm, 0.0005 inch].
    #[arg(long, value_parser = length)]
    pub tolerance: Option<f64>,
    /// The sequence CYCLE600 writes and CYCLE800 swivels in (`_BIN_OUT`, `_MODE`).
    #[arg(long, default_value = "i:ZYX", value_name = "SEQUENCE")]
    pub to: Sequence,
    /// The head: CYCLE600's `_MIHEAD` and CYCLE800's `_TC`, the machine's
    /// swivel data record (`$TC_CARR34`, at most 32 characters). Without it
    /// the angles are printed and no call.
    #[arg(long, value_name = "NAME", value_parser = record_name)]
    pub head: Option<String>,
    /// Decimals of the numbers in the calls (0 to 15).
    #[arg(long, default_value_t = 6, value_parser = decimals)]
    pub precision: usize,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
}

#[derive(Debug, clap::Args)]
#[command(group(clap::ArgGroup::new("measured").required(true).args(["before", "positions"])))]
pub struct AxisArgs {
    /// The angle the axis turned, degrees (right-handed about the axis found).
    #[arg(long, value_parser = finite_angle)]
    pub angle: Option<f64>,
    /// The point before the turn, relative to a point on the axis: X,Y,Z.
    #[arg(long, value_name = "X,Y,Z", value_parser = point, allow_hyphen_values = true, requires_all = ["after", "angle"])]
    pub before: Option<[f64; 3]>,
    /// The point after the turn, relative to the same point.
    #[arg(long, value_name = "X,Y,Z", value_parser = point, allow_hyphen_values = true, requires = "before")]
    pub after: Option<[f64; 3]>,
    /// Two or three positions of one point measured as the axis turned
    /// (machine coordinates): three give the axis; two need --angle (the
    /// turn from the first to the second) and --direction. It reads up to
    /// three values, so give it after the other options.
    #[arg(long, num_args = 2..=3, value_name = "X,Y,Z", value_parser = point, allow_hyphen_values = true)]
    pub positions: Option<Vec<[f64; 3]>>,
    /// The axis's nominal direction, for two positions (the record's `$TC_CARR` vector).
    #[arg(long, value_name = "X,Y,Z", value_parser = point, allow_hyphen_values = true)]
    pub direction: Option<[f64; 3]>,
    /// The swivel data record `m` of `$TC_CARRn[m]` the axis vector is written for
    /// (1 to 999999, as a machine file's records are read).
    #[arg(long, default_value_t = 1, value_name = "M", value_parser = clap::value_parser!(u32).range(1..=i64::from(crate::semantic::machine::MAX_RECORD)))]
    pub record: u32,
    /// Which of the record's rotary axes: 1 (`$TC_CARR7..9`) or 2 (`$TC_CARR10..12`).
    #[arg(long, default_value_t = 1, value_name = "1|2", value_parser = clap::value_parser!(u8).range(1..=2))]
    pub rotary: u8,
    /// How far (a length, in the points' unit) the measurements may be from fitting.
    #[arg(long, default_value_t = 0.01, value_parser = length)]
    pub tolerance: f64,
    /// Decimals of the numbers printed, 0 to 15 (JSON: full precision).
    #[arg(long, default_value_t = 6, value_parser = decimals)]
    pub precision: usize,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
}

/// Three finite numbers separated by commas: a point or a vector.
fn point(text: &str) -> Result<[f64; 3], String> {
    // An option that takes points starting with `-` reads the next option
    // as a point when it has room for one more.
    if text.starts_with("--") {
        return Err(format!(
            "`{text}` is not a point: an option taking several points reads until it has its most, so give it after the other options"
        ));
    }
    let fields: Vec<&str> = text.split(',').map(str::trim).collect();
    let numbers: Vec<f64> = fields
        .iter()
        .filter_map(|f| f.parse::<f64>().ok().filter(|v| v.is_finite()))
        .collect();
    match (fields.len(), &numbers[..]) {
        // Past ±1e9 (1000 km in mm) a coordinate is a typo, and squares of
        // differences could leave the range of f64.
        (3, &[x, y, z]) if [x, y, z].iter().any(|v| v.abs() > 1e9) => Err(format!(
            "`{text}` has a number beyond ±1e9, which no machine's coordinate is"
        )),
        (3, &[x, y, z]) => Ok([x, y, z]),
        _ => Err(format!(
            "`{text}` is not three finite numbers X,Y,Z; give them separated by commas, as 10,-2.5,0.003"
        )),
    }
}

/// A length above zero, at most 1e9 as a point's coordinates.
fn length(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(value) if value.is_finite() && value > 0.0 && value <= 1e9 => Ok(value),
        _ => Err(format!(
            "`{text}` is not a length above 0 and at most 1e9, which no machine's length exceeds"
        )),
    }
}

#[derive(Debug, clap::Args)]
pub struct ConvertArgs {
    /// The rotation in the --from form, numbers separated by blanks or commas: three
    /// angles for a sequence, nine (rows; or the 16 of a 4x4 without translation) for
    /// `matrix`, `w x y z` for `quaternion`, `x y z angle` for `axis-angle`, three for
    /// `gibbs` and `chain`; statements for `sinumerik` and `gpp` (an argument a block).
    /// Without them, stdin is read: one rotation a line in numbers (printed one after
    /// the other), or the statements.
    #[arg(value_name = "VALUES")]
    pub values: Vec<String>,
    /// Input form: a sequence (`intrinsic:ZXY`, `extrinsic:XYZ`, `i:ZXY`, `e:57`),
    /// `matrix`, `quaternion`, `axis-angle`, `gibbs`, `sinumerik` (TRANS, ROT, AROT, ...
    /// as the control composes them), `gpp` (ROT_MAT1..9, TRANS_MATX..Z) or `chain`
    /// (intrinsic Z, X', Y'').
    #[arg(long)]
    pub from: Notation,
    /// Output form, same forms as --from.
    #[arg(long)]
    pub to: Notation,
    /// Decimals of the numbers in a form's text and of the angles read from
    /// stdin, 0 to 15, trailing zeros trimmed (the table: 6; JSON: full precision).
    #[arg(long, default_value_t = EXACT_DECIMALS, value_parser = decimals)]
    pub precision: usize,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
}

/// The decimals `convert` and `frame` print by default: the conversions
/// hold angles and matrix entries to about 1e-13, so twelve decimals are
/// exact (`45`, not `44.99999999999999`).
pub const EXACT_DECIMALS: usize = 12;

#[derive(Debug, clap::Args)]
pub struct FrameArgs {
    /// The frame in the --from form: X Y Z, then the rotation as `convert` takes it
    /// (16 or 12 numbers, rows, for `matrix`); statements for `sinumerik` and `gpp`.
    /// Without them (and without --tool), stdin is read.
    #[arg(value_name = "VALUES", conflicts_with = "tool")]
    pub values: Vec<String>,
    /// Input form, as `convert --from` (also the form of --tool and --piece).
    #[arg(long)]
    pub from: Notation,
    /// Output form, as `convert --to`; `chain` gives the position and the angles
    /// about Z, X', Y'' of the tool-to-piece chain.
    #[arg(long)]
    pub to: Notation,
    /// A link of the tool's chain in the fixed system (T_SO), in the --from form;
    /// repeated, the links are chained in order. With --piece, the output is the
    /// tool seen from the piece, T_SP = T_PO^-1 · T_SO.
    #[arg(
        long,
        value_name = "FRAME",
        requires = "piece",
        allow_hyphen_values = true
    )]
    pub tool: Vec<String>,
    /// A link of the piece's chain in the fixed system (T_PO), as --tool.
    #[arg(
        long,
        value_name = "FRAME",
        requires = "tool",
        allow_hyphen_values = true
    )]
    pub piece: Vec<String>,
    /// Decimals of the numbers in the form's text, 0 to 15, trailing zeros
    /// trimmed (JSON: full precision).
    #[arg(long, default_value_t = EXACT_DECIMALS, value_parser = decimals)]
    pub precision: usize,
    /// Print one JSON object instead of the form's text.
    #[arg(long)]
    pub json: bool,
}

/// `axes --prefer`: which table angle a split chooses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Prefer {
    Middle,
    Nearest,
}

fn direction(text: &str) -> Result<i8, String> {
    match text.trim() {
        "-1" => Ok(-1),
        "1" | "+1" => Ok(1),
        _ => Err(format!(
            "`{text}` is no _DIR: give -1 (the lower position) or 1 (the higher)"
        )),
    }
}

/// The name of a swivel data record as the control holds it (`$TC_CARR34`,
/// a string of at most 32 characters) and as an NC string can carry it: no
/// `"`, which would end the string, and no control character (a line end
/// would end the block).
pub(crate) fn record_name(text: &str) -> Result<String, String> {
    let count = text.chars().count();
    if count == 0 || count > 32 {
        return Err(format!(
            "a swivel data record's name has 1 to 32 characters ($TC_CARR34), this one {count}"
        ));
    }
    if let Some(bad) = text.chars().find(|c| *c == '"' || c.is_control()) {
        return Err(format!(
            "{bad:?} cannot stand in an NC string: give the record's name as the machine holds it"
        ));
    }
    Ok(text.to_string())
}

/// A count of decimals: 0 to 15, as many as a double's digits hold (as
/// `rewrite --precision`).
fn decimals(text: &str) -> Result<usize, String> {
    match text.trim().parse::<usize>() {
        Ok(count) if count <= 15 => Ok(count),
        _ => Err(format!(
            "`{text}` is no count of decimals from 0 to 15 (a double holds about 15 digits)"
        )),
    }
}

fn finite_angle(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(value) if value.is_finite() => crate::cli::notation::angle(value),
        Ok(_) => Err(format!(
            "`{text}` is not a finite angle; give degrees such as -16.28"
        )),
        Err(_) => Err(format!(
            "`{text}` is not a number; give degrees such as -16.28"
        )),
    }
}
