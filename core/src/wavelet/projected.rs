//! 3D wavelet noise projected onto a 2D surface (Cook & DeRose 2005, §3.7, §4.1 eqs. 35–36,
//! Appendix 2 with erratum 7).
//!
//! A planar slice of band-limited 3D noise is not band-limited (the Fourier slice theorem,
//! §3.7). Integrating the 3D noise along the surface normal, weighted by the B-spline, restores
//! the band limit: `N_n(p) = Σ_c n_c B(t_x) B(t_y) B(t_z)` with each coefficient's basis
//! evaluated at the coefficient moved halfway to `p` along the normal,
//! `t = (c + n·(n·(p − c))/2) − (p − 1.5)`. This asymmetric basis is the paper's approximation
//! `β(z) ≈ B((z + 3/2)/2)` of the exact quintic projection kernel: double width along the
//! normal, unchanged across it.

use crate::{ProjectedNoise, Real};

use super::band::{Placement, TileData, Wavelet, blend_weight, tile_index};

/// The quadratic B-spline of width 3 on `[0, 3)` (erratum 7): `t²/2`, `3/4 − (t − 3/2)²`,
/// `(3 − t)²/2`, 0 elsewhere.
#[inline]
pub(crate) fn bspline<R: Real>(t: R) -> R {
    let half = R::from_ratio(1, 1);
    let three = R::from_i32(3);
    if t <= R::ZERO || t >= three {
        R::ZERO
    } else if t < R::ONE {
        t.mul_rn(t).mul_rn(half)
    } else if t < R::from_i32(2) {
        let u = t - R::from_ratio(3, 1);
        R::from_ratio(3, 2) - u.mul_rn(u)
    } else {
        let u = three - t;
        u.mul_rn(u).mul_rn(half)
    }
}

/// [`bspline`]'s derivative: `t`, `3 − 2t`, `t − 3` on its three pieces, 0 outside `(0, 3)`
/// (continuous: the B-spline is C¹).
#[inline]
fn bspline_derivative<R: Real>(t: R) -> R {
    let three = R::from_i32(3);
    if t <= R::ZERO || t >= three {
        R::ZERO
    } else if t < R::ONE {
        t
    } else if t < R::from_i32(2) {
        three - t - t
    } else {
        t - three
    }
}

/// The unit normal used for projection.
///
/// A finite normal of any non-zero length is normalised: divided by its largest component
/// first (so no squared length can overflow or underflow, in any number type), then by the
/// length of the result, which lies in `[1, √3]`. Scaling a normal by a power of two that keeps
/// it finite (and, in fixed point, unsaturated) therefore gives the same unit normal, bit for
/// bit. A zero normal, or one with a NaN or infinite component, projects along z: `(0, 0, 1)`.
///
/// # Examples
///
/// ```
/// use bandnoise::{I16F16, wavelet::unit_normal};
///
/// assert_eq!(unit_normal([0.0f32, 3.0, 4.0]), [0.0, 0.6, 0.8]);
/// assert_eq!(unit_normal([1e30f32, 0.0, 0.0]), [1.0, 0.0, 0.0]);
/// let big = I16F16::from_num(200);
/// assert_eq!(unit_normal([big, I16F16::ZERO, I16F16::ZERO])[0], I16F16::ONE);
/// assert_eq!(unit_normal([f32::NAN, 1.0, 0.0]), [0.0, 0.0, 1.0]);
/// ```
#[must_use]
pub fn unit_normal<R: Real>(n: [R; 3]) -> [R; 3] {
    let along_z = [R::ZERO, R::ZERO, R::ONE];
    if n.iter().any(|x| x.is_nan()) {
        return along_z;
    }
    let largest = n.iter().fold(R::ZERO, |m, x| {
        let a = x.abs();
        if a > m { a } else { m }
    });
    // ±∞ exceeds MAX; fixed point's MIN has abs MAX, which is fine.
    if largest == R::ZERO || largest > R::MAX {
        return along_z;
    }
    // Each component in [−1, 1], the largest ±1 exactly: the length is in [1, √3].
    let scaled = n.map(|x| x.div(largest));
    let len2 = scaled.iter().fold(R::ZERO, |acc, x| acc + x.mul_rn(*x));
    let len = len2.sqrt();
    scaled.map(|x| x.div(len).clamp_to(-R::ONE, R::ONE))
}

/// [`projected_gain`]'s polynomial: `g = c₀ + c₁ s + c₂ p + c₃ s²` in the cube-symmetric
/// invariants `s = n_x⁴ + n_y⁴ + n_z⁴` and `p = n_x² n_y² n_z²` of the unit normal, fitted
/// (least squares over 3000 random normals) to the exact `1/√ρ(n)` that
/// `tests/tests/projected_variance.rs` computes from the tile filters, in units of 2⁻¹⁶ (the
/// same dyadic constants in every number type); within 2.0e-5 of it.
const GAIN: [i32; 4] = [54859, -2777, -4249, 374];

/// The largest [`projected_gain`] over all normals (0.8212 along the cube's diagonals), rounded
/// up: the projected bounds use it.
pub(crate) const GAIN_MAX: f32 = 0.822;

/// The factor that gives a band projected along `normal` the variance of the same band
/// sampled in 3D: `1/√ρ(n)`, with `ρ(n)` the ratio of the projected band's variance to the
/// sampled band's.
///
/// Projecting integrates the noise along the normal with the paper's double-width basis, whose
/// overlap with itself depends on the normal's direction: `ρ` is 1.561 along an axis, 1.497
/// along a face diagonal and 1.483 along a cube diagonal (1.512 averaged over directions), so
/// one constant cannot normalise every normal. `ρ(n) = Σ_δ R(δ) · 2 Π_a Q((M δ)_a) /
/// Σ_δ R(δ) Π_a Q(δ_a)`, with `R` the coefficients' autocovariance (from the tile filters),
/// `Q` the B-spline's autocorrelation and `M = I − ½ n nᵀ`; it has the cube's symmetry, and a
/// quadratic in two of its invariants reproduces `1/√ρ` within 2.0e-5 (`GAIN`). The normal
/// goes through [`unit_normal`] first. [`Multiband`](super::Multiband) multiplies its projected
/// sums by it.
///
/// # Examples
///
/// ```
/// use bandnoise::wavelet::projected_gain;
///
/// let axis: f32 = projected_gain([0.0, 0.0, 1.0]);
/// let diagonal: f32 = projected_gain([1.0, 1.0, 1.0]);
/// assert!((axis - 1.0 / 1.5608f32.sqrt()).abs() < 1e-4);
/// assert!((diagonal - 1.0 / 1.4830f32.sqrt()).abs() < 1e-4);
/// ```
#[must_use]
pub fn projected_gain<R: Real>(normal: [R; 3]) -> R {
    gain_unit(unit_normal(normal))
}

/// [`projected_gain`] of a normal that [`unit_normal`] returned. Every factor is below 1 in
/// magnitude, so `mul_fraction` (no saturation) is exact where `mul_rn` would be.
pub(crate) fn gain_unit<R: Real>(n: [R; 3]) -> R {
    let q = n.map(|x| x.mul_fraction(x));
    let s = q[0].mul_fraction(q[0]) + q[1].mul_fraction(q[1]) + q[2].mul_fraction(q[2]);
    let p = q[0].mul_fraction(q[1]).mul_fraction(q[2]);
    let c = GAIN.map(|k| R::from_ratio(k, 16));
    c[0] + c[1].mul_fraction(s) + c[2].mul_fraction(p) + c[3].mul_fraction(s.mul_fraction(s))
}

impl<R: Real, T: TileData<3>> ProjectedNoise<R> for Wavelet<'_, T> {
    /// The band projected onto the surface through `p` with normal `normal` (see
    /// [`unit_normal`] for non-unit, zero and non-finite normals).
    ///
    /// It costs several plain samples: the basis spans up to 8 coefficients per axis (about
    /// 5 × 5 × 7 for an axis-aligned normal).
    ///
    /// # Contract
    ///
    /// Never panics. A NaN or ±∞ coordinate is 0 and cells beyond `i32` wrap, as for
    /// [`Noise::sample`](crate::Noise::sample); the normal goes through [`unit_normal`] (any
    /// finite non-zero normal keeps its direction; zero or non-finite normals project along z).
    /// The result is finite and at most three times the largest (blended) coefficient in magnitude
    /// (the basis weights sum to 2 along an axis-aligned normal and below 3 for any normal,
    /// measured by the fuzz target `wavelet`; fixed point saturates).
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{ProjectedNoise, wavelet::{Tile3, Wavelet}};
    ///
    /// static TILE: Tile3<16> = Tile3::generate(1);
    /// let band = Wavelet::new(0, &TILE);
    /// let up: f32 = band.sample_projected([0.3, 0.6, 2.0], [0.0, 0.0, 1.0]);
    /// // Non-unit normals are normalised.
    /// assert_eq!(up, band.sample_projected([0.3, 0.6, 2.0], [0.0, 0.0, 5.0]));
    /// ```
    #[inline]
    fn sample_projected(&self, p: [R; 3], normal: [R; 3]) -> R {
        self.sample_projected_unit(p, unit_normal(normal))
    }

    fn projected_bound(&self) -> f32 {
        Wavelet::projected_bound(self)
    }
}

impl<R: Real, T: TileData<3>> crate::ProjectedNoiseGradient<R> for Wavelet<'_, T> {
    /// The projected band and its analytic gradient in `p`: each coefficient's B-spline
    /// product differentiated through `t = 3/2 − (p − c) + n (n·(p − c))/2` (C¹, like the
    /// band itself).
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{ProjectedNoise, ProjectedNoiseGradient, wavelet::{TILE3, Wavelet}};
    ///
    /// let band = Wavelet::new(0, &TILE3);
    /// let (p, up) = ([0.3f32, 0.6, 2.0], [0.0, 0.0, 1.0]);
    /// let (v, g) = band.sample_projected_with_gradient(p, up);
    /// assert_eq!(v, band.sample_projected(p, up));
    /// assert!(g.iter().all(|d| d.is_finite()));
    /// ```
    #[inline]
    fn sample_projected_with_gradient(&self, p: [R; 3], normal: [R; 3]) -> (R, [R; 3]) {
        self.sample_projected_unit_with_gradient(p, unit_normal(normal))
    }
}

/// Block placements for the up to 3 blocks per axis that a projected sample touches.
pub(crate) struct Placements<const D: usize> {
    base: [i32; D],
    cache: [[[Option<Placement<D>>; 3]; 3]; 3],
}

impl<const D: usize> Placements<D> {
    /// An empty cache whose block slots start at `base` along each axis.
    #[inline]
    pub(crate) fn new(base: [i32; D]) -> Self {
        Placements {
            base,
            cache: [[[None; 3]; 3]; 3],
        }
    }
}

impl<T: TileData<3>> Wavelet<'_, T> {
    /// A bound on `|sample_projected|`: three times the largest (blended) coefficient (the
    /// projected basis weights sum to 2 along an axis-aligned normal and stay below 3 for any
    /// normal, measured by the fuzz target `wavelet`), plus rounding.
    #[must_use]
    pub fn projected_bound(&self) -> f32 {
        3.0 * crate::Noise::<f32, 3>::amplitude_bound(self)
    }

    /// [`sample_projected`](ProjectedNoise::sample_projected) with a normal that
    /// [`unit_normal`] already returned (multiband noise normalises once for all its bands).
    pub(crate) fn sample_projected_unit<R: Real>(&self, p: [R; 3], nrm: [R; 3]) -> R {
        self.projected::<R, false>(p, nrm).0
    }

    /// [`sample_projected_unit`](Self::sample_projected_unit) and its gradient.
    pub(crate) fn sample_projected_unit_with_gradient<R: Real>(
        &self,
        p: [R; 3],
        nrm: [R; 3],
    ) -> (R, [R; 3]) {
        self.projected::<R, true>(p, nrm)
    }

    /// The projected band at `p` along the unit normal `nrm` and, with `GRADIENT`, its
    /// gradient in `p` (otherwise zeros). The value is the same, bit for bit, either way.
    ///
    /// Each coefficient's basis is `Π_a B(t_a)` with `t = 3/2 − d + n (n·d)/2`, `d = p − c`,
    /// so `∂t_a/∂p_b = −δ_ab + n_a n_b / 2`: with `G_a = Σ_c n_c B'(t_a) Π_{a'≠a} B(t_a')`, the
    /// gradient is `−G + n (n·G)/2`.
    #[inline]
    fn projected<R: Real, const GRADIENT: bool>(&self, p: [R; 3], nrm: [R; 3]) -> (R, [R; 3]) {
        let n = T::SIZE as i32;
        let half = R::from_ratio(1, 1);
        let three_halves = R::from_ratio(3, 1);
        let mut cell = [0i32; 3];
        let mut frac = [R::ZERO; 3];
        let mut kmin = [0i32; 3];
        let mut kmax = [0i32; 3];
        for a in 0..3 {
            (cell[a], frac[a]) = p[a].split();
            // support = 3|n_a| + 3 sqrt((1 − n_a²)/2), rounded up a little for safety.
            let na = nrm[a].abs();
            let s = R::from_i32(3).mul_rn(na)
                + R::from_i32(3).mul_rn((R::ONE - na.mul_rn(na)).mul_rn(half).sqrt())
                + R::from_ratio(1, 8);
            let (lo, lo_frac) = (frac[a] - s).split();
            kmin[a] = if lo_frac == R::ZERO { lo } else { lo + 1 };
            kmax[a] = (frac[a] + s).split().0;
        }
        // Block q reaches coefficients [qn − h, qn + n + h): the first coefficient's blocks
        // start one before that of c + h.
        let h = self.half_width::<3>() as i32;
        let mut placements = Placements::new(core::array::from_fn(|a| {
            let c = cell[a].wrapping_add(kmin[a]).wrapping_add(h);
            c.div_euclid(n).wrapping_sub(1)
        }));
        let mut sum = R::ZERO;
        // G_a of the doc comment.
        let mut partial = [R::ZERO; 3];
        for kz in kmin[2]..=kmax[2] {
            for ky in kmin[1]..=kmax[1] {
                for kx in kmin[0]..=kmax[0] {
                    let k = [kx, ky, kz];
                    // p − c, small whatever p is: the fraction minus an integer offset.
                    let d: [R; 3] = core::array::from_fn(|a| frac[a] - R::from_i32(k[a]));
                    let dot = nrm[0].mul_rn(d[0]) + nrm[1].mul_rn(d[1]) + nrm[2].mul_rn(d[2]);
                    let t: [R; 3] = core::array::from_fn(|a| {
                        three_halves - d[a] + nrm[a].mul_rn(dot).mul_rn(half)
                    });
                    let b = t.map(bspline);
                    let weight = R::ONE.mul_rn(b[0]).mul_rn(b[1]).mul_rn(b[2]);
                    // A weight of 0 adds nothing to the value, but the gradient skips only
                    // coefficients outside the support (0, 3) on some axis: B(t) = t²/2 rounds
                    // to 0 in fixed point for t < 2⁻⁸, where B' = t still counts.
                    let skip = if GRADIENT {
                        t.iter().any(|&t| t <= R::ZERO || t >= R::from_i32(3))
                    } else {
                        weight == R::ZERO
                    };
                    if skip {
                        continue;
                    }
                    let g: [i32; 3] = core::array::from_fn(|a| cell[a].wrapping_add(k[a]));
                    let c = self.fetch(g, &mut placements);
                    // Saturating: the weights sum to less than 3, so a tile whose
                    // coefficients exceed a third of fixed point's range could overflow.
                    sum = sum.saturating_add(weight.mul_rn(c));
                    if GRADIENT {
                        let db = t.map(bspline_derivative);
                        let terms = [
                            db[0].mul_rn(b[1]).mul_rn(b[2]),
                            b[0].mul_rn(db[1]).mul_rn(b[2]),
                            b[0].mul_rn(b[1]).mul_rn(db[2]),
                        ];
                        for (ga, term) in partial.iter_mut().zip(terms) {
                            *ga = ga.saturating_add(term.mul_rn(c));
                        }
                    }
                }
            }
        }
        if !GRADIENT {
            return (sum.canonical(), [R::ZERO; 3]);
        }
        // n (n·G)/2 − G, saturating throughout (fixed point's G may have saturated).
        let along = nrm
            .iter()
            .zip(partial)
            .fold(R::ZERO, |acc, (na, ga)| acc.saturating_add(na.mul_rn(ga)))
            .mul_rn(half);
        let gradient = core::array::from_fn(|a| {
            nrm[a]
                .mul_rn(along)
                .saturating_add(partial[a].saturating_mul(-R::ONE))
                .canonical()
        });
        (sum.canonical(), gradient)
    }
}

impl<T> Wavelet<'_, T> {
    /// The coefficient at global index `g`: `Σ ω_b t_b(g)` over the (up to 2ᴰ) blocks `b` that
    /// reach it, each read in its placement and weighted by its blend weights.
    #[inline]
    pub(crate) fn fetch<R: Real, const D: usize>(
        &self,
        g: [i32; D],
        placements: &mut Placements<D>,
    ) -> R
    where
        T: TileData<D>,
    {
        let n = T::SIZE;
        let h = self.half_width::<D>();
        // Along each axis: the first block reaching g, g's local index in it plus n, and the
        // number of blocks (2 in a blend zone).
        let mut first = [0i32; D];
        let mut local = [0usize; D];
        let mut count = [1usize; 3];
        for a in 0..D {
            let u = g[a].wrapping_add(h as i32);
            let (q, r) = (u.div_euclid(n as i32), u.rem_euclid(n as i32) as usize);
            if r < 2 * h {
                (first[a], local[a], count[a]) = (q.wrapping_sub(1), r + 2 * n - h, 2);
            } else {
                (first[a], local[a]) = (q, r + n - h);
            }
        }
        let mut value = R::ZERO;
        for mz in 0..count[2] {
            for my in 0..count[1] {
                for mx in 0..count[0] {
                    let m = [mx, my, mz];
                    let block: [i32; D] =
                        core::array::from_fn(|a| first[a].wrapping_add(m[a] as i32));
                    let slot: [usize; 3] = core::array::from_fn(|a| {
                        if a < D {
                            block[a].wrapping_sub(placements.base[a]).clamp(0, 2) as usize
                        } else {
                            0
                        }
                    });
                    let place = *placements.cache[slot[2]][slot[1]][slot[0]]
                        .get_or_insert_with(|| self.placement(block));
                    let l: [usize; D] = core::array::from_fn(|a| local[a] - m[a] * n);
                    let mut c: R = self.tile().flat(tile_index(l, &place, n));
                    for a in 0..D {
                        if count[a] == 2 {
                            c = blended(c, l[a], n, h);
                        }
                    }
                    value = value.saturating_add(c);
                }
            }
        }
        value
    }
}

/// `c` times its blend weight at local index `l_plus_n − n` ([`blend_weight`]). Out of line:
/// only blend zones call it.
#[inline(never)]
fn blended<R: Real>(c: R, l_plus_n: usize, n: usize, h: usize) -> R {
    c.mul_fraction(blend_weight(l_plus_n, n, h))
}
