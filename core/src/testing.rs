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

/// Coordinates that take the special paths of a split or a skew: zeros of both signs, cell
/// boundaries, tiny, far (beyond `i32` cells), huge and non-finite values.
pub const SPECIAL_COORDINATES: [f32; 14] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    1e-30,
    -1e-30,
    -2e7,
    3e9,
    -3e9,
    1e20,
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
];
