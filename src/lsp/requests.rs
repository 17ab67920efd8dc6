//! Requests answered off the main loop, by a fixed number of threads: a
//! hover on a variable walks the program, and a request about a document
//! still being analysed waits for it, so neither may hold up the others.
//! The threads take the requests in the order they came. One the client
//! cancelled (`$/cancelRequest`) before its turn is answered
//! `RequestCancelled` without its work, and so is one of the same kind on
//! the same document that a newer one has superseded (an editor asks for a
//! hover at every pause of the mouse): however many come, the work is
//! bounded by the threads, and what is answered is what is still wanted.

use std::collections::{HashMap, HashSet};
use std::sync::{Arc, Mutex};

use crossbeam_channel::{unbounded, Receiver, Sender};
use lsp_server::{ErrorCode, Message, RequestId};
use lsp_types as lsp;

use super::{failed, response, Answer};

/// How many requests are worked on at once: the machine's cores, at least
/// two (one long request leaves another thread free) and at most four (the
/// findings have a thread of their own).
fn threads() -> usize {
    std::thread::available_parallelism().map_or(2, |n| n.get().clamp(2, 4))
}

/// A request to be answered, the document and method it is about (a newer
/// request for both supersedes it; `None` for one about no document), and
/// the work that answers it.
pub struct Job {
    pub id: RequestId,
    pub about: Option<(lsp::Uri, String)>,
    pub work: Box<dyn FnOnce() -> Answer + Send>,
}

/// What the main loop and the threads share: the requests queued, those of
/// them not to answer, and for each document and method the newest queued.
#[derive(Default)]
struct Wanted {
    queued: HashSet<RequestId>,
    cancelled: HashSet<RequestId>,
    newest: HashMap<(lsp::Uri, String), RequestId>,
}

pub struct Requests {
    jobs: Sender<Job>,
    wanted: Arc<Mutex<Wanted>>,
}

impl Requests {
    /// The threads, answering on `out`; they end when this is dropped.
    pub fn start(out: Sender<Message>) -> Self {
        let (jobs, queue) = unbounded::<Job>();
        let wanted = Arc::new(Mutex::new(Wanted::default()));
        for n in 0..threads() {
            let (queue, out, wanted) = (queue.clone(), out.clone(), wanted.clone());
            let spawned = std::thread::Builder::new()
                .name(format!("sinuprep-request-{n}"))
                .spawn(move || work(&queue, &out, &wanted));
            if let Err(error) = spawned {
                eprintln!("sinuprep lsp: no thread for requests: {error}");
            }
        }
        Self { jobs, wanted }
    }

    /// Queues `job`; an older request of the same kind on the same
    /// document, still queued, is superseded.
    pub fn answer(&self, job: Job) {
        if let Ok(mut wanted) = self.wanted.lock() {
            wanted.queued.insert(job.id.clone());
            if let Some(about) = &job.about {
                if let Some(older) = wanted.newest.insert(about.clone(), job.id.clone()) {
                    wanted.cancelled.insert(older);
                }
            }
        }
        // The threads end only when this sender is dropped.
        let _ = self.jobs.send(job);
    }

    /// `$/cancelRequest`: the request is answered `RequestCancelled` if its
    /// turn has not come (one answered or being answered is no longer
    /// known, so that nothing is kept of it).
    pub fn cancel(&self, id: RequestId) {
        if let Ok(mut wanted) = self.wanted.lock() {
            if wanted.queued.contains(&id) {
                wanted.cancelled.insert(id);
            }
        }
    }
}

fn work(queue: &Receiver<Job>, out: &Sender<Message>, wanted: &Mutex<Wanted>) {
    for job in queue {
        let cancelled = match wanted.lock() {
            Ok(mut wanted) => {
                if let Some(about) = &job.about {
                    if wanted.newest.get(about) == Some(&job.id) {
                        wanted.newest.remove(about);
                    }
                }
                wanted.queued.remove(&job.id);
                wanted.cancelled.remove(&job.id)
            }
            Err(_) => false,
        };
        let answer = if cancelled {
            Err((
                ErrorCode::RequestCanceled,
                "cancelled, or superseded by a newer request of its kind".to_string(),
            ))
        } else {
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(job.work))
                .unwrap_or_else(|_| Err(failed()))
        };
        // A client gone away ends the main loop through the receiver.
        if out.send(response(job.id, answer)).is_err() {
            return;
        }
    }
}
