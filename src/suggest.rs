//! Did-you-mean: the nearest of some candidates to a word the program got
//! wrong (a keyword, a label, an accessory), compared without case.

/// Levenshtein distance between `a` and `b`, by characters.
pub fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut previous: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut current = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let cost = usize::from(!ca.eq_ignore_ascii_case(cb));
            current.push(
                (previous[j] + cost)
                    .min(previous[j + 1] + 1)
                    .min(current[j] + 1),
            );
        }
        previous = current;
    }
    previous[b.len()]
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
        .map(|c| (distance(word, c.as_ref()), c))
        .filter(|&(d, _)| d > 0 && d <= most)
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levenshtein() {
        assert_eq!(distance("UFK600", "UFK060"), 2);
        assert_eq!(distance("", "ABC"), 3);
        assert_eq!(distance("endif", "ENDIF"), 0);
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
