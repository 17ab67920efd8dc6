//! `sinuprep.toml`: the project's settings, found in the file's directory or
//! its parents (or given with `--config`). Command-line options win over it.
//! Unknown keys are errors that name the key.

use std::path::{Path, PathBuf};

use crate::diagnostic::Severity;
use crate::emit::cycle600::Form;
use crate::workspace::SettingsError;

pub const FILE_NAME: &str = "sinuprep.toml";

#[derive(Debug, Default, Clone, serde::Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct Config {
    /// Rule codes or prefixes to report (all when absent).
    pub select: Option<Vec<String>>,
    /// Rule codes or prefixes not to report.
    pub ignore: Option<Vec<String>>,
    pub severity_min: Option<SeverityName>,
    pub deny_warnings: Option<bool>,
    /// Default `--emit` form of `rewrite`.
    pub emit: Option<Form>,
    /// Decimals of emitted numbers, 0 to 15 (`--precision`).
    #[serde(default, deserialize_with = "decimals")]
    pub precision: Option<u8>,
    /// HEAD_DEF path, relative to the configuration file.
    pub heads: Option<PathBuf>,
    /// Measured values file, relative to the configuration file.
    pub values: Option<PathBuf>,
    pub emit_runtime: Option<bool>,
    /// The first R parameter of the run-time code (`--runtime-r`).
    #[serde(default, deserialize_with = "r_base")]
    pub runtime_r: Option<u32>,
    /// The machine's axis names (channel and machine axes: `["X", "XC", "AX1"]`),
    /// which a program may use where a variable could stand.
    pub axes: Option<Vec<String>>,
    /// Definition files (GUD, macros) whose globals and macros programs use,
    /// and machine data (`.INI`) whose axis names they use; relative to the
    /// configuration file.
    pub definitions: Option<Vec<PathBuf>>,
    /// The control's cycle directories (CUS, CMA, CST as copied from the
    /// machine), searched in this order after the program's own directory
    /// for the subprograms it calls; relative to the configuration file.
    pub cycles: Option<Vec<PathBuf>>,
    /// The machine's swivel data records (`$TC_CARRn[m]=value`), relative to
    /// the configuration file.
    pub machine: Option<PathBuf>,
    /// The record of a rotary table under the machine's heads (kinematics
    /// "P", one rotary axis), by name or number: a swivel on a head record
    /// is split over the table and the head.
    pub table: Option<String>,
    /// The orientation error (degrees) a Hirth grid's rounding may make
    /// before `check` reports it (K004).
    #[serde(default, deserialize_with = "tolerance_degrees")]
    pub hirth_tolerance: Option<f64>,
    /// The files a directory walk takes, as patterns (`.gitignore` lines,
    /// relative to this file, any case) [default: `*.mpf`, `*.spf`, `*.arc`].
    pub include: Option<Vec<String>>,
    /// Patterns added to `include` (`["*.nc", "_N_*_MPF"]`).
    pub extend_include: Option<Vec<String>>,
    /// Files and folders a walk leaves out (`["old", "/parts/draft"]`);
    /// `--exclude` replaces it.
    pub exclude: Option<Vec<String>>,
    /// Added to `exclude`, also when `--exclude` is given.
    pub extend_exclude: Option<Vec<String>>,
    /// Whether a walk leaves out what `.gitignore`, `.ignore` and git's
    /// exclude files ignore [default: true].
    pub respect_gitignore: Option<bool>,
    /// Whether a file named on the command line is left out when `exclude`
    /// matches it (or a folder it lies in), as a walk leaves it out: for
    /// tools that pass every changed file, as pre-commit does [default:
    /// false].
    pub force_exclude: Option<bool>,
    /// Rule codes or prefixes not reported in the files a pattern matches
    /// (`"probe/*" = ["N005"]`), over `select` and `ignore`.
    pub per_file_ignores: Option<std::collections::BTreeMap<String, Vec<String>>>,
    /// `[format]`: how `sinuprep fmt` lays programs out.
    pub format: Option<crate::format::FormatConfig>,
    /// `[run]`: what `sinuprep run` cannot know from the program and the
    /// machine's data.
    pub run: Option<RunConfig>,
    /// Where the file was read from (not a key).
    #[serde(skip)]
    pub path: Option<PathBuf>,
}

/// `[run]` of sinuprep.toml.
#[derive(Debug, Clone, Default, PartialEq, serde::Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct RunConfig {
    /// Seconds a word or a call takes each time it runs, which neither the
    /// program nor the machine's data say: a tool change (`M6 = 7.5`), a
    /// clamping (`M10 = 2`), a swivel with its retract (`CYCLE800 = 12`).
    pub times: Option<std::collections::BTreeMap<String, f64>>,
}

impl RunConfig {
    /// The times by word or name in upper case (`M06` as `M6`), or why one
    /// is none.
    pub fn times(&self) -> Result<std::collections::BTreeMap<String, f64>, String> {
        let mut times = std::collections::BTreeMap::new();
        for (key, seconds) in self.times.iter().flatten() {
            if !seconds.is_finite() || *seconds < 0.0 {
                return Err(format!(
                    "[run] times: `{key}` takes {seconds} s: give seconds, 0 or more"
                ));
            }
            let upper = key.trim().to_ascii_uppercase();
            let letter = upper.chars().next().filter(|c| c.is_ascii_alphabetic());
            let digits = upper
                .get(1..)
                .filter(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()));
            let key = match (letter, digits) {
                // `M06` is `M6`, as the control reads it.
                (Some(letter), Some(digits)) if letter != 'L' => {
                    match digits.trim_start_matches('0') {
                        "" => format!("{letter}0"),
                        number => format!("{letter}{number}"),
                    }
                }
                _ => upper,
            };
            times.insert(key, *seconds);
        }
        Ok(times)
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum SeverityName {
    Info,
    Warning,
    Error,
}

impl From<SeverityName> for Severity {
    fn from(name: SeverityName) -> Severity {
        match name {
            SeverityName::Info => Severity::Info,
            SeverityName::Warning => Severity::Warning,
            SeverityName::Error => Severity::Error,
        }
    }
}

impl Config {
    /// `--config FILE`, or the nearest `sinuprep.toml` (any case) from
    /// `start` upward.
    pub fn find(explicit: Option<&Path>, start: &Path) -> Result<Config, SettingsError> {
        let path = match explicit {
            Some(path) => Some(path.to_path_buf()),
            None => nearest(start, super::folder::settings_in)?,
        };
        match path {
            Some(path) => Config::read(&path),
            None => Ok(Config::default()),
        }
    }

    pub fn read(path: &Path) -> Result<Config, SettingsError> {
        Self::read_with(path, super::file::read)
    }

    /// [`Self::read`], the bytes read by `read` (an editor's buffer of the
    /// file, say).
    pub fn read_with(
        path: &Path,
        read: impl FnOnce(&Path) -> std::io::Result<Vec<u8>>,
    ) -> Result<Config, SettingsError> {
        let bytes = read(path).map_err(|source| SettingsError::Read {
            path: path.to_path_buf(),
            source,
        })?;
        let read = |source| SettingsError::Read {
            path: path.to_path_buf(),
            source,
        };
        let text = String::from_utf8(bytes)
            .map_err(|e| read(std::io::Error::new(std::io::ErrorKind::InvalidData, e)))?;
        let mut config: Config = toml::from_str(&text).map_err(|error| {
            let at = error.span().map_or(0, |span| span.start);
            let position = crate::span::LineIndex::new(text.as_bytes()).position(at);
            SettingsError::Config {
                path: path.to_path_buf(),
                line: position.row,
                column: position.column,
                why: with_did_you_mean(error.message()),
            }
        })?;
        config.path = Some(path.to_path_buf());
        Ok(config)
    }

    /// The file's path for messages (`sinuprep.toml` when none was found).
    pub fn describe(&self) -> String {
        self.path
            .as_ref()
            .map_or_else(|| "sinuprep.toml".to_string(), |p| p.display().to_string())
    }

    /// A path written in the file, taken relative to the file's directory.
    pub(crate) fn resolve(&self, path: &Path) -> PathBuf {
        match self.path.as_ref().and_then(|p| p.parent()) {
            Some(dir) if path.is_relative() => dir.join(path),
            _ => path.to_path_buf(),
        }
    }
}

/// `precision`: as many decimals as `--precision` takes, the digits a
/// double holds.
fn decimals<'de, D: serde::Deserializer<'de>>(from: D) -> Result<Option<u8>, D::Error> {
    let count = <i64 as serde::Deserialize>::deserialize(from)?;
    match u8::try_from(count) {
        Ok(count) if count <= 15 => Ok(Some(count)),
        _ => Err(serde::de::Error::custom(format!(
            "precision {count} is no count of decimals from 0 to 15 (a double holds about 15 digits)"
        ))),
    }
}

/// `runtime-r`: an R parameter's number, as `--runtime-r` takes it.
fn r_base<'de, D: serde::Deserializer<'de>>(from: D) -> Result<Option<u32>, D::Error> {
    use crate::emit::runtime::MAX_R_BASE;
    let base = <i64 as serde::Deserialize>::deserialize(from)?;
    match u32::try_from(base) {
        Ok(base) if base <= MAX_R_BASE => Ok(Some(base)),
        _ => Err(serde::de::Error::custom(format!(
            "runtime-r {base} is no R parameter's number from 0 to {MAX_R_BASE}"
        ))),
    }
}

/// `hirth-tolerance`: an orientation error, 0 to 180 degrees (NaN would
/// let every rounding pass unseen, a negative number report every one).
fn tolerance_degrees<'de, D: serde::Deserializer<'de>>(from: D) -> Result<Option<f64>, D::Error> {
    let degrees = <f64 as serde::Deserialize>::deserialize(from)?;
    if (0.0..=180.0).contains(&degrees) {
        Ok(Some(degrees))
    } else {
        Err(serde::de::Error::custom(format!(
            "hirth-tolerance {degrees} is no angle from 0 to 180 degrees"
        )))
    }
}

/// The keys of the file.
const KEYS: [&str; 24] = [
    "select",
    "ignore",
    "severity-min",
    "deny-warnings",
    "emit",
    "precision",
    "heads",
    "values",
    "emit-runtime",
    "runtime-r",
    "axes",
    "definitions",
    "cycles",
    "machine",
    "table",
    "hirth-tolerance",
    "include",
    "extend-include",
    "exclude",
    "extend-exclude",
    "respect-gitignore",
    "per-file-ignores",
    "force-exclude",
    "format",
];

/// The parser's message, with the key an unknown one was probably meant as.
fn with_did_you_mean(message: &str) -> String {
    let Some((key, rest)) = message
        .strip_prefix("unknown field `")
        .and_then(|rest| rest.split_once('`'))
    else {
        return message.to_string();
    };
    match crate::suggest::closest(key, &KEYS, 2) {
        Some(meant) => format!("unknown field `{key}` (did you mean `{meant}`?){rest}"),
        None => message.to_string(),
    }
}

/// The nearest `sinuprep.toml` from `start` upward, as `settings_in` finds
/// it in each directory (any case: the name is looked for in the
/// directory's listing, not asked of the file system).
pub(crate) fn nearest(
    start: &Path,
    mut settings_in: impl FnMut(&Path) -> Result<Option<PathBuf>, SettingsError>,
) -> Result<Option<PathBuf>, SettingsError> {
    let start = if start.is_dir() {
        start.to_path_buf()
    } else {
        start.parent().map(Path::to_path_buf).unwrap_or_default()
    };
    let Ok(absolute) = super::file::canonical(if start.as_os_str().is_empty() {
        Path::new(".")
    } else {
        &start
    }) else {
        return Ok(None);
    };
    for dir in absolute.ancestors() {
        if let Some(found) = settings_in(dir)? {
            return Ok(Some(found));
        }
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_key_reads_and_unknown_keys_are_named() {
        let config: Config = toml::from_str(
            "select = [\"N\", \"C6\"]\nignore = [\"N014\"]\nseverity-min = \"warning\"\ndeny-warnings = true\nemit = \"frames\"\nprecision = 4\nheads = \"HEAD_DEF.SPF\"\nvalues = \"probe.values\"\nemit-runtime = true\nruntime-r = 100\naxes = [\"XC\", \"AX1\"]\n",
        )
        .expect("valid");
        assert_eq!(config.emit, Some(Form::Frames));
        assert_eq!(config.severity_min, Some(SeverityName::Warning));
        let error = toml::from_str::<Config>("selct = [\"N\"]").expect_err("unknown key");
        assert!(error.message().contains("selct"), "{}", error.message());
        assert!(with_did_you_mean(error.message())
            .starts_with("unknown field `selct` (did you mean `select`?), expected one of"));
        // Every key the file reads is one the did-you-mean knows.
        for key in KEYS {
            let text = format!("{key} = 0");
            let message = toml::from_str::<Config>(&text)
                .err()
                .map(|e| e.message().to_string());
            assert!(
                !message.unwrap_or_default().contains("unknown field"),
                "{key}"
            );
        }
    }
}
