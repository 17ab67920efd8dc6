//! What the walk needs of the program beyond the model, built once before
//! it: the regions backward jumps repeat, what each line writes, and the
//! lines sinuprep wrote itself (a `; sinuprep:` call and the blocks emitted
//! for it). Labels, block pairs and STOPRE lines are the model's.

use std::borrow::Cow;
use std::sync::Arc;

use crate::hash::{HashMap, HashSet};
use crate::semantic::blocks::opener;
use crate::semantic::calls::{call_kind, CallKind};
use crate::semantic::env::Writers;
use crate::semantic::eval::key;
use crate::semantic::frames;
use crate::semantic::model::Model;
use crate::syntax::tree::{
    upper, Block, Call, Expr, Goto, GotoKind, Statement, StatementKind, SyncAction,
};
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
/// parameters a subprogram may change, the swivel rotation, frames.
fn block_writes(source: &[u8], block: &Block, line: usize) -> Written {
    let mut written = Written {
        frames: frames::frame_effect(source, block).is_some(),
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
#[derive(Debug, PartialEq)]
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

/// What [`Structure`] reads of each line that is not plain, taken line by
/// line: by the model's pass while it holds each tree (no line is parsed
/// again for it), or by [`Structure::build`] from the line table.
#[derive(Default)]
pub(crate) struct LineFacts {
    writers: Writers,
    rotation_lines: Vec<usize>,
    /// Lines with a frame statement, those sinuprep emitted among them.
    frame_lines: Vec<usize>,
    cycle600_lines: Vec<usize>,
    jumps: Vec<(usize, Goto)>,
}

impl LineFacts {
    /// The facts of `block`, on line `line` (lines in order).
    pub(crate) fn line(&mut self, source: &[u8], line: usize, block: &Block) {
        let writes = block_writes(source, block, line);
        for name in writes.names {
            self.writers.push(line, name);
        }
        if writes.rotation {
            self.rotation_lines.push(line);
        }
        if writes.frames {
            self.frame_lines.push(line);
        }
        self.cycle600_lines.extend(writes.cycle600_lines);
        self.jumps
            .extend(gotos(block).into_iter().map(|goto| (line, goto.clone())));
    }
}

impl Structure {
    /// The structure of `model`, its lines read from its line table.
    pub(crate) fn build(model: &Model) -> Structure {
        let lines = &model.lines;
        let mut facts = LineFacts::default();
        for line in 0..lines.len() {
            if lines.is_plain(line) {
                continue;
            }
            if let Some(block) = lines.block(line) {
                facts.line(lines.source, line, &block);
            }
        }
        Self::of(facts, model)
    }

    /// The structure of `model` from the facts of its lines.
    pub(crate) fn of(facts: LineFacts, model: &Model) -> Structure {
        let mut structure = Structure {
            loop_starts: HashMap::default(),
            writers: Arc::new(facts.writers),
            rotation_lines: facts.rotation_lines,
            frame_lines: facts.frame_lines,
            cycle600_lines: facts.cycle600_lines,
            marked: HashMap::default(),
            emitted: HashSet::default(),
        };
        structure.find_emitted(&model.lines);
        if !structure.marked.is_empty() {
            // A marked call may swivel or recalculate, as it did; the
            // frames emitted for it are the call's, not the program's own.
            structure.cycle600_lines.extend(structure.marked.keys());
            structure.cycle600_lines.sort_unstable();
            let emitted = &structure.emitted;
            structure.frame_lines.retain(|line| !emitted.contains(line));
        }
        // Backward jumps make loops: GOTOB/GOTO/GOTOC to a label above, and GOTOS.
        for (line, goto) in facts.jumps {
            let target = match (&goto.kind, &goto.target) {
                (GotoKind::Start, _) => Some(0),
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The structure made of the facts the model's pass took is the one
    /// made from the line table: loops, writers, swivels, the program's
    /// frames and not those emitted for a marked call, CYCLE600 lines.
    #[test]
    fn the_structure_taken_on_the_way_is_the_one_read_from_the_lines() {
        let program = "DEF REAL _Z\nSTART:\nN10 AROT Z=5\n_Z=_Z-1 R3=2\n\
            WHILE _Z>-5\nG1 X=_Z F800\nENDWHILE\nCYCLE800(1,\"TC1\",200000,57,0,0,0,30,0,0,0,0,0,1,100,1)\n\
            ; sinuprep: CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\n\
            N40 TRANS X0 Y0 Z0\nAROT Z=37.792346\nAROT X=20.704811\nAROT Y=49.106605\nATRANS X0 Y0 Z0\n\
            N50 CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\n\
            CYCLE977(101,1,,1,20)\nSUB1\nIF _Z<0 GOTOB START\nGOTOS\nM30\n";
        let model = Model::of(program.as_bytes());
        let taken = model.structure();
        let read = Structure::build(&model);
        assert_eq!(*taken, read);
        assert_eq!(read.frame_lines, [2]);
        assert_eq!(read.rotation_lines, [7]);
        assert_eq!(read.cycle600_lines, [8, 14]);
        assert_eq!(read.loop_starts, HashMap::from_iter([(0, 18), (1, 17)]));
        assert!(read.writers.writes("_OVR", 15, 16) && read.writers.writes("R", 16, 17));
    }
}
