//! A large program mapped into memory instead of read into it, with its
//! pages given back to the kernel as the analysis goes.
//!
//! `check` and `rewrite` read a program front to back several times (the
//! line scan, the line index, the report). Mapped, a page costs no copy and
//! no zeroed memory of our own; and as the mapping is read-only, dropping its
//! pages from our address space loses nothing: the next read of a dropped
//! page maps it again from the page cache. Two things drop them:
//! - a releaser thread, every millisecond: the passes that go front to back
//!   stream through a few megabytes at a time;
//! - the reads themselves, whenever they have moved [`FAR`] (`pages::reading`):
//!   the kernel maps a whole page-cache folio (up to 2 MiB here) at the first
//!   read of any byte in it, so passes that read a line here and there (the
//!   CYCLE600 walk, the rewrite's edits) would map the whole file between
//!   two ticks of the timer.
//!
//! A file truncated by another program while it is mapped ends the process
//! with SIGBUS, as in every program that maps files; only files of at least
//! [`MAPPED_FROM`] bytes are mapped (an editor saves files far smaller).

use std::cell::Cell;
use std::fs::File;
use std::ops::Deref;
use std::sync::mpsc::{channel, RecvTimeoutError, Sender};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::Duration;

use memmap2::{Advice, Mmap};

use crate::pages;

/// Files from this size on are mapped; smaller ones are read.
pub const MAPPED_FROM: u64 = 4 << 20;

/// How long pages stay mapped at most, unless the reads give them back first.
const RELEASE_EVERY: Duration = Duration::from_millis(1);

/// How far the reads move before the pages are given back: about a folio.
const FAR: usize = 2 << 20;

/// A file's bytes, mapped; its releaser thread stops when it is dropped.
pub struct Mapped {
    map: Arc<Mmap>,
    releaser: Option<(Sender<()>, JoinHandle<()>)>,
}

impl Mapped {
    pub fn new(file: &File) -> std::io::Result<Self> {
        // SAFETY: the mapping is read-only, and every read of it goes through
        // `&[u8]`. Its bytes change under us only if another program writes
        // the file meanwhile: the report is then as unreliable as for any
        // file read while it is written, and the offsets an earlier pass
        // found stay within the mapping, whose length is fixed;
        // truncation is the SIGBUS case the module documents.
        #[allow(unsafe_code)]
        let map = Arc::new(unsafe { Mmap::map(file)? });
        // Only a hint for read-ahead; a refusal changes nothing.
        let _ = map.advise(Advice::Sequential);
        let (stop, stopped) = channel::<()>();
        let pages = Arc::clone(&map);
        let releaser = std::thread::Builder::new()
            .name("sinuprep-release".into())
            .spawn(move || {
                while let Err(RecvTimeoutError::Timeout) = stopped.recv_timeout(RELEASE_EVERY) {
                    release(&pages);
                }
            })?;
        Ok(Self {
            map,
            releaser: Some((stop, releaser)),
        })
    }

    /// Until the guard is dropped, this thread's reads of the file give its
    /// pages back whenever they have moved [`FAR`].
    pub fn watch_reads(&self) -> pages::Watching {
        let map = Arc::clone(&self.map);
        let released_at = Cell::new(0);
        pages::watch(Box::new(move |at| {
            let offset = (at as usize).wrapping_sub(map.as_ptr() as usize);
            if offset < map.len() && offset.abs_diff(released_at.get()) >= FAR {
                released_at.set(offset);
                release(&map);
            }
        }))
    }
}

/// Drops every page of the mapping from the process's memory.
fn release(map: &Mmap) {
    // SAFETY: `DontNeed` would discard changes made through a private
    // mapping; this one is shared and read-only, so nothing was changed
    // through it, and the next read of a page maps the file's page again, the
    // same bytes as before the release. Failure only leaves the pages mapped.
    #[allow(unsafe_code)]
    let _ = unsafe { map.unchecked_advise(memmap2::UncheckedAdvice::DontNeed) };
}

impl Deref for Mapped {
    type Target = [u8];

    fn deref(&self) -> &[u8] {
        &self.map
    }
}

impl Drop for Mapped {
    fn drop(&mut self) {
        if let Some((stop, releaser)) = self.releaser.take() {
            drop(stop);
            let _ = releaser.join();
        }
    }
}
