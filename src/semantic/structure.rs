//! What the walk needs of the program beyond the model, built once before
//! it: the regions backward jumps repeat, what each line writes, and the
//! lines sinuprep wrote itself (a `; sinuprep:` call and the blocks emitted
//! for it). Labels, block pairs and STOPRE lines are the model's.

use std::borrow::Cow;
use std::collections::{HashMap, HashSet};
use std::sync::Arc;

use crate::semantic::blocks::opener;
use crate::semantic::calls::{call_kind, CallKind};
use crate::semantic::env::Writers;
use crate::semantic::eval::key;
use crate::semantic::frames;
use crate::semantic::model::Model;
use crate::syntax::tree::{upper, Block, Call, Expr, Statement, StatementKind, SyncAction};
use crate::syntax::visit::gotos;
use crate::syntax::Lines;

/// Names a line writes, for forgetting them.
#[derive(Default, Clone)]
struct Written {
    names: Vec<String>,
    /// A CYCLE800 (or another call that certainly swivels) is there.
    rotation: bool,
    /// Lines of CYCLE600 calls: they swivel or write their results.
    cycle600_lines: Vec<usize>,
    /// A frame statement of the program's own is there.
    frames: bool,
}

/// How the walk goes through a block: into an IF, a loop, past an ELSE.
pub(crate) enum Control<'a> {
    IfBlock(&'a Expr),
    Loop {
        condition: Option<&'a Expr>,
        runs_once: bool,
    },
    Else,
    None,
}

/// The variables a synchronized action assigns, in the walk's keys: it
/// writes them in the main run, at a time preprocessing cannot know. `$R1`
/// there is the R parameter `R1`.
pub(crate) fn sync_writes<'s>(
    source: &'s [u8],
    sync: &'s SyncAction,
) -> impl Iterator<Item = String> + 's {
    let otherwise = sync.otherwise.iter().flat_map(|(_, actions)| actions);
    sync.actions
        .iter()
        .chain(otherwise)
        .filter_map(move |action| {
            let StatementKind::Assign(assign) = &action.kind else {
                return None;
            };
            let name = upper(assign.target.name.text(source));
            let name = match name.strip_prefix('$') {
                Some(r) if r.starts_with('R') && r[1..].bytes().all(|b| b.is_ascii_digit()) => {
                    r.to_string()
                }
                _ => name,
            };
            Some(if assign.target.indices.is_empty() {
                key(&name, &[])
            } else {
                name
            })
        })
}

/// What one block may write: variables, arrays a measuring cycle fills, R
/// parameters a subprogram may change, the swivel rotation, frames (not
/// those of a block sinuprep `emitted`).
fn block_writes(source: &[u8], block: &Block, line: usize, emitted: bool) -> Written {
    let mut written = Written {
        frames: !emitted && frames::frame_effect(source, block).is_some(),
        ..Written::default()
    };
    for statement in &block.statements {
        match &statement.kind {
            StatementKind::Assign(assign) => {
                let name = upper(assign.target.name.text(source));
                written.names.push(if assign.target.indices.is_empty() {
                    key(&name, &[])
                } else {
                    name
                });
            }
            StatementKind::Def(def) => written
                .names
                .extend(def.variables.iter().map(|d| upper(d.name.text(source)))),
            StatementKind::For { variable, .. } => {
                written.names.push(key(&upper(variable.text(source)), &[]))
            }
            StatementKind::SyncAction(sync) => written.names.extend(sync_writes(source, sync)),
            StatementKind::Call(Call { name, .. }) | StatementKind::Command(name) => {
                match call_kind(&upper(name.text(source))) {
                    CallKind::Cycle600 => written.cycle600_lines.push(line),
                    CallKind::Cycle800 => written.rotation = true,
                    CallKind::Measuring => written
                        .names
                        .extend(["_OVR".to_string(), "_OVI".to_string()]),
                    CallKind::Builtin => {}
                    CallKind::Subprogram => written.names.push("R".to_string()),
                }
            }
            _ => {}
        }
    }
    written
}

/// What the walk follows beyond the model: backward jumps, writers, marks.
pub(crate) struct Structure {
    /// First line of a region a backward jump repeats -> its last line.
    pub(crate) loop_starts: HashMap<usize, usize>,
    /// Where each name is written, for forgetting a region's names.
    pub(crate) writers: Arc<Writers>,
    /// Lines with a CYCLE800 (or another call that certainly swivels), in order.
    pub(crate) rotation_lines: Vec<usize>,
    /// Lines with a frame statement of the program's own, in order.
    pub(crate) frame_lines: Vec<usize>,
    /// Lines with a CYCLE600 call (or a `; sinuprep:` line keeping one), in order.
    pub(crate) cycle600_lines: Vec<usize>,
    /// `; sinuprep:` lines -> the CYCLE600 call they keep.
    pub(crate) marked: HashMap<usize, Statement>,
    /// Lines sinuprep emitted with frames or CYCLE800 for a marked call.
    pub(crate) emitted: HashSet<usize>,
}

impl Structure {
    pub(crate) fn build(model: &Model) -> Structure {
        let lines = &model.lines;
        let source = lines.source;
        let mut structure = Structure {
            loop_starts: HashMap::new(),
            writers: Arc::default(),
            rotation_lines: Vec::new(),
            frame_lines: Vec::new(),
            cycle600_lines: Vec::new(),
            marked: HashMap::new(),
            emitted: HashSet::new(),
        };
        structure.find_emitted(lines);
        // Jumps, resolved once every label is known.
        let mut jumps: Vec<(usize, crate::syntax::tree::Goto)> = Vec::new();
        let mut writers = Writers::default();
        for line in 0..lines.len() {
            if structure.marked.contains_key(&line) {
                // The call it keeps may swivel or recalculate, as it did.
                structure.cycle600_lines.push(line);
            }
            if lines.is_plain(line) {
                continue;
            }
            let Some(block) = lines.block(line) else {
                continue;
            };
            let block = &*block;
            let writes = block_writes(source, block, line, structure.is_emitted(line));
            for name in writes.names {
                writers.push(line, name);
            }
            if writes.rotation {
                structure.rotation_lines.push(line);
            }
            if writes.frames {
                structure.frame_lines.push(line);
            }
            structure.cycle600_lines.extend(writes.cycle600_lines);
            jumps.extend(gotos(block).into_iter().map(|goto| (line, goto.clone())));
        }
        structure.writers = Arc::new(writers);
        // Backward jumps make loops: GOTOB/GOTO/GOTOC to a label above, and GOTOS.
        for (line, goto) in jumps {
            let target = match (&goto.kind, &goto.target) {
                (crate::syntax::tree::GotoKind::Start, _) => Some(0),
                (kind, Some(target)) => model.landing(target, *kind, line),
                _ => None,
            };
            if let Some(target) = target.filter(|&t| t <= line) {
                let last = structure.loop_starts.entry(target).or_insert(line);
                *last = (*last).max(line);
            }
        }
        structure
    }

    /// The `; sinuprep:` lines and the blocks emitted below them. A program
    /// sinuprep never rewrote has none: one search of the bytes says so.
    fn find_emitted(&mut self, lines: &Lines) {
        let source = lines.source;
        if memchr::memmem::find(source, frames::MARKER).is_none() {
            return;
        }
        for line in 0..lines.len() {
            let Some(statement) = frames::marked_call(source, lines.raw(line).content) else {
                continue;
            };
            let block = |offset: usize| {
                let at = line + 1 + offset;
                if at >= lines.len() {
                    return None;
                }
                lines.block(at).map(Cow::into_owned)
            };
            let count = frames::emitted_blocks(source, block);
            self.emitted.extend(line + 1..line + 1 + count);
            self.marked.insert(line, statement);
        }
    }

    /// The CYCLE600 kept in the `; sinuprep:` line `line`, if it is one
    /// (most programs have none: no hashing of every line then).
    pub(crate) fn marked_call(&self, line: usize) -> Option<&Statement> {
        if self.marked.is_empty() {
            return None;
        }
        self.marked.get(&line)
    }

    /// Whether sinuprep emitted `line` for a marked call.
    pub(crate) fn is_emitted(&self, line: usize) -> bool {
        !self.emitted.is_empty() && self.emitted.contains(&line)
    }

    /// The lines of `lines` (in order) within `start..end`.
    pub(crate) fn within(lines: &[usize], start: usize, end: usize) -> &[usize] {
        let first = lines.partition_point(|&line| line < start);
        let last = lines.partition_point(|&line| line < end);
        &lines[first..last.max(first)]
    }
}

/// The control statement that decides how a block is walked: the block it
/// opens (the model's matching's opener), else an ELSE.
pub(crate) fn control(block: &Block) -> Control<'_> {
    match opener(block) {
        Some((_, statement)) => match &statement.kind {
            StatementKind::If { condition } => Control::IfBlock(condition),
            StatementKind::While { condition } => Control::Loop {
                condition: Some(condition),
                runs_once: false,
            },
            StatementKind::For { .. } => Control::Loop {
                condition: None,
                runs_once: false,
            },
            // LOOP and REPEAT.
            _ => Control::Loop {
                condition: None,
                runs_once: true,
            },
        },
        None if block
            .statements
            .iter()
            .any(|s| matches!(s.kind, StatementKind::Else)) =>
        {
            Control::Else
        }
        None => Control::None,
    }
}
