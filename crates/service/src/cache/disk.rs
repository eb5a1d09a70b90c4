//! The optional disk tier: one content-addressed file per complete model,
//! named by the hex cache key, written atomically (temporary file, then
//! rename) and read back when the in-process store misses. It survives a
//! restart; the in-process store does not.
//!
//! File layout: the magic `RMCACHE3`, a little-endian `u32` header length,
//! a JSON header (content type, language, seed, counts, ETag, and a printed
//! model's figures: the render's typed results travel with its bytes), the model bytes,
//! then a 32-byte BLAKE3 content hash of the cache key followed by
//! everything before the hash. An entry that does not check out (bad magic,
//! hash mismatch, unknown content type or language, ETag not the BLAKE3 of
//! the bytes) is a miss: never served, removed, and counted in
//! `rulemesh_cache_corrupt_total`. Hashing the key in binds an entry to the
//! request it answers, so a valid entry copied under another key is refused
//! too. (A content hash catches damage and careless copies, not a writer who
//! can compute BLAKE3: Redis and the cache directory must still be private.)
//! `RMCACHE2` entries, written before print figures were kept, are misses.

use super::{CacheKey, Rendered};
use crate::export::Format;
use crate::core::Choice;
use crate::lang::Language;
use serde::{Deserialize, Serialize};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

const MAGIC: &[u8; 8] = b"RMCACHE3";
/// Bytes of the trailing content hash.
const HASH_BYTES: usize = 32;
/// Largest accepted header, in bytes.
const MAX_HEADER: u32 = 4096;
/// Prefix of files being written (removed at startup if a crash left them).
const TMP_PREFIX: &str = ".tmp-";

/// Why the disk tier could not be opened.
#[derive(Debug, thiserror::Error)]
pub enum DiskError {
    /// The directory could not be created or listed.
    #[error("cache directory {path}: {source}")]
    Dir {
        /// The directory.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
}

/// What the header of a cache file records besides the bytes.
#[derive(Debug, Serialize, Deserialize)]
struct Header {
    content_type: String,
    language: String,
    /// Absent in entries written before seeds were recorded: such an entry
    /// reads as a miss (and is rendered and written again).
    #[serde(default)]
    seed: Option<u64>,
    primitives: u64,
    triangles: u64,
    etag: String,
    /// A printed model's figures (`None` for everything else).
    print: Option<crate::print::PrintSummary>,
}

/// The disk tier: a directory and a byte budget it never grows past.
#[derive(Debug)]
pub struct DiskTier {
    dir: PathBuf,
    budget: u64,
    used: AtomicU64,
    counter: AtomicU64,
    hits: AtomicU64,
    writes: AtomicU64,
    skipped: AtomicU64,
    corrupt: AtomicU64,
}

fn is_key_name(name: &str) -> bool {
    name.len() == 64 && name.bytes().all(|b| b.is_ascii_hexdigit() && !b.is_ascii_uppercase())
}

impl DiskTier {
    /// Opens (creating if needed) `dir`, counts the bytes its cache files
    /// hold and removes temporary files an interrupted write left behind.
    /// Once the files reach `budget` bytes no more are written.
    pub fn open(dir: &Path, budget: u64) -> Result<DiskTier, DiskError> {
        let err = |source| DiskError::Dir { path: dir.to_path_buf(), source };
        std::fs::create_dir_all(dir).map_err(err)?;
        let mut used = 0u64;
        for entry in std::fs::read_dir(dir).map_err(err)? {
            let Ok(entry) = entry else { continue };
            let name = entry.file_name();
            let name = name.to_string_lossy();
            if name.starts_with(TMP_PREFIX) {
                let _ = std::fs::remove_file(entry.path());
            } else if is_key_name(&name) {
                used = used.saturating_add(entry.metadata().map_or(0, |m| m.len()));
            }
        }
        Ok(DiskTier {
            dir: dir.to_path_buf(),
            budget,
            used: AtomicU64::new(used),
            counter: AtomicU64::new(0),
            hits: AtomicU64::new(0),
            writes: AtomicU64::new(0),
            skipped: AtomicU64::new(0),
            corrupt: AtomicU64::new(0),
        })
    }

    /// The file holding `key`'s model.
    pub fn path(&self, key: &CacheKey) -> PathBuf {
        self.dir.join(key.hex())
    }

    /// Bytes held by cache files.
    pub(crate) fn used_bytes(&self) -> u64 {
        self.used.load(Ordering::Relaxed)
    }

    /// Models read back from disk.
    pub fn hits(&self) -> u64 {
        self.hits.load(Ordering::Relaxed)
    }

    /// Models written to disk.
    pub fn writes(&self) -> u64 {
        self.writes.load(Ordering::Relaxed)
    }

    /// Models not written because the budget was reached or writing failed.
    pub fn skipped(&self) -> u64 {
        self.skipped.load(Ordering::Relaxed)
    }

    /// Files that did not verify (removed, re-rendered, never served).
    pub fn corrupt(&self) -> u64 {
        self.corrupt.load(Ordering::Relaxed)
    }

    /// Reads `key`'s model, if a valid file holds it (on the blocking pool).
    pub async fn read(self: &Arc<Self>, key: CacheKey) -> Option<Rendered> {
        let me = self.clone();
        let r = tokio::task::spawn_blocking(move || me.read_blocking(&key)).await.ok().flatten();
        if r.is_some() {
            self.hits.fetch_add(1, Ordering::Relaxed);
        }
        r
    }

    fn read_blocking(&self, key: &CacheKey) -> Option<Rendered> {
        let path = self.path(key);
        let len = std::fs::metadata(&path).ok()?.len();
        if len > self.budget || len > u64::from(u32::MAX) {
            return None;
        }
        let data = std::fs::read(&path).ok()?;
        let r = decode(key, &data);
        if r.is_none() {
            self.corrupt.fetch_add(1, Ordering::Relaxed);
            if std::fs::remove_file(&path).is_ok() {
                self.used.fetch_sub(len.min(self.used_bytes()), Ordering::AcqRel);
            }
            tracing::warn!(path = %path.display(), "removed a cache file that did not verify");
        }
        r
    }

    /// Stores a complete model under `key` (on the blocking pool); failures
    /// are logged and leave the tier as it was.
    pub async fn write(self: &Arc<Self>, key: CacheKey, model: Arc<Rendered>) {
        if !model.cacheable() {
            return;
        }
        let me = self.clone();
        let _ = tokio::task::spawn_blocking(move || me.write_blocking(&key, &model)).await;
    }

    fn write_blocking(&self, key: &CacheKey, model: &Rendered) {
        let path = self.path(key);
        if path.exists() {
            return;
        }
        let Some(data) = encode(key, model) else {
            self.skipped.fetch_add(1, Ordering::Relaxed);
            return;
        };
        let len = data.len() as u64;
        let before = self.used.fetch_add(len, Ordering::AcqRel);
        if before.saturating_add(len) > self.budget {
            self.used.fetch_sub(len, Ordering::AcqRel);
            self.skipped.fetch_add(1, Ordering::Relaxed);
            tracing::debug!(key = %key.hex(), "disk cache budget reached; not written");
            return;
        }
        let n = self.counter.fetch_add(1, Ordering::Relaxed);
        let tmp = self.dir.join(format!("{TMP_PREFIX}{}-{}-{n}", key.hex(), std::process::id()));
        let written = (|| -> std::io::Result<()> {
            let mut f = std::fs::File::create(&tmp)?;
            f.write_all(&data)?;
            f.sync_data()?;
            std::fs::rename(&tmp, &path)
        })();
        match written {
            Ok(()) => {
                self.writes.fetch_add(1, Ordering::Relaxed);
            }
            Err(e) => {
                let _ = std::fs::remove_file(&tmp);
                self.used.fetch_sub(len, Ordering::AcqRel);
                self.skipped.fetch_add(1, Ordering::Relaxed);
                tracing::warn!(path = %path.display(), error = %e, "cannot write a cache file");
            }
        }
    }
}

/// The entry's content hash: BLAKE3 of the key, then of `body` (all but the hash).
fn content_hash(key: &CacheKey, body: &[u8]) -> [u8; HASH_BYTES] {
    let mut h = blake3::Hasher::new();
    h.update(&key.0);
    h.update(body);
    *h.finalize().as_bytes()
}

/// Encodes `model` as `key`'s entry (shared with the Redis tier).
pub(super) fn encode(key: &CacheKey, model: &Rendered) -> Option<Vec<u8>> {
    let header = serde_json::to_vec(&Header {
        content_type: model.content_type.to_string(),
        language: model.language.name().to_string(),
        seed: Some(model.seed),
        primitives: model.primitives,
        triangles: model.triangles,
        etag: model.etag.clone(),
        print: model.print,
    })
    .ok()?;
    let header_len = u32::try_from(header.len()).ok().filter(|&n| n <= MAX_HEADER)?;
    let mut out = Vec::with_capacity(12 + header.len() + model.bytes.len() + HASH_BYTES);
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&header_len.to_le_bytes());
    out.extend_from_slice(&header);
    out.extend_from_slice(&model.bytes);
    let hash = content_hash(key, &out);
    out.extend_from_slice(&hash);
    Some(out)
}

fn static_content_type(s: &str) -> Option<&'static str> {
    Format::ALL.iter().map(|f| f.content_type()).chain(["application/json"]).find(|c| *c == s)
}

/// Decodes `key`'s entry; `None` unless every check passes (shared with the Redis tier).
pub(super) fn decode(key: &CacheKey, data: &[u8]) -> Option<Rendered> {
    let (body, hash) = data.split_at_checked(data.len().checked_sub(HASH_BYTES)?)?;
    // blake3::Hash compares in constant time.
    if blake3::Hash::from(content_hash(key, body)) != blake3::Hash::from(<[u8; HASH_BYTES]>::try_from(hash).ok()?) {
        return None;
    }
    let rest = body.strip_prefix(MAGIC)?;
    let (len, rest) = rest.split_first_chunk::<4>()?;
    let len = u32::from_le_bytes(*len);
    if len > MAX_HEADER {
        return None;
    }
    let (header, bytes) = rest.split_at_checked(usize::try_from(len).ok()?)?;
    let header: Header = serde_json::from_slice(header).ok()?;
    let etag = blake3::hash(bytes).to_hex()[..32].to_string();
    if etag != header.etag {
        return None;
    }
    Some(Rendered {
        bytes: bytes::Bytes::copy_from_slice(bytes),
        etag,
        content_type: static_content_type(&header.content_type)?,
        language: Language::from_name(&header.language)?,
        seed: header.seed?,
        primitives: header.primitives,
        triangles: header.triangles,
        truncated: None,
        print: header.print,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn model() -> Rendered {
        let bytes = b"solid x\nendsolid x\n".to_vec();
        Rendered {
            etag: blake3::hash(&bytes).to_hex()[..32].to_string(),
            bytes: bytes.into(),
            content_type: "model/stl",
            language: Language::Mdg,
            seed: (1 << 63) + 1,
            primitives: 1,
            triangles: 0,
            truncated: None,
            print: None,
        }
    }

    #[test]
    fn round_trip_and_damage() {
        let m = model();
        let k = CacheKey([7; 32]);
        let data = encode(&k, &m).expect("encodes");
        assert_eq!(decode(&k, &data), Some(m.clone()));
        // A printed model's figures travel in the header.
        let printed = Rendered { print: Some(crate::print::PrintSummary { volume_mm3: 1.5, surface_area_mm2: 8.0, bbox_mm: [1.5, 1.0, 1.0], shells: 1, watertight: true }), ..m };
        assert_eq!(decode(&k, &encode(&k, &printed).expect("encodes")), Some(printed));
        for cut in [0, 7, 11, 20, data.len() - 1] {
            assert_eq!(decode(&k, &data[..cut]), None, "cut at {cut}");
        }
        // Any flipped bit anywhere (magic, header counts, model bytes, hash) is refused.
        for at in [0, 9, 14, data.len() - 40, data.len() - 33, data.len() - 1] {
            let mut flipped = data.clone();
            flipped[at] ^= 1;
            assert_eq!(decode(&k, &flipped), None, "bit flipped at {at}");
        }
        // A valid entry under another key is refused.
        assert_eq!(decode(&CacheKey([8; 32]), &data), None);
        // Every language round-trips (the Redis tier shares this encoding).
        let l = Rendered { language: Language::Lsystem, ..model() };
        assert_eq!(encode(&k, &l).and_then(|d| decode(&k, &d)), Some(l));
    }

    #[tokio::test]
    async fn budget_stops_writes_and_tmp_files_are_swept() {
        let dir = tempfile::tempdir().expect("tempdir");
        std::fs::write(dir.path().join(".tmp-left-over"), b"x").expect("write");
        let tier = Arc::new(DiskTier::open(dir.path(), 60).expect("opens"));
        assert!(!dir.path().join(".tmp-left-over").exists());
        let m = Arc::new(model());
        tier.write(CacheKey([1; 32]), m.clone()).await;
        assert_eq!(tier.writes(), 0, "a file larger than the budget is not written");
        assert_eq!(tier.skipped(), 1);
        let roomy = Arc::new(DiskTier::open(dir.path(), 1 << 20).expect("opens"));
        roomy.write(CacheKey([1; 32]), m.clone()).await;
        assert_eq!(roomy.writes(), 1);
        assert_eq!(roomy.read(CacheKey([1; 32])).await.as_ref(), Some(&*m));
        assert_eq!(roomy.read(CacheKey([2; 32])).await, None);
        let reopened = DiskTier::open(dir.path(), 1 << 20).expect("opens");
        assert_eq!(reopened.used_bytes(), roomy.used_bytes());
    }
}
