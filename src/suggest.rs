//! Did-you-mean: the nearest of some candidates to a word the program got
//! wrong (a keyword, a label, an accessory), compared without case.

use std::collections::{HashMap, HashSet};

/// Levenshtein distance between `a` and `b`, by characters.
pub fn distance(a: &str, b: &str) -> usize {
    within(a, b, usize::MAX).unwrap_or(usize::MAX)
}

/// The distance between `a` and `b` if it is at most `most`. Stops as soon
/// as every way on is longer, and does not start when the lengths alone
/// differ by more: a did-you-mean over thousands of names costs a length
/// comparison for most of them.
fn within(a: &str, b: &str, most: usize) -> Option<usize> {
    let b: Vec<char> = b.chars().collect();
    let a_len = a.chars().count();
    if a_len.abs_diff(b.len()) > most {
        return None;
    }
    let mut previous: Vec<usize> = (0..=b.len()).collect();
    let mut current = vec![0; b.len() + 1];
    for (i, ca) in a.chars().enumerate() {
        current[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cost = usize::from(!ca.eq_ignore_ascii_case(cb));
            current[j + 1] = (previous[j] + cost)
                .min(previous[j + 1] + 1)
                .min(current[j] + 1);
        }
        if current.iter().min().is_some_and(|&m| m > most) {
            return None;
        }
        std::mem::swap(&mut previous, &mut current);
    }
    Some(previous[b.len()]).filter(|&d| d <= most)
}

/// The candidate nearest to `word`, if at most `most` edits away and not
/// `word` itself; of equals, the first.
pub fn closest<'c, S: AsRef<str> + ?Sized>(
    word: &str,
    candidates: impl IntoIterator<Item = &'c S>,
    most: usize,
) -> Option<&'c S> {
    candidates
        .into_iter()
        .filter_map(|c| Some((within(word, c.as_ref(), most)?, c)))
        .filter(|&(d, _)| d > 0)
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

/// Names to suggest from, however many: searched name by name while the
/// list is short or searches are few, and past that through an index of
/// every way to delete up to [`Nearest::MOST`] characters from each name
/// (two words within `k` edits share a form with at most `k` characters
/// deleted from each), so that a search costs the word's own deletions, not
/// the list's length. Thousands of findings over thousands of names stay
/// linear, and a program with a few findings never pays for the index.
#[derive(Default)]
pub struct Nearest {
    /// Upper case, in the order given.
    names: Vec<String>,
    /// Deleted form -> indices into `names`; built at the first search of a
    /// long list.
    index: Option<HashMap<String, Vec<u32>>>,
    searches: usize,
}

impl Nearest {
    /// The most edits a search may ask for.
    pub const MOST: usize = 2;
    /// Lists up to this long are searched name by name.
    const SCAN: usize = 64;
    /// Searches made name by name before the index is built.
    const SCANNED_SEARCHES: usize = 16;

    pub fn push(&mut self, name: &str) {
        let name = name.to_ascii_uppercase();
        let at = self.names.len() as u32;
        if let Some(index) = &mut self.index {
            for form in deletions(&name, Self::MOST) {
                index.entry(form).or_default().push(at);
            }
        }
        self.names.push(name);
    }

    /// The name nearest to `word`, at most `most` (at most [`Self::MOST`])
    /// edits away and not `word` itself; of equals, the first given.
    pub fn closest(&mut self, word: &str, most: usize) -> Option<&str> {
        self.closest_where(word, most, |_| true)
    }

    /// As [`Self::closest`], of the names `allowed` keeps (upper case).
    pub fn closest_where(
        &mut self,
        word: &str,
        most: usize,
        allowed: impl Fn(&str) -> bool,
    ) -> Option<&str> {
        let most = most.min(Self::MOST);
        self.searches += 1;
        if self.index.is_none()
            && (self.names.len() <= Self::SCAN || self.searches <= Self::SCANNED_SEARCHES)
        {
            let names = self.names.iter().filter(|name| allowed(name));
            return closest(word, names, most).map(String::as_str);
        }
        let names = &self.names;
        let index = self.index.get_or_insert_with(|| {
            let mut index: HashMap<String, Vec<u32>> = HashMap::new();
            for (at, name) in names.iter().enumerate() {
                for form in deletions(name, Self::MOST) {
                    index.entry(form).or_default().push(at as u32);
                }
            }
            index
        });
        let mut found: Option<(usize, u32)> = None;
        for form in deletions(&word.to_ascii_uppercase(), most) {
            for &at in index.get(&form).into_iter().flatten() {
                let name = &names[at as usize];
                let Some(d) = within(word, name, most).filter(|&d| d > 0 && allowed(name)) else {
                    continue;
                };
                if found.is_none_or(|best| (d, at) < best) {
                    found = Some((d, at));
                }
            }
        }
        found.map(|(_, at)| names[at as usize].as_str())
    }
}

/// `word` and every form of it with up to `most` characters deleted, once each.
fn deletions(word: &str, most: usize) -> HashSet<String> {
    let mut forms = HashSet::from([word.to_string()]);
    let mut last = vec![word.to_string()];
    for _ in 0..most {
        let mut next = Vec::new();
        for form in &last {
            for (at, c) in form.char_indices() {
                let mut shorter = form.clone();
                shorter.replace_range(at..at + c.len_utf8(), "");
                if forms.insert(shorter.clone()) {
                    next.push(shorter);
                }
            }
        }
        last = next;
    }
    forms
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levenshtein() {
        assert_eq!(distance("UFK600", "UFK060"), 2);
        assert_eq!(distance("", "ABC"), 3);
        assert_eq!(distance("endif", "ENDIF"), 0);
        assert_eq!(within("UFK600", "UFK060", 1), None);
        assert_eq!(within("UFK600", "UFK060", 2), Some(2));
        assert_eq!(within("AB", "ABCD", 1), None, "lengths alone too far apart");
    }

    proptest::proptest! {
        /// Searched through the index or name by name, the nearest name is
        /// the same: the first of the nearest.
        #[test]
        fn the_index_finds_what_the_scan_finds(
            names in proptest::collection::vec("[abc]{1,6}", 65..120),
            word in "[abcd]{0,7}",
            most in 0usize..3,
        ) {
            let mut nearest = Nearest::default();
            for name in &names {
                nearest.push(name);
            }
            let upper: Vec<String> = names.iter().map(|n| n.to_ascii_uppercase()).collect();
            let scanned = closest(&word, upper.iter(), most).cloned();
            // The first searches scan; later ones go through the index.
            for _ in 0..=Nearest::SCANNED_SEARCHES {
                proptest::prop_assert_eq!(nearest.closest(&word, most).map(str::to_string), scanned.clone());
            }
            proptest::prop_assert!(nearest.index.is_some());
            // Names pushed once the index is built are found as well.
            nearest.push("ABCDDD");
            proptest::prop_assert_eq!(nearest.closest("ABCDD", 1), Some("ABCDDD"));
        }

        /// Cut short or not, the distance is the full computation's.
        #[test]
        fn the_bounded_distance_is_the_distance(a in "[abAB]{0,8}", b in "[abc]{0,8}", most in 0usize..10) {
            let full = distance(&a, &b);
            proptest::prop_assert_eq!(within(&a, &b, most), (full <= most).then_some(full));
        }
    }

    #[test]
    fn the_nearest_within_reach() {
        let words = ["WHILE", "ENDIF", "IF"];
        assert_eq!(closest("ENDIFF", &words, 2), Some(&"ENDIF"));
        assert_eq!(closest("WHILEE", &words, 1), Some(&"WHILE"));
        assert_eq!(closest("CYCLE800", &words, 2), None);
        assert_eq!(closest("IF", &words, 2), None, "not the word itself");
    }
}
