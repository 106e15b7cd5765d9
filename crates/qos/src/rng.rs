//! A tiny seeded pseudo-random generator (SplitMix64) for the `random` drop policy and the
//! QoI simulator.
//!
//! Design choice: no `rand` dependency — the policy needs one uniform index per eviction,
//! must be reproducible from a seed across platforms and releases, and must not allocate.

/// SplitMix64 (Steele, Lea, Flood 2014): 64-bit state, passes BigCrush, one add + mix.
#[derive(Debug, Clone)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        SplitMix64 { state: seed }
    }

    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `0..n` (`n > 0`), by Lemire's multiply-shift; the bias is below 2^-32 for
    /// the queue lengths we use, which is irrelevant for a drop policy.
    pub fn below(&mut self, n: usize) -> usize {
        debug_assert!(n > 0);
        ((self.next_u64() as u128 * n as u128) >> 64) as usize
    }
}
