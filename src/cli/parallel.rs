//! Work over many files on all cores, each result handed on in the files'
//! order as soon as it and those before it are done.
//!
//! Neither the items nor the results are collected: the items are taken
//! from an iterator as threads become free (a directory walk goes on while
//! the first files are checked), and the threads run at most [`WINDOW`]
//! items ahead of the one the caller waits for, so a run over 50,000 files
//! holds a few dozen files' results, and the first file's findings are
//! printed while the walk is still going.

use std::collections::VecDeque;
use std::sync::{Condvar, Mutex, MutexGuard};

/// Items done or being worked on ahead of the next one handed on: enough
/// that one slow file does not leave the other threads idle, few enough
/// that what waits is small.
const WINDOW: usize = 64;

/// `work(item)` for each of `items` on as many threads as there are cores
/// (none started for one item: the editor-on-save case reads no cgroup
/// files), each item taken by the next free thread; each result handed to
/// `take` on the calling thread, in the items' order. An error from `take`
/// (output that cannot be written) ends the run: no further item is taken,
/// and it is returned.
pub fn each<I: Send, T: Send, E>(
    items: impl Iterator<Item = I> + Send,
    work: impl Fn(I) -> T + Sync,
    mut take: impl FnMut(T) -> Result<(), E>,
) -> Result<(), E> {
    let mut items = items.fuse();
    // Two items looked at before any thread is started.
    let first: Vec<I> = items.by_ref().take(2).collect();
    let workers = match first.len() {
        0 | 1 => 1,
        _ => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    let items = first.into_iter().chain(items);
    if workers == 1 {
        return items.map(work).try_for_each(take);
    }
    let shared = Shared {
        state: Mutex::new(State {
            items,
            next: 0,
            exhausted: false,
            handed: 0,
            done: VecDeque::new(),
            running: workers,
            stop: false,
        }),
        changed: Condvar::new(),
    };
    std::thread::scope(|scope| {
        for _ in 0..workers {
            scope.spawn(|| shared.work(&work));
        }
        let result = shared.hand_on(&mut take);
        // On an error the threads finish the items they hold, then stop.
        shared.lock().stop = true;
        shared.changed.notify_all();
        result
    })
}

struct Shared<T, Items> {
    state: Mutex<State<T, Items>>,
    /// Signalled when an item is done, handed on, or a thread ends.
    changed: Condvar,
}

struct State<T, Items> {
    items: Items,
    /// The index of the next item a thread takes.
    next: usize,
    /// The items have all been taken.
    exhausted: bool,
    /// Items handed on so far; `done[i]` is item `handed + i`.
    handed: usize,
    done: VecDeque<Option<T>>,
    /// Threads not yet ended.
    running: usize,
    stop: bool,
}

impl<T, I, Items: Iterator<Item = I>> Shared<T, Items> {
    fn lock(&self) -> MutexGuard<'_, State<T, Items>> {
        // A thread that panicked holding the lock leaves the state as it
        // was between two steps: still usable.
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    fn wait<'a>(&self, guard: MutexGuard<'a, State<T, Items>>) -> MutexGuard<'a, State<T, Items>> {
        self.changed.wait(guard).unwrap_or_else(|e| e.into_inner())
    }

    /// One thread: takes the next item while it is within the window.
    fn work(&self, work: &(impl Fn(I) -> T + Sync)) {
        // Counts this thread out however it ends, a panic included, so that
        // the caller never waits for an item no thread will finish.
        let _ended = Ended(self);
        loop {
            let (index, item) = {
                let mut state = self.lock();
                while !state.stop && !state.exhausted && state.next >= state.handed + WINDOW {
                    state = self.wait(state);
                }
                if state.stop || state.exhausted {
                    return;
                }
                // The walk behind the items goes on under the lock: one
                // thread at a time, in order.
                let Some(item) = state.items.next() else {
                    state.exhausted = true;
                    drop(state);
                    self.changed.notify_all();
                    return;
                };
                state.next += 1;
                (state.next - 1, item)
            };
            let result = work(item);
            let mut state = self.lock();
            let at = index - state.handed;
            if state.done.len() <= at {
                state.done.resize_with(at + 1, || None);
            }
            state.done[at] = Some(result);
            drop(state);
            self.changed.notify_all();
        }
    }

    /// The calling thread: hands each result on in order as it comes.
    fn hand_on<E>(&self, take: &mut impl FnMut(T) -> Result<(), E>) -> Result<(), E> {
        loop {
            let result = {
                let mut state = self.lock();
                loop {
                    if let Some(result) = state.done.front_mut().and_then(Option::take) {
                        state.done.pop_front();
                        state.handed += 1;
                        break result;
                    }
                    if state.exhausted && state.handed == state.next {
                        return Ok(());
                    }
                    if state.running == 0 {
                        // Every thread ended without this item: one
                        // panicked, and the scope's join passes that on.
                        return Ok(());
                    }
                    state = self.wait(state);
                }
            };
            self.changed.notify_all();
            take(result)?;
        }
    }
}

/// Counts a thread out when it ends; one that panicked stops the others,
/// which would otherwise wait for the window to move past its item.
struct Ended<'a, T, Items>(&'a Shared<T, Items>);

impl<T, Items> Drop for Ended<'_, T, Items> {
    fn drop(&mut self) {
        let mut state = self.0.state.lock().unwrap_or_else(|e| e.into_inner());
        state.running -= 1;
        state.stop |= std::thread::panicking();
        drop(state);
        self.0.changed.notify_all();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    #[test]
    fn results_come_in_order_and_the_threads_stay_within_the_window() {
        let started = AtomicUsize::new(0);
        let mut seen = Vec::new();
        let result: Result<(), ()> = each(
            0..1000,
            |index| {
                started.fetch_add(1, Ordering::SeqCst);
                // Later items finish first.
                std::thread::sleep(std::time::Duration::from_micros(((index * 7) % 13) as u64));
                index
            },
            |index| {
                // No thread ran further ahead than the window.
                assert!(started.load(Ordering::SeqCst) <= index + 1 + WINDOW);
                seen.push(index);
                Ok(())
            },
        );
        assert_eq!(result, Ok(()));
        assert_eq!(seen, (0..1000).collect::<Vec<_>>());
    }

    #[test]
    fn a_panic_in_one_item_ends_the_run_instead_of_hanging_it() {
        let run = std::panic::catch_unwind(|| {
            each(
                0..10_000,
                |index| {
                    assert_ne!(index, 5, "the item that fails");
                    index
                },
                |_| Ok::<(), ()>(()),
            )
        });
        // With one core the panic comes straight from the item.
        assert!(run.is_err());
    }

    #[test]
    fn an_error_from_the_taker_ends_the_run() {
        let started = AtomicUsize::new(0);
        let result = each(
            0..10_000,
            |index| {
                started.fetch_add(1, Ordering::SeqCst);
                index
            },
            |index| if index == 3 { Err(index) } else { Ok(()) },
        );
        assert_eq!(result, Err(3));
        assert!(started.load(Ordering::SeqCst) <= 4 + WINDOW);
    }

    #[test]
    fn items_are_taken_as_threads_become_free_not_collected_first() {
        // An endless iterator: the run ends only because items are taken
        // one at a time, at most the window ahead of what is handed on.
        let taken = AtomicUsize::new(0);
        let items = (0..).inspect(|_| {
            taken.fetch_add(1, Ordering::SeqCst);
        });
        let result = each(
            items,
            |index: usize| index,
            |index| {
                assert!(taken.load(Ordering::SeqCst) <= index + 2 + WINDOW);
                if index == 500 {
                    Err(index)
                } else {
                    Ok(())
                }
            },
        );
        assert_eq!(result, Err(500));
        assert!(taken.load(Ordering::SeqCst) <= 502 + WINDOW);
    }
}
