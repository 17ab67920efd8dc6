//! The settings a program is checked and rewritten with, resolved in one
//! place for the command line and an editor's server alike: what the caller
//! gives ([`Given`]: options, an editor's settings) over the nearest
//! `sinuprep.toml` ([`Config`]), the measured values, HEAD_DEF beside the
//! program, and the machine's definition files (read once for every program
//! that names the same ones).
//!
//! ```text
//! Given + sinuprep.toml + files they name -> Resolved { lint::Settings (with the emit Options) }
//!                                         -> Document::check_outcome / Document::rewrite
//! ```

mod config;
mod error;
pub mod file;
mod folder;
mod patterns;
mod recent;
mod values;

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

pub use config::{Config, SeverityName, FILE_NAME};
pub use error::SettingsError;
pub use patterns::{Patterns, WalkGiven, DEFAULT_INCLUDE};

use folder::Listing;
use recent::Recent;

use crate::archive::{self, MemberKind};
use crate::diagnostic::Severity;
use crate::emit::cycle600::{Form, Options};
use crate::lint::{self, Selection, Settings};
use crate::semantic::environment::{holds_machine_data, Procedure};
use crate::semantic::machine::{Machine, Reading};
use crate::semantic::swivels::{self, OnMachine};
use crate::semantic::{Environment, Heads, Supplied};

/// What the caller sets over `sinuprep.toml`; each field left empty falls
/// back to the file. A list given here replaces the file's list.
#[derive(Debug, Default, Clone)]
pub struct Given {
    /// The settings file; by default the nearest `sinuprep.toml` from the
    /// program's directory upward.
    pub config: Option<PathBuf>,
    /// A file of measured values (NC assignments).
    pub values: Option<PathBuf>,
    /// Measured values, one NC assignment each (`R10=0.215`).
    pub set: Vec<String>,
    /// HEAD_DEF; by default `HEAD_DEF.SPF` beside the program, any case.
    pub heads: Option<PathBuf>,
    pub select: Vec<String>,
    pub ignore: Vec<String>,
    pub severity_min: Option<Severity>,
    pub deny_warnings: bool,
    /// Definition files (GUD, macros).
    pub definitions: Vec<PathBuf>,
    /// Cycle directories, searched after the program's own directory.
    pub cycles: Vec<PathBuf>,
    /// Whether a link met in a directory (a subprogram or HEAD_DEF beside
    /// the program, in a cycle directory) is followed, as the walk's
    /// `--follow-links`; by default it is not found there.
    pub follow_links: bool,
    /// Which files a directory walk takes.
    pub walk: WalkGiven,
    /// The machine's swivel data records, for `check`'s swivel rules.
    pub machine: Option<PathBuf>,
    /// The record of a rotary table under the machine's heads (`--table`).
    pub table: Option<String>,
    /// Whether the records' fine offsets apply (SD42974).
    pub fine_offsets: bool,
    pub emit: Option<Form>,
    pub precision: Option<u8>,
    pub emit_runtime: bool,
    pub runtime_r: Option<u32>,
}

/// One program's settings.
pub struct Resolved {
    /// The `sinuprep.toml` that applies (empty when there is none).
    pub config: Config,
    /// What [`crate::document::Document`] checks and rewrites with.
    pub settings: Settings,
    /// Whether warnings fail the program.
    pub deny_warnings: bool,
}

/// The settings of a run over many programs: [`Given`], and what was read
/// for the programs so far, shared by the threads that check them: the
/// definition files (by the list that names them), the directories (each
/// listed once, however many programs lie in it: looking beside each program
/// anew made a folder of n programs cost n listings of n names), their
/// subprograms, the settings files and the HEAD_DEF files.
#[derive(Default)]
pub struct Workspace {
    given: Given,
    definitions: Mutex<HashMap<Vec<PathBuf>, Environment>>,
    listings: Recent<PathBuf, Arc<Listing>>,
    subprograms: Recent<PathBuf, Arc<Procedures>>,
    /// The machines read, by file and the table named under their heads.
    machines: Mutex<HashMap<MachineKey, Arc<OnMachine>>>,
    /// The nearest `sinuprep.toml` of a program's directory.
    nearest: Recent<PathBuf, Option<PathBuf>>,
    configs: Mutex<HashMap<PathBuf, Config>>,
    /// The patterns of each settings file (`None`: no file).
    patterns: Mutex<HashMap<Option<PathBuf>, Arc<Patterns>>>,
    heads: Mutex<HashMap<PathBuf, Heads>>,
    /// Files an editor holds open, read from its buffers instead of the
    /// disk: settings a user is typing apply before they are saved.
    buffers: HashMap<PathBuf, Arc<[u8]>>,
    /// Every file read so far (settings, definitions, machine, HEAD_DEF,
    /// values, subprograms), for an editor: a change to one of them changes
    /// the settings. A run over files keeps none (it would grow with them).
    read: Option<Mutex<std::collections::HashSet<PathBuf>>>,
}

/// A machine file and the table named under its heads.
type MachineKey = (PathBuf, Option<String>);

/// A directory's subprograms: file name (upper case, without `.SPF`) and
/// the parameter count of its PROC.
type Procedures = HashMap<String, Procedure>;

/// `cache[key]`, made by `make` the first time it is asked for. Two threads
/// asking at once may both make it; one is kept.
fn cached<K, V>(
    cache: &Mutex<HashMap<K, V>>,
    key: &K,
    make: impl FnOnce() -> Result<V, SettingsError>,
) -> Result<V, SettingsError>
where
    K: std::hash::Hash + Eq + Clone,
    V: Clone,
{
    if let Some(known) = cache.lock().ok().and_then(|c| c.get(key).cloned()) {
        return Ok(known);
    }
    let made = make()?;
    if let Ok(mut cache) = cache.lock() {
        cache.insert(key.clone(), made.clone());
    }
    Ok(made)
}

impl Workspace {
    /// Refuses a rule code that names no rule before any program is read.
    pub fn new(given: Given) -> Result<Self, SettingsError> {
        codes(&given.select, "--select")?;
        codes(&given.ignore, "--ignore")?;
        Ok(Self {
            given,
            ..Self::default()
        })
    }

    /// The file at `path`, given as an option or (`key`) in sinuprep.toml: an
    /// error names where it was given.
    fn read_setting(
        &self,
        config: &Config,
        path: &Path,
        key: Option<&'static str>,
    ) -> Result<Vec<u8>, SettingsError> {
        self.read(path)
            .map_err(|source| unreadable(config, path, key, source))
    }

    /// An editor's workspace: it reads the files in `buffers` (the open
    /// documents, unsaved) from them, and remembers what it read.
    pub fn with_buffers(given: Given, buffers: HashMap<PathBuf, Arc<[u8]>>) -> Self {
        Self {
            given,
            buffers,
            read: Some(Mutex::default()),
            ..Self::default()
        }
    }

    /// Whether the settings read so far read `path` (an editor's workspace).
    pub fn has_read(&self, path: &Path) -> bool {
        let read = self.read.as_ref().and_then(|read| read.lock().ok());
        read.is_some_and(|read| read.contains(path))
    }

    /// The bytes of `path`, from an editor's buffer of it if there is one;
    /// in an editor's workspace the path is remembered ([`Self::has_read`]).
    fn read(&self, path: &Path) -> std::io::Result<Vec<u8>> {
        if let Some(Ok(mut read)) = self.read.as_ref().map(Mutex::lock) {
            read.insert(path.to_path_buf());
        }
        match self.buffers.get(path) {
            Some(buffer) => Ok(buffer.to_vec()),
            None => file::read(path),
        }
    }

    /// What `check` needs for `program` (a path, `-` for stdin): the
    /// values and HEAD_DEF, the rules to report and the machine's names.
    pub fn for_check(&self, program: &Path) -> Result<Resolved, SettingsError> {
        let mut resolved = self.for_rewrite(program)?;
        let config = &resolved.config;
        let given = &self.given;
        let in_config = |key: &str| format!("{} ({key})", config.describe());
        // A list given replaces the file's (both are checked).
        let list = |given: &[String], flag: &str, file: &Option<Vec<String>>, key: &str| {
            let from_file = codes(file.as_deref().unwrap_or_default(), &in_config(key))?;
            if given.is_empty() {
                Ok(from_file)
            } else {
                codes(given, flag)
            }
        };
        resolved.settings.selection = Selection {
            select: list(&given.select, "--select", &config.select, "select")?,
            ignore: list(&given.ignore, "--ignore", &config.ignore, "ignore")?,
            severity_min: given
                .severity_min
                .or(config.severity_min.map(Severity::from))
                .unwrap_or(Severity::Info),
        };
        if program != Path::new("-") {
            let ignored = self.patterns_of(config)?.ignored_in(program);
            resolved.settings.selection.ignore.extend(ignored);
        }
        let (environment, found) = self.environment(config, program)?;
        resolved.settings.environment = environment;
        resolved.settings.environment.procedures = self.procedures(config, program)?;
        resolved.settings.machine = self.machine(config)?;
        // The machine file is machine data too: the axes it names, of every
        // channel, are names a program may write.
        if let Some(machine) = &resolved.settings.machine {
            resolved.settings.environment.learn_axes(&machine.source);
        }
        resolved.settings.environment.given = found
            || !given.definitions.is_empty()
            || !given.cycles.is_empty()
            || config.definitions.iter().flatten().next().is_some()
            || config.cycles.iter().flatten().next().is_some()
            || config.axes.iter().flatten().next().is_some();
        Ok(resolved)
    }

    /// What `rewrite` and `eval` need for `program`: the values, HEAD_DEF
    /// and how the code is written.
    pub fn for_rewrite(&self, program: &Path) -> Result<Resolved, SettingsError> {
        let given = &self.given;
        let start = if program == Path::new("-") {
            Path::new(".")
        } else {
            program
        };
        let config = self.config(start)?;
        let (supplied, heads) = self.inputs(&config, program)?;
        let emit = self.options(&config);
        let deny_warnings = given.deny_warnings || config.deny_warnings == Some(true);
        Ok(Resolved {
            config,
            settings: Settings {
                supplied,
                heads,
                emit,
                ..Settings::default()
            },
            deny_warnings,
        })
    }

    /// What `fmt` does with `program` (a path, `-` for stdin): `[format]`
    /// of its settings file.
    pub fn for_format(&self, program: &Path) -> Result<crate::format::Settings, SettingsError> {
        let start = if program == Path::new("-") {
            Path::new(".")
        } else {
            program
        };
        let config = self.config(start)?;
        if let Some(why) = config.format.as_ref().and_then(|f| f.check().err()) {
            return Err(SettingsError::Config {
                path: config.path.clone().unwrap_or_default(),
                line: 1,
                column: 1,
                why: format!("[format] {why}"),
            });
        }
        Ok(crate::format::Settings::from_config(config.format.as_ref()))
    }

    /// `--config FILE`, or the nearest `sinuprep.toml` (any case) from
    /// `start` upward; each directory is looked up and each file read once a
    /// run.
    fn config(&self, start: &Path) -> Result<Config, SettingsError> {
        let path = match &self.given.config {
            Some(path) => Some(path.clone()),
            None => {
                let dir = if start.is_dir() {
                    start
                } else {
                    start.parent().unwrap_or(Path::new(""))
                };
                self.nearest_settings(dir)?
            }
        };
        match path {
            Some(path) => cached(&self.configs, &path, || {
                Config::read_with(&path, |path| self.read(path))
            }),
            None => Ok(Config::default()),
        }
    }

    /// The nearest `sinuprep.toml` from `dir` upward. A walk asks for a
    /// folder after its parent, so each folder is looked at once: the
    /// folders up to the first one already known (or holding the file) are
    /// listed, and each is kept with the answer. Linear in a tree's depth.
    fn nearest_settings(&self, dir: &Path) -> Result<Option<PathBuf>, SettingsError> {
        let settings_in = |dir: &Path| match self.listing(dir) {
            Ok(listing) => listing.settings(),
            Err(_) => folder::settings_in(dir),
        };
        let mut looked_at = Vec::new();
        let mut at = if dir.as_os_str().is_empty() {
            PathBuf::from(".")
        } else {
            dir.to_path_buf()
        };
        let found = loop {
            if let Some(known) = self.nearest.get(&at) {
                break known;
            }
            if let Some(found) = settings_in(&at)? {
                looked_at.push(at);
                break Some(found);
            }
            looked_at.push(at.clone());
            match at.parent() {
                Some(parent) if !parent.as_os_str().is_empty() => at = parent.to_path_buf(),
                // Above a relative path's first folder, or at the root:
                // the folders around the path as the file system has them.
                _ => break config::nearest(&at, settings_in)?,
            }
        };
        for dir in looked_at {
            self.nearest.insert(&dir, found.clone());
        }
        Ok(found)
    }

    /// The patterns that say which files a walk takes in `dir`: those of
    /// its settings file (the nearest, or `--config`) and the command line.
    pub fn patterns(&self, dir: &Path) -> Result<Arc<Patterns>, SettingsError> {
        self.patterns_of(&self.config(dir)?)
    }

    fn patterns_of(&self, config: &Config) -> Result<Arc<Patterns>, SettingsError> {
        cached(&self.patterns, &config.path, || {
            Ok(Arc::new(Patterns::new(config, &self.given.walk)?))
        })
    }

    /// The values the user gives: `--values` (or else sinuprep.toml's
    /// `values`) and `--set`, the latter winning.
    fn given_values(&self, config: &Config) -> Result<Supplied, SettingsError> {
        let mut supplied = Supplied::default();
        let file = match &self.given.values {
            Some(path) => Some((path.clone(), None)),
            None => config
                .values
                .as_ref()
                .map(|p| (config.resolve(p), Some("values"))),
        };
        if let Some((path, key)) = file {
            values::read_file(
                &path,
                &self.read_setting(config, &path, key)?,
                &mut supplied,
            )?;
        }
        for text in &self.given.set {
            values::read_set(text, &mut supplied)?;
        }
        Ok(supplied)
    }

    /// Measured values and HEAD_DEF: given first, then `sinuprep.toml`.
    fn inputs(
        &self,
        config: &Config,
        program: &Path,
    ) -> Result<(Supplied, Option<Heads>), SettingsError> {
        let given = &self.given;
        // A path given, or the one sinuprep.toml gives under `key`.
        let setting =
            |given: &Option<PathBuf>, file: &Option<PathBuf>, key: &'static str| match given {
                Some(path) => Some((path.clone(), None)),
                None => file.as_ref().map(|p| (config.resolve(p), Some(key))),
            };
        let read = |path: &Path, key: Option<&'static str>| self.read_setting(config, path, key);
        let mut supplied = self.given_values(config)?;
        // What the machine's data hold is known offline, unless a value given
        // says otherwise; of a key assigned twice, the last (the file loaded
        // later), so the walk goes from the end.
        if let Some(on) = self.machine(config)? {
            let by = format!("the machine data of {}", on.name);
            for (key, value) in on.values.iter().rev() {
                if supplied.get(key).is_none() {
                    supplied.insert(key.clone(), value.clone(), by.clone());
                }
            }
        }
        let heads = match setting(&given.heads, &config.heads, "heads") {
            Some(given) => Some(given),
            None => self.heads_beside(program)?.map(|path| (path, None)),
        };
        let heads = match heads {
            Some((path, key)) => Some(cached(&self.heads, &path, || {
                Ok(Heads::read(path.display().to_string(), &read(&path, key)?))
            })?),
            None => None,
        };
        Ok((supplied, heads))
    }

    /// The rewrite's options: given, then sinuprep.toml, then defaults.
    fn options(&self, config: &Config) -> Options {
        let given = &self.given;
        let runtime = if given.emit_runtime || given.runtime_r.is_some() {
            Some(given.runtime_r)
        } else if config.emit_runtime == Some(true) || config.runtime_r.is_some() {
            Some(config.runtime_r)
        } else {
            None
        };
        Options {
            form: given.emit.or(config.emit).unwrap_or_default(),
            precision: usize::from(given.precision.or(config.precision).unwrap_or(6)),
            runtime,
            ..Options::default()
        }
    }

    /// The machine's names: axes from sinuprep.toml, globals and macros from
    /// the definition files given (or else sinuprep.toml's, or else those
    /// beside `program`: [`definitions_beside`]), each list read once a run;
    /// with whether any definition file was found.
    fn environment(
        &self,
        config: &Config,
        program: &Path,
    ) -> Result<(Environment, bool), SettingsError> {
        let listed: Vec<PathBuf> = config
            .definitions
            .iter()
            .flatten()
            .map(|path| config.resolve(path))
            .collect();
        // Files found rather than named: one that cannot be read is passed
        // over (its own check reports it), not the programs' error.
        let (files, lenient) = match (self.given.definitions.is_empty(), listed.is_empty()) {
            (false, _) => (self.given.definitions.clone(), false),
            (true, false) => (listed, false),
            (true, true) => {
                // Found: beside the program, and the machine's archive's
                // definition members (`_N_DEF_DIR`: its GUD and macros).
                let mut found = definitions_beside(program);
                let machine = match (&self.given.machine, &config.machine) {
                    (Some(path), _) => Some(path.clone()),
                    (None, Some(path)) => Some(config.resolve(path)),
                    (None, None) => None,
                };
                let archive = |path: &PathBuf| {
                    path.is_file()
                        && path
                            .extension()
                            .is_some_and(|e| e.eq_ignore_ascii_case("arc"))
                };
                found.extend(machine.filter(archive));
                (found, true)
            }
        };
        let found = !files.is_empty();
        let known = self
            .definitions
            .lock()
            .ok()
            .and_then(|read| read.get(&files).cloned());
        let mut environment = match known {
            Some(environment) => environment,
            None => {
                let environment = definitions(&files, lenient, |path| self.read(path))?;
                if let Ok(mut read) = self.definitions.lock() {
                    read.insert(files, environment.clone());
                }
                environment
            }
        };
        let listed = Environment::with_axes(config.axes.iter().flatten()).axes;
        environment.axes.extend(listed);
        Ok((environment, found))
    }

    /// The machine given (or else sinuprep.toml's), read once a run: the one
    /// way every command (`check`, `rewrite`, `eval`, `axes`) reads a
    /// machine file, so that each finds the same in it (its findings are
    /// [`Machine::diagnostics`], the caller's to report once a run).
    pub fn machine(&self, config: &Config) -> Result<Option<Arc<OnMachine>>, SettingsError> {
        // The table under the heads: the one given, or else sinuprep.toml's.
        let table = self.given.table.clone().or_else(|| config.table.clone());
        let (path, key) = match (&self.given.machine, &config.machine) {
            (Some(path), _) => (path.clone(), None),
            (None, Some(path)) => (config.resolve(path), Some("machine")),
            (None, None) => {
                return match table {
                    Some(table) => Err(SettingsError::Table {
                        origin: self.table_origin(config),
                        why: format!("the table `{table}` is named, but no machine: give --machine FILE or `machine` in sinuprep.toml"),
                    }),
                    None => Ok(None),
                };
            }
        };
        let cache_key = (path.clone(), table.clone());
        if let Some(known) = self
            .machines
            .lock()
            .ok()
            .and_then(|m| m.get(&cache_key).cloned())
        {
            return Ok(Some(known));
        }
        let reading = Reading {
            fine_offsets: self.given.fine_offsets,
        };
        let shown = path.display().to_string();
        let read = if path.is_dir() {
            let files = file::setup_files(&path)
                .map_err(|source| unreadable(config, &path, key, source))?;
            archive::setup_data_of_files(&shown, &files)
        } else {
            let source = self.read_setting(config, &path, key)?;
            archive::setup_data(&source, &shown).map(|data| archive::SetupData {
                bytes: std::borrow::Cow::Owned(data.bytes.into_owned()),
                name: data.name,
                parts: data.parts,
            })
        };
        let data = read.map_err(|error| SettingsError::Archive {
            path: path.clone(),
            error,
        })?;
        let machine = Machine::read_knowing(&data.bytes, reading, &self.given_values(config)?);
        if let Some(name) = &table {
            if let Err(why) = table_record(&machine, name) {
                return Err(SettingsError::Table {
                    origin: self.table_origin(config),
                    why: format!("{}: {why}", data.name),
                });
            }
        }
        let machine_data = crate::machine::MachineData::read(&data.bytes);
        let axes = crate::machine::axes(&machine_data);
        let on = Arc::new(OnMachine {
            machine,
            values: crate::machine::keyed(&machine_data, &axes),
            name: data.name,
            parts: data.parts,
            source: data.bytes.into_owned(),
            hirth_tolerance_deg: config
                .hirth_tolerance
                .unwrap_or(swivels::HIRTH_TOLERANCE_DEG),
            table,
        });
        if let Ok(mut machines) = self.machines.lock() {
            machines.insert(cache_key, on.clone());
        }
        Ok(Some(on))
    }

    /// Where the table's name comes from, for a message.
    fn table_origin(&self, config: &Config) -> String {
        match (&self.given.table, &config.path) {
            (Some(_), _) => "--table".to_string(),
            (None, Some(path)) => format!("`table` in {}", path.display()),
            (None, None) => "`table`".to_string(),
        }
    }

    /// The subprograms a call of `program` may reach, as the control
    /// searches them: the program's own directory, then the cycle
    /// directories given (or else sinuprep.toml's) in their order; the first
    /// found wins. Each directory is read once a run.
    fn procedures(
        &self,
        config: &Config,
        program: &Path,
    ) -> Result<Arc<Procedures>, SettingsError> {
        let searched = self.searched_directories(config, program);
        let mut out: Option<Arc<Procedures>> = None;
        for (index, (dir, from_config)) in searched.iter().enumerate() {
            // The program's own directory may be unreadable (stdin in a
            // directory one cannot list): nothing is found there.
            let found = match self.listing(dir) {
                Ok(listing) => self.subprograms_in(dir, &listing)?,
                Err(_) if index == 0 => continue,
                Err(source) => {
                    return Err(match from_config {
                        Some(config) => SettingsError::ReadSetting {
                            path: dir.clone(),
                            key: "cycles",
                            config: config.describe(),
                            source,
                        },
                        None => SettingsError::Read {
                            path: dir.clone(),
                            source,
                        },
                    })
                }
            };
            match &mut out {
                // One directory (the common case): its table, shared.
                None => out = Some(found),
                Some(out) => {
                    for (name, procedure) in found.iter() {
                        let out = Arc::make_mut(out);
                        out.entry(name.clone()).or_insert_with(|| procedure.clone());
                    }
                }
            }
        }
        Ok(out.unwrap_or_default())
    }

    /// The directories a call of `program` searches for its subprogram, in
    /// order: the program's own, then the cycle directories given (or else
    /// sinuprep.toml's), each with the settings file that named it.
    fn searched_directories<'c>(
        &self,
        config: &'c Config,
        program: &Path,
    ) -> Vec<(PathBuf, Option<&'c Config>)> {
        let mut searched = vec![(own_directory(program), None)];
        if self.given.cycles.is_empty() {
            let listed = config.cycles.iter().flatten();
            searched.extend(listed.map(|dir| (config.resolve(dir), Some(config))));
        } else {
            searched.extend(self.given.cycles.iter().map(|dir| (dir.clone(), None)));
        }
        searched
    }

    /// The subprogram files (`.SPF`, any case) a call of `program` reaches,
    /// by name in upper case without the extension: searched as the control
    /// searches them, the first found winning; a directory that cannot be
    /// listed holds none.
    pub fn subprogram_files(
        &self,
        config: &Config,
        program: &Path,
    ) -> Result<HashMap<String, PathBuf>, SettingsError> {
        let mut files = HashMap::new();
        for (dir, _) in self.searched_directories(config, program) {
            let Ok(listing) = self.listing(&dir) else {
                continue;
            };
            for (name, path) in listing.subprograms(self.given.follow_links)? {
                files.entry(name).or_insert(path);
            }
        }
        Ok(files)
    }

    /// The names in `dir` that matter to a program beside them (any case).
    /// Each directory is listed once while its programs are checked.
    fn listing(&self, dir: &Path) -> std::io::Result<Arc<Listing>> {
        self.listings
            .get_or_make(&dir.to_path_buf(), || Listing::read(dir).map(Arc::new))
    }

    /// The subprograms of `dir` (its `.SPF` files, any case, and the
    /// parameter count of each one's PROC), each read once while the
    /// directory is in use.
    fn subprograms_in(
        &self,
        dir: &Path,
        listing: &Listing,
    ) -> Result<Arc<Procedures>, SettingsError> {
        self.subprograms.get_or_make(&dir.to_path_buf(), || {
            let mut procedures = Procedures::new();
            for (name, path) in listing.subprograms(self.given.follow_links)? {
                // A subprogram that vanished, cannot be read, or is no
                // regular file of a sane size is not found (its calls are
                // unchecked).
                let Ok(source) = self.read(&path) else {
                    continue;
                };
                let mut environment = Environment::default();
                environment.read_procedure(&source, Some(&path));
                if let Some(procedure) = environment.procedures.values().next() {
                    procedures.insert(name, procedure.clone());
                }
            }
            Ok(Arc::new(procedures))
        })
    }

    /// A HEAD_DEF.SPF (any case) beside the program (in the current
    /// directory for stdin), read when a program needs it: one that is no
    /// regular file is then an error naming it.
    fn heads_beside(&self, program: &Path) -> Result<Option<PathBuf>, SettingsError> {
        match self.listing(&own_directory(program)) {
            Ok(listing) => listing.head_def(self.given.follow_links),
            Err(_) => Ok(None),
        }
    }
}

/// The directory a program lies in (the current one for stdin).
fn own_directory(program: &Path) -> PathBuf {
    match program.parent() {
        _ if program == Path::new("-") => PathBuf::from("."),
        Some(dir) if !dir.as_os_str().is_empty() => dir.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// What the definition files `files` define: GUD and macro files give
/// variables and macros, machine data axis names (an `.INI`, or any file or
/// archive member that holds machine data, [`holds_machine_data`]); an
/// archive gives what its `_DEF` and data members do. `lenient`: a file
/// that cannot be read is passed over rather than an error.
fn definitions(
    files: &[PathBuf],
    lenient: bool,
    read: impl Fn(&Path) -> std::io::Result<Vec<u8>>,
) -> Result<Environment, SettingsError> {
    let mut environment = Environment::default();
    for path in files {
        match definitions_of(path, &mut environment, &read) {
            Err(_) if lenient => continue,
            result => result?,
        }
    }
    Ok(environment)
}

/// What the definition file `path` defines, added to `environment`.
fn definitions_of(
    path: &Path,
    environment: &mut Environment,
    read: impl Fn(&Path) -> std::io::Result<Vec<u8>>,
) -> Result<(), SettingsError> {
    let bytes = read(path).map_err(|source| SettingsError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    let name = path.display().to_string();
    let members = match archive::read(&bytes, &name) {
        None => vec![(path.to_path_buf(), 0..bytes.len(), definition_kind(path))],
        Some(read) => read
            .map_err(|error| SettingsError::Archive {
                path: path.to_path_buf(),
                error,
            })?
            .members
            .into_iter()
            .map(|m| (PathBuf::from(format!("{name}:{}", m.name)), m.data, m.kind))
            .collect(),
    };
    for (member, range, kind) in members {
        let start = range.start;
        let bytes = &bytes[range];
        let read = match kind {
            MemberKind::Data => environment.read_machine_data(bytes),
            _ if holds_machine_data(bytes) => environment.read_machine_data(bytes),
            MemberKind::Definitions => environment.read_definitions(bytes, Some((path, start))),
            _ => continue,
        };
        if let Err(errors) = read {
            let Some(first) = errors.first() else {
                continue;
            };
            let position = crate::span::LineIndex::new(bytes).position(first.span.start);
            return Err(SettingsError::Definitions {
                path: member,
                line: position.row,
                column: position.column,
                why: first.message.clone(),
            });
        }
    }
    Ok(())
}

/// The definition files a control would hold for `program` where none are
/// named: the `.DEF` files of its folder, and the files of a `_N_DEF_DIR`
/// beside it or beside its folder (a control's own tree: `_N_MPF_DIR` and
/// `_N_DEF_DIR` side by side, `_N_MGUD_DEF` within), in name order.
pub fn definitions_beside(program: &Path) -> Vec<PathBuf> {
    if program == Path::new("-") {
        return Vec::new();
    }
    let folder = match program.parent() {
        Some(folder) if folder.as_os_str().is_empty() => Path::new("."),
        Some(folder) => folder,
        None => return Vec::new(),
    };
    let is_definitions = |name: &std::ffi::OsStr| {
        folder::name_ends_with(name, b"_DEF") || folder::name_ends_with(name, b".DEF")
    };
    let mut found = Vec::new();
    let folders = [
        folder.to_path_buf(),
        folder.join("_N_DEF_DIR"),
        folder.join("..").join("_N_DEF_DIR"),
    ];
    for folder in folders {
        let Ok(entries) = std::fs::read_dir(&folder) else {
            continue;
        };
        // By name first, then a stat for the few that match.
        let mut here: Vec<PathBuf> = entries
            .flatten()
            .filter(|e| is_definitions(&e.file_name()))
            .map(|e| e.path())
            .filter(|p| p.is_file())
            .collect();
        here.sort();
        found.extend(here);
    }
    found
}

/// A definition file's kind by its extension: machine data (`.INI`) or
/// definitions (anything else given as one).
fn definition_kind(path: &Path) -> MemberKind {
    if path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("ini"))
    {
        MemberKind::Data
    } else {
        MemberKind::Definitions
    }
}

/// `list` as rule codes: trimmed, upper case, each naming a rule or a family.
fn codes(list: &[String], origin: &str) -> Result<Vec<String>, SettingsError> {
    lint::codes::normalize(list).map_err(|unknown| SettingsError::UnknownCode {
        origin: origin.to_string(),
        code: unknown.code,
        did_you_mean: unknown.did_you_mean,
    })
}

/// Whether `name` is a record of `machine` that can be a rotary table under
/// its heads: kinematics "P", one rotary axis.
/// Why the file at `path`, given as an option or (`key`) in sinuprep.toml,
/// could not be read: the error names where it was given.
fn unreadable(
    config: &Config,
    path: &Path,
    key: Option<&'static str>,
    source: std::io::Error,
) -> SettingsError {
    match key {
        Some(key) => SettingsError::ReadSetting {
            path: path.to_path_buf(),
            key,
            config: config.describe(),
            source,
        },
        None => SettingsError::Read {
            path: path.to_path_buf(),
            source,
        },
    }
}

fn table_record(machine: &Machine, name: &str) -> Result<(), String> {
    let Some(record) = machine.record(name) else {
        let known: Vec<&str> = machine.usable().map(|r| r.name.as_str()).collect();
        let meant = crate::suggest::closest(name, &known, 3)
            .map(|m| format!(" (did you mean `{m}`?)"))
            .unwrap_or_default();
        return Err(format!("no record `{name}` for the table{meant}"));
    };
    if record.kinematics != crate::kinematics::Kinematics::Table || record.axis_count() != 1 {
        return Err(format!(
            "the table `{name}` must be a record of kinematics \"P\" with one rotary axis"
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A directory of its own under the temporary directory.
    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("sinuprep-ws-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("parts")).expect("scratch directory");
        dir
    }

    #[test]
    fn given_settings_win_over_the_nearest_file_and_its_paths_are_its_own() {
        let dir = scratch("resolve");
        std::fs::write(
            dir.join(FILE_NAME),
            "ignore = [\"n016\"]\nseverity-min = \"warning\"\nvalues = \"probe.values\"\naxes = [\"XC\"]\nprecision = 3\n",
        )
        .expect("config");
        std::fs::write(dir.join("probe.values"), "R10=0.25\n").expect("values");
        std::fs::write(dir.join("parts/head_def.spf"), "PROC HEAD_DEF\nM17\n").expect("heads");
        let program = dir.join("parts/PART.MPF");

        let from_file = Workspace::new(Given::default()).expect("no codes given");
        let resolved = from_file.for_check(&program).expect("settings");
        assert_eq!(resolved.settings.selection.ignore, ["N016"]);
        assert_eq!(resolved.settings.selection.severity_min, Severity::Warning);
        assert_eq!(resolved.settings.emit.precision, 3);
        assert!(
            resolved.settings.heads.is_some(),
            "HEAD_DEF beside the program"
        );
        assert!(resolved.settings.environment.axes.contains("XC"));
        assert!(resolved.config.path.is_some());

        let given = Given {
            ignore: vec![" n005 ".into()],
            severity_min: Some(Severity::Error),
            precision: Some(5),
            ..Given::default()
        };
        let resolved = Workspace::new(given)
            .expect("known code")
            .for_check(&program)
            .expect("settings");
        assert_eq!(resolved.settings.selection.ignore, ["N005"]);
        assert_eq!(resolved.settings.selection.severity_min, Severity::Error);
        assert_eq!(resolved.settings.emit.precision, 5);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_directory_is_listed_once_for_all_its_programs() {
        let dir = scratch("listed-once");
        let workspace = Workspace::new(Given::default()).expect("no codes");
        let first = workspace
            .for_check(&dir.join("parts/A.MPF"))
            .expect("settings");
        assert!(first.settings.heads.is_none());
        // Made after the folder was read: the run does not list it again
        // for the next program (a folder of n programs cost n listings).
        std::fs::write(dir.join("parts/HEAD_DEF.SPF"), "PROC HEAD_DEF\nM17\n").expect("heads");
        std::fs::write(dir.join("parts/SUB.SPF"), "PROC SUB(REAL _A)\nM17\n").expect("sub");
        let second = workspace
            .for_check(&dir.join("parts/B.MPF"))
            .expect("settings");
        assert!(second.settings.heads.is_none());
        assert!(second.settings.environment.procedures.is_empty());
        // A new run reads it.
        let fresh = Workspace::new(Given::default()).expect("no codes");
        let third = fresh.for_check(&dir.join("parts/B.MPF")).expect("settings");
        assert!(third.settings.heads.is_some());
        assert!(third.settings.environment.procedures.contains_key("SUB"));
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_code_that_names_no_rule_is_refused_before_any_program_is_read() {
        let given = Given {
            select: vec!["N05".into()],
            ..Given::default()
        };
        let Err(error) = Workspace::new(given) else {
            panic!("N05 names no rule");
        };
        assert_eq!(
            error.to_string(),
            "--select: no rule has the code `N05` (did you mean `N005`?)"
        );
    }

    #[test]
    fn a_missing_file_named_by_the_settings_names_its_key() {
        let dir = scratch("missing");
        std::fs::write(dir.join(FILE_NAME), "heads = \"nowhere.spf\"\n").expect("config");
        let workspace = Workspace::new(Given::default()).expect("no codes");
        let Err(error) = workspace.for_rewrite(&dir.join("parts/PART.MPF")) else {
            panic!("the HEAD_DEF named does not exist");
        };
        assert!(error.to_string().contains("named by `heads` in"), "{error}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
