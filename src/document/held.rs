//! A document an editor holds open, with its analysis kept beside its text
//! until the text or its settings change: every request about one version
//! of the document reads one analysis, instead of parsing it again. It can
//! be shared across threads: the analysis is made by whichever asks first
//! (a thread of its own for a large program), and the others wait for it.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::OnceLock;

use self_cell::self_cell;

use super::text::Text;
use super::Analyzed;
use crate::lint::Settings;
use crate::semantic::uses::Uses;

/// The analysis of one version of the text, made when first asked for;
/// `None` if it was stopped because the version went stale.
#[derive(Default)]
struct Lazy<'t> {
    analyzed: OnceLock<Option<Analyzed<'t>>>,
    uses: OnceLock<Uses>,
    /// The text or the settings changed since: an analysis under way stops.
    stale: AtomicBool,
}

self_cell!(
    /// An open document: its text, and the analysis that borrows it.
    pub struct Held {
        owner: Text,
        #[not_covariant]
        dependent: Lazy,
    }
);

/// What the requests about one version of a document read.
pub struct Analysis<'a, 't> {
    pub text: &'t Text,
    pub analyzed: &'a Analyzed<'t>,
    uses: &'a OnceLock<Uses>,
}

impl Analysis<'_, '_> {
    /// The table of uses, built by the first request that reads names.
    pub fn uses(&self) -> &Uses {
        self.uses.get_or_init(|| Uses::of(&self.analyzed.model))
    }
}

impl Held {
    pub fn open(text: Text) -> Self {
        Self::new(text, |_| Lazy::default())
    }

    pub fn text(&self) -> &Text {
        self.borrow_owner()
    }

    /// Edits the text; the analysis of the old text is dropped.
    pub fn edit(self, edit: impl FnOnce(&mut Text)) -> Self {
        let mut text = self.into_owner();
        edit(&mut text);
        Self::open(text)
    }

    /// Drops the analysis, as when the settings it was made with change.
    pub fn forget(self) -> Self {
        Self::open(self.into_owner())
    }

    /// Says that this version is no longer wanted (another took its place
    /// while a thread still reads it): an analysis of it under way stops
    /// within a few thousand lines, and none is made after.
    pub fn stop(&self) {
        self.with_dependent(|_, lazy| lazy.stale.store(true, Ordering::Relaxed));
    }

    /// Whether the analysis is made (or refused, the version stopped): a
    /// question asked now is answered without waiting for it.
    pub fn is_analysed(&self) -> bool {
        self.with_dependent(|_, lazy| lazy.analyzed.get().is_some())
    }

    /// Answers from the analysis of the text as it is now, made with
    /// `settings` under the name `name` by the first question asked;
    /// `None` once the version is [stopped](Self::stop) before its analysis
    /// was made.
    pub fn with_analysis<R>(
        &self,
        name: &str,
        settings: &Settings,
        answer: impl for<'a, 't> FnOnce(Analysis<'a, 't>) -> R,
    ) -> Option<R> {
        self.with_dependent(|text, lazy| {
            let analyzed = lazy.analyzed.get_or_init(|| {
                // As `Document::analyze` (each program of an archive), the
                // name borrowed for no longer than the analysis runs.
                let source = text.bytes();
                let stale = || lazy.stale.load(Ordering::Relaxed);
                if stale() {
                    return None;
                }
                // An archive's programs are analysed whole: an archive is
                // the size of a few programs, not of a CAM program.
                super::archive::analyze(name, source, settings).or_else(|| {
                    let kind = crate::syntax::program_kind(Some(name), source);
                    crate::lint::analyze_program_until(source, name, kind, settings, &stale)
                })
            });
            Some(answer(Analysis {
                text,
                analyzed: analyzed.as_ref()?,
                uses: &lazy.uses,
            }))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_held_document_is_shared_across_threads() {
        fn shared<T: Send + Sync>() {}
        shared::<Held>();
    }

    fn findings(held: &Held, settings: &Settings) -> (usize, Vec<&'static str>) {
        held.with_analysis("A.MPF", settings, |analysis| {
            let at = analysis.analyzed as *const Analyzed as usize;
            (
                at,
                analysis.analyzed.findings.iter().map(|f| f.code).collect(),
            )
        })
        .expect("a version not stopped")
    }

    /// A version stopped before it is analysed is never analysed: the
    /// requests about it get no answer from it, and the next version is
    /// analysed as usual.
    #[test]
    fn a_stopped_version_is_not_analysed() {
        let settings = Settings::default();
        let held = Held::open(Text::new(
            b"GOTOF NOWHERE
M30
"
            .to_vec(),
        ));
        held.stop();
        let answered = held.with_analysis("A.MPF", &settings, |_| ());
        assert_eq!(answered, None);
        let held = held.edit(|text| {
            text.replace(
                6..13,
                b"END
END:",
            )
        });
        let (_, codes) = findings(&held, &settings);
        assert!(!codes.contains(&"N001"), "{codes:?}");
    }

    /// One analysis answers until the text changes; the next reads the
    /// edited text.
    #[test]
    fn an_analysis_lasts_until_the_text_changes() {
        let settings = Settings::default();
        let held = Held::open(Text::new(b"G1 X1\nGOTOF END\nEND:\nM30\n".to_vec()));
        let (first, clean) = findings(&held, &settings);
        let (again, _) = findings(&held, &settings);
        assert_eq!(first, again, "the second question reads the first analysis");
        assert!(!clean.contains(&"N001"), "{clean:?}");
        let held = held.edit(|text| text.replace(6..15, b"GOTOF NOWHERE"));
        assert_eq!(held.text().bytes(), b"G1 X1\nGOTOF NOWHERE\nEND:\nM30\n");
        let (_, edited) = findings(&held, &settings);
        assert!(edited.contains(&"N001"), "{edited:?}");
    }
}
