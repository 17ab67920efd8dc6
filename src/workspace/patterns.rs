//! The glob patterns of the settings, compiled once per settings file:
//! which files a directory walk takes (`include`, `exclude`, as ruff's) and
//! which rules a file ignores (`per-file-ignores`). A pattern is read as a
//! line of a `.gitignore` is: `OLD` or `*.nc` matches that name at any
//! depth, `parts/old` or `/OLD` only there, below the settings file's
//! directory (the current directory's for the command line's), `**` any
//! depth. Any case matches, as the control's own names are case-free.
//!
//! The `.gitignore` files met by a walk are not read here: the walk reads
//! them as it enters each directory.

use std::path::{Path, PathBuf};

use ignore::gitignore::{Gitignore, GitignoreBuilder};

use crate::workspace::{codes, Config, SettingsError};

/// What a walk takes when nothing says otherwise: programs (main and
/// subprograms) and archives, any case.
pub const DEFAULT_INCLUDE: [&str; 3] = ["*.mpf", "*.spf", "*.arc"];

/// What the command line says of the walk, over `sinuprep.toml`.
#[derive(Debug, Default, Clone)]
pub struct WalkGiven {
    /// In place of the file's `exclude` (when not empty).
    pub exclude: Vec<String>,
    /// Added to the file's `exclude` and `extend-exclude`.
    pub extend_exclude: Vec<String>,
    /// In place of the file's `include` and the default (when not empty).
    pub include: Vec<String>,
    /// Added to the file's `include` and `extend-include`.
    pub extend_include: Vec<String>,
    /// Whether `.gitignore`, `.ignore` and git's exclude files are
    /// respected, over the file's `respect-gitignore` (by default they are).
    pub respect_gitignore: Option<bool>,
    /// Whether `exclude` applies to the files named too, over the file's
    /// `force-exclude` (by default it does not).
    pub force_exclude: Option<bool>,
}

/// One settings file's patterns, with the command line's.
pub struct Patterns {
    /// Files taken: the file's `include` (or [`DEFAULT_INCLUDE`], unless
    /// the command line has its own) and `extend-include`, then the command
    /// line's.
    include: [Gitignore; 2],
    /// [`DEFAULT_INCLUDE`] is taken, told by the extension: a matcher of
    /// patterns in any case is a regular expression, which costs about
    /// 1 MiB of memory to compile.
    by_default: bool,
    /// Files and folders left out: the file's, then the command line's.
    exclude: [Gitignore; 2],
    /// The include patterns, for messages.
    pub included: Vec<String>,
    pub respect_gitignore: bool,
    pub force_exclude: bool,
    /// Rule codes or prefixes by the files they are ignored in.
    per_file_ignores: Vec<(Gitignore, Vec<String>)>,
}

impl Patterns {
    /// `config`'s patterns with `given`'s; a pattern that does not compile
    /// or a code that names no rule is an error naming where it comes from.
    pub fn new(config: &Config, given: &WalkGiven) -> Result<Self, SettingsError> {
        let here = canonical(Path::new("."));
        let root = config
            .path
            .as_ref()
            .and_then(|p| p.parent())
            .map_or_else(|| here.clone(), canonical);
        let origin = |key: &str| format!("{} ({key})", config.describe());
        let from_line: Vec<String> = given
            .include
            .iter()
            .chain(&given.extend_include)
            .cloned()
            .collect();
        let (by_default, mut included) = match &config.include {
            _ if !given.include.is_empty() => (false, Vec::new()),
            None => (true, Vec::new()),
            Some(include) => (false, include.clone()),
        };
        included.extend(config.extend_include.iter().flatten().cloned());
        let include = [
            matcher(&root, &included, &origin("include"))?,
            matcher(&here, &from_line, "--include, --extend-include")?,
        ];
        included.extend(from_line);
        if by_default {
            included.splice(0..0, DEFAULT_INCLUDE.map(String::from));
        }
        let mut from_file = if given.exclude.is_empty() {
            config.exclude.clone().unwrap_or_default()
        } else {
            Vec::new()
        };
        from_file.extend(config.extend_exclude.iter().flatten().cloned());
        let mut from_line = given.exclude.clone();
        from_line.extend(given.extend_exclude.iter().cloned());
        let exclude = [
            matcher(&root, &from_file, &origin("exclude"))?,
            matcher(&here, &from_line, "--exclude")?,
        ];
        let mut per_file_ignores = Vec::new();
        for (pattern, listed) in config.per_file_ignores.iter().flatten() {
            let origin = origin(&format!("per-file-ignores, `{pattern}`"));
            let glob = matcher(&root, std::slice::from_ref(pattern), &origin)?;
            per_file_ignores.push((glob, codes(listed, &origin)?));
        }
        Ok(Self {
            include,
            by_default,
            exclude,
            included,
            respect_gitignore: given
                .respect_gitignore
                .or(config.respect_gitignore)
                .unwrap_or(true),
            per_file_ignores,
            force_exclude: given
                .force_exclude
                .or(config.force_exclude)
                .unwrap_or(false),
        })
    }

    /// Whether a walk takes the file at `path` (absolute, as the walk
    /// reached it, below a canonical directory).
    pub fn includes(&self, path: &Path) -> bool {
        let extension = path.extension().and_then(|e| e.to_str());
        let by_default = self.by_default
            && extension.is_some_and(|extension| {
                let mut defaults = DEFAULT_INCLUDE.iter().filter_map(|p| p.strip_prefix("*."));
                defaults.any(|default| default.eq_ignore_ascii_case(extension))
            });
        by_default
            || self
                .include
                .iter()
                .any(|m| m.matched(path, false).is_ignore())
    }

    /// Whether a walk leaves out the file or folder at `path`.
    pub fn excludes(&self, path: &Path, is_dir: bool) -> bool {
        self.exclude
            .iter()
            .any(|m| m.matched(path, is_dir).is_ignore())
    }

    /// Whether `exclude` leaves out the file at `path` (absolute), named on
    /// the command line: it, or a folder it lies in, matches.
    pub fn excludes_named(&self, path: &Path) -> bool {
        // A path that could not be resolved (a file that does not exist)
        // is as typed: `//dir` and `dir/./x` are read as `/dir` and `dir/x`
        // by `starts_with`, not by the matcher, which cuts its root off the
        // bytes (and panics where they differ). Rebuilt from its components,
        // the bytes say what the components do.
        let path: PathBuf = path.components().collect();
        self.exclude.iter().any(|m| {
            // The matcher reads only paths below its own root.
            path.starts_with(m.path()) && m.matched_path_or_any_parents(&path, false).is_ignore()
        })
    }

    /// The rule codes and prefixes `per-file-ignores` ignores in the program
    /// at `path`.
    pub fn ignored_in(&self, path: &Path) -> Vec<String> {
        if self.per_file_ignores.is_empty() {
            return Vec::new();
        }
        let path = canonical(path);
        self.per_file_ignores
            .iter()
            .filter(|(glob, _)| glob.matched(&path, false).is_ignore())
            .flat_map(|(_, codes)| codes.iter().cloned())
            .collect()
    }
}

/// `path` resolved, or made absolute when it cannot be (a file to be, as
/// stdin's `--stdin-filename`).
fn canonical(path: &Path) -> PathBuf {
    std::fs::canonicalize(path)
        .or_else(|_| std::path::absolute(path))
        .unwrap_or_else(|_| path.to_path_buf())
}

/// The patterns `lines`, read as `.gitignore` lines below `root`.
fn matcher(root: &Path, lines: &[String], origin: &str) -> Result<Gitignore, SettingsError> {
    let mut builder = GitignoreBuilder::new(root);
    builder
        .case_insensitive(true)
        .map_err(|error| bad(origin, "", &error))?;
    for line in lines {
        builder
            .add_line(None, line)
            .map_err(|error| bad(origin, line, &error))?;
    }
    builder.build().map_err(|error| bad(origin, "", &error))
}

fn bad(origin: &str, pattern: &str, error: &ignore::Error) -> SettingsError {
    SettingsError::Pattern {
        origin: origin.to_string(),
        pattern: pattern.to_string(),
        why: error.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn config(text: &str, dir: &Path) -> Config {
        let mut config: Config = toml::from_str(text).expect("valid");
        config.path = Some(dir.join(crate::workspace::FILE_NAME));
        config
    }

    #[test]
    fn patterns_are_gitignore_lines_below_the_settings_file_in_any_case() {
        let dir = canonical(&std::env::temp_dir());
        let config = config(
            "extend-include = [\"*.nc\"]\nexclude = [\"old\", \"/parts/draft\"]\n[per-file-ignores]\n\"probe/*\" = [\"N005\"]\n",
            &dir,
        );
        let patterns = Patterns::new(&config, &WalkGiven::default()).expect("patterns");
        assert!(patterns.includes(&dir.join("a/PART.MPF")));
        assert!(patterns.includes(&dir.join("a/part.Nc")));
        assert!(!patterns.includes(&dir.join("a/notes.txt")));
        assert!(patterns.excludes(&dir.join("x/OLD"), true));
        assert!(patterns.excludes(&dir.join("parts/draft"), true));
        assert!(!patterns.excludes(&dir.join("x/parts/draft"), true));
        assert_eq!(patterns.ignored_in(&dir.join("probe/P.MPF")), ["N005"]);
        assert!(patterns.ignored_in(&dir.join("P.MPF")).is_empty());

        // The command line's --exclude replaces the file's `exclude`.
        let given = WalkGiven {
            exclude: vec!["new".into()],
            ..WalkGiven::default()
        };
        let patterns = Patterns::new(&config, &given).expect("patterns");
        assert!(!patterns.excludes(&dir.join("x/old"), true));
        assert!(patterns.excludes(&dir.join("x/new"), true));

        let bad = config_error("[per-file-ignores]\n\"*\" = [\"N05\"]\n", &dir);
        assert!(bad.contains("no rule has the code `N05`"), "{bad}");
        let bad = config_error("exclude = [\"{old,draft\"]\n", &dir);
        assert!(bad.contains("`{old,draft`"), "{bad}");
    }

    fn config_error(text: &str, dir: &Path) -> String {
        match Patterns::new(&config(text, dir), &WalkGiven::default()) {
            Ok(_) => panic!("{text} is refused"),
            Err(error) => error.to_string(),
        }
    }
}
