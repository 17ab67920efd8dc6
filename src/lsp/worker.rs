//! The findings of open documents, made off the main loop: a large program
//! takes seconds to analyse, and meanwhile the server answers the requests
//! about the others. One thread takes the documents in the order they
//! changed; of a document changed again before its turn, only the newest
//! version is analysed, so findings are published in order and never for a
//! version older than one already published. A version changed while it is
//! analysed stops being analysed within a few thousand lines, unpublished.

use std::thread::JoinHandle;

use crossbeam_channel::{unbounded, Receiver, Sender};
use lsp_server::{Message, Notification};
use lsp_types as lsp;
use lsp_types::notification::Notification as _;

use super::Open;
use crate::span::ColumnUnit;

/// A document whose findings are to be published; `open` is `None` for a
/// document closed, whose findings are cleared.
pub struct Job {
    pub uri: lsp::Uri,
    pub open: Option<Open>,
    pub unit: ColumnUnit,
}

pub struct Worker {
    jobs: Sender<Job>,
    thread: JoinHandle<()>,
}

impl Worker {
    /// A worker that publishes on `out`.
    pub fn start(out: Sender<Message>) -> Self {
        let (jobs, queue) = unbounded();
        let thread = std::thread::spawn(move || work(&queue, &out));
        Self { jobs, thread }
    }

    pub fn publish(&self, job: Job) {
        // The worker ends only when this sender is dropped.
        let _ = self.jobs.send(job);
    }

    /// Publishes what is queued, then ends.
    pub fn finish(self) {
        drop(self.jobs);
        let _ = self.thread.join();
    }
}

fn work(queue: &Receiver<Job>, out: &Sender<Message>) {
    while let Ok(first) = queue.recv() {
        let mut newest: Vec<Job> = Vec::new();
        for job in std::iter::once(first).chain(queue.try_iter()) {
            newest.retain(|queued| queued.uri != job.uri);
            newest.push(job);
        }
        for job in newest {
            let analysed = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                match job.open.as_ref() {
                    Some(open) => {
                        open.with_snapshot(job.unit, |snapshot| snapshot.diagnostics(&job.uri))
                    }
                    None => Some(Vec::new()),
                }
            }));
            // A failure inside sinuprep is said on stderr by the panic
            // itself; the document keeps the findings it had. A version
            // changed while it was analysed stopped: the newer one is
            // queued behind it.
            let Ok(Some(diagnostics)) = analysed else {
                continue;
            };
            let params = lsp::PublishDiagnosticsParams::new(job.uri, diagnostics, None);
            let method = lsp::notification::PublishDiagnostics::METHOD.to_string();
            if out
                .send(Message::Notification(Notification::new(method, params)))
                .is_err()
            {
                return;
            }
        }
    }
}
