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
//! Both pools are the process's own, and found without a lock: a child forked from it
//! (Python's `multiprocessing` on Linux) has none of their threads, so its first large call
//! builds its pools afresh instead of handing work to threads that do not exist (rayon's
//! global pool, which the package never uses, would wait for them forever), and no lock
//! another thread held at the fork can stop it. A small call (a batch below the library's
//! two chunks, a `Joint.evaluate` below two of its chunks) stays on the calling thread and
//! uses no pool. The pools last as long as the process (rayon keeps a pool whose worker 0 is a
//! thread of the caller's; at most two per process, asleep between calls).

use std::sync::atomic::{AtomicPtr, AtomicU32, Ordering};
use std::thread::ThreadId;

/// A pool of a process: the process, the thread it belongs to (the owner's pool: None for
/// the others' pool), the pool (None when it could not be built).
struct Entry {
    process: u32,
    thread: Option<ThreadId>,
    pool: Option<&'static rayon::ThreadPool>,
}

/// One of a process's two pools, without a lock (a child forked while another thread held a
/// lock would wait for it forever): the process that claimed the right to build it, and the
/// entry published once built. A claim or an entry of another process (the parent of a fork)
/// counts as none.
struct Slot {
    claim: AtomicU32,
    entry: AtomicPtr<Entry>,
}

impl Slot {
    const fn new() -> Self {
        Slot { claim: AtomicU32::new(0), entry: AtomicPtr::new(std::ptr::null_mut()) }
    }

    /// The entry built in `process`, if published.
    fn entry(&self, process: u32) -> Option<&'static Entry> {
        // SAFETY: a non-null pointer here is a leaked `Box<Entry>` (`publish`), never freed.
        let e = unsafe { self.entry.load(Ordering::Acquire).as_ref() }?;
        (e.process == process).then_some(e)
    }

    /// Claim the right to build this process's entry: true for one caller in `process`.
    fn claim(&self, process: u32) -> bool {
        let seen = self.claim.load(Ordering::Acquire);
        seen != process && self.claim.compare_exchange(seen, process, Ordering::AcqRel, Ordering::Acquire).is_ok()
    }

    /// Publish the claimer's entry (kept for the process's life).
    fn publish(&self, e: Entry) -> &'static Entry {
        let e: &'static Entry = Box::leak(Box::new(e));
        self.entry.store(std::ptr::from_ref(e).cast_mut(), Ordering::Release);
        e
    }
}

/// The first large caller's pool, and the others'.
static OWNER: Slot = Slot::new();
static OTHERS: Slot = Slot::new();

/// A pool kept for the process's life (None when its threads cannot be started).
fn build(builder: rayon::ThreadPoolBuilder) -> Option<&'static rayon::ThreadPool> {
    builder.build().ok().map(|pool| &*Box::leak(Box::new(pool)))
}

/// The pool for a large call from the calling thread (None: no pool could be built).
fn pool() -> Option<&'static rayon::ThreadPool> {
    let (process, me) = (std::process::id(), std::thread::current().id());
    match OWNER.entry(process) {
        Some(e) if e.thread == Some(me) && e.pool.is_some() => return e.pool,
        Some(_) => {}
        // The process's first large call (or a forked child's: its parent's pools have no
        // threads here). A thread already in a pool (the parent's owner, after a fork) cannot
        // join another: it uses the others' pool.
        None if OWNER.claim(process) => {
            let pool = build(rayon::ThreadPoolBuilder::new().use_current_thread());
            if OWNER.publish(Entry { process, thread: Some(me), pool }).pool.is_some() {
                return pool;
            }
        }
        None => {}
    }
    loop {
        if let Some(e) = OTHERS.entry(process) {
            return e.pool;
        }
        if OTHERS.claim(process) {
            return OTHERS.publish(Entry { process, thread: None, pool: build(rayon::ThreadPoolBuilder::new()) }).pool;
        }
        // Another thread of this process is building it (a few hundred microseconds).
        std::thread::yield_now();
    }
}

/// Run `f`, a call's work (the GIL released): on the calling thread when it is not `large`
/// (it then uses no pool), else as [`install`].
pub fn run<R: Send>(large: bool, f: impl FnOnce() -> R + Send) -> R {
    if large { install(f) } else { f() }
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
