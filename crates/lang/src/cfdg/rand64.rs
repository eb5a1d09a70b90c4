//! Context Free's random stream, ported exactly so that a variation code
//! gives the shapes cfdg 3.4 gives: the xorshift64* generator with its
//! multiplier and default seed (John Horigan, `xorshift64star.h`, Context
//! Free 3.4, 2015), and the `Rand64` wrapper around it (`Rand64.h`,
//! `Rand64.cpp`): doubles from the low 52 bits, seeds combined by xor, and
//! the "entropy" strings xored in byte by byte with a step after each byte.
//!
//! Written by hand because the stream must match cfdg bit for bit; no crate
//! implements Context Free's variant (its `discard` steps without the
//! multiplier, and the seed 0 stands for the default seed).

/// Context Free's multiplier (`RAND64_MULT`).
const MULT: u64 = 2_685_821_657_736_338_717;
/// The seed used when 0 is given (`RAND64_SEED`).
pub(crate) const DEFAULT_SEED: u64 = 0x3DF4_1234_ABCD_330E;

/// One random stream: `Rand64` of Context Free (a xorshift64* state).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Rand64 {
    /// The raw state (`mSeed.mSeed`); may be 0 after an xor, as in cfdg.
    pub state: u64,
}

impl Default for Rand64 {
    fn default() -> Self {
        Rand64 { state: DEFAULT_SEED }
    }
}

impl Rand64 {
    /// A stream with raw state `state` (no substitution of 0, as `mSeed.mSeed = …`).
    pub const fn raw(state: u64) -> Rand64 {
        Rand64 { state }
    }

    /// `seed(s)`: the state `s`, or the default seed when `s` is 0.
    pub fn seeded(s: u64) -> Rand64 {
        Rand64 { state: if s == 0 { DEFAULT_SEED } else { s } }
    }

    /// One xorshift step without output (`discard(1)`).
    pub(crate) fn discard(&mut self) {
        let mut s = self.state;
        s ^= s >> 12;
        s ^= s << 25;
        s ^= s >> 27;
        self.state = s;
    }

    /// The next 64-bit output (`operator()`): the state times the
    /// multiplier, then a step.
    pub(crate) fn next_u64(&mut self) -> u64 {
        let r = self.state.wrapping_mul(MULT);
        self.discard();
        r
    }

    /// A double in [0, 1) from the low 52 bits of the next output (`getDouble`).
    pub(crate) fn next_double(&mut self) -> f64 {
        let n = self.next_u64() & 0x000F_FFFF_FFFF_FFFF;
        n as f64 * (1.0 / 4_503_599_627_370_496.0)
    }

    /// Xors `bytes` in at byte positions starting from `*index` (mod 8),
    /// stepping after each byte (`xorString`); `*index` moves on.
    pub(crate) fn xor_bytes(&mut self, bytes: &[u8], index: &mut u32) {
        for &c in bytes {
            self.state ^= u64::from(c) << (*index * 8);
            self.discard();
            *index = (*index + 1) & 7;
        }
    }

    /// `*this ^= other`.
    pub fn xor(&mut self, other: Rand64) {
        self.state ^= other.state;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Seeds as `cfdg -J` prints them for `SQUARE [x 1 rotate 0.1]` and
    /// `A [size 0.5]` (cfdg 3.4): entropy from a zero state.
    #[test]
    fn entropy_matches_cfdg_json() {
        let x: &[u8] = b"\x95\xE7\x48\x5E\xCC\x06";
        let rot: &[u8] = b"\x84\xB0\x92\x26\x59\xE2";
        let size: &[u8] = b"\x64\xEC\x5B\x4B\xEE\x2B";
        let mut r = Rand64::raw(0);
        let mut i = 0;
        for part in [[b"1" as &[u8], x].concat(), [b"0.1" as &[u8], rot].concat(), b"SQUARE".to_vec()] {
            r.xor_bytes(&part, &mut i);
        }
        assert_eq!(r.state, 0x1EAF_D5DF_85D9_528D);
        let mut r = Rand64::raw(0);
        let mut i = 0;
        r.xor_bytes(&[b"0.5" as &[u8], size].concat(), &mut i);
        r.xor_bytes(b"A", &mut i);
        assert_eq!(r.state, 0xE56D_CA22_317D_E20D);
    }

    #[test]
    fn zero_seed_is_default() {
        assert_eq!(Rand64::seeded(0), Rand64::default());
        let mut r = Rand64::default();
        let d = r.next_double();
        assert!((0.0..1.0).contains(&d));
    }
}
