//! The semantic tokens last sent for each open document, so that the next
//! request (`textDocument/semanticTokens/full/delta`) is answered with what
//! changed: after a keystroke in a program of 100,000 lines the client is
//! sent the few tokens of the lines around it, not megabytes of JSON.
//!
//! The tokens are compared as the protocol encodes them, each relative to
//! the one before: a line inserted changes the tokens of the lines edited
//! and the first token after them (its line delta), and every token before
//! and after is the same. One edit replaces the tokens between the longest
//! common start and the longest common end; its `start` and `deleteCount`
//! count integers, five to a token (LSP 3.17, "Semantic Tokens").

use std::collections::HashMap;
use std::sync::Mutex;

use lsp_types as lsp;

#[derive(Default)]
pub struct TokensSent {
    /// Per document: the result id of the tokens last sent, and the tokens.
    sent: Mutex<HashMap<lsp::Uri, (String, Vec<lsp::SemanticToken>)>>,
    /// The next result id: unique across documents and versions.
    next: std::sync::atomic::AtomicU64,
}

impl TokensSent {
    /// `tokens`, with a result id the client names them by next time.
    pub fn full(&self, uri: &lsp::Uri, tokens: Vec<lsp::SemanticToken>) -> lsp::SemanticTokens {
        let id = self.remember(uri, &tokens);
        lsp::SemanticTokens {
            result_id: Some(id),
            data: tokens,
        }
    }

    /// What changed from the tokens sent as `previous` to `tokens`; all of
    /// them where `previous` is not the last sent (the client missed an
    /// answer, or the document was opened again).
    pub fn delta(
        &self,
        uri: &lsp::Uri,
        previous: &str,
        tokens: Vec<lsp::SemanticToken>,
    ) -> lsp::SemanticTokensFullDeltaResult {
        let edit = {
            let sent = self.lock();
            match sent.get(uri) {
                Some((id, old)) if id == previous => Some(edit(old, &tokens)),
                _ => None,
            }
        };
        match edit {
            None => lsp::SemanticTokensFullDeltaResult::Tokens(self.full(uri, tokens)),
            Some(edit) => {
                let id = self.remember(uri, &tokens);
                lsp::SemanticTokensFullDeltaResult::TokensDelta(lsp::SemanticTokensDelta {
                    result_id: Some(id),
                    edits: edit.into_iter().collect(),
                })
            }
        }
    }

    /// A closed document's tokens are dropped.
    pub fn forget(&self, uri: &lsp::Uri) {
        self.lock().remove(uri);
    }

    fn remember(&self, uri: &lsp::Uri, tokens: &[lsp::SemanticToken]) -> String {
        let id = self
            .next
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed)
            .to_string();
        self.lock()
            .insert(uri.clone(), (id.clone(), tokens.to_vec()));
        id
    }

    fn lock(
        &self,
    ) -> std::sync::MutexGuard<'_, HashMap<lsp::Uri, (String, Vec<lsp::SemanticToken>)>> {
        // A thread that panicked while holding it left whole entries.
        self.sent
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
    }
}

/// The one edit that turns `old` into `new`, `None` when they are equal.
fn edit(old: &[lsp::SemanticToken], new: &[lsp::SemanticToken]) -> Option<lsp::SemanticTokensEdit> {
    let same_start = old.iter().zip(new).take_while(|(a, b)| a == b).count();
    let (old_rest, new_rest) = (&old[same_start..], &new[same_start..]);
    let same_end = old_rest
        .iter()
        .rev()
        .zip(new_rest.iter().rev())
        .take_while(|(a, b)| a == b)
        .count();
    let deleted = old_rest.len() - same_end;
    let inserted = &new_rest[..new_rest.len() - same_end];
    if deleted == 0 && inserted.is_empty() {
        return None;
    }
    let integers = |tokens: usize| u32::try_from(tokens * 5).unwrap_or(u32::MAX);
    Some(lsp::SemanticTokensEdit {
        start: integers(same_start),
        delete_count: integers(deleted),
        data: Some(inserted.to_vec()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn token(delta_line: u32, delta_start: u32, length: u32) -> lsp::SemanticToken {
        lsp::SemanticToken {
            delta_line,
            delta_start,
            length,
            token_type: 0,
            token_modifiers_bitset: 0,
        }
    }

    /// The edit applied as a client applies it, to the integers.
    fn applied(old: &[lsp::SemanticToken], edit: &lsp::SemanticTokensEdit) -> Vec<u32> {
        let flat = |tokens: &[lsp::SemanticToken]| -> Vec<u32> {
            tokens
                .iter()
                .flat_map(|t| {
                    [
                        t.delta_line,
                        t.delta_start,
                        t.length,
                        t.token_type,
                        t.token_modifiers_bitset,
                    ]
                })
                .collect()
        };
        let mut integers = flat(old);
        let start = edit.start as usize;
        let end = start + edit.delete_count as usize;
        integers.splice(start..end, flat(edit.data.as_deref().unwrap_or_default()));
        integers
    }

    #[test]
    fn one_edit_turns_the_old_tokens_into_the_new() {
        let old: Vec<_> = (0..6).map(|i| token(1, i, 3)).collect();
        let cases: Vec<Vec<lsp::SemanticToken>> = vec![
            // A token inserted in the middle, one changed, one removed.
            [&old[..3], &[token(0, 4, 2)], &old[3..]].concat(),
            [&old[..2], &[token(2, 1, 3)], &old[3..]].concat(),
            [&old[..4], &old[5..]].concat(),
            // At either end, everything, nothing.
            [&[token(0, 0, 1)], &old[..]].concat(),
            old[..5].to_vec(),
            Vec::new(),
            // Repeated tokens: the common start and end must not overlap.
            vec![token(1, 0, 3); 3],
        ];
        for new in cases {
            let edit = edit(&old, &new).expect("the tokens differ");
            let want = applied(
                &new,
                &lsp::SemanticTokensEdit {
                    start: 0,
                    delete_count: 0,
                    data: None,
                },
            );
            assert_eq!(applied(&old, &edit), want, "{new:?}");
        }
        assert!(edit(&old, &old).is_none());
        let repeated = vec![token(1, 0, 3); 4];
        let fewer = vec![token(1, 0, 3); 2];
        let edit = edit(&repeated, &fewer).expect("two fewer");
        assert_eq!((edit.start, edit.delete_count), (10, 10));
    }

    #[test]
    fn a_delta_is_of_the_tokens_last_sent_or_all_of_them() {
        let sent = TokensSent::default();
        let uri: lsp::Uri = "file:///P.MPF".parse().expect("a URI");
        let first = sent.full(&uri, vec![token(0, 0, 3), token(1, 0, 3)]);
        let id = first.result_id.expect("an id");
        let second = vec![token(0, 0, 3), token(1, 0, 4)];
        match sent.delta(&uri, &id, second.clone()) {
            lsp::SemanticTokensFullDeltaResult::TokensDelta(delta) => {
                assert_eq!(delta.edits.len(), 1);
                assert_eq!(delta.edits[0].start, 5);
                assert_ne!(delta.result_id, Some(id.clone()));
            }
            other => panic!("a delta expected, got {other:?}"),
        }
        // The first id is no longer the last sent: all the tokens.
        match sent.delta(&uri, &id, second.clone()) {
            lsp::SemanticTokensFullDeltaResult::Tokens(tokens) => assert_eq!(tokens.data, second),
            other => panic!("all the tokens expected, got {other:?}"),
        }
        sent.forget(&uri);
        assert!(matches!(
            sent.delta(&uri, "0", second),
            lsp::SemanticTokensFullDeltaResult::Tokens(_)
        ));
    }
}
