//! A document an editor holds open, with its analysis kept beside its text
//! until the text or its settings change: every request about one version
//! of the document reads one analysis, instead of parsing it again. It can
//! be shared across threads: the analysis is made by whichever asks first
//! (a thread of its own for a large program), and the others wait for it.

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, OnceLock, PoisonError};

use self_cell::self_cell;

use super::text::Text;
use super::Analyzed;
use crate::lint::Settings;
use crate::semantic::uses::{Namespace, Role, Uses};
use crate::semantic::walk::{self, Probe, Seen};
use crate::span::Span;

/// The analysis of one version of the text, made when first asked for;
/// `None` if it was stopped because the version went stale.
#[derive(Default)]
struct Lazy<'t> {
    analyzed: OnceLock<Option<Analyzed<'t>>>,
    uses: OnceLock<Uses>,
    values: Mutex<HashMap<String, Walked>>,
    /// The text or the settings changed since: an analysis under way stops.
    stale: AtomicBool,
}

/// The values of one variable's uses, made by the first request that asks
/// (the others wait for it); `None` if the version went stale meanwhile.
type Walked = Arc<OnceLock<Option<Arc<Values>>>>;

self_cell!(
    /// An open document: its text, and the analysis that borrows it.
    pub struct Held {
        owner: Text,
        #[not_covariant]
        dependent: Lazy,
    }
);

/// The size from which a text's old analysis is freed beside the edit
/// ([`Held::edit`]): below it, the analysis frees faster than a thread starts.
const FREED_ASIDE: usize = 256 * 1024;

/// What the requests about one version of a document read.
pub struct Analysis<'a, 't> {
    pub text: &'t Text,
    pub analyzed: &'a Analyzed<'t>,
    uses: &'a OnceLock<Uses>,
    values: &'a Mutex<HashMap<String, Walked>>,
    stale: &'a AtomicBool,
}

/// What the walk finds in a variable at each use of it.
pub struct Values {
    /// By the name's place, in source order.
    seen: Vec<(Span, Seen)>,
}

impl Values {
    /// What the walk finds in the variable named at `name`.
    pub fn at(&self, name: Span) -> Option<&Seen> {
        let index = self
            .seen
            .binary_search_by_key(&name, |(span, _)| *span)
            .ok()?;
        Some(&self.seen[index].1)
    }
}

impl Analysis<'_, '_> {
    /// The table of uses, built by the first request that reads names.
    pub fn uses(&self) -> &Uses {
        self.uses.get_or_init(|| Uses::of(&self.analyzed.model))
    }

    /// What the variable `name` (as the table of uses spells it) holds at
    /// each use, from one walk made by the first request that asks for it
    /// (a hover): the next hovers on it read that walk until the text
    /// changes. `None` if the version went stale while it was made.
    ///
    /// A walk per name, not one for every variable at once: looking at
    /// every use costs about three walks, one variable's uses at most two
    /// (`cargo bench --bench walk -- values_at`), and the first hover after
    /// each edit waits for it.
    pub fn values(&self, name: &str, settings: &Settings) -> Option<Arc<Values>> {
        let walked = {
            let mut walks = self.values.lock().unwrap_or_else(PoisonError::into_inner);
            Arc::clone(walks.entry(name.to_string()).or_default())
        };
        let values = walked.get_or_init(|| {
            let uses = self.uses().all().iter();
            let probes: Vec<Probe> = uses
                .filter(|u| u.namespace == Namespace::Variable && u.name == name)
                .map(|found| Probe {
                    row: found.row,
                    name: found.span,
                    after: matches!(found.role, Role::Writes | Role::Defines),
                })
                .collect();
            let stale = || self.stale.load(Ordering::Relaxed);
            let seen = walk::values_at(
                &self.analyzed.model,
                &settings.supplied,
                settings.heads.as_ref(),
                &probes,
                Some(&stale),
            )?;
            let at = probes.iter().map(|probe| probe.name);
            Some(Arc::new(Values {
                seen: at.zip(seen).collect(),
            }))
        });
        values.clone()
    }
}

impl Held {
    pub fn open(text: Text) -> Self {
        Self::new(text, |_| Lazy::default())
    }

    pub fn text(&self) -> &Text {
        self.borrow_owner()
    }

    /// Edits the text; the analysis of the old text is dropped, on a thread
    /// of its own for a large text: freeing the trees of 75,000 lines takes
    /// some 7 ms, which the findings of the edit would otherwise wait for.
    pub fn edit(self, edit: impl FnOnce(&mut Text)) -> Self {
        let mut text = if self.text().bytes().len() < FREED_ASIDE {
            self.into_owner()
        } else {
            let text = self.text().clone();
            std::thread::spawn(move || drop(self));
            text
        };
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
                values: &lazy.values,
                stale: &lazy.stale,
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
                analysis
                    .analyzed
                    .findings
                    .iter()
                    .map(|f| f.code())
                    .collect(),
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

    /// A large text's old analysis is freed aside; the edit is the same.
    #[test]
    fn a_large_text_is_edited_as_a_small_one() {
        let settings = Settings::default();
        let mut source = b"GOTOF END\n".to_vec();
        source.extend(b"G1 X1 Y2 Z3 F100\n".repeat(FREED_ASIDE / 10));
        source.extend(b"END:\nM30\n");
        let held = Held::open(Text::new(source.clone()));
        let (_, clean) = findings(&held, &settings);
        assert!(!clean.contains(&"N001"), "{clean:?}");
        let held = held.edit(|text| text.replace(6..9, b"NOWHERE"));
        source.splice(6..9, *b"NOWHERE");
        assert_eq!(held.text().bytes(), &source[..]);
        let (_, edited) = findings(&held, &settings);
        assert!(edited.contains(&"N001"), "{edited:?}");
    }
}
