//! The log writer: lines are appended to a shared buffer that one thread
//! of its own writes out in batches, so a worker never makes a system call,
//! wakes a thread or waits for a reader to log a line.
//!
//! Why not tracing-appender's `NonBlocking` (Tokio project, 2019–2025),
//! used before: it sends each line through a channel to its writer thread,
//! which writes it with a system call of its own. At tens of thousands of
//! cached requests a second that is a thread wake-up and a `write` per
//! request, and issue 33 measured the access log at a quarter of the
//! cached-GET throughput. Here a line costs a short lock and a copy; the
//! writer thread wakes every [`FLUSH_EVERY`] (or as soon as
//! [`WAKE_BYTES`] are waiting) and writes everything queued with one call,
//! as nginx's `access_log … buffer=` does. No crate does this for
//! `tracing-subscriber`'s `MakeWriter`; it is written by hand.
//!
//! Bounded: at most `capacity` lines wait. Past that (a stalled or slow
//! reader) a line is dropped and counted ([`BatchWriter::dropped`]), never
//! waited for. Lines keep their order. Dropping the [`FlushGuard`] writes
//! out what is queued and stops the thread.

use std::io::Write;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::Duration;

/// How long a line may wait for its batch: short enough to read a log live.
pub(crate) const FLUSH_EVERY: Duration = Duration::from_millis(20);

/// Queued bytes that wake the writer before [`FLUSH_EVERY`] has passed, so
/// a burst is written in pieces of about this size.
pub(crate) const WAKE_BYTES: usize = 64 * 1024;

/// The queue and its bookkeeping, behind one lock.
#[derive(Debug, Default)]
struct Queue {
    bytes: Vec<u8>,
    lines: usize,
    closing: bool,
}

#[derive(Debug)]
struct Shared {
    queue: Mutex<Queue>,
    wake: Condvar,
    capacity: usize,
    dropped: AtomicU64,
}

impl Shared {
    /// The queue, even if a thread panicked holding it (a log line is not
    /// worth a second panic; the queue's bytes stay whole lines).
    fn lock(&self) -> MutexGuard<'_, Queue> {
        self.queue.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
    }
}

/// A `MakeWriter` for `tracing-subscriber` whose lines are written by a
/// thread of its own (module docs). Cheap to clone.
#[derive(Debug, Clone)]
pub(crate) struct BatchWriter {
    shared: Arc<Shared>,
}

/// Writes the queue out and stops the writer thread when dropped.
#[derive(Debug)]
pub(crate) struct FlushGuard {
    shared: Arc<Shared>,
    thread: Option<JoinHandle<()>>,
}

impl BatchWriter {
    /// A writer to `out` holding at most `capacity` lines (at least one),
    /// and the guard that flushes it. Fails only if the thread cannot start.
    pub fn start<W: Write + Send + 'static>(out: W, capacity: usize) -> std::io::Result<(BatchWriter, FlushGuard)> {
        let shared = Arc::new(Shared { queue: Mutex::new(Queue::default()), wake: Condvar::new(), capacity: capacity.max(1), dropped: AtomicU64::new(0) });
        let for_thread = Arc::clone(&shared);
        let thread = std::thread::Builder::new().name("rulemesh-log".into()).spawn(move || run(&for_thread, out))?;
        Ok((BatchWriter { shared: Arc::clone(&shared) }, FlushGuard { shared, thread: Some(thread) }))
    }

    /// Lines dropped because `capacity` lines were already waiting.
    pub fn dropped(&self) -> u64 {
        self.shared.dropped.load(Ordering::Relaxed)
    }

    /// Queues `line` (one formatted event), or drops and counts it when
    /// the queue is full.
    fn push(&self, line: &[u8]) {
        self.push_with(|bytes| bytes.extend_from_slice(line));
    }

    /// Queues the line `write` appends to the queue's bytes (one whole
    /// line, its `\n` included), or drops and counts it, unwritten, when
    /// the queue is full. Writing in place spares the line a buffer of its
    /// own: the access log's direct line (`access_line`) is written so.
    pub(crate) fn push_with(&self, write: impl FnOnce(&mut Vec<u8>)) {
        let mut q = self.shared.lock();
        if q.lines >= self.shared.capacity {
            drop(q);
            self.shared.dropped.fetch_add(1, Ordering::Relaxed);
            return;
        }
        let before = q.bytes.len();
        write(&mut q.bytes);
        q.lines += 1;
        let wake = before < WAKE_BYTES && q.bytes.len() >= WAKE_BYTES;
        drop(q);
        if wake {
            self.shared.wake.notify_one();
        }
    }
}

/// The writer thread: every [`FLUSH_EVERY`], or when woken, takes the whole
/// queue and writes it with one call, outside the lock.
fn run<W: Write>(shared: &Shared, mut out: W) {
    let mut batch = Vec::new();
    loop {
        let closing = {
            let mut q = shared.lock();
            if q.bytes.is_empty() && !q.closing {
                q = shared.wake.wait_timeout(q, FLUSH_EVERY).map(|(q, _)| q).unwrap_or_else(|p| p.into_inner().0);
            }
            std::mem::swap(&mut batch, &mut q.bytes);
            q.lines = 0;
            q.closing
        };
        if !batch.is_empty() {
            // A reader that went away (EPIPE) or a full disk loses these
            // lines; there is nowhere to report it but the counter.
            if out.write_all(&batch).and_then(|()| out.flush()).is_err() {
                let lines = batch.iter().filter(|&&b| b == b'\n').count().max(1);
                shared.dropped.fetch_add(lines as u64, Ordering::Relaxed);
            }
            batch.clear();
        }
        if closing {
            return;
        }
    }
}

impl Drop for FlushGuard {
    fn drop(&mut self) {
        self.shared.lock().closing = true;
        self.shared.wake.notify_one();
        if let Some(t) = self.thread.take() {
            // A writer thread that panicked has nothing left to flush.
            let _ = t.join();
        }
    }
}

/// One event's writer: `tracing-subscriber` formats an event into a buffer
/// of its own and writes it with one `write_all`, which becomes one line of
/// the queue.
#[derive(Debug)]
pub(crate) struct LineWriter<'a> {
    writer: &'a BatchWriter,
}

impl Write for LineWriter<'_> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.writer.push(buf);
        Ok(buf.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl<'a> tracing_subscriber::fmt::MakeWriter<'a> for BatchWriter {
    type Writer = LineWriter<'a>;

    fn make_writer(&'a self) -> LineWriter<'a> {
        LineWriter { writer: self }
    }
}

/// A writer whose bytes a test reads back (this module's tests, and
/// `access_log`'s, which captures `tracing-subscriber`'s text with it).
#[cfg(test)]
#[derive(Clone, Default)]
pub(crate) struct Sink(pub(crate) Arc<Mutex<Vec<u8>>>);

#[cfg(test)]
impl Write for Sink {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.lock().expect("sink").extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lines arrive whole and in order, and the guard writes out the rest.
    #[test]
    fn lines_arrive_in_order_and_the_guard_flushes_them() {
        let sink = Sink::default();
        let (w, guard) = BatchWriter::start(sink.clone(), 100_000).expect("starts");
        for i in 0..10_000 {
            w.push(format!("line {i}\n").as_bytes());
        }
        drop(guard);
        let text = String::from_utf8(sink.0.lock().expect("sink").clone()).expect("utf-8");
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 10_000);
        assert!(lines.iter().enumerate().all(|(i, l)| *l == format!("line {i}")));
        assert_eq!(w.dropped(), 0);
    }

    /// A reader that never reads: lines past the capacity are dropped and
    /// counted at once, and pushing never waits for the writer.
    #[test]
    fn a_stalled_reader_costs_counted_lines_not_a_wait() {
        let gate = Arc::new(Mutex::new(()));
        struct Stalled(Arc<Mutex<()>>, Sink);
        impl Write for Stalled {
            fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
                let _held = self.0.lock().expect("gate");
                self.1.write(buf)
            }
            fn flush(&mut self) -> std::io::Result<()> {
                Ok(())
            }
        }
        let sink = Sink::default();
        let held = gate.lock().expect("gate");
        let (w, guard) = BatchWriter::start(Stalled(Arc::clone(&gate), sink.clone()), 16).expect("starts");
        // The first batch may already be in the stalled write; the queue
        // holds 16 more lines at most, so of 1 000 at least 1 000 − 32 drop.
        for i in 0..1000 {
            w.push(format!("{i}\n").as_bytes());
        }
        let dropped = w.dropped();
        assert!(dropped >= 1000 - 32, "{dropped}");
        drop(held);
        drop(guard);
        let written = sink.0.lock().expect("sink").iter().filter(|&&b| b == b'\n').count() as u64;
        assert_eq!(written + dropped, 1000);
    }
}
