//! What a program reads from the machine it runs on rather than from its
//! own text: the axis names of the machine data (`$MC_AXCONF_...`), and
//! (to come) the global variables of GUD files, the macros of macro files
//! and the subprograms of the control's cycle directories. Given in
//! sinuprep.toml; a program checked without it is checked on its own text.

use std::collections::HashSet;

/// Names defined outside the program.
#[derive(Clone, Debug, Default)]
pub struct Environment {
    /// Axis names (upper case), as machine data names them: channel axes
    /// (`X`, `XC`), machine axes (`X1`, `AX1`), ...
    pub axes: HashSet<String>,
}

impl Environment {
    /// With the axis names `names` (any case).
    pub fn with_axes<S: AsRef<str>>(names: impl IntoIterator<Item = S>) -> Self {
        Self {
            axes: names
                .into_iter()
                .map(|n| n.as_ref().trim().to_ascii_uppercase())
                .collect(),
        }
    }

    /// Whether `name` (upper case) is an axis of the machine.
    pub fn is_axis(&self, name: &str) -> bool {
        self.axes.contains(name)
    }
}
