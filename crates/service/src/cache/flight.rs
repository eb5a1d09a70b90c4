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

use super::CacheKey;
use std::any::Any;
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};
use tokio::sync::watch;

/// What a finished fill hands the callers that waited on it: `V` is the
/// store's value (generic, so that this module needs nothing of the store's).
#[derive(Clone)]
pub(super) enum Landed<V> {
    /// A complete model, stored in the table before the flight ended.
    Stored(V),
    /// A model that may not be stored (truncated).
    Unstored(V),
    /// The fill's error, its type erased: the store is generic over the
    /// error, and a follower takes it back with `downcast_ref`.
    Failed(Arc<dyn Any + Send + Sync>),
}

/// A flight in the air: its number (so that only its own leader ends it)
/// and where its outcome will appear.
type InAir<V> = (u64, watch::Receiver<Option<Landed<V>>>);

/// The fills in the air, by key.
pub(super) struct Flights<V> {
    air: Mutex<HashMap<CacheKey, InAir<V>, foldhash::fast::RandomState>>,
    next: AtomicU64,
}

impl<V> Default for Flights<V> {
    fn default() -> Self {
        Flights { air: Mutex::default(), next: AtomicU64::new(0) }
    }
}

/// A caller's part in a fill.
pub(super) enum Turn<'a, V> {
    /// The table holds the model now.
    Ready(V),
    /// Another caller leads the fill: wait for its outcome.
    Follow(watch::Receiver<Option<Landed<V>>>),
    /// This caller fills, and must [`Leader::land`] what it made.
    Lead(Leader<'a, V>),
}

impl<V> Flights<V> {
    /// The in-air map; a poisoned lock (a panic while it was held, which
    /// nothing in it can cause) still holds a consistent map.
    fn air(&self) -> MutexGuard<'_, HashMap<CacheKey, InAir<V>, foldhash::fast::RandomState>> {
        self.air.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
    }
}

impl<V: Clone> Flights<V> {
    /// This caller's turn for `key`; `stored` reads the table, under the
    /// lock that orders it against a landing leader.
    pub(super) fn turn(&self, key: CacheKey, stored: impl FnOnce() -> Option<V>) -> Turn<'_, V> {
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
pub(super) async fn outcome<V: Clone>(mut rx: watch::Receiver<Option<Landed<V>>>) -> Option<Landed<V>> {
    rx.wait_for(Option::is_some).await.ok().and_then(|landed| landed.clone())
}

/// The caller that fills a key; ends its flight when landed or dropped.
pub(super) struct Leader<'a, V> {
    flights: &'a Flights<V>,
    key: CacheKey,
    id: u64,
    tx: watch::Sender<Option<Landed<V>>>,
}

impl<V> Leader<'_, V> {
    /// Hands `landed` to every follower and ends the flight. A `Stored`
    /// model must be in the table already, so that a caller arriving after
    /// the flight ends finds it there.
    pub(super) fn land(self, landed: Landed<V>) {
        self.tx.send_replace(Some(landed));
    }
}

impl<V> Drop for Leader<'_, V> {
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

    #[tokio::test]
    async fn followers_get_the_leaders_outcome_and_a_dropped_leader_lets_one_lead() {
        let flights = Flights::<u64>::default();
        let key = CacheKey([7; 32]);
        let Turn::Lead(leader) = flights.turn(key, || None) else { panic!("the first caller leads") };
        let Turn::Follow(rx) = flights.turn(key, || Some(1)) else { panic!("the second follows") };
        leader.land(Landed::Failed(Arc::new(String::from("boom"))));
        match outcome(rx).await {
            Some(Landed::Failed(e)) => assert_eq!(e.downcast_ref::<String>().map(String::as_str), Some("boom")),
            _ => panic!("the follower gets the failure"),
        }
        // The flight ended: the table answers, or a new flight starts.
        assert!(matches!(flights.turn(key, || Some(2)), Turn::Ready(2)));
        let Turn::Lead(leader) = flights.turn(key, || None) else { panic!("a new flight") };
        let Turn::Follow(rx) = flights.turn(key, || None) else { panic!("follows it") };
        drop(leader);
        assert!(outcome(rx).await.is_none(), "a leader gone without landing ends its followers' wait");
        assert!(matches!(flights.turn(key, || None), Turn::Lead(_)), "and the next caller leads");
    }
}
