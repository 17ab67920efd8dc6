//! A large program mapped into memory instead of read into it.
//!
//! `check` and `rewrite` read a program front to back several times (the
//! line scan, the line index, the report). Mapped, a page costs no copy and
//! no memory of the process's own: its pages are the page cache's, which the
//! kernel reclaims at will, and the next read of a reclaimed page maps it
//! again. The process's own (anonymous) memory therefore grows with what the
//! analysis keeps (findings, line tables), not with the file.
//!
//! A file truncated by another program while it is mapped ends the process
//! with SIGBUS, as in every program that maps files; only files of at least
//! [`MAPPED_FROM`] bytes are mapped (an editor saves files far smaller).

use std::fs::File;
use std::ops::Deref;

use memmap2::Mmap;

/// Files from this size on are mapped; smaller ones are read.
pub const MAPPED_FROM: u64 = 4 << 20;

/// A file's bytes, mapped read-only.
pub struct Mapped {
    map: Mmap,
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
        let map = unsafe { Mmap::map(file)? };
        // Only a hint for read-ahead; a refusal changes nothing.
        #[cfg(unix)]
        let _ = map.advise(memmap2::Advice::Sequential);
        Ok(Self { map })
    }
}

impl Deref for Mapped {
    type Target = [u8];

    fn deref(&self) -> &[u8] {
        &self.map
    }
}
