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
//!
//! **Cost.** The basis is non-zero on a parallelepiped of volume 54 coefficients (27 over the
//! determinant ½ of `I − n nᵀ/2`) inside a bounding box of up to 8³. A sample
//! (`Wavelet::projected_fast`) visits only the coefficients that can be non-zero. Along an
//! axis the basis is a product of per-axis B-splines over the 3 × 3 × 6 product of per-axis
//! supports, and a blended coefficient a sum over blocks of per-axis blend weights, so the
//! sample is summed block by block, each block's reads weighted separably, as a plain band is
//! (`Wavelet::projected_axis`). Along an oblique normal each basis argument is affine in the
//! offsets, so the window is summed row by row: a row's arguments are its start plus a rise
//! per lane, rows outside the support are skipped, the others clipped to it, their basis
//! weights computed once and summed in each block that reaches the row
//! (`Wavelet::projected_oblique`). Windows that reach three blocks along an axis (tiles
//! narrower than the window and the blend zones) are summed coefficient by coefficient
//! through a `Window`, which resolves each axis and each tile block once per sample. The tests
//! hold all three to a reference that visits the whole box and finds each coefficient on its
//! own (`compact.rs`): within rounding where the sums run block by block (their order
//! differs, and along oblique normals the arguments are computed from their affine form),
//! bit for bit through the `Window`.

use crate::{ProjectedNoise, Real};

use core::ops::Range;

use super::band::{
    CROSSING, CUBE, PERMUTATIONS3, Placement, TileData, Wavelet, first_block, offset_run, within,
};
use super::window::{WIDTH, Window};

mod rows;

/// The quadratic B-spline of width 3 on `[0, 3)` (erratum 7): `t²/2`, `3/4 − (t − 3/2)²`,
/// `(3 − t)²/2`, 0 elsewhere.
///
/// The two outer pieces are one, `s²/2` with `s = min(t, 3 − t)` the distance to the nearer
/// end (`3 − t` is exact where it is the smaller, and at `t = 2` both pieces give ½), so a
/// sample picks between two pieces with selects rather than branching three ways: the
/// projected basis's `t` follow no pattern a branch predictor learns.
#[inline]
pub(crate) fn bspline<R: Real>(t: R) -> R {
    let half = R::from_ratio(1, 1);
    let v = R::from_i32(3) - t;
    let s = if v < t { v } else { t };
    let u = t - R::from_ratio(3, 1);
    let outer = s.mul_rn(s).mul_rn(half);
    let middle = R::from_ratio(3, 2) - u.mul_rn(u);
    let piece = if s < R::ONE { outer } else { middle };
    if s <= R::ZERO { R::ZERO } else { piece }
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
    // Along an axis, the divisions below give the two zeros as they are and the third
    // component's sign, exactly: skip them (projections onto planes of the axes are common).
    if n.iter().filter(|&&x| x == R::ZERO).count() == 2 {
        return n.map(|x| match x {
            x if x == R::ZERO => x,
            x if x > R::ZERO => R::ONE,
            _ => R::NEG_ONE,
        });
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
    /// It costs several plain samples: the basis reaches 54 coefficients, 3 × 3 × 6 along an
    /// axis-aligned normal (the module docs say how they are visited).
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

    /// The band over `grid` along one normal, bit for bit as
    /// [`sample_projected`](ProjectedNoise::sample_projected) at each point: the normal is
    /// normalised once, and along an axis-aligned normal each grid row resolves its y and z
    /// weights and blocks once and sums groups of up to 16 samples together, each coefficient
    /// read once for the group (`projected/rows.rs`).
    fn fill_grid_projected(
        &self,
        grid: &crate::batch::Grid<R, 3>,
        normal: [R; 3],
        out: &mut [R],
    ) -> Result<(), crate::Error> {
        self.fill_grid_projected_unit(grid, unit_normal(normal), out)
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
        self.projected_fast::<R, GRADIENT>(p, nrm)
    }
}

impl<T: TileData<3>> Wavelet<'_, T> {
    /// [`projected_fast`](Self::projected_fast) along an axis-aligned unit normal (two
    /// components zero, the third at most 1 in magnitude), summed block by block
    /// ([`projected_axis`](Self::projected_axis)); `None` for another normal, or a window
    /// `projected_axis` does not take, which the caller then sums coefficient by coefficient.
    ///
    /// Each axis's basis arguments are computed only at the offsets from the cell that can
    /// reach `(0, 3)` ([`ACROSS`], [`ALONG`]), by the window path's operations,
    /// `t = (3/2 − d) + n_a (n_a d)/2` with `d = frac − k`: the same numbers, and so the same
    /// support, the offsets where `t` lies in `(0, 3)` (consecutive: `t` falls by at least ½
    /// per offset), without the window path's terms for every offset of a bounding box sized
    /// for any normal.
    #[inline]
    fn projected_along<R: Real, const GRADIENT: bool, const PERMUTED: bool>(
        &self,
        p: [R; 3],
        nrm: [R; 3],
    ) -> Option<Sums<R, GRADIENT>> {
        let normal = axis_of(nrm)?;
        let mut first = [0i32; 3];
        let mut t = [[R::ZERO; WIDTH]; 3];
        let mut support = [0..0, 0..0, 0..0];
        for a in 0..3 {
            let len;
            (first[a], len, t[a]) = axis_support(p[a], a, nrm, normal)?;
            support[a] = 0..len;
        }
        let sums = self.projected_axis::<R, GRADIENT, PERMUTED>(first, &t, &support, normal)?;
        Some(Sums {
            value: sums[0],
            partial: [sums[1], sums[2], sums[3]],
        })
    }

    /// [`projected_fast`](Self::projected_fast)'s sums along an axis-aligned normal, block by
    /// block: the basis is a product of per-axis B-splines `Π_a B(t_a)`, and a blended
    /// coefficient is the sum, over the blocks that reach it, of the block's tile read times
    /// per-axis blend weights, so the window's sum is, block by block, a separable sum of the
    /// block's reads weighted along each axis by `B(t_a)` times the block's blend weight: a
    /// plain band's block sum (`band.rs`) over 3 × 3 × 6 coefficients instead of a blended
    /// coefficient found for each of the 54. Rounded in that order (z outermost, then y, x
    /// innermost; the blocks' sums added in slot order), not the reference's coefficient by
    /// coefficient: within rounding of it (`fast_path_is_the_compact_path`). The gradient's
    /// `G_a` are the same sums with axis `a`'s B-splines replaced by their derivatives.
    ///
    /// `t` holds each axis's basis arguments from global coefficient `first`, `support` the
    /// offsets where they lie in `(0, 3)`, `normal` the axis of the normal. Each axis is
    /// resolved once from its support's first coefficient (its block and local index; the
    /// other offsets' local indices follow by counting), and its weights kept per slot for
    /// the [`span`] offsets from the support's start. The value and, with `GRADIENT`, `G_x`,
    /// `G_y`, `G_z` (otherwise zeros); `None` where some axis's support reaches more than two
    /// blocks (tiles narrower than the support and the blend zones), is wider than its span,
    /// or nears the end of `i32`'s range: the caller then finds each coefficient through a
    /// `Window`. Out of line, one copy per number type (the demo's module has a size budget;
    /// a call per sample costs nothing against its thousands of instructions).
    #[inline(never)]
    fn projected_axis<R: Real, const GRADIENT: bool, const PERMUTED: bool>(
        &self,
        first: [i32; 3],
        t: &[[R; WIDTH]; 3],
        support: &[Range<usize>; 3],
        normal: usize,
    ) -> Option<[R; 4]> {
        let (n, h) = (T::SIZE, self.half_width::<3>());
        // Per slot (the block of an axis's first coefficient in its support, or the next)
        // and axis, for the `span` offsets from the support's start: the B-splines times the
        // slot's blend weights (0 beyond the block's reach, and past the support), and their
        // derivatives times them; per axis, the local index (plus n) of the support's first
        // coefficient in the first slot's block.
        let mut w = [[[R::ZERO; SPAN]; 3]; 2];
        let mut dw = [[[R::ZERO; SPAN]; 3]; 2];
        let mut local = [0usize; 3];
        let mut base = [0i32; 3];
        // Whether the next block reaches the support along each axis.
        let mut two = [false; 3];
        for a in 0..3 {
            let (start, len, span) = (support[a].start, support[a].len(), span(a, normal));
            if len == 0 {
                return Some([R::ZERO; 4]); // nothing in reach (the sums start at +0)
            }
            // The support within its span and the span within the offsets, and no global
            // index past `i32`'s range (the caller then takes the coefficients one by one).
            let g = first[a].checked_add(start as i32)?;
            if len > span || start + span > WIDTH || g.checked_add(span as i32).is_none() {
                return None;
            }
            let (block, l0, _) = first_block(g, n, h);
            (base[a], local[a]) = (block, l0);
            // Offset i's local index in the first block is l0 + i (plus n), in the next
            // l0 + i − n; the block after that reaches local l0 + i ≥ 3n − h.
            if l0 + len > 3 * n - h {
                return None;
            }
            two[a] = l0 + len > 2 * n - h;
            if two[a] {
                // The support crosses the zone where the first block fades into the next:
                // both blocks' weights from the table.
                let at = zone_offset(l0, n, h);
                for i in 0..len {
                    let t = t[a][(start + i) % WIDTH];
                    let (b, db) = (bspline(t), bspline_derivative(t));
                    for (s, omega) in crossing::<R>(at + i, h).into_iter().enumerate() {
                        w[s][a][i] = b.mul_rn(omega);
                        if GRADIENT {
                            dw[s][a][i] = db.mul_rn(omega);
                        }
                    }
                }
            } else {
                // Within the first block's interior (`l0 ≥ n + h`, `l0 + len ≤ 2n − h`):
                // every blend weight 1, whose products are the B-splines themselves.
                for i in 0..len {
                    let t = t[a][(start + i) % WIDTH];
                    w[0][a][i] = bspline(t);
                    if GRADIENT {
                        dw[0][a][i] = bspline_derivative(t);
                    }
                }
            }
        }
        // One copy per normal axis, whose loops have known lengths, where code size is cheap;
        // in wasm, one copy for the demo's size budget (the three took 4 KB).
        if cfg!(target_arch = "wasm32") {
            return Some(
                self.axis_blocks::<R, GRADIENT, PERMUTED>(&w, &dw, local, two, base, normal),
            );
        }
        Some(match normal {
            0 => self.axis_blocks::<R, GRADIENT, PERMUTED>(&w, &dw, local, two, base, 0),
            1 => self.axis_blocks::<R, GRADIENT, PERMUTED>(&w, &dw, local, two, base, 1),
            _ => self.axis_blocks::<R, GRADIENT, PERMUTED>(&w, &dw, local, two, base, 2),
        })
    }

    /// [`projected_axis`](Self::projected_axis)'s sums over the blocks, along axis `normal`:
    /// per block, the value's (and with `GRADIENT`, each `G_a`'s) sum over the offsets from
    /// each axis's support's start ([`span`]: 6 along the normal, 3 across it), whatever the
    /// block reaches of them: the others weigh 0 in `w` and `dw`, and add `±0` to sums that
    /// start at `+0` and so are never `−0` (fixed point: 0), which leaves them as summing the
    /// reached offsets alone leaves them, bit for bit. Inlined wherever `normal` is a constant,
    /// its loops have known lengths: the compiler unrolls them and keeps each axis's index
    /// parts in registers. With `PERMUTED` ([`CUBE`]: x86-64 and AArch64), each block is summed
    /// by a copy for its axis permutation ([`permuted_sums`](Self::permuted_sums)); otherwise
    /// (the firmware cores and wasm, whose code size six copies would cost) through flat
    /// index parts: the same reads in the same order, so the same bits (a test compares them).
    #[inline(always)]
    fn axis_blocks<R: Real, const GRADIENT: bool, const PERMUTED: bool>(
        &self,
        w: &[[[R; SPAN]; 3]; 2],
        dw: &[[[R; SPAN]; 3]; 2],
        local: [usize; 3],
        two: [bool; 3],
        base: [i32; 3],
        normal: usize,
    ) -> [R; 4] {
        let n = T::SIZE;
        let tile = self.tile();
        let unit = tile.unit::<R>();
        // The value, then G_x, G_y, G_z.
        let mut sums = [R::ZERO; 4];
        let weights = |block: usize, set: usize| -> [&[R; SPAN]; 3] {
            core::array::from_fn(|a| &(if set == a + 1 { dw } else { w })[block >> a & 1][a])
        };
        // The blocks the support reaches (numbered by their slots, bit a along axis a), in
        // increasing order, each with its placement, all found before any is summed: with
        // `PERMUTED` each block's copy is chosen by its permutation, a jump no predictor
        // foresees, whose misprediction costs least when the target is known as the jump is
        // reached (3D band points the same, `Wavelet::add_cubes`).
        let slots = (0..3).fold(0, |m, a| m | usize::from(two[a]) << a);
        let mut places = [(0, Placement::UNSHIFTED); 8];
        let count = self.slot_placements(base, slots, &mut places);
        for &(block, ref place) in places.iter().take(count) {
            let weights = |set| weights(block, set);
            if PERMUTED {
                let (s, p) = (&mut sums, place);
                match place.permutation() {
                    0 => self.permuted_sums::<R, GRADIENT, 0>(s, weights, p, local, normal),
                    1 => self.permuted_sums::<R, GRADIENT, 1>(s, weights, p, local, normal),
                    2 => self.permuted_sums::<R, GRADIENT, 2>(s, weights, p, local, normal),
                    3 => self.permuted_sums::<R, GRADIENT, 3>(s, weights, p, local, normal),
                    4 => self.permuted_sums::<R, GRADIENT, 4>(s, weights, p, local, normal),
                    _ => self.permuted_sums::<R, GRADIENT, 5>(s, weights, p, local, normal),
                }
                continue;
            }
            // Each offset's part of the tile's flat index in this block (its local index
            // l0 + i in the first slot's block, l0 + i − n in the next: the same index mod n).
            // Past the support, or the block's reach, the part is some coefficient's, read
            // with weight 0.
            let mut parts = [[0usize; SPAN]; 3];
            for (a, part) in parts.iter_mut().enumerate() {
                let axis = place.axis(a, n);
                for (i, p) in part.iter_mut().enumerate().take(span(a, normal)) {
                    *p = axis.offset(local[a] + i, n);
                }
            }
            block_sums::<R, GRADIENT>(&mut sums, weights, normal, |[jx, jy, jz]| {
                tile.flat_with(parts[0][jx] + (parts[1][jy] + parts[2][jz]), unit)
            });
        }
        sums
    }

    /// [`axis_blocks`](Self::axis_blocks)' sums over one block, for the blocks whose output
    /// axis `a` reads tile axis `PERMUTATIONS3[P][a]`: each coefficient read at its indices
    /// along the tile's axes, each masked where `n` is a power of two (every default tile), so
    /// that the optimiser sees the flat index `x + n·(y + n·z)` in range: no mask per read, and
    /// the masks of the indices that stay fixed over a loop computed once. (Through flat index
    /// parts, whose strides are known only at run time, each read was masked.) Written once
    /// per permutation, so that each output axis's stride is known at compile time, as
    /// [`Wavelet::add_cube`] is for a band's point samples.
    #[inline(always)]
    fn permuted_sums<'w, R: Real, const GRADIENT: bool, const P: usize>(
        &self,
        sums: &mut [R; 4],
        weights: impl Fn(usize) -> [&'w [R; SPAN]; 3],
        place: &Placement<3>,
        local: [usize; 3],
        normal: usize,
    ) {
        let (n, tile) = (T::SIZE, self.tile());
        let unit = tile.unit::<R>();
        let perm = PERMUTATIONS3[P];
        // Each offset's index along the tile axis its output axis reads.
        let mut coordinate = [[0usize; SPAN]; 3];
        for (a, c) in coordinate.iter_mut().enumerate() {
            let axis = place.axis(a, n);
            for (i, c) in c.iter_mut().enumerate().take(span(a, normal)) {
                *c = axis.coordinate(local[a] + i, n);
            }
        }
        // The output axis that reads tile x: its offsets lie side by side in the tile's rows.
        let star = if perm[1] == 0 {
            1
        } else if perm[2] == 0 {
            2
        } else {
            0
        };
        if tile.row(0, 0).is_some() {
            let len = span(star, normal);
            let (c0, c1, cl) = (
                coordinate[star][0],
                coordinate[star][1],
                coordinate[star][(len - 1) % SPAN],
            );
            let window = if len == 3 { 4 } else { 6 };
            let rows = |j: [usize; 2]| {
                let mut k = [0usize; 3];
                let mut o = 0;
                for (a, &target) in perm.iter().enumerate() {
                    if a != star {
                        k[target] = coordinate[a][j[o] % SPAN];
                        o += 1;
                    }
                }
                tile.row(k[1], k[2]).unwrap_or(&[])
            };
            // The run's lowest tile index, and whether the offsets walk it backwards.
            let run = if c1 == c0 + 1 && cl == c0 + len - 1 && c0 + window <= n {
                Some((c0, false))
            } else if c0 == c1 + 1 && c0 == cl + len - 1 && cl + window <= n {
                Some((cl, true))
            } else {
                None
            };
            if let Some((lo, flip)) = run {
                let (w, s) = (&weights, sums);
                match (len == 3, flip) {
                    (true, false) => {
                        row_sums::<R, GRADIENT, 4, false>(s, w, normal, star, lo, rows)
                    }
                    (false, false) => {
                        row_sums::<R, GRADIENT, 8, false>(s, w, normal, star, lo, rows)
                    }
                    (true, true) => row_sums::<R, GRADIENT, 4, true>(s, w, normal, star, lo, rows),
                    (false, true) => row_sums::<R, GRADIENT, 8, true>(s, w, normal, star, lo, rows),
                }
                return;
            }
        }
        block_sums::<R, GRADIENT>(sums, weights, normal, |j| {
            let mut k = [0usize; 3];
            for (a, &target) in perm.iter().enumerate() {
                k[target] = within(coordinate[a][j[a] % SPAN], n);
            }
            tile.flat_with(k[0] + n * (k[1] + n * k[2]), unit)
        });
    }
}

/// One block's part of [`Wavelet::axis_blocks`]' sums: for each sum (the value, then with
/// `GRADIENT` each `G_a`) with its weights (`weights(set)`: per axis, the block's slot's
/// B-splines, or for `G_a` along axis `a` their derivatives, times the blend weights), the
/// coefficients `read([jx, jy, jz])` at the offsets from each axis's support's start, summed
/// with z outermost and x innermost, then added to the sum.
#[inline(always)]
fn block_sums<'w, R: Real + 'w, const GRADIENT: bool>(
    sums: &mut [R; 4],
    weights: impl Fn(usize) -> [&'w [R; SPAN]; 3],
    normal: usize,
    read: impl Fn([usize; 3]) -> R,
) {
    for (set, sum) in sums
        .iter_mut()
        .enumerate()
        .take(if GRADIENT { 4 } else { 1 })
    {
        let [wx, wy, wz] = weights(set);
        let mut block_sum = R::ZERO;
        for (jz, &wz) in wz.iter().enumerate().take(span(2, normal)) {
            let mut plane = R::ZERO;
            for (jy, &wy) in wy.iter().enumerate().take(span(1, normal)) {
                let mut line = R::ZERO;
                for (jx, &wx) in wx.iter().enumerate().take(span(0, normal)) {
                    line = line.saturating_add(wx.mul_rn(read([jx, jy, jz])));
                }
                plane = plane.saturating_add(wy.mul_rn(line));
            }
            block_sum = block_sum.saturating_add(wz.mul_rn(plane));
        }
        *sum = sum.saturating_add(block_sum);
    }
}

/// [`block_sums`] for a block whose output axis `star` reads tile x: the coefficients at its
/// offsets, adjacent in the tile's rows (`rows([j, j'])`: the row at the other two axes'
/// offsets, in output order), read `W` at a time from `lo` (`W = 4`: the 3 offsets across the
/// normal; `W = 8`: the normal's 6, as two overlapping runs of 4 from `lo` and `lo + 2`),
/// backwards with `FLIP`. Where `star` is y or z, each lane sums as `block_sums` does and the
/// sums over `star`'s offsets walk the lanes in its order; where it is x, each line sums its
/// run's lanes in order: the same operations in the same order either way.
#[inline(always)]
fn row_sums<'w, 'r, R: Real + 'w, const GRADIENT: bool, const W: usize, const FLIP: bool>(
    sums: &mut [R; 4],
    weights: &impl Fn(usize) -> [&'w [R; SPAN]; 3],
    normal: usize,
    star: usize,
    lo: usize,
    rows: impl Fn([usize; 2]) -> &'r [f32],
) {
    let len = if W == 4 { 3 } else { 6 };
    let load = |j: [usize; 2]| -> [R; W] {
        let row = rows(j);
        let mut v = [R::ZERO; W];
        for (part, start) in v.chunks_exact_mut(4).zip([lo, lo + 2]) {
            if let Some(run) = row.get(start..start + 4) {
                for (v, &c) in part.iter_mut().zip(run) {
                    *v = R::from_f32(c);
                }
            }
        }
        v
    };
    // The lane of the coefficient at offset j along `star`.
    let lane = |j: usize| {
        let p = if FLIP { len - 1 - j } else { j };
        if p < 4 { p } else { p + 2 }
    };
    for (set, sum) in sums
        .iter_mut()
        .enumerate()
        .take(if GRADIENT { 4 } else { 1 })
    {
        let [wx, wy, wz] = weights(set);
        let mut block_sum = R::ZERO;
        if star == 0 {
            for (jz, &wz) in wz.iter().enumerate().take(span(2, normal)) {
                let mut plane = R::ZERO;
                for (jy, &wy) in wy.iter().enumerate().take(span(1, normal)) {
                    let c = load([jy, jz]);
                    let mut line = R::ZERO;
                    for (jx, &wx) in wx.iter().enumerate().take(len) {
                        line = line.saturating_add(wx.mul_rn(c[lane(jx) % W]));
                    }
                    plane = plane.saturating_add(wy.mul_rn(line));
                }
                block_sum = block_sum.saturating_add(wz.mul_rn(plane));
            }
        } else if star == 2 {
            let mut plane = [R::ZERO; W];
            for (jy, &wy) in wy.iter().enumerate().take(span(1, normal)) {
                let mut line = [R::ZERO; W];
                for (jx, &wx) in wx.iter().enumerate().take(span(0, normal)) {
                    let c = load([jx, jy]);
                    for (l, c) in line.iter_mut().zip(c) {
                        *l = l.saturating_add(wx.mul_rn(c));
                    }
                }
                for (p, l) in plane.iter_mut().zip(line) {
                    *p = p.saturating_add(wy.mul_rn(l));
                }
            }
            for (jz, &wz) in wz.iter().enumerate().take(len) {
                block_sum = block_sum.saturating_add(wz.mul_rn(plane[lane(jz) % W]));
            }
        } else {
            for (jz, &wz) in wz.iter().enumerate().take(span(2, normal)) {
                let mut line = [R::ZERO; W];
                for (jx, &wx) in wx.iter().enumerate().take(span(0, normal)) {
                    let c = load([jx, jz]);
                    for (l, c) in line.iter_mut().zip(c) {
                        *l = l.saturating_add(wx.mul_rn(c));
                    }
                }
                let mut plane = R::ZERO;
                for (jy, &wy) in wy.iter().enumerate().take(len) {
                    plane = plane.saturating_add(wy.mul_rn(line[lane(jy) % W]));
                }
                block_sum = block_sum.saturating_add(wz.mul_rn(plane));
            }
        }
        *sum = sum.saturating_add(block_sum);
    }
}

/// The axis of a unit normal that the axis path takes (two components zero, the third at
/// most 1 in magnitude), or `None`.
#[inline]
fn axis_of<R: Real>(nrm: [R; 3]) -> Option<usize> {
    let normal = nrm.iter().position(|&x| x != R::ZERO)?;
    let zeros = nrm.iter().filter(|&&x| x == R::ZERO).count();
    (zeros == 2 && nrm[normal % 3].abs() <= R::ONE).then_some(normal)
}

/// Axis `a` of a sample at coordinate `x` along the axis-aligned unit normal `nrm` (whose
/// axis is `normal`): the offsets from the cell where the basis argument
/// `t = (3/2 − d) + n_a (n_a d)/2`, `d = frac − k`, lies in `(0, 3)` (consecutive: `t` falls
/// by at least ½ per offset, [`ACROSS`], [`ALONG`]), as the support's first global
/// coefficient (`None` past `i32`'s range), its length and its `t` from the first.
#[inline(always)]
fn axis_support<R: Real>(
    x: R,
    a: usize,
    nrm: [R; 3],
    normal: usize,
) -> Option<(i32, usize, [R; WIDTH])> {
    let (half, three) = (R::from_ratio(1, 1), R::from_i32(3));
    let (cell, frac) = x.split();
    let [lo, hi] = if a == normal { ALONG } else { ACROSS };
    let n = nrm[a % 3];
    let (mut from, mut len) = (lo, 0);
    let mut t = [R::ZERO; WIDTH];
    for k in lo..hi {
        let d = frac - R::from_i32(k);
        let ta = (R::from_ratio(3, 1) - d) + n.mul_rn(n.mul_rn(d)).mul_rn(half);
        if ta > R::ZERO && ta < three {
            if len == 0 {
                from = k;
            }
            // At most 6 offsets (`ALONG`), so below WIDTH.
            t[len % WIDTH] = ta;
            len += 1;
        }
    }
    Some((cell.checked_add(from)?, len, t))
}

/// The offsets `k` from the cell (`lo..hi`) whose basis argument can lie in `(0, 3)` across an
/// axis-aligned normal: `t = 3/2 − (frac − k)`, `frac` in `[0, 1)`, so `|frac − k| < 3/2`.
const ACROSS: [i32; 2] = [-1, 3];

/// [`ACROSS`] along the normal `n_a`, `|n_a| ≤ 1`: `t = 3/2 − (frac − k)(1 − n_a²/2)`, so
/// `|frac − k| < 3` (rounding keeps `k = −3` and `k = 4` at `t ≤ 0` and `t ≥ 3`).
const ALONG: [i32; 2] = [-2, 4];

/// The most offsets a projected window has along an axis-aligned normal: 6 along it (`t` in
/// `(0, 3)` rises by ½ per offset), 3 across it (by 1).
const SPAN: usize = 6;

/// The offsets [`Wavelet::axis_blocks`] sums along axis `a` of a window projected along axis
/// `normal`.
#[inline]
const fn span(a: usize, normal: usize) -> usize {
    if a == normal { SPAN } else { 3 }
}

/// The offsets `kmin..=kmax` from the cell, along one axis, of the coefficients the projected
/// basis can reach from fraction `frac` along a unit normal with component `na` and 1-norm
/// `l1` (`|n_x| + |n_y| + |n_z|`). The basis arguments are `t = 3/2 − u` with
/// `u = (I − n nᵀ/2) d` (`d = p − c`), so `d = u + n (n·u)` (for a unit normal `I + n nᵀ` is
/// the inverse), and the basis is 0 unless `u` lies in the cube `(−3/2, 3/2)³`: there `d_a`
/// is linear in `u`, largest in magnitude at a corner, `3/2 (1 + |n_a| l1)`. Plus 1/8 for the
/// rounding of `t` and of the normal's length. At most 3.67 (`|n_a| l1 ≤ 1/2 + √3/2` for a
/// unit normal), so at most 8 offsets.
#[inline]
pub(super) fn support_box<R: Real>(frac: R, na: R, l1: R) -> (i32, i32) {
    let s = R::from_ratio(3, 1).mul_rn(R::ONE + na.abs().mul_rn(l1)) + R::from_ratio(1, 3);
    offsets_within(frac, s)
}

/// The offsets `kmin..=kmax` from the cell of the coefficients within `s` of fraction `frac`
/// (the closed interval `[frac − s, frac + s]`).
#[inline]
pub(super) fn offsets_within<R: Real>(frac: R, s: R) -> (i32, i32) {
    let (lo, lo_frac) = (frac - s).split();
    let kmin = if lo_frac == R::ZERO { lo } else { lo + 1 };
    (kmin, (frac + s).split().0)
}

/// A projected sum `Σ_c w(c) n_c` and, with `GRADIENT`, the `G_a` of
/// [`Wavelet::projected`]'s doc comment, accumulated in the
/// reference's order (`compact.rs`): the whole box, x fastest.
#[derive(Default)]
pub(super) struct Sums<R, const GRADIENT: bool> {
    value: R,
    partial: [R; 3],
}

impl<R: Real, const GRADIENT: bool> Sums<R, GRADIENT> {
    /// The basis weight `Π_a B(t_a)` of the coefficient with basis arguments `t` and
    /// B-splines `b`, if it counts. A weight of 0 adds nothing to the value, but the gradient
    /// skips only coefficients outside the support (0, 3) on some axis: B(t) = t²/2 rounds to
    /// 0 in fixed point for t < 2⁻⁸, where B' = t still counts.
    #[inline]
    pub(super) fn weight(t: &[R; 3], b: &[R; 3]) -> Option<R> {
        let weight = R::ONE.mul_rn(b[0]).mul_rn(b[1]).mul_rn(b[2]);
        let counts = if GRADIENT {
            t.iter().all(|&t| t > R::ZERO && t < R::from_i32(3))
        } else {
            weight != R::ZERO
        };
        counts.then_some(weight)
    }

    /// Adds coefficient `c` with basis weight `weight` ([`weight`](Self::weight)), basis
    /// arguments `t` and B-splines `b`.
    #[inline]
    pub(super) fn add(&mut self, weight: R, t: [R; 3], b: [R; 3], c: R) {
        // Saturating: the weights sum to less than 3, so a tile whose coefficients exceed a
        // third of fixed point's range could overflow.
        self.value = self.value.saturating_add(weight.mul_rn(c));
        if GRADIENT {
            let db = t.map(bspline_derivative);
            let terms = [
                db[0].mul_rn(b[1]).mul_rn(b[2]),
                b[0].mul_rn(db[1]).mul_rn(b[2]),
                b[0].mul_rn(b[1]).mul_rn(db[2]),
            ];
            for (ga, term) in self.partial.iter_mut().zip(terms) {
                *ga = ga.saturating_add(term.mul_rn(c));
            }
        }
    }

    /// The value and, with `GRADIENT`, the gradient `n (n·G)/2 − G` (otherwise zeros).
    #[inline]
    pub(super) fn finish(self, nrm: [R; 3]) -> (R, [R; 3]) {
        if !GRADIENT {
            return (self.value.canonical(), [R::ZERO; 3]);
        }
        // Saturating throughout (fixed point's G may have saturated).
        let along = nrm
            .iter()
            .zip(self.partial)
            .fold(R::ZERO, |acc, (na, ga)| acc.saturating_add(na.mul_rn(ga)))
            .mul_rn(R::from_ratio(1, 1));
        let gradient = core::array::from_fn(|a| {
            nrm[a]
                .mul_rn(along)
                .saturating_add(self.partial[a].saturating_mul(-R::ONE))
                .canonical()
        });
        (self.value.canonical(), gradient)
    }
}

impl<T: TileData<3>> Wavelet<'_, T> {
    /// [`projected`](Self::projected), visiting only the coefficients where the basis can be
    /// non-zero. Along an axis (two components of the normal 0) each `t_a` depends on its own
    /// offset only (across the normal `t_a = 3/2 − d_a`, along it `3/2 − d_a + n_a (n_a d_a)/2`:
    /// the other terms of `n·d` are zeros), so the B-splines are computed per axis and the
    /// sum runs block by block over the product of their supports
    /// ([`projected_along`](Self::projected_along)); along another normal, row by row and
    /// block by block ([`projected_oblique`](Self::projected_oblique)); both within rounding
    /// of the reference (`compact.rs`). The windows neither takes (a window reaching three
    /// blocks along an axis) go through a [`Window`], each row clipped by [`Oblique`]: the
    /// same operations in the same order as the reference for every coefficient that is
    /// summed, so the same values, bit for bit.
    pub(crate) fn projected_fast<R: Real, const GRADIENT: bool>(
        &self,
        p: [R; 3],
        nrm: [R; 3],
    ) -> (R, [R; 3]) {
        if let Some(sums) = self.projected_along::<R, GRADIENT, CUBE>(p, nrm) {
            return sums.finish(nrm);
        }
        let window = ProjectedWindow::new(p, nrm);
        if let Some([value, gx, gy, gz]) = self.projected_oblique::<R, GRADIENT>(&window, nrm) {
            let sums = Sums::<R, GRADIENT> {
                value,
                partial: [gx, gy, gz],
            };
            return sums.finish(nrm);
        }
        let (first, count) = (window.first, window.count);
        let (centre, along) = (&window.centre, &window.along);
        let half = R::from_ratio(1, 1);
        // Coefficient by coefficient: the windows whose blocks neither block path takes (along
        // an axis the rows' `t` are the same numbers: the other components' terms of `n·d`
        // are zeros).
        let mut sums = Sums::<R, GRADIENT>::default();
        let mut window = Window::new(self, first, count);
        let oblique = Oblique::new(nrm, count[0]);
        for jz in 0..count[2] {
            for jy in 0..count[1] {
                let t_at = |jx: usize| -> [R; 3] {
                    let k = [jx, jy, jz].map(|j| j % WIDTH);
                    let dot = along[0][k[0]] + along[1][k[1]] + along[2][k[2]];
                    core::array::from_fn(|a| centre[a][k[a]] + nrm[a].mul_rn(dot).mul_rn(half))
                };
                for jx in oblique.range(t_at(0)) {
                    let t = t_at(jx);
                    let b = t.map(bspline);
                    if let Some(weight) = Sums::<R, GRADIENT>::weight(&t, &b) {
                        sums.add(weight, t, b, window.coefficient([jx, jy, jz]));
                    }
                }
            }
        }
        sums.finish(nrm)
    }

    /// [`projected_fast`](Self::projected_fast)'s sums along any normal, row by row and block
    /// by block: the value and, with `GRADIENT`, `G_x`, `G_y`, `G_z` (otherwise zeros); `None`
    /// where some axis of the window reaches more than two blocks (tiles narrower than the
    /// window and the blend zones) or nears the end of `i32`'s range, which the caller then
    /// sums coefficient by coefficient through a [`Window`].
    ///
    /// Each basis argument is affine in the offsets: `t(j) = t(0) + Σ_b r_b j_b`, with
    /// `r_b = e_b − n n_b/2` (the offset `j_b` moves `d_b` by −1). So a row's `t` (`jy`, `jz`
    /// fixed) are its start plus one precomputed rise per lane; a row whose `t_y` or `t_z`
    /// lies past 0 or 3 at both of its ends is skipped (the `t` rise or fall monotonically
    /// along it, rounding included), the others keep the lanes whose three `t` lie in
    /// `(0, 3)` (an interval: each `t` is monotonic) and compute their basis weights once.
    /// A blended coefficient is, block by block, the block's read times per-axis blend
    /// weights, so each block that reaches the row adds `ω_y ω_z Σ_x w(x) (c ω_x)`: the row's
    /// reads in that block, each weighted by its basis weight and x blend weight, times the
    /// row's y and z blend weights. The blocks' placements are found once per sample, into
    /// per-axis parts of the tile's flat index.
    ///
    /// Within rounding of the reference (`t` from the affine form, the sums in another
    /// order): `fast_path_is_the_compact_path`. Out of line, one copy per number type and
    /// gradient flag.
    #[inline(never)]
    fn projected_oblique<R: Real, const GRADIENT: bool>(
        &self,
        window: &ProjectedWindow<R>,
        nrm: [R; 3],
    ) -> Option<[R; 4]> {
        let (n, h) = (T::SIZE, self.half_width::<3>());
        let ProjectedWindow {
            first,
            count,
            centre,
            along,
        } = window;
        // Per axis: the first slot's block and the local index (plus n) of the window's first
        // coefficient in it; the offsets each slot reaches; per slot and offset, the blend
        // weight (1 along an axis that stays within its first block).
        let mut base = [0i32; 3];
        let mut local = [0usize; 3];
        let mut slots = 0usize;
        let mut reach = [[(0usize, 0usize); 3]; 2];
        let mut omega = [[[R::ONE; WIDTH]; 3]; 2];
        for a in 0..3 {
            let len = count[a];
            if len == 0 {
                return Some([R::ZERO; 4]); // nothing in reach (the sums start at +0)
            }
            first[a].checked_add(WIDTH as i32)?;
            let (block, l0, _) = first_block(first[a], n, h);
            // Offset k's local index (plus n) in the first block is l0 + k, in the next
            // l0 + k − n; the block after that reaches local l0 + k ≥ 3n − h.
            if l0 + len > 3 * n - h {
                return None;
            }
            (base[a], local[a]) = (block, l0);
            reach[0][a] = (0, len.min((2 * n + h).saturating_sub(l0)));
            if l0 + len > 2 * n - h {
                slots |= 1 << a;
                reach[1][a] = ((2 * n - h).saturating_sub(l0).min(len), len);
                let at = zone_offset(l0, n, h);
                let [first, next] = &mut omega;
                for (k, (first, next)) in first[a].iter_mut().zip(&mut next[a]).enumerate() {
                    [*first, *next] = crossing::<R>(at + k, h);
                }
            }
        }
        // Per block (numbered by its slots, bit a along axis a) and axis, each offset's part
        // of the tile's flat index in that block (its local index l0 + k in the first slot's
        // block, l0 + k − n in the next: the same index mod n). Offsets the block does not
        // reach are never read.
        let mut places = [(0, Placement::UNSHIFTED); 8];
        let blocks = self.slot_placements(base, slots, &mut places);
        let mut parts = [[[0usize; WIDTH]; 3]; 8];
        for &(block, ref place) in places.iter().take(blocks) {
            for (a, part) in parts[block % 8].iter_mut().enumerate() {
                *part = offset_run(place, a, block, local[a], n);
            }
        }
        // The basis arguments at offset 0, and each axis's rise per offset along each axis,
        // `rise[b][a][j] = r_b,a · j`.
        let half = R::from_ratio(1, 1);
        let dot = along[0][0] + along[1][0] + along[2][0];
        let t0: [R; 3] = core::array::from_fn(|a| centre[a][0] + nrm[a].mul_rn(dot).mul_rn(half));
        let mut rise = [[[R::ZERO; WIDTH]; 3]; 3];
        for (b, rise) in rise.iter_mut().enumerate() {
            for (a, rise) in rise.iter_mut().enumerate() {
                let cross = nrm[a].mul_rn(nrm[b]).mul_rn(half);
                let slope = if a == b {
                    R::ONE - cross
                } else {
                    R::ZERO - cross
                };
                for (j, r) in rise.iter_mut().enumerate() {
                    *r = slope.mul_rn(R::from_i32(j as i32));
                }
            }
        }
        // Per slot and axis, the offsets it reaches (bit j: offset j); along x, each slot's
        // offsets and how many slots there are.
        let reached: [[u32; 3]; 2] =
            reach.map(|reach| reach.map(|(from, to)| (1u32 << to) - (1u32 << from.min(to))));
        let x_reach = [reach[0][0], reach[1][0]];
        let x_slots = 1 + (slots & 1);
        let (tile, three) = (self.tile(), R::from_i32(3));
        let unit = tile.unit::<R>();
        let sets = if GRADIENT { 4 } else { 1 };
        let lanes = (1u32 << count[0].min(WIDTH)) - 1;
        let last = (count[0] - 1) % WIDTH;
        let mut sums = [R::ZERO; 4];
        for jz in 0..count[2].min(WIDTH) {
            let plane: [R; 3] = core::array::from_fn(|a| t0[a] + rise[2][a][jz]);
            for jy in 0..count[1].min(WIDTH) {
                let start: [R; 3] = core::array::from_fn(|a| plane[a] + rise[1][a][jy]);
                // Past an end at both ends of the row, t_y or t_z is past it all along.
                let outside = |a: usize| {
                    let end = start[a] + rise[0][a][last];
                    (start[a] <= R::ZERO && end <= R::ZERO) || (start[a] >= three && end >= three)
                };
                if outside(1) || outside(2) {
                    continue;
                }
                let t: [[R; WIDTH]; 3] =
                    core::array::from_fn(|a| core::array::from_fn(|l| start[a] + rise[0][a][l]));
                let mut inside = 0u32;
                for l in 0..WIDTH {
                    let within = |t: R| (t > R::ZERO) & (t < three);
                    let ok = within(t[0][l]) & within(t[1][l]) & within(t[2][l]);
                    inside |= u32::from(ok) << l;
                }
                inside &= lanes;
                if inside == 0 {
                    continue;
                }
                let (lo, hi) = (
                    inside.trailing_zeros() as usize,
                    (u32::BITS - inside.leading_zeros()) as usize,
                );
                // Every lane's basis weights (those outside `lo..hi` are not read): the
                // value's, then with `GRADIENT` each G_a's (axis a's B-spline replaced by its
                // derivative).
                let b = t.map(|t| t.map(bspline));
                let mut w = [[R::ZERO; WIDTH]; 4];
                w[0] = core::array::from_fn(|l| b[0][l].mul_rn(b[1][l]).mul_rn(b[2][l]));
                if GRADIENT {
                    let db = t.map(|t| t.map(bspline_derivative));
                    w[1] = core::array::from_fn(|l| db[0][l].mul_rn(b[1][l]).mul_rn(b[2][l]));
                    w[2] = core::array::from_fn(|l| b[0][l].mul_rn(db[1][l]).mul_rn(b[2][l]));
                    w[3] = core::array::from_fn(|l| b[0][l].mul_rn(b[1][l]).mul_rn(db[2][l]));
                }
                // The blocks that reach the row, in increasing order (x fastest).
                for sz in 0..2 {
                    if reached[sz][2] >> jz & 1 == 0 {
                        continue;
                    }
                    for sy in 0..2 {
                        if reached[sy][1] >> jy & 1 == 0 {
                            continue;
                        }
                        let across = omega[sy][1][jy].mul_rn(omega[sz][2][jz]);
                        for (sx, &(from, to)) in x_reach.iter().enumerate().take(x_slots) {
                            let run = lo.max(from)..hi.min(to).min(WIDTH);
                            if run.is_empty() {
                                continue;
                            }
                            let part = &parts[(sx | sy << 1 | sz << 2) % 8];
                            let row = part[1][jy] + part[2][jz];
                            let mut line = [R::ZERO; 4];
                            for l in run {
                                let mut c = tile.flat_with(part[0][l] + row, unit);
                                if x_slots == 2 {
                                    c = c.mul_rn(omega[sx][0][l]);
                                }
                                for (line, w) in line.iter_mut().zip(&w).take(sets) {
                                    *line = line.saturating_add(w[l].mul_rn(c));
                                }
                            }
                            for (sum, line) in sums.iter_mut().zip(line).take(sets) {
                                *sum = sum.saturating_add(line.mul_rn(across));
                            }
                        }
                    }
                }
            }
        }
        Some(sums)
    }

    /// The placements of the blocks a window or support reaches, into `places`: each subset
    /// `block` of `slots` (bit `a` set: the block past `base` along axis `a`) in increasing
    /// order, with the block's placement, all found before any block is summed; returns how
    /// many there are. (Written in place: returned by value, the array was copied.)
    #[inline(always)]
    fn slot_placements(
        &self,
        base: [i32; 3],
        slots: usize,
        places: &mut [(usize, Placement<3>); 8],
    ) -> usize {
        let (mut block, mut count) = (0, 0);
        loop {
            let place = self.placement(core::array::from_fn(|a| {
                base[a].wrapping_add((block >> a & 1) as i32)
            }));
            places[count % 8] = (block, place);
            count += 1;
            if block == slots {
                return count;
            }
            block = block.wrapping_sub(slots) & slots; // the next subset of `slots`
        }
    }
}

/// A projected window's coefficients, from global index `first` along each axis, `count`
/// of them (at most [`WIDTH`]); per axis and offset `j` (coefficient `first + j`),
/// `3/2 − d` and `n_a d_a` with `d = p − c`: the terms of the reference's basis arguments
/// `t = (3/2 − d) + n (n·d)/2` (`compact.rs`).
pub(super) struct ProjectedWindow<R> {
    first: [i32; 3],
    count: [usize; 3],
    centre: [[R; WIDTH]; 3],
    along: [[R; WIDTH]; 3],
}

impl<R: Real> ProjectedWindow<R> {
    /// The window around `p` for unit normal `nrm` ([`support_box`] per axis).
    #[inline]
    fn new(p: [R; 3], nrm: [R; 3]) -> Self {
        let mut window = ProjectedWindow {
            first: [0; 3],
            count: [0; 3],
            centre: [[R::ZERO; WIDTH]; 3],
            along: [[R::ZERO; WIDTH]; 3],
        };
        let l1 = nrm[0].abs() + nrm[1].abs() + nrm[2].abs();
        for a in 0..3 {
            let (cell, frac) = p[a].split();
            let (kmin, kmax) = support_box(frac, nrm[a], l1);
            window.first[a] = cell.wrapping_add(kmin);
            // At most WIDTH (s < 3.7: at most 8 integers lie within it).
            window.count[a] = kmax
                .wrapping_sub(kmin)
                .wrapping_add(1)
                .clamp(0, WIDTH as i32) as usize;
            for (j, (c, e)) in window.centre[a]
                .iter_mut()
                .zip(&mut window.along[a])
                .enumerate()
            {
                if j < window.count[a] {
                    let d = frac - R::from_i32(kmin + j as i32);
                    *c = R::from_ratio(3, 1) - d;
                    *e = nrm[a].mul_rn(d);
                }
            }
        }
        window
    }
}

/// Where a run of offsets along an axis that crosses from its first block into the next
/// (first local index `l0`, plus `n`, with `l0 + len > 2n − h` for a length `len` of at most
/// 8) lies in [`CROSSING`]: its offset `k`'s weights are `crossing(at + k, h)`.
#[inline]
fn zone_offset(l0: usize, n: usize, h: usize) -> usize {
    (l0 + h + 8).wrapping_sub(2 * n)
}

/// The blend weights at `at` in [`CROSSING`] ([`zone_offset`]) in the first block and the next.
#[inline]
fn crossing<R: Real>(at: usize, h: usize) -> [R; 2] {
    let [first, next] = &CROSSING[usize::from(h > 0)];
    [
        R::from_ratio(first[at & 31], 16),
        R::from_ratio(next[at & 31], 16),
    ]
}

/// The offsets `jx` of a row of a projected window (at fixed `jy`, `jz`) where the basis can
/// be non-zero, for the windows summed coefficient by coefficient through a [`Window`].
///
/// Along a row, each `t_a` is linear in `jx`: with `d_x` falling by 1 per step,
/// `t_a(jx) = t_a(0) + σ_a jx`, `σ_x = 1 − n_x²/2` (in `[½, 1]`), `σ_y = −n_x n_y/2`,
/// `σ_z = −n_x n_z/2`. The basis is 0 unless every `t_a` lies in `(0, 3)`. Along x that bounds
/// `jx` by `−t_x(0)/σ_x` and `(3 − t_x(0))/σ_x`, computed with `1/σ_x` once per sample to
/// within 10⁻³ of a step; each bound is moved outwards by 1/16 before it is rounded to the
/// integers inside, so the row keeps every coefficient whose `t_x` rounds into `(0, 3)`
/// (rounding moves `t` by less than 10⁻³ from the line). The row is skipped when `t_y` or `t_z`
/// is past 0 or 3 by 1/16 at both ends (they are linear too); each coefficient kept is still
/// tested on its own, as the reference tests it.
struct Oblique<R> {
    /// `σ_a` per axis.
    slopes: [R; 3],
    /// `1/σ_x`.
    inverse: R,
    /// The number of offsets along x.
    count: usize,
}

impl<R: Real> Oblique<R> {
    #[inline]
    fn new(nrm: [R; 3], count: usize) -> Self {
        let half = R::from_ratio(1, 1);
        let across = (R::ZERO - nrm[0]).mul_rn(half);
        let slopes = [
            R::ONE - nrm[0].mul_rn(nrm[0]).mul_rn(half),
            across.mul_rn(nrm[1]),
            across.mul_rn(nrm[2]),
        ];
        Oblique {
            slopes,
            inverse: R::ONE.div(slopes[0]),
            count,
        }
    }

    /// The offsets to visit in the row whose `t` at `jx = 0` is `t0`.
    #[inline]
    fn range(&self, t0: [R; 3]) -> Range<usize> {
        let three = R::from_i32(3);
        let margin = R::from_ratio(1, 4);
        let outside = |lo: R, hi: R| {
            (lo <= -margin && hi <= -margin) || (lo >= three + margin && hi >= three + margin)
        };
        // The whole row first (cheaper than clipping it along x): t_y or t_z past an end at
        // both of the row's ends.
        let last = R::from_i32(self.count as i32 - 1);
        for (&t, &slope) in t0.iter().zip(&self.slopes).skip(1) {
            if outside(t, t + slope.mul_rn(last)) {
                return 0..0;
            }
        }
        // Where t_x crosses 0 and 3 (σ_x > 0); the integers strictly between, widened by 1/16.
        let first = ((R::ZERO - t0[0]).mul_rn(self.inverse) - margin).split().0 + 1;
        let end = ((three - t0[0]).mul_rn(self.inverse) + margin).split().0 + 1;
        let (first, end) = (first.max(0), end.min(self.count as i32));
        if end <= first {
            return 0..0;
        }
        let ends = [R::from_i32(first), R::from_i32(end - 1)];
        for (&t, &slope) in t0.iter().zip(&self.slopes).skip(1) {
            let [lo, hi] = ends.map(|jx| t + slope.mul_rn(jx));
            if outside(lo, hi) {
                return 0..0;
            }
        }
        first as usize..end as usize
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wavelet::compact::fetcher;
    use crate::wavelet::{Tile3, Tiling};
    use crate::{FilteredNoise, I16F16};

    static TILE4: Tile3<4> = Tile3::generate(3);
    static TILE6: Tile3<6> = Tile3::generate(4);
    static TILE12: Tile3<12> = Tile3::generate(5);
    static TILE16: Tile3<16> = Tile3::generate(6);

    /// The set-up's weights, from `crossing` where a support or window crosses into the next
    /// block and 1 where it does not, are `blend_weight`'s, for every first local index
    /// `first_block` gives, every length up to a window's 8, blended and not, several tile
    /// sizes.
    #[test]
    fn crossing_weights_are_blend_weights() {
        use crate::wavelet::band::{BLEND, blend_weight};
        for n in [4, 6, 11, 12, 16, 32] {
            for h in [0, BLEND] {
                if h > 0 && n < 2 * BLEND + 3 {
                    continue; // such tiles are not blended (`half_width`)
                }
                for l0 in n + h..2 * n + h {
                    for len in 1..=WIDTH {
                        if l0 + len > 3 * n - h {
                            continue; // the window's case: a third block
                        }
                        for i in 0..len {
                            let reference =
                                |s: usize| blend_weight::<f32>(l0 + i - s * n, n, h).to_bits();
                            let weights = if l0 + len > 2 * n - h {
                                crossing::<f32>(zone_offset(l0, n, h) + i, h).map(f32::to_bits)
                            } else {
                                [1.0f32.to_bits(), 0.0f32.to_bits()]
                            };
                            assert_eq!(
                                weights,
                                [reference(0), reference(1)],
                                "n {n} h {h} l0 {l0} {i}/{len}"
                            );
                        }
                    }
                }
            }
        }
    }

    /// A small xorshift generator: uniform in [lo, hi).
    struct Rng(u64);
    impl Rng {
        fn uniform(&mut self, lo: f32, hi: f32) -> f32 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            lo + (hi - lo) * ((self.0 >> 40) as f32 / (1u64 << 24) as f32)
        }
    }

    /// Normals along each axis (either sign), on faces and diagonals, with one component 0,
    /// nearly axis-aligned, and random ones.
    fn normals(rng: &mut Rng) -> impl Iterator<Item = [f32; 3]> + '_ {
        let fixed = [
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
            [1.0, 0.0, 0.0],
            [0.0, -1.0, 0.0],
            [1.0, 1.0, 1.0],
            [0.0, 0.6, 0.8],
            [0.48, 0.6, 0.64],
            [1e-6, 0.0, 1.0],
            [0.05, -0.02, 1.0],
            [-0.9, 0.3, 0.1],
        ];
        fixed.into_iter().chain((0..20).map(|_| {
            [
                rng.uniform(-1.0, 1.0),
                rng.uniform(-1.0, 1.0),
                rng.uniform(-1.0, 1.0),
            ]
        }))
    }

    /// Whether the fast path sums the window around `p` block by block (along an axis or
    /// not), rather than coefficient by coefficient.
    fn by_blocks<R: Real, T: TileData<3>>(band: &Wavelet<'_, T>, p: [R; 3], n: [R; 3]) -> bool {
        band.projected_along::<R, false, CUBE>(p, n).is_some()
            || band
                .projected_oblique::<R, false>(&ProjectedWindow::new(p, n), n)
                .is_some()
    }

    /// The fast path gives the compact path's values and gradients within rounding where it
    /// sums block by block, bit for bit elsewhere, for every tile size and tiling (tiles of 4
    /// and 6 reach 3 blocks per axis, so neither block path nor the window's cache takes
    /// them; 12 blends without room to cache), number type and normal, at points near the
    /// origin, on block borders and far away. `worst` keeps the largest differences: f32 and
    /// f64 as fractions of the bound, I16F16 in units of its last place.
    fn same_as_compact<T: TileData<3>>(tile: &T, rng: &mut Rng, worst: &mut [f64; 3]) -> usize {
        let mut checked = 0;
        let normals: [[f32; 3]; 30] = {
            let mut all = normals(rng);
            core::array::from_fn(|_| all.next().unwrap_or([0.0; 3]))
        };
        for tiling in [Tiling::Periodic, Tiling::Varied, Tiling::Blended] {
            for seed in [0, 9] {
                let band = Wavelet::new(seed, tile).with_tiling(tiling);
                for n in &normals {
                    for i in 0..40 {
                        let scale = [2.0, 40.0, 3e5][i % 3];
                        let p = [0; 3].map(|_| rng.uniform(-scale, scale));
                        // A window whose axes reach at most two blocks each is summed block by
                        // block (`projected_axis` along an axis, `projected_oblique`
                        // otherwise): within rounding of the reference (measured: see
                        // `fast_path_is_the_compact_path`); the other windows (small tiles)
                        // coefficient by coefficient, the same bits.
                        let bound = f64::from(band.projected_bound());
                        let unit = unit_normal(*n);
                        let fast = band.projected_fast::<f32, true>(p, unit);
                        let compact = band.projected_compact::<f32, true>(p, unit);
                        let blocks = by_blocks(&band, p, unit);
                        let f = [fast.0, fast.1[0], fast.1[1], fast.1[2]].map(f64::from);
                        let c = [compact.0, compact.1[0], compact.1[1], compact.1[2]];
                        for (f, c) in f.into_iter().zip(c.map(f64::from)) {
                            if blocks {
                                let e = (f - c).abs() / bound;
                                worst[0] = worst[0].max(e);
                                assert!(e <= 1e-6, "{p:?} {n:?} {tiling:?} {e}");
                            } else {
                                assert_eq!(f.to_bits(), c.to_bits(), "{p:?} {n:?} {tiling:?}");
                            }
                        }
                        let value = band.projected_fast::<f32, false>(p, unit).0;
                        assert_eq!(value.to_bits(), fast.0.to_bits());
                        let pq = p.map(|x| I16F16::from_num(x.clamp(-30000.0, 30000.0)));
                        let uq = unit_normal(n.map(I16F16::from_num));
                        let fast = band.projected_fast::<I16F16, true>(pq, uq);
                        let compact = band.projected_compact::<I16F16, true>(pq, uq);
                        let ulps = |a: I16F16, b: I16F16| (a - b).to_bits().unsigned_abs();
                        let most = (0..3).fold(ulps(fast.0, compact.0), |m, a| {
                            m.max(ulps(fast.1[a], compact.1[a]))
                        });
                        if by_blocks(&band, pq, uq) {
                            worst[1] = worst[1].max(f64::from(most));
                            assert!(most <= 64, "{p:?} {n:?} {most}");
                        } else {
                            assert_eq!(most, 0, "{p:?} {n:?}");
                        }
                        let value = band.projected_fast::<I16F16, false>(pq, uq).0;
                        assert_eq!(value, fast.0);
                        let pd = p.map(f64::from);
                        let ud = unit_normal(n.map(f64::from));
                        let fast = band.projected_fast::<f64, false>(pd, ud).0;
                        let compact = band.projected_compact::<f64, false>(pd, ud).0;
                        if by_blocks(&band, pd, ud) {
                            let e = (fast - compact).abs() / bound;
                            worst[2] = worst[2].max(e);
                            assert!(e <= 1e-14, "{p:?} {n:?} {tiling:?} {e}");
                        } else {
                            assert_eq!(fast.to_bits(), compact.to_bits(), "{p:?} {n:?}");
                        }
                        checked += 1;
                    }
                }
                // The box-widened basis reads the same kind of window.
                for i in 0..200 {
                    let p = [0; 3].map(|_| rng.uniform(-70.0, 70.0));
                    let w = [0.3, 1.0, 2.9, 3.5][i % 4];
                    let widths = [w, rng.uniform(0.3, 3.9), rng.uniform(0.3, 3.9)];
                    let fast: f32 = band.widened(p, widths);
                    let compact = band.widened_by(p, widths, |first, _| fetcher(&band, first));
                    assert_eq!(fast.to_bits(), compact.to_bits(), "{p:?} {widths:?}");
                    let pq = p.map(I16F16::from_num);
                    let fast: I16F16 = band.widened(pq, widths);
                    let compact = band.widened_by(pq, widths, |first, _| fetcher(&band, first));
                    assert_eq!(fast, compact);
                    // And through the public entry point.
                    let d = [w * 0.6, 0.0, 0.0];
                    let _: f32 = band.sample_filtered(p, d, [0.0, w * 0.8, 0.0]);
                }
            }
        }
        checked
    }

    /// `support_box` holds every coefficient whose basis arguments, computed as the reference
    /// computes them (`compact.rs`), all lie in `(0, 3)`, in f32, f64 and I16F16, for normals
    /// over the sphere (along the axes and the diagonals too) and fractions over the cell;
    /// and it is not loose: for most samples some coefficient of the support lies at each end
    /// of the box along x.
    #[test]
    fn support_boxes_hold_the_support() {
        fn check<R: Real>(normals: &[[f32; 3]]) -> usize {
            let (half, three) = (R::from_ratio(1, 1), R::from_i32(3));
            let mut tight = 0;
            for (i, &n) in normals.iter().enumerate() {
                let nrm = unit_normal(n.map(R::from_f32));
                let l1 = nrm[0].abs() + nrm[1].abs() + nrm[2].abs();
                for step in 0..16 {
                    let frac = [7, 11, 13].map(|m| R::from_ratio(((step + i) * m % 16) as i32, 4));
                    let boxes: [(i32, i32); 3] =
                        core::array::from_fn(|a| support_box(frac[a], nrm[a], l1));
                    let mut ends = [false; 2];
                    for k in (-6..=6)
                        .flat_map(|x| (-6..=6).flat_map(move |y| (-6..=6).map(move |z| [x, y, z])))
                    {
                        let d: [R; 3] = core::array::from_fn(|a| frac[a] - R::from_i32(k[a]));
                        let dot = nrm[0].mul_rn(d[0]) + nrm[1].mul_rn(d[1]) + nrm[2].mul_rn(d[2]);
                        let t: [R; 3] = core::array::from_fn(|a| {
                            R::from_ratio(3, 1) - d[a] + nrm[a].mul_rn(dot).mul_rn(half)
                        });
                        if t.iter().all(|&t| t > R::ZERO && t < three) {
                            for a in 0..3 {
                                let (lo, hi) = boxes[a];
                                assert!((lo..=hi).contains(&k[a]), "{n:?} {k:?} {:?}", boxes);
                            }
                            ends[0] |= k[0] == boxes[0].0;
                            ends[1] |= k[0] == boxes[0].1;
                        }
                    }
                    tight += usize::from(ends[0] && ends[1]);
                }
            }
            tight
        }
        let fixed = [
            [1.0, 0.0, 0.0],
            [0.0, -1.0, 0.0],
            [1.0, 1.0, 1.0],
            [-1.0, 1.0, 0.0],
        ];
        let mut state = 0x2545_f491u32;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            (state >> 8) as f32 / (1 << 23) as f32 - 1.0
        };
        let normals: [[f32; 3]; 64] = core::array::from_fn(|i| {
            if i < 4 {
                fixed[i]
            } else {
                [next(), next(), next()]
            }
        });
        let samples = normals.len() * 16;
        let tight = [
            check::<f32>(&normals),
            check::<f64>(&normals),
            check::<I16F16>(&normals),
        ];
        // Measured: 498, 499 and 498 of 1024 (the bound before, `compact.rs`'s, 128).
        assert!(
            tight.iter().all(|&t| t * 5 > samples * 2),
            "{tight:?} of {samples}"
        );
    }

    /// `unit_normal`'s axis shortcut gives what its divisions give, bit for bit: zeros with
    /// their signs, the third component's sign.
    #[test]
    fn axis_normals_are_the_divided_ones() {
        fn divided<R: Real>(n: [R; 3]) -> [R; 3] {
            let largest = n
                .iter()
                .fold(R::ZERO, |m, x| if x.abs() > m { x.abs() } else { m });
            let scaled = n.map(|x| x.div(largest));
            let len = scaled
                .iter()
                .fold(R::ZERO, |acc, x| acc + x.mul_rn(*x))
                .sqrt();
            scaled.map(|x| x.div(len).clamp_to(-R::ONE, R::ONE))
        }
        for c in [1.0f32, -1.0, 5.0, -3.0e-30, 1.0e-45, 3.0e38, -0.25] {
            for axis in 0..3 {
                for zero in [0.0f32, -0.0] {
                    let mut n = [zero; 3];
                    n[axis] = c;
                    let bits = |v: [f32; 3]| v.map(f32::to_bits);
                    assert_eq!(bits(unit_normal(n)), bits(divided(n)), "{n:?}");
                    let d = n.map(f64::from);
                    let bits = |v: [f64; 3]| v.map(f64::to_bits);
                    assert_eq!(bits(unit_normal(d)), bits(divided(d)), "{n:?}");
                    let q = n.map(I16F16::saturating_from_num);
                    if q[axis] != I16F16::ZERO {
                        assert_eq!(unit_normal(q), divided(q), "{n:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn fast_path_is_the_compact_path() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        let mut worst = [0.0; 3];
        let mut checked = same_as_compact(&TILE4, &mut rng, &mut worst);
        checked += same_as_compact(&TILE6, &mut rng, &mut worst);
        checked += same_as_compact(&TILE12, &mut rng, &mut worst);
        checked += same_as_compact(&TILE16, &mut rng, &mut worst);
        checked += same_as_compact(&crate::wavelet::TILE3, &mut rng, &mut worst);
        assert_eq!(checked, 5 * 3 * 2 * 30 * 40);
        // Measured (printed as [f32, I16F16, f64]): 2.3e-7 (f32) and 2.0e-16 (f64) of the
        // bound, 51 units of I16F16's last place (which rounds each `t` to 2⁻¹⁶).
        extern crate std;
        std::eprintln!("largest differences from the reference: {worst:?}");
    }

    /// Along an axis, the default tile's windows are summed block by block (so the test
    /// above compares the block sums with the reference), and a tile of 4 reaches three
    /// blocks along an axis, which the block sums refuse (the test above compares the
    /// coefficient-by-coefficient path with the reference there).
    #[test]
    fn axis_windows_are_summed_block_by_block() {
        let support = [1..4, 1..4, 0..6];
        let t = [[1.0f32; WIDTH]; 3];
        // Six offsets along z from a coefficient at 3 mod 4 reach three blocks of 4.
        for first in [[-3, -2, 3], [0, 5, 7], [-40, 7, 1003]] {
            let band = Wavelet::new(0, &crate::wavelet::TILE3);
            assert!(
                band.projected_axis::<f32, false, CUBE>(first, &t, &support, 2)
                    .is_some()
            );
            let small = Wavelet::new(5, &TILE4).with_tiling(Tiling::Varied);
            assert!(
                small
                    .projected_axis::<f32, false, CUBE>(first, &t, &support, 2)
                    .is_none()
            );
        }
    }

    /// Along oblique normals, the default tile's windows are summed block by block (so
    /// `fast_path_is_the_compact_path` compares the block sums with the reference), and a
    /// tile of 4's are not where they reach three blocks along an axis (most of them).
    #[test]
    fn oblique_windows_are_summed_block_by_block() {
        let n = unit_normal([0.48f32, 0.6, 0.64]);
        let mut rng = Rng(7);
        let band = Wavelet::new(0, &crate::wavelet::TILE3);
        let small = Wavelet::new(5, &TILE4).with_tiling(Tiling::Varied);
        let mut refused = 0;
        for _ in 0..200 {
            let p = [0; 3].map(|_| rng.uniform(-500.0, 500.0));
            let window = ProjectedWindow::new(p, n);
            assert!(band.projected_oblique::<f32, true>(&window, n).is_some());
            refused += usize::from(small.projected_oblique::<f32, true>(&window, n).is_none());
        }
        // Measured: 120 (with the looser support box before 2026-12-07, more than 150).
        assert!(refused > 100, "{refused}");
    }

    /// Along an axis, the block sums written per axis permutation (`PERMUTED`: x86-64 and
    /// AArch64) and through flat index parts (the other targets) are the same, bit for bit:
    /// values and gradients, along each axis with either sign, every tiling, in f32, f64 and
    /// I16F16, over the default tile, the quantized one and a tile whose side is not a power
    /// of two.
    #[test]
    fn permuted_block_sums_are_the_flat_ones() {
        fn same<R: Real, T: TileData<3>>(band: &Wavelet<'_, T>, p: [R; 3], n: [R; 3]) -> bool {
            let bits = |(v, g): (R, [R; 3])| [v, g[0], g[1], g[2]].map(|x| x.to_f64().to_bits());
            let permuted = band.projected_along::<R, true, true>(p, n);
            let flat = band.projected_along::<R, true, false>(p, n);
            let value = |s: Option<Sums<R, false>>| s.map(|s| bits(s.finish(n)));
            let values = value(band.projected_along::<R, false, true>(p, n))
                == value(band.projected_along::<R, false, false>(p, n));
            values
                && match (permuted, flat) {
                    (Some(a), Some(b)) => bits(a.finish(n)) == bits(b.finish(n)),
                    (a, b) => a.is_none() && b.is_none(),
                }
        }
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        let mut summed = 0;
        for tiling in [Tiling::Blended, Tiling::Varied, Tiling::Periodic] {
            let bands = (
                Wavelet::new(1, &crate::wavelet::TILE3).with_tiling(tiling),
                Wavelet::new(2, &TILE12).with_tiling(tiling),
                Wavelet::new(3, &crate::wavelet::TILE3_I16).with_tiling(tiling),
            );
            for i in 0..600 {
                let axis = i % 3;
                let n: [f32; 3] = core::array::from_fn(|a| {
                    if a == axis {
                        [1.0, -1.0][i / 3 % 2]
                    } else {
                        0.0
                    }
                });
                let p: [f32; 3] = core::array::from_fn(|_| rng.uniform(-300.0, 300.0));
                let (pd, nd) = (p.map(f64::from), n.map(f64::from));
                let (pq, nq) = (p.map(I16F16::from_num), n.map(I16F16::from_num));
                assert!(same(&bands.0, p, n) && same(&bands.0, pd, nd) && same(&bands.0, pq, nq));
                assert!(same(&bands.1, p, n) && same(&bands.2, p, n) && same(&bands.2, pq, nq));
                summed += usize::from(bands.0.projected_along::<f32, false, true>(p, n).is_some());
            }
        }
        // The block sums, not the window, took (nearly) every point.
        assert!(summed > 1700, "{summed}");
    }

    /// Tiles of 4 and 6 with varied tiling reach 3 blocks along an axis: each keeps its own
    /// placement (a cache of 3 slots from the wrong base once read two blocks as one, which
    /// the fast path, resolving each block on its own there, exposed).
    #[test]
    fn small_tiles_place_every_block() {
        let band = Wavelet::new(5, &TILE4).with_tiling(Tiling::Varied);
        let n = unit_normal([0.48f32, 0.6, 0.64]);
        for i in 0..400 {
            let p = [i as f32 * 0.37 - 70.0, 1.3, -2.2];
            assert_eq!(
                band.projected_fast::<f32, false>(p, n).0.to_bits(),
                band.projected_compact::<f32, false>(p, n).0.to_bits()
            );
        }
    }
}
