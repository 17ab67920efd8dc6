//! sinuprep: a preprocessor and linter for Siemens Sinumerik (840D sl / ONE)
//! part programs.
//!
//! The pipeline runs one way:
//!
//! ```text
//! bytes -> syntax (lossless lines, spans, trees)
//!       -> semantic (the model: names, labels, blocks, modal state; the CYCLE600 walk)
//!       -> rotation, kinematics, measure (pure math: no spans, no syntax)
//!       -> run (the program executed offline on the machine: positions, limits, time)
//!       -> emit, format (text edits) and lint (findings with their fixes; on a machine,
//!          the limits the dry run finds passed among them)
//!       -> document (one program's analysis, over the settings `workspace` resolved)
//!       -> report (a call and a swivel in words, for either front end)
//!       -> cli, lsp (the command line prints it, the server answers from it)
//! ```
//!
//! Modules:
//! - [`span`]: byte ranges and their line/column positions.
//! - [`number`]: numbers as the control reads them (fixed point, never an exponent).
//! - [`uri`]: paths as `file` URIs, as SARIF and an editor name files.
//! - [`diagnostic`]: the one diagnostic type for syntax errors, findings and refusals,
//!   with the fix a finding may carry.
//! - [`edit`]: text edits (span, new bytes) and applying them.
//! - [`registry`]: every rule's code, name, severity and docs below the linter; diagnostics are
//!   built from them.
//! - [`syntax`]: the lossless nom parser (`grammar/sinumerik.ebnf` is its grammar).
//! - [`rotation`]: rotation sequences, Euler/Tait-Bryan angles, additive rotations on nalgebra, and
//!   the other forms of a rotation (quaternion, axis-angle, Gibbs vector, a post-processor's
//!   ROT_MAT, the tool-to-piece chain); knows nothing of syntax.
//! - [`kinematics`]: swivel data records and the rotary axis positions they give a frame
//!   rotation (two solutions, limits, `_DIR`, Hirth), and a table's A3200 setup; pure math
//!   beside `rotation`.
//! - [`measure`]: from measurements to rotations: a probed face's angles, the axis of a known
//!   turn (the Rodrigues inverse problem), an axis from measured positions; pure math.
//! - [`semantic`]: the model every reader shares (what each line holds, names and where
//!   they are defined, labels and jumps, control blocks, modal state), values, the walk through
//!   the program, CYCLE600 binding, HEAD_DEF and the machine's swivel data records.
//! - [`machine`]: the machine as its own data describe it: machine data by name and index,
//!   axes with limits and dynamics, tool offsets, settable frames.
//! - [`run`]: the dry run: the program executed offline on the machine its data describe,
//!   each block's machine positions against the software limits, and its time.
//! - [`emit`]: text edits that rewrite CYCLE600 calls; never re-prints untouched bytes; and a
//!   swivel split over a table and a head in words (what the machine is told), shared by `axes`,
//!   `eval` and the rewrite's refusal.
//! - [`format`]: `sinuprep fmt`: layout, case and renumbering as text edits, from the model's
//!   block structure and jumps; strings, comments and the HMI's regions untouched.
//! - [`lint`]: the rules of `check`, one file each, and suppression comments.
//! - [`suggest`]: did-you-mean, shared by the parser's and the rules' messages.
//! - [`document`]: the front door: a program in, its findings and its rewrite out, for the
//!   command line and an editor alike.
//! - [`workspace`]: a program's settings: sinuprep.toml, the caller's options, measured values,
//!   HEAD_DEF and definition files, resolved once for the command line and a server alike.
//! - [`archive`]: the members of archives in text (`%_N_PART_MPF` sections) and binary form
//!   (`.arc`); a member's change as edits of the archive, headers included.
//! - [`report`]: what a CYCLE600 call evaluates to and where a swivel takes the axes, in words
//!   and as JSON: the tables `eval` and `axes` print and an editor's hover shows.
//! - [`cli`]: the command line (options, files, reports); the only place that prints.
//! - [`lsp`]: the language server (`sinuprep lsp`): protocol messages on stdout, its log
//!   on stderr, every answer from the analysis the command line uses.

pub mod archive;
pub mod cli;
pub mod diagnostic;
pub mod document;
pub mod edit;
pub mod emit;
pub mod format;
pub mod hash;
pub mod kinematics;
pub mod lint;
pub mod lsp;
pub mod machine;
pub mod measure;
pub mod number;
pub mod registry;
pub mod report;
pub mod rotation;
pub mod run;
pub mod semantic;
pub mod span;
pub mod suggest;
pub mod syntax;
pub mod uri;
pub mod workspace;
