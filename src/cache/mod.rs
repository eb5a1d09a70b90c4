//! The content-hash model cache: canonical request keys ([`key`]) and an
//! in-process, byte-budgeted, single-flight store ([`store`]), optionally
//! backed by files on disk ([`disk`]).

pub mod disk;
pub mod key;
pub mod store;

pub use disk::{DiskError, DiskTier};
pub use key::{normalize_source, CacheKey};
pub use store::{CacheOutcome, ModelCache, Rendered};
