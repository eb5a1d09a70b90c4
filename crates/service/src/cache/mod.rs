//! The content-hash model cache: keyed by the canonical request keys of
//! [`crate::pipeline::key`] (which live with the pipeline, so that outputs
//! can carry their own key), an in-process, byte-budgeted, single-flight store ([`store`]), optionally
//! backed by files on disk ([`disk`]) and by a Redis shared between workers
//! ([`redis`]).

pub mod disk;
mod flight;
pub mod observe;
pub mod redis;
pub mod store;

pub(crate) use disk::{DiskError, DiskTier};
pub use crate::pipeline::key::{normalize_source, CacheKey};
pub(crate) use observe::{CacheObserver, Lookup, Tier};
pub(crate) use self::redis::{RedisError, RedisSettings, RedisTier};
pub(crate) use store::{CacheOutcome, ModelCache, Rendered};
