//! Helpers shared by the unit tests: a small random generator and Pearson's χ².

extern crate std;

/// Marsaglia's xorshift32 (shifts 13, 17, 5) from a non-zero `seed`: random inputs for
/// tests that compare two implementations over many values.
pub fn xorshift32(mut state: u32) -> impl FnMut() -> u32 {
    move || {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        state
    }
}

/// Pearson's χ² of `counts` against equal expectations.
pub fn chi2(counts: &[u32]) -> f64 {
    let total: u32 = counts.iter().sum();
    let e = f64::from(total) / counts.len() as f64;
    counts.iter().map(|&c| (f64::from(c) - e).powi(2) / e).sum()
}
