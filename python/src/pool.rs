//! The threads a large call runs on: the calling thread among them when it can be.
//!
//! A call from Python that hands its work to a pool sleeps until the pool's threads finish,
//! and they are woken for it: on a 2-core machine that hand-over cost about a tenth of a
//! table-level step of 10⁴ joints (the per-call median 288–293 µs against 262–265 µs when
//! the calling thread works as one of the pool's threads; in Rust 269–271 against 247–249 µs).
//! So the first thread of a process that makes a large call (as a rule the interpreter's
//! main thread) becomes worker 0 of a pool of its own (rayon's `use_current_thread`; the
//! others new threads, RAYON_NUM_THREADS in all, else one per logical CPU), and its large
//! calls run there, the calling thread working alongside the others. Every other thread's
//! calls go to a second pool of as many threads, built at the first of them. The answers are
//! the same whichever pool runs a call (each joint's or point's answer depends on its own
//! inputs alone, whatever the threads or chunking).
//!
//! Both pools are the process's own: a child forked from it (Python's `multiprocessing` on
//! Linux) has none of their threads, so its first large call builds its pools afresh instead
//! of handing work to threads that do not exist (rayon's global pool, which this module never
//! uses, would wait for them forever). The pools last as long as the process (rayon keeps a
//! pool whose worker 0 is a thread of the caller's; at most two per process, asleep between
//! calls).

use std::sync::{Mutex, PoisonError};
use std::thread::ThreadId;

/// A process's pools: its id, the first large caller's thread and pool (None when that thread
/// could not join one: it works in a pool already, e.g. the parent's after a fork), and the
/// pool of the others.
struct Pools {
    process: u32,
    owner: Option<(ThreadId, &'static rayon::ThreadPool)>,
    others: Option<&'static rayon::ThreadPool>,
}

static POOLS: Mutex<Option<Pools>> = Mutex::new(None);

/// A pool kept for the process's life (None when its threads cannot be started).
fn build(builder: rayon::ThreadPoolBuilder) -> Option<&'static rayon::ThreadPool> {
    builder.build().ok().map(|pool| &*Box::leak(Box::new(pool)))
}

/// The pool for a large call from the calling thread (None: no pool could be built).
fn pool() -> Option<&'static rayon::ThreadPool> {
    let (process, me) = (std::process::id(), std::thread::current().id());
    let mut guard = POOLS.lock().unwrap_or_else(PoisonError::into_inner);
    let pools = match &mut *guard {
        Some(p) if p.process == process => p,
        // The first large call of this process (or of a forked child: its parent's pools have
        // no threads here).
        slot => {
            let owner = build(rayon::ThreadPoolBuilder::new().use_current_thread()).map(|pool| (me, pool));
            slot.insert(Pools { process, owner, others: None })
        }
    };
    match pools.owner {
        Some((owner, pool)) if owner == me => Some(pool),
        _ => {
            if pools.others.is_none() {
                pools.others = build(rayon::ThreadPoolBuilder::new());
            }
            pools.others
        }
    }
}

/// Run `f`, a call's parallel work (the GIL released): on the calling thread's pool
/// ([`pool`]), the calling thread working in it when it owns it, else handed over once (`f`'s
/// parallel passes all run inside that one hand-over). Where no pool can be built (no thread
/// could be started), `f` runs from the calling thread as the library would.
pub fn install<R: Send>(f: impl FnOnce() -> R + Send) -> R {
    match pool() {
        Some(pool) => pool.install(f),
        None => f(),
    }
}
