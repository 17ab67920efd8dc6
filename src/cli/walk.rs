//! Which files a command takes from the paths named on the command line:
//! a file named is taken as it is; a directory is walked, as ripgrep and
//! ruff walk one. It does not read the programs (see `input`).
//!
//! What a walk leaves out, in this order: hidden files and folders (a name
//! beginning with `.`) unless `--hidden`; what `exclude` and `extend-exclude`
//! name (sinuprep.toml, the command line); what `.ignore` files, and inside
//! a git repository `.gitignore` files, `.git/info/exclude` and git's global
//! excludes file ignore, unless `respect-gitignore = false` or
//! `--no-respect-gitignore`; files that `include` does not name; links,
//! unless `--follow-links`; anything that is no regular file. The settings
//! file that applies to a folder (the nearest `sinuprep.toml`) says what is
//! taken there.

use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use ignore::gitignore::{Gitignore, GitignoreBuilder};

use crate::cli::error::CliError;
use crate::cli::input::{Found, Links};
use crate::cli::platform;
use crate::cli::render::printable;
use crate::workspace::{file, Patterns, Workspace};

/// How a command walks the directories named.
pub struct Walk<'a> {
    /// A directory that holds no program is no error.
    pub allow_empty: bool,
    pub follow_links: bool,
    /// Hidden files and folders are taken too.
    pub hidden: bool,
    /// Where the settings come from, for the patterns of each folder.
    pub workspace: &'a Workspace,
}

/// The files the command-line paths name: a directory yields the files its
/// settings include (by default its `.mpf`/`.spf` files and `.arc`
/// archives, any case), recursively, sorted; a file named is taken whatever
/// its name. Every file and directory is taken once, by its device and
/// inode, so links that loop (`a -> .`, `up -> ..`) or name a file twice do
/// not repeat it.
///
/// The walk is lazy: each directory is read when the files before it have
/// been taken, so what it holds is the entries of the directories it is in
/// (the deepest path's), never the list of every file, and the first files
/// are checked while it goes on.
///
/// As ripgrep and ruff walk: a link met in a directory is not followed
/// unless `follow_links`, and nothing but a regular file is taken (a FIFO
/// named `*.MPF` would hang the run, a device never ends); what is skipped
/// is named in a note on stderr. A directory that cannot be read, an entry
/// whose kind cannot be told (a path past the system's length limit), is an
/// error naming it. A path named on the command line is taken through a link.
///
/// A directory that holds no program ends the walk with an error unless
/// `allow_empty` (then a note): a CI run over a mistyped or emptied folder
/// must not pass in silence. Either says what was left out and how to take
/// it. Such an error, or settings that cannot be read, is [`Files::end`]'s.
pub fn files<'w>(paths: &'w [PathBuf], walk: &'w Walk<'w>) -> Files<'w> {
    Files {
        walk,
        links: if walk.follow_links {
            Links::Follow
        } else {
            Links::Skip
        },
        named: paths.iter(),
        seen: Seen::named(paths),
        root: None,
        fatal: None,
    }
}

/// The files of a command, found as they are asked for (see [`files`]):
/// each a file to read, or an error naming an entry that could not be read.
pub struct Files<'w> {
    walk: &'w Walk<'w>,
    links: Links,
    named: std::slice::Iter<'w, PathBuf>,
    seen: Seen,
    /// The directory named on the command line being walked.
    root: Option<Root>,
    /// What ended the walk early.
    fatal: Option<CliError>,
}

/// A directory named on the command line, being walked.
struct Root {
    path: PathBuf,
    /// Files (and unreadable entries) taken from it so far.
    taken: usize,
    left: Left,
    /// The directories the walk is in, the deepest last.
    folders: Vec<Folder>,
}

/// A directory being walked: its entries not yet looked at, sorted.
struct Folder {
    entries: std::vec::IntoIter<Entry>,
    /// Its path below a canonical directory, for the patterns.
    absolute: PathBuf,
    patterns: Arc<Patterns>,
    ignores: Ignores,
}

/// An entry's path, and its kind as the directory gives it (the link
/// itself, not what it names), read without opening anything.
type Entry = (PathBuf, std::io::Result<std::fs::FileType>);

impl Iterator for Files<'_> {
    type Item = Result<Found, CliError>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            if self.fatal.is_some() {
                return None;
            }
            if let Some(mut root) = self.root.take() {
                match self.step(&mut root) {
                    Ok(Some(found)) => {
                        root.taken += 1;
                        self.root = Some(root);
                        return Some(found);
                    }
                    Ok(None) => {
                        if root.taken == 0 {
                            if let Err(error) = self.none_in(&root) {
                                self.fatal = Some(error);
                            }
                        }
                    }
                    Err(error) => self.fatal = Some(error),
                }
                continue;
            }
            let path = self.named.next()?;
            if path.is_dir() {
                let mut root = Root {
                    path: path.clone(),
                    taken: 0,
                    left: Left::default(),
                    folders: Vec::new(),
                };
                match self.enter(&mut root, path, canonical(path), Ignores::above(path)) {
                    Ok(None) => self.root = Some(root),
                    Ok(Some(unreadable)) => return Some(Err(unreadable)),
                    Err(error) => self.fatal = Some(error),
                }
                continue;
            }
            match excluded_when_named(path, self.walk) {
                Ok(true) => {
                    let name = printable(&path.display().to_string()).into_owned();
                    tellln!("note: {name} is excluded (force-exclude): not checked");
                }
                Ok(false) if self.seen.first_named(path) => {
                    return Some(Ok(Found::named(path.clone())));
                }
                Ok(false) => {}
                Err(error) => self.fatal = Some(error),
            }
        }
    }
}

impl Files<'_> {
    /// What ended the walk early, if anything: settings that cannot be
    /// read, or a directory without programs (unless `allow_empty`).
    pub fn end(&mut self) -> Result<(), CliError> {
        self.fatal.take().map_or(Ok(()), Err)
    }

    /// The next file (or unreadable entry) of `root`'s walk; `None` when it
    /// is done.
    fn step(&mut self, root: &mut Root) -> Result<Option<Result<Found, CliError>>, CliError> {
        while let Some(folder) = root.folders.last_mut() {
            let Some((path, kind)) = folder.entries.next() else {
                root.folders.pop();
                continue;
            };
            let Some(name) = path.file_name() else {
                continue;
            };
            let absolute = folder.absolute.join(name);
            if !self.walk.hidden && name.as_encoded_bytes().starts_with(b".") {
                root.left.hidden += 1;
                continue;
            }
            let kind = match kind {
                Ok(kind) => kind,
                Err(source) => return Ok(Some(Err(CliError::Read { path, source }))),
            };
            let link = kind.is_symlink();
            let kind = if link {
                // What the link names, looked up without opening it.
                match std::fs::metadata(&path) {
                    Ok(target) => Some(target.file_type()),
                    Err(_) => None,
                }
            } else {
                Some(kind)
            };
            let is_dir = kind.is_some_and(|k| k.is_dir());
            let patterns = &folder.patterns;
            if patterns.excludes(&absolute, is_dir) {
                root.left.excluded += 1;
                continue;
            }
            if patterns.respect_gitignore && folder.ignores.ignores(&absolute, is_dir) {
                root.left.ignored += 1;
                continue;
            }
            if !is_dir && !patterns.includes(&absolute) {
                root.left.not_included += 1;
                if root.left.examples.len() < 5 {
                    let name = printable(&name.to_string_lossy()).into_owned();
                    root.left.examples.push(name);
                }
                continue;
            }
            let Some(kind) = kind else {
                skipped(&path, "a link that names nothing");
                continue;
            };
            if link && self.links == Links::Skip {
                skipped(&path, "a symbolic link (--follow-links follows links)");
                continue;
            }
            if kind.is_dir() {
                let absolute = if link { canonical(&path) } else { absolute };
                let ignores = folder.ignores.clone();
                if let Some(unreadable) = self.enter(root, &path, absolute, ignores)? {
                    return Ok(Some(Err(unreadable)));
                }
            } else if !kind.is_file() {
                skipped(&path, "not a regular file (a FIFO, a socket or a device)");
            } else if self.seen.first_walked(&path, self.links) {
                return Ok(Some(Ok(Found::walked(path, self.links))));
            }
        }
        Ok(None)
    }

    /// Reads the directory `dir` (as named and reached, at `absolute` below
    /// a canonical directory, under the ignore files `ignores` of the
    /// folders above) into `root`'s walk; one already walked is left out.
    /// One that cannot be read is the error returned in `Ok`.
    fn enter(
        &mut self,
        root: &mut Root,
        dir: &Path,
        absolute: PathBuf,
        ignores: Ignores,
    ) -> Result<Option<CliError>, CliError> {
        if !self.seen.first_directory(dir) {
            return Ok(None);
        }
        let entries = match std::fs::read_dir(dir) {
            Ok(entries) => entries,
            Err(source) => {
                let path = dir.to_path_buf();
                return Ok(Some(CliError::Read { path, source }));
            }
        };
        let mut entries: Vec<Entry> = entries
            .filter_map(|e| e.ok().map(|e| (e.path(), e.file_type())))
            .collect();
        entries.sort_by(|a, b| a.0.cmp(&b.0));
        let patterns = self.walk.workspace.patterns(dir)?;
        let ignores = if patterns.respect_gitignore {
            ignores.enter(&absolute, &entries)
        } else {
            ignores
        };
        root.folders.push(Folder {
            entries: entries.into_iter(),
            absolute,
            patterns,
            ignores,
        });
        Ok(None)
    }

    /// The error, or the note, for a directory that yielded no program.
    fn none_in(&self, root: &Root) -> Result<(), CliError> {
        let patterns = self.walk.workspace.patterns(&root.path)?;
        let why = root.left.describe();
        let help = root.left.help(&patterns, self.walk.allow_empty);
        if !self.walk.allow_empty {
            return Err(CliError::NoPrograms {
                path: root.path.clone(),
                why,
                help,
            });
        }
        let name = printable(&root.path.display().to_string()).into_owned();
        tellln!("note: {name} holds no program{why}\n  help: {help}");
        Ok(())
    }
}

/// Whether the file `path`, named on the command line, is left out:
/// `force-exclude` is on for its folder's settings, and `exclude` matches it
/// or a folder it lies in. Standard input is never left out.
fn excluded_when_named(path: &Path, walk: &Walk) -> Result<bool, CliError> {
    if path == Path::new("-") {
        return Ok(false);
    }
    let dir = match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    };
    let patterns = walk.workspace.patterns(dir)?;
    Ok(patterns.force_exclude && patterns.excludes_named(&canonical(path)))
}

/// What a walk left out, counted for the message of a folder that yields
/// nothing.
#[derive(Default)]
struct Left {
    /// Files that `include` does not name: how many, and the first names.
    not_included: usize,
    examples: Vec<String>,
    ignored: usize,
    hidden: usize,
    excluded: usize,
}

impl Left {
    /// `: left out: 3 files include names not (PART.NC, ...), 1 hidden`,
    /// or nothing when the folder is empty.
    fn describe(&self) -> String {
        let plural = |n: usize, one: &str, many: &str| {
            if n == 1 {
                format!("1 {one}")
            } else {
                format!("{n} {many}")
            }
        };
        let mut parts = Vec::new();
        if self.not_included > 0 {
            let mut names = self.examples.join(", ");
            if self.not_included > self.examples.len() {
                names.push_str(", ...");
            }
            parts.push(format!(
                "{} that `include` does not take ({names})",
                plural(self.not_included, "file", "files")
            ));
        }
        let mut add = |n: usize, why: &str| {
            if n > 0 {
                parts.push(format!("{} {why}", plural(n, "entry", "entries")));
            }
        };
        add(self.ignored, "ignored by .gitignore or .ignore");
        add(self.hidden, "hidden");
        add(self.excluded, "excluded by `exclude`");
        if parts.is_empty() {
            String::new()
        } else {
            format!("; left out: {}", parts.join(", "))
        }
    }

    /// How to take what was left out.
    fn help(&self, patterns: &Patterns, allow_empty: bool) -> String {
        let mut ways = Vec::new();
        if self.not_included > 0 {
            let example = self
                .examples
                .iter()
                .find_map(|name| name.rsplit_once('.'))
                .map(|(_, extension)| format!("*.{}", extension.to_ascii_lowercase()))
                .unwrap_or_else(|| "_N_*_MPF".to_string());
            ways.push(format!(
                "a walk takes {}: take more with `extend-include = [\"{example}\"]` in sinuprep.toml or --extend-include '{example}'",
                patterns.included.join(", ")
            ));
        }
        if self.ignored > 0 {
            ways.push("--no-respect-gitignore takes ignored files".to_string());
        }
        if self.hidden > 0 {
            ways.push("--hidden takes hidden ones".to_string());
        }
        if self.excluded > 0 {
            ways.push("`exclude` and `extend-exclude` name what is left out".to_string());
        }
        ways.push("a file named on the command line is always read".to_string());
        if !allow_empty {
            ways.push("with --allow-empty a folder without programs is no error".to_string());
        }
        ways.join("; ")
    }
}

/// The ignore files that apply in a folder: those of the folder and of
/// each folder above it, the deepest first, as git and ripgrep read them.
#[derive(Clone, Default)]
struct Ignores {
    /// From the root of the file system down.
    levels: Vec<Arc<Level>>,
    /// Git's global excludes file, read once inside a repository.
    global: Option<Arc<Gitignore>>,
}

/// One folder's ignore files.
struct Level {
    ignore: Option<Gitignore>,
    gitignore: Option<Gitignore>,
    /// `.git/info/exclude`, in a repository's top folder.
    exclude: Option<Gitignore>,
    /// The top folder of a git repository (it holds `.git`).
    git: bool,
}

impl Ignores {
    /// The ignore files of the folders above `dir` (named on the command
    /// line).
    fn above(dir: &Path) -> Self {
        let mut ignores = Ignores::default();
        let Some(parent) = canonical(dir).parent().map(Path::to_path_buf) else {
            return ignores;
        };
        let mut folders: Vec<&Path> = parent.ancestors().collect();
        folders.reverse();
        for folder in folders {
            let has = |name: &str| std::fs::symlink_metadata(folder.join(name)).is_ok();
            ignores = ignores.with(folder, has(".ignore"), has(".gitignore"), has(".git"));
        }
        ignores
    }

    /// These and those of `dir` (at `absolute`), whose entries are `entries`.
    fn enter(self, absolute: &Path, entries: &[Entry]) -> Self {
        let has = |name: &str| {
            entries
                .iter()
                .any(|(path, _)| path.file_name().is_some_and(|n| n == name))
        };
        self.with(absolute, has(".ignore"), has(".gitignore"), has(".git"))
    }

    fn with(mut self, dir: &Path, ignore: bool, gitignore: bool, git: bool) -> Self {
        let read = |present: bool, name: &str| present.then(|| ignore_file(dir, &dir.join(name)));
        let level = Level {
            ignore: read(ignore, ".ignore"),
            gitignore: read(gitignore, ".gitignore"),
            exclude: git
                .then(|| ignore_file(dir, &dir.join(".git/info/exclude")))
                .filter(|exclude| !exclude.is_empty()),
            git,
        };
        if git && self.global.is_none() {
            self.global = Some(Arc::new(Gitignore::global().0));
        }
        if level.ignore.is_some() || level.gitignore.is_some() || git {
            self.levels.push(Arc::new(level));
        }
        self
    }

    /// Whether the ignore files ignore `path` (absolute): `.ignore` files
    /// first, then inside a repository `.gitignore` files up to its top
    /// folder, its exclude file and the global one. In each, the deepest
    /// folder's file that says anything of the path decides (a `!pattern`
    /// takes back what a folder above ignored).
    fn ignores(&self, path: &Path, is_dir: bool) -> bool {
        let decided = |files: &mut dyn Iterator<Item = &Gitignore>| {
            files
                .map(|file| file.matched(path, is_dir))
                .find(|m| !m.is_none())
                .map(|m| m.is_ignore())
        };
        let levels = || self.levels.iter().rev();
        let in_git = || {
            let repo = self.levels.iter().rposition(|level| level.git)?;
            let inside = self.levels[repo..].iter().rev();
            decided(&mut inside.filter_map(|level| level.gitignore.as_ref()))
                .or_else(|| decided(&mut self.levels[repo].exclude.iter()))
                .or_else(|| decided(&mut self.global.iter().map(Arc::as_ref)))
        };
        decided(&mut levels().filter_map(|level| level.ignore.as_ref()))
            .or_else(in_git)
            .unwrap_or(false)
    }
}

/// The ignore file at `path`, of the folder `dir`: read as a settings file
/// is (a regular file of a sane size; a FIFO is never opened). One that
/// cannot be read ignores nothing, as for git.
fn ignore_file(dir: &Path, path: &Path) -> Gitignore {
    let mut builder = GitignoreBuilder::new(dir);
    if let Ok(bytes) = file::read(path) {
        for line in String::from_utf8_lossy(&bytes).lines() {
            // A line that is no pattern ignores nothing, as for git.
            let _ = builder.add_line(Some(path.to_path_buf()), line);
        }
    }
    builder.build().unwrap_or_else(|_| Gitignore::empty())
}

/// `path` resolved, or as it is when it cannot be.
fn canonical(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}

/// The files and directories a walk has taken, by identity, so that none
/// is taken twice. What it holds grows with the directories, not with the
/// files: a file is kept only where it can be met again (named on the
/// command line, reached through links, or with more than one name).
#[derive(Default)]
struct Seen {
    taken: HashSet<(u64, u64)>,
    /// The files named on the command line, which a walk may meet too.
    named: HashSet<(u64, u64)>,
}

impl Seen {
    fn named(paths: &[PathBuf]) -> Self {
        let named = paths
            .iter()
            .filter_map(|path| std::fs::metadata(path).ok())
            .filter(|metadata| !metadata.is_dir())
            .filter_map(|metadata| platform::identity(&metadata))
            .collect();
        Seen {
            taken: HashSet::new(),
            named,
        }
    }

    /// Whether the directory `path` has not been walked before.
    fn first_directory(&mut self, path: &Path) -> bool {
        self.first_named(path)
    }

    /// Whether the file `path`, named on the command line, has not been
    /// taken before. A path that cannot be read is taken, to be reported
    /// when it is read.
    fn first_named(&mut self, path: &Path) -> bool {
        match std::fs::metadata(path)
            .ok()
            .as_ref()
            .and_then(platform::identity)
        {
            Some(id) => self.taken.insert(id),
            None => true,
        }
    }

    /// Whether the file `path`, met in a directory reached following
    /// `links` or not, has not been taken before.
    fn first_walked(&mut self, path: &Path, links: Links) -> bool {
        let Ok(metadata) = std::fs::metadata(path) else {
            return true;
        };
        let Some(id) = platform::identity(&metadata) else {
            return true;
        };
        let met_again =
            links == Links::Follow || platform::names(&metadata) > 1 || self.named.contains(&id);
        if met_again {
            self.taken.insert(id)
        } else {
            !self.taken.contains(&id)
        }
    }
}

/// A note on stderr naming what a walk left out.
fn skipped(path: &Path, why: &str) {
    let name = printable(&path.display().to_string()).into_owned();
    tellln!("note: skipped {name}: {why}");
}
