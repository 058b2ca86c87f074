//! Turning a user's seed into well-mixed bits, at compile time if wanted.

/// SplitMix64 (Steele, Lea & Flood 2014): one step of the generator, returning the new state
/// and a 64-bit output. `const`, so seeded tables can be built at compile time.
#[must_use]
pub(crate) const fn splitmix64(state: u64) -> (u64, u64) {
    let state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    (state, z ^ (z >> 31))
}
