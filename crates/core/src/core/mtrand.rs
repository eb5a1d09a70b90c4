//! The Mersenne Twister (MT19937) as Structure Synth uses it: Richard
//! Wagner's `MTRand` (`ThirdPartyCode/MersenneTwister/MersenneTwister.h` in
//! Structure Synth's source) behind `SyntopiaCore::Math::RandomNumberGenerator`
//! (`SyntopiaCore/Math/Random.h`). EisenScript's builder draws from two of
//! these, exactly as Structure Synth does, so that a script and a seed give
//! the same random choices — and so the same objects — as Structure Synth.
//!
//! Only the three draws Structure Synth makes are provided: a raw 32-bit
//! integer (`getInt()`), an integer in `[0, n]` by masked rejection
//! (`getInt(n)`, `MTRand::randInt(n)`) and a double in `[0, 1]`
//! (`getDouble()`, `MTRand::rand()`, both ends included).

const N: usize = 624;
const M: usize = 397;

/// One MT19937 stream, seeded like `MTRand::seed(uint32)`.
pub struct MtRand {
    state: Box<[u32; N]>,
    /// Index of the next state word to temper; `N` means the block is used up.
    next: usize,
}

impl Clone for MtRand {
    fn clone(&self) -> Self {
        MtRand { state: self.state.clone(), next: self.next }
    }

    /// Copies in place, without allocating (the builder reseeds this way per state).
    fn clone_from(&mut self, source: &Self) {
        self.state.copy_from_slice(&source.state[..]);
        self.next = source.next;
    }
}

impl std::fmt::Debug for MtRand {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "MtRand {{ next: {} }}", self.next)
    }
}

impl MtRand {
    /// A stream seeded with `seed` (`MTRand::seed(oneSeed)`: `initialize` then `reload`).
    pub fn new(seed: u32) -> MtRand {
        let mut m = MtRand { state: Box::new([0; N]), next: N };
        m.seed(seed);
        m
    }

    /// Reseeds the stream (`RandomNumberGenerator::setSeed`).
    pub fn seed(&mut self, seed: u32) {
        self.state[0] = seed;
        for i in 1..N {
            let prev = self.state[i - 1];
            self.state[i] = 1_812_433_253u32.wrapping_mul(prev ^ (prev >> 30)).wrapping_add(i as u32);
        }
        self.reload();
    }

    fn reload(&mut self) {
        let twist = |m: u32, s0: u32, s1: u32| m ^ (((s0 & 0x8000_0000) | (s1 & 0x7fff_ffff)) >> 1) ^ ((s1 & 1).wrapping_neg() & 0x9908_b0df);
        let s = &mut self.state;
        for i in 0..N - M {
            s[i] = twist(s[i + M], s[i], s[i + 1]);
        }
        for i in N - M..N - 1 {
            s[i] = twist(s[i + M - N], s[i], s[i + 1]);
        }
        s[N - 1] = twist(s[M - 1], s[N - 1], s[0]);
        self.next = 0;
    }

    /// A raw 32-bit draw (`MTRand::randInt()`, Structure Synth's `getInt()`).
    pub fn next_u32(&mut self) -> u32 {
        if self.next >= N {
            self.reload();
        }
        let mut y = self.state[self.next];
        self.next += 1;
        y ^= y >> 11;
        y ^= (y << 7) & 0x9d2c_5680;
        y ^= (y << 15) & 0xefc6_0000;
        y ^ (y >> 18)
    }

    /// An integer in `[0, n]`, both ends included (`MTRand::randInt(n)`):
    /// draws are masked to the bits `n` uses and rejected until one fits.
    pub fn int_to(&mut self, n: u32) -> u32 {
        let mut used = n;
        used |= used >> 1;
        used |= used >> 2;
        used |= used >> 4;
        used |= used >> 8;
        used |= used >> 16;
        loop {
            let i = self.next_u32() & used;
            if i <= n {
                return i;
            }
        }
    }

    /// A double in `[0, 1]`, both ends included (`MTRand::rand()`).
    pub fn double(&mut self) -> f64 {
        f64::from(self.next_u32()) * (1.0 / 4_294_967_295.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_the_reference_mt19937() {
        // The reference implementation's first outputs for seed 5489 (mt19937ar.c).
        let mut m = MtRand::new(5489);
        assert_eq!([m.next_u32(), m.next_u32(), m.next_u32()], [3_499_211_612, 581_869_302, 3_890_346_734]);
        // The 10 000th output of std::mt19937 with the default seed (C++11 §26.5.5).
        let mut m = MtRand::new(5489);
        let last = (0..10_000).map(|_| m.next_u32()).last();
        assert_eq!(last, Some(4_123_659_995));
    }

    #[test]
    fn bounded_draws_stay_in_range_and_reseeding_repeats() {
        let mut m = MtRand::new(7);
        assert!((0..1000).all(|_| m.int_to(5) <= 5));
        assert!((0..1000).all(|_| (0.0..=1.0).contains(&m.double())));
        let mut a = MtRand::new(1);
        let first: Vec<u32> = (0..5).map(|_| a.next_u32()).collect();
        a.seed(1);
        assert_eq!((0..5).map(|_| a.next_u32()).collect::<Vec<_>>(), first);
        assert_eq!(MtRand::new(3).int_to(0), 0);
    }
}
