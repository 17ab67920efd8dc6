//! `sinuprep fmt`: a program's layout, case and (asked for) block numbers
//! made regular without changing what it does.
//!
//! The formatter reads the model every other command reads (the lossless
//! lines, their trees, the block structure and where each jump lands) and
//! returns text edits, one per line it changes; bytes no edit touches are
//! the source's. It never touches what a person or another program must
//! find as it was written: strings, comments, `; sinuprep:` lines and the
//! blocks emitted under them, the regions the control's HMI generates
//! ([`protect`]), lines that use macros and the lines after the program's
//! end. A program with a syntax error is not formatted at all.
//!
//! It does not reflow or reorder anything: it changes blanks, the case of
//! the language's own words, and with `--renumber` block numbers and the
//! references to them.
//!
//! - [`layout`]: indentation by block depth, blanks between words, blank lines
//! - [`case`]: which words are the language's and take the configured case
//! - [`protect`]: the lines left exactly as they are
//! - [`renumber`]: new block numbers and every reference to them
//! - [`driver`]: one program, line by line, into edits

pub mod case;
pub mod driver;
pub mod layout;
pub mod protect;
pub mod renumber;

pub use driver::{format, format_merged, format_rows, Formatted, Note};

/// How the language's own words are written.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Case {
    /// `IF`, `G1`, `SIN`, `$P_UIFR` (the control's manuals write them so).
    #[default]
    Upper,
    Lower,
    /// As written.
    Keep,
}

/// What `fmt` does, from `[format]` in `sinuprep.toml` and the command line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Settings {
    /// One level of indentation (default two spaces).
    pub indent: String,
    /// Whether a PROC's body is indented one level.
    pub indent_proc_body: bool,
    pub case: Case,
    /// The user's names (DEF variables, labels, PROC and subprogram names)
    /// take `case` too: the control ignores their case, so it changes
    /// nothing it does; by default they stay as written.
    pub case_names: bool,
    /// Blank lines kept in a row, at most.
    pub max_blank_lines: usize,
    /// `--renumber START,STEP`.
    pub renumber: Option<(u64, u64)>,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            indent: "  ".to_string(),
            indent_proc_body: true,
            case: Case::Upper,
            case_names: false,
            max_blank_lines: 1,
            renumber: None,
        }
    }
}

/// `[format]` in `sinuprep.toml`.
#[derive(Debug, Default, Clone, PartialEq, Eq, serde::Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct FormatConfig {
    /// Spaces per level (0 to 16), or `"tab"`.
    pub indent: Option<Indent>,
    pub indent_proc_body: Option<bool>,
    pub case: Option<Case>,
    pub case_names: Option<bool>,
    pub max_blank_lines: Option<usize>,
}

/// `indent = 4` or `indent = "tab"`.
#[derive(Debug, Clone, PartialEq, Eq, serde::Deserialize)]
#[serde(untagged)]
pub enum Indent {
    Spaces(u8),
    Tab(TabWord),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum TabWord {
    Tab,
}

impl Settings {
    /// The defaults, with what `config` sets; an indent of more than 16
    /// spaces is refused by the caller (see [`FormatConfig::check`]).
    pub fn from_config(config: Option<&FormatConfig>) -> Self {
        let mut settings = Settings::default();
        let Some(config) = config else {
            return settings;
        };
        match &config.indent {
            Some(Indent::Spaces(n)) => settings.indent = " ".repeat(usize::from(*n)),
            Some(Indent::Tab(_)) => settings.indent = "\t".to_string(),
            None => {}
        }
        if let Some(proc_body) = config.indent_proc_body {
            settings.indent_proc_body = proc_body;
        }
        if let Some(case) = config.case {
            settings.case = case;
        }
        if let Some(names) = config.case_names {
            settings.case_names = names;
        }
        if let Some(max) = config.max_blank_lines {
            settings.max_blank_lines = max;
        }
        settings
    }
}

impl FormatConfig {
    /// What is wrong with the values, if anything.
    pub fn check(&self) -> Result<(), String> {
        match self.indent {
            Some(Indent::Spaces(n)) if n > 16 => {
                Err(format!("indent = {n}: at most 16 spaces a level"))
            }
            _ => Ok(()),
        }
    }
}
