//! Where the analysis reads a program, told to whoever holds its bytes.
//!
//! A large program is mapped from its file (`cli::mapped`), and the kernel
//! maps a whole page-cache folio (up to 2 MiB on the project's machines) at
//! the first read of any byte in it. A pass that reads a line here and there
//! (the CYCLE600 walk, the rewrite's edits, a report of scattered findings)
//! would map the whole program within a millisecond or two, faster than a
//! timer gives it back. Such passes say where they read, and the holder gives
//! its pages back as the reads move on.
//!
//! The watcher belongs to the thread that analyses the program (`check`
//! analyses one file per thread), so the analysis takes no extra argument
//! for it; without one, [`reading`] does nothing.

use std::cell::RefCell;

/// How much a pass that goes front to back reads between two calls of
/// [`reading`].
pub const STEP: usize = 1 << 20;

/// Told the address of each read.
pub type Watcher = Box<dyn Fn(*const u8)>;

thread_local! {
    static WATCHER: RefCell<Option<Watcher>> = const { RefCell::new(None) };
}

/// The analysis reads `bytes` next.
pub fn reading(bytes: &[u8]) {
    WATCHER.with(|watcher| {
        if let Some(watcher) = &*watcher.borrow() {
            watcher(bytes.as_ptr());
        }
    });
}

/// Tells `watcher` where this thread reads, until the guard is dropped.
pub fn watch(watcher: Watcher) -> Watching {
    WATCHER.with(|slot| *slot.borrow_mut() = Some(watcher));
    Watching(())
}

/// While it lives, [`reading`] calls the thread's watcher.
pub struct Watching(());

impl Drop for Watching {
    fn drop(&mut self) {
        WATCHER.with(|slot| *slot.borrow_mut() = None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Arc;

    #[test]
    fn reads_reach_the_watcher_only_while_it_watches() {
        let bytes = b"N10 X1";
        let seen = Arc::new(AtomicUsize::new(0));
        reading(bytes);
        let counter = Arc::clone(&seen);
        let at = bytes[4..].as_ptr();
        let watching = watch(Box::new(move |read| {
            assert_eq!(read, at);
            counter.fetch_add(1, Ordering::Relaxed);
        }));
        reading(&bytes[4..]);
        drop(watching);
        reading(&bytes[4..]);
        assert_eq!(seen.load(Ordering::Relaxed), 1);
    }
}
