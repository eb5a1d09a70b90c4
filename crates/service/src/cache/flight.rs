//! Single-flight fills of the model store: concurrent misses on one key
//! share one fill (a disk or Redis read, or a render), and every caller
//! waiting on it gets what it landed, a failure included.
//!
//! Why by hand: the store's table (`quick_cache`, see `store`) coordinates
//! fills through a placeholder that hands a failed fill's turn to the next
//! waiter, so a hundred concurrent requests for a render that fails would
//! render a hundred times, one after another. Here the leader's outcome,
//! success or failure, goes to everyone waiting at the time, as the moka
//! store before it did.
//!
//! The protocol: under one lock, a caller follows the flight in the air for
//! its key, or finds the model already in the table (a fill that landed
//! between its lookup and now: the leader stores the model before it ends
//! its flight), or starts a flight and leads it. A leader lands its outcome
//! on a `tokio::sync::watch` channel. A leader dropped before landing (its
//! request went away) drops the channel's sender, and its followers start
//! over, one of them leading.

use super::store::Rendered;
use super::CacheKey;
use std::any::Any;
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};
use tokio::sync::watch;

/// What a finished fill hands the callers that waited on it.
#[derive(Clone)]
pub(super) enum Landed {
    /// A complete model, stored in the table before the flight ended.
    Stored(Arc<Rendered>),
    /// A model that may not be stored (truncated).
    Unstored(Arc<Rendered>),
    /// The fill's error, its type erased: the store is generic over the
    /// error, and a follower takes it back with `downcast_ref`.
    Failed(Arc<dyn Any + Send + Sync>),
}

/// A flight in the air: its number (so that only its own leader ends it)
/// and where its outcome will appear.
type InAir = (u64, watch::Receiver<Option<Landed>>);

/// The fills in the air, by key.
#[derive(Default)]
pub(super) struct Flights {
    air: Mutex<HashMap<CacheKey, InAir, foldhash::fast::RandomState>>,
    next: AtomicU64,
}

/// A caller's part in a fill.
pub(super) enum Turn<'a> {
    /// The table holds the model now.
    Ready(Arc<Rendered>),
    /// Another caller leads the fill: wait for its outcome.
    Follow(watch::Receiver<Option<Landed>>),
    /// This caller fills, and must [`Leader::land`] what it made.
    Lead(Leader<'a>),
}

impl Flights {
    /// The in-air map; a poisoned lock (a panic while it was held, which
    /// nothing in it can cause) still holds a consistent map.
    fn air(&self) -> MutexGuard<'_, HashMap<CacheKey, InAir, foldhash::fast::RandomState>> {
        self.air.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// This caller's turn for `key`; `stored` reads the table, under the
    /// lock that orders it against a landing leader.
    pub(super) fn turn(&self, key: CacheKey, stored: impl FnOnce() -> Option<Arc<Rendered>>) -> Turn<'_> {
        let mut air = self.air();
        if let Some((_, rx)) = air.get(&key) {
            return Turn::Follow(rx.clone());
        }
        if let Some(r) = stored() {
            return Turn::Ready(r);
        }
        let id = self.next.fetch_add(1, Ordering::Relaxed);
        let (tx, rx) = watch::channel(None);
        air.insert(key, (id, rx));
        Turn::Lead(Leader { flights: self, key, id, tx })
    }
}

/// Waits for the flight `rx` follows to land; `None` when its leader went
/// away without landing (start over).
pub(super) async fn outcome(mut rx: watch::Receiver<Option<Landed>>) -> Option<Landed> {
    rx.wait_for(Option::is_some).await.ok().and_then(|landed| landed.clone())
}

/// The caller that fills a key; ends its flight when landed or dropped.
pub(super) struct Leader<'a> {
    flights: &'a Flights,
    key: CacheKey,
    id: u64,
    tx: watch::Sender<Option<Landed>>,
}

impl Leader<'_> {
    /// Hands `landed` to every follower and ends the flight. A `Stored`
    /// model must be in the table already, so that a caller arriving after
    /// the flight ends finds it there.
    pub(super) fn land(self, landed: Landed) {
        self.tx.send_replace(Some(landed));
    }
}

impl Drop for Leader<'_> {
    fn drop(&mut self) {
        let mut air = self.flights.air();
        if air.get(&self.key).is_some_and(|(id, _)| *id == self.id) {
            air.remove(&self.key);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn model(seed: u64) -> Arc<Rendered> {
        Arc::new(Rendered {
            bytes: bytes::Bytes::from_static(b"m"),
            etag: String::new(),
            content_type: "model/gltf-binary",
            language: crate::lang::Language::Mdg,
            seed,
            primitives: 0,
            triangles: 0,
            truncated: None,
            print: None,
        })
    }

    #[tokio::test]
    async fn followers_get_the_leaders_outcome_and_a_dropped_leader_lets_one_lead() {
        let flights = Flights::default();
        let key = CacheKey([7; 32]);
        let Turn::Lead(leader) = flights.turn(key, || None) else { panic!("the first caller leads") };
        let Turn::Follow(rx) = flights.turn(key, || Some(model(1))) else { panic!("the second follows") };
        leader.land(Landed::Failed(Arc::new(String::from("boom"))));
        match outcome(rx).await {
            Some(Landed::Failed(e)) => assert_eq!(e.downcast_ref::<String>().map(String::as_str), Some("boom")),
            _ => panic!("the follower gets the failure"),
        }
        // The flight ended: the table answers, or a new flight starts.
        assert!(matches!(flights.turn(key, || Some(model(2))), Turn::Ready(m) if m.seed == 2));
        let Turn::Lead(leader) = flights.turn(key, || None) else { panic!("a new flight") };
        let Turn::Follow(rx) = flights.turn(key, || None) else { panic!("follows it") };
        drop(leader);
        assert!(outcome(rx).await.is_none(), "a leader gone without landing ends its followers' wait");
        assert!(matches!(flights.turn(key, || None), Turn::Lead(_)), "and the next caller leads");
    }
}
