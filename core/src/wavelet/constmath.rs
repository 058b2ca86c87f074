//! The math tile generation needs, as `const fn`, so tiles are computed at compile time (white
//! noise's Gaussian table uses its `ln` and `sqrt` too).
//!
//! Loops are kept out of the per-value work (the series are unrolled): rustc's
//! `long_running_const_eval` lint counts loop iterations of a constant's evaluation, and a 32³
//! tile must stay well inside it.

use crate::hash::seed::splitmix64;

const LN2: f64 = core::f64::consts::LN_2;

/// `sqrt(x)` for `x > 0`: an exponent-halving first guess and five Newton steps (each doubles
/// the correct bits: 5 → 10 → … → 53+).
pub(crate) const fn sqrt(x: f64) -> f64 {
    let guess = f64::from_bits((x.to_bits() >> 1) + (1023u64 << 51));
    let mut r = guess;
    r = 0.5 * (r + x / r);
    r = 0.5 * (r + x / r);
    r = 0.5 * (r + x / r);
    r = 0.5 * (r + x / r);
    0.5 * (r + x / r)
}

/// `ln(x)` for a normal `x > 0`: `x = m·2^e` with `m ∈ [1, 2)`, `ln m = 2 atanh((m−1)/(m+1))`
/// by its series (`y ≤ 1/3`, 13 terms: error below 1e-14).
pub(crate) const fn ln(x: f64) -> f64 {
    let bits = x.to_bits();
    let e = ((bits >> 52) & 0x7FF) as i64 - 1023;
    let m = f64::from_bits((bits & 0x000F_FFFF_FFFF_FFFF) | (1023u64 << 52));
    let y = (m - 1.0) / (m + 1.0);
    let z = y * y;
    let s = 1.0 / 25.0;
    let s = 1.0 / 23.0 + z * s;
    let s = 1.0 / 21.0 + z * s;
    let s = 1.0 / 19.0 + z * s;
    let s = 1.0 / 17.0 + z * s;
    let s = 1.0 / 15.0 + z * s;
    let s = 1.0 / 13.0 + z * s;
    let s = 1.0 / 11.0 + z * s;
    let s = 1.0 / 9.0 + z * s;
    let s = 1.0 / 7.0 + z * s;
    let s = 1.0 / 5.0 + z * s;
    let s = 1.0 / 3.0 + z * s;
    let s = 1.0 + z * s;
    e as f64 * LN2 + 2.0 * y * s
}

/// A `const` source of Gaussian numbers (mean 0, variance 1): SplitMix64 uniforms through the
/// polar Box-Muller method, as Cook & DeRose use (§4.2), two values per accepted pair.
pub(crate) struct Gaussian {
    state: u64,
    spare: f64,
    has_spare: bool,
}

impl Gaussian {
    pub(crate) const fn new(seed: u64) -> Self {
        Self {
            state: seed,
            spare: 0.0,
            has_spare: false,
        }
    }

    /// Uniform in `(-1, 1)`.
    const fn uniform(&mut self) -> f64 {
        let (s, r) = splitmix64(self.state);
        self.state = s;
        ((r >> 11) as f64 + 0.5) / (1u64 << 52) as f64 - 1.0
    }

    pub(crate) const fn next(&mut self) -> f64 {
        if self.has_spare {
            self.has_spare = false;
            return self.spare;
        }
        loop {
            let u = self.uniform();
            let v = self.uniform();
            let s = u * u + v * v;
            if s < 1.0 && s > 0.0 {
                let f = sqrt(-2.0 * ln(s) / s);
                self.spare = v * f;
                self.has_spare = true;
                return u * f;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn const_math_matches_libm() {
        for &x in &[1e-300, 1e-8, 0.1, 0.5, 0.999, 1.0, 2.0, 3.7, 1e10] {
            assert!(
                (ln(x) - libm::log(x)).abs() <= 1e-13 * libm::log(x).abs().max(1.0),
                "{x}"
            );
            assert!(
                (sqrt(x) - libm::sqrt(x)).abs() <= 1e-15 * libm::sqrt(x),
                "{x}"
            );
        }
    }

    #[test]
    fn gaussian_moments() {
        let mut g = Gaussian::new(1);
        let n = 200_000;
        let (mut m1, mut m2, mut m4) = (0.0, 0.0, 0.0);
        for _ in 0..n {
            let x = g.next();
            m1 += x;
            m2 += x * x;
            m4 += x * x * x * x;
        }
        let (m1, m2, m4) = (m1 / n as f64, m2 / n as f64, m4 / n as f64);
        // Standard errors: mean 1/sqrt(n) = 0.0022, variance sqrt(2/n) = 0.0032, kurtosis ~0.02.
        assert!(m1.abs() < 0.01 && (m2 - 1.0).abs() < 0.015 && (m4 - 3.0).abs() < 0.1);
    }
}
