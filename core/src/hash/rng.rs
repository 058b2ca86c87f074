//! Random numbers that belong to a cell: the impulses of sparse convolution and Gabor noise
//! (Lewis 1989 §3; Lagae et al. 2009), the feature points of cellular noise (Worley 1996).
//!
//! A cell's numbers must be the same whenever the cell is visited, from any point and in any
//! order, so they come from a counter-based generator keyed by the cell's hash: draw `k` is
//! `mix(key + (k + 1)·φ)` (a Weyl sequence through the [`CellHash`] mixer, as SplitMix
//! does). Integer arithmetic only; numbers become exact dyadic fractions, so `f32`, `f64` and
//! I16F16 see the same value up to their precision, on every target.

use super::cell::{CellHash, mix};
use crate::{Error, Real};

/// The golden-ratio increment of the Weyl sequence (odd, so the counter visits every `u32`).
pub(crate) const WEYL: u32 = 0x9E37_79B9;

/// The random numbers of one cell.
///
/// # Examples
///
/// ```
/// use bandnoise::hash::{CellHash, CellRng, Poisson};
///
/// let hash = CellHash::new(42);
/// let mut rng = CellRng::new(&hash, [3, -7]);
/// let x: f32 = rng.uniform();
/// assert!((0.0..1.0).contains(&x));
/// // The same cell gives the same numbers, in any number type.
/// let y: f64 = CellRng::new(&hash, [3, -7]).uniform();
/// assert_eq!(x as f64, y);
/// let impulses = CellRng::new(&hash, [3, -7]).poisson(&Poisson::new(3.0).unwrap());
/// assert!(impulses <= Poisson::new(3.0).unwrap().cap());
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CellRng {
    /// `key + k·φ` after `k` draws: the Weyl sequence's state.
    state: u32,
}

impl CellRng {
    /// The generator of `cell` under `hash` (whose seed is the noise's).
    #[inline]
    #[must_use]
    pub fn new<const D: usize>(hash: &CellHash, cell: [i32; D]) -> Self {
        Self::from_key(hash.hash(cell))
    }

    /// The generator for a key (a cell's hash, or any 32 bits).
    #[inline]
    #[must_use]
    pub const fn from_key(key: u32) -> Self {
        Self { state: key }
    }

    /// The next 32 random bits.
    #[inline]
    pub fn next_u32(&mut self) -> u32 {
        self.state = self.state.wrapping_add(WEYL);
        mix(self.state)
    }

    /// Skips `n` draws: what drawing them would have done to the generator, so a caller that
    /// needs a draw only sometimes keeps the later draws where they were.
    #[inline]
    pub(crate) fn skip(&mut self, n: u32) {
        *self = self.ahead(n);
    }

    /// The generator `n` draws on from this one ([`skip`](Self::skip) without changing this
    /// one): draws at known places of the sequence, taken out of order.
    #[inline]
    #[must_use]
    pub(crate) const fn ahead(&self, n: u32) -> Self {
        Self {
            state: self.state.wrapping_add(n.wrapping_mul(WEYL)),
        }
    }

    /// Uniform in `[0, 1)`: a multiple of 2⁻²⁴, exact in `f32` and `f64`; I16F16 gets it
    /// rounded down to 2⁻¹⁶.
    #[inline]
    pub fn uniform<R: Real>(&mut self) -> R {
        R::from_ratio((self.next_u32() >> 8) as i32, 24)
    }

    /// Uniform in `[-1, 1)`: a multiple of 2⁻²⁴, exact in `f32` and `f64`; I16F16 gets it
    /// rounded down to 2⁻¹⁶.
    #[inline]
    pub fn signed_uniform<R: Real>(&mut self) -> R {
        R::from_ratio((self.next_u32() >> 7) as i32 - (1 << 24), 24)
    }

    /// A Poisson-distributed count with the mean of `poisson`, capped at
    /// [`poisson.cap()`](Poisson::cap). Takes one draw.
    #[inline]
    pub fn poisson(&mut self, poisson: &Poisson) -> u32 {
        let u = self.next_u32();
        // The count is the number of thresholds at or below u: P(k) = (T_k − T_{k−1}) / 2³².
        // (`take` and the iterator keep it within the table, provably.)
        poisson.thresholds[..]
            .iter()
            .take(poisson.cap as usize)
            .take_while(|&&t| u >= t)
            .count() as u32
    }
}

/// The most thresholds a [`Poisson`] table holds.
const MAX_THRESHOLDS: usize = 96;

/// A Poisson distribution, tabulated for [`CellRng::poisson`].
///
/// The table holds the cumulative distribution scaled to 2³², computed once in `f64` with
/// `libm` (the same on every target). A count is capped at [`cap`](Self::cap), the first count
/// whose upper tail is below 2⁻³² (what one 32-bit draw resolves): the rare larger counts are
/// that cap, so a noise built on it can prove an amplitude bound. For a mean of 1 the cap is
/// 12, for 8 it is 31, for 32 it is 73 (printed by `tests/tests/hash.rs`).
///
/// # Examples
///
/// ```
/// use bandnoise::{Error, hash::Poisson};
///
/// let p = Poisson::new(2.5)?;
/// assert_eq!(p.mean(), 2.5);
/// assert!(Poisson::new(0.0).is_err());
/// # Ok::<(), Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Poisson {
    mean: u32,
    cap: u32,
    thresholds: [u32; MAX_THRESHOLDS],
}

impl Poisson {
    /// The largest mean.
    pub const MAX_MEAN: f32 = 32.0;

    /// The distribution with mean `mean`.
    ///
    /// # Errors
    ///
    /// [`Error::PoissonMean`] unless `0 < mean ≤ 32` (and finite).
    pub fn new(mean: f32) -> Result<Self, Error> {
        if !(mean > 0.0 && mean <= Self::MAX_MEAN) {
            return Err(Error::PoissonMean(mean));
        }
        Ok(Self::tabulate(mean))
    }

    /// The distribution with mean `mean`, which the caller has checked is in `(0, 32]`.
    pub(crate) fn tabulate(mean: f32) -> Self {
        let lambda = mean as f64;
        let scale = 4_294_967_296.0;
        let mut thresholds = [u32::MAX; MAX_THRESHOLDS];
        let mut pmf = libm::exp(-lambda);
        let mut cdf = pmf;
        let mut cap = MAX_THRESHOLDS as u32;
        for (k, t) in thresholds.iter_mut().enumerate() {
            // Saturate: once the tail is below 2⁻³², every draw is below the threshold.
            let scaled = cdf * scale;
            if scaled >= scale - 1.0 {
                cap = k as u32;
                break;
            }
            *t = scaled as u32;
            pmf *= lambda / (k + 1) as f64;
            cdf += pmf;
        }
        Self {
            mean: mean.to_bits(),
            cap,
            thresholds,
        }
    }

    /// The mean.
    #[must_use]
    pub fn mean(&self) -> f32 {
        f32::from_bits(self.mean)
    }

    /// The largest count [`CellRng::poisson`] returns.
    #[must_use]
    pub fn cap(&self) -> u32 {
        self.cap
    }
}
