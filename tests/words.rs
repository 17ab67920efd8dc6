//! How many of the language's words that real programs write the editor can
//! explain: every word of the outside corpus that is the language's own
//! (`words::is_language_word`), as the highlighting classes it (a keyword, a
//! function or cycle called, a system variable, or a name: a command alone
//! in its block, `STOPRE`, is coloured as one), looked up as the hover looks
//! it up. The floors sit just under what the table reaches, so that a word
//! lost from it fails here.

mod support;

use std::collections::BTreeMap;

use sinuprep::semantic::highlight::{tokens, Class};
use sinuprep::semantic::uses::Uses;
use sinuprep::semantic::words::is_language_word;
use sinuprep::semantic::{cycles, vocabulary, Model};

/// The least share of the distinct language words, and of their
/// occurrences, that must be explained.
const DISTINCT_FLOOR: f64 = 0.98;
const OCCURRENCE_FLOOR: f64 = 0.99;

#[test]
fn the_language_words_of_the_corpus_are_explained() {
    // Each word in upper case: how often it occurs, and whether explained.
    let mut seen: BTreeMap<String, (usize, bool)> = BTreeMap::new();
    for path in support::corpus_files() {
        let source = std::fs::read(&path).expect("corpus file");
        let model = Model::of(&source);
        let uses = Uses::of(&model);
        for token in tokens(&model, &uses, 0..model.lines.len()) {
            let counted = matches!(
                token.class,
                Class::Keyword | Class::Function | Class::SystemVariable | Class::Variable
            );
            let word = token.span.of(&source);
            if !counted || !is_language_word(word) {
                continue;
            }
            let explained = vocabulary::explain(word).is_some() || cycles::cycle(word).is_some();
            let name = String::from_utf8_lossy(word).to_ascii_uppercase();
            seen.entry(name).or_insert((0, explained)).0 += 1;
        }
    }
    let distinct = seen.len();
    let occurrences: usize = seen.values().map(|(count, _)| count).sum();
    let unexplained: Vec<(&String, usize)> = seen
        .iter()
        .filter(|(_, (_, explained))| !explained)
        .map(|(name, (count, _))| (name, *count))
        .collect();
    let missed: usize = unexplained.iter().map(|(_, count)| count).sum();
    let share = |part: usize, whole: usize| part as f64 / whole.max(1) as f64;
    let distinct_share = share(distinct - unexplained.len(), distinct);
    let occurrence_share = share(occurrences - missed, occurrences);
    eprintln!(
        "explained: {} of {distinct} distinct language words ({:.1} %), {} of {occurrences} \
         occurrences ({:.1} %); not explained: {unexplained:?}",
        distinct - unexplained.len(),
        100.0 * distinct_share,
        occurrences - missed,
        100.0 * occurrence_share,
    );
    if distinct == 0 {
        // The corpus was skipped on purpose (`SINUPREP_CORPUS=none`).
        return;
    }
    assert!(
        distinct_share >= DISTINCT_FLOOR,
        "{:.1} % of the distinct words explained, under {:.0} %; not explained: {unexplained:?}",
        100.0 * distinct_share,
        100.0 * DISTINCT_FLOOR
    );
    assert!(
        occurrence_share >= OCCURRENCE_FLOOR,
        "{:.1} % of the occurrences explained, under {:.0} %; not explained: {unexplained:?}",
        100.0 * occurrence_share,
        100.0 * OCCURRENCE_FLOOR
    );
}
