//! OpenSimplex2 and OpenSimplex2S (K. Jordan, "KdotJPG", 2019–2022): gradient noise on lattices
//! chosen for isotropy, reproducing the reference implementation (the `KdotJPG/OpenSimplex2`
//! repository's Rust port, the `opensimplex2` crate 1.1.0) within 10⁻⁶ in `f64`.
//!
//! Like [`Simplex`](super::Simplex), each lattice vertex near the point contributes
//! `(r² − |d|²)⁴ (g·d)` for its offset `d` and its gradient `g`; the lattices and radii differ:
//!
//! * **2D** (both): the triangular lattice, Perlin's skewed square lattice (`F = (√3 − 1)/2`).
//!   OpenSimplex2 takes the three corners of the point's triangle with `r² = ½` (simplex noise
//!   with other gradients and hash); OpenSimplex2S four vertices with `r² = ⅔`, a wider kernel
//!   that is smoother and less grid-aligned.
//! * **3D**: the body-centred cubic lattice, built as two cubic lattices offset by `(½, ½, ½)`
//!   and rotated so that no axis lies along a lattice direction. OpenSimplex2 takes the two
//!   closest vertices of each cubic lattice with `r² = 0.6`; OpenSimplex2S up to eight chosen
//!   near the point with `r² = ¾`.
//! * **4D**: OpenSimplex2 takes one vertex from each of five copies of the A₄* lattice offset
//!   along the main diagonal by steps of `0.2` (`r² = 0.6`); OpenSimplex2S every vertex of the
//!   A₄ lattice within `r² = 0.8`.
//!
//! The vertex choices are the reference's, including where they leave a vertex in reach out:
//! 3D and 4D OpenSimplex2 and 3D OpenSimplex2S have small jumps there (up to 4·10⁻³,
//! measured; see [`OpenSimplex2`]), the reference's own.
//!
//! **Hash**: no permutation table. A vertex's hash is `(seed ⊕ Σₐ cellₐ·primeₐ) · m` in
//! wrapping 64-bit integers (four 64-bit primes and a multiplier); its top bits folded onto its
//! low bits pick one of 24 (2D), 48 (3D) or 160 (4D) gradients, each set cycled over a
//! power-of-two table as in the reference. The seed is any `i64`; seeds that differ give
//! unrelated noise.
//!
//! **Orientation** ([`Improve`]): the reference offers its lattices turned so that a plane of
//! the input is as isotropic as possible and the remaining axis is the "different" one (height,
//! time). bandnoise offers the default orientation and the two for a vertical `z` or `y`.
//!
//! **Numbers**: the coordinates are turned onto the lattice in `f64` whatever the number type
//! (`f32` and I16F16 coordinates are exact in `f64`), as the reference does, because the
//! rotations have irrational coefficients that no integer skew reproduces; the cells are the
//! floors (or, 3D OpenSimplex2, the nearest integers) of the turned coordinates, and the
//! offsets within the cell are rounded once to the number type, where everything else is
//! computed. So `f32` keeps its offsets' precision far from the origin, and fixed point never
//! overflows. On cores without a double-precision unit the turn costs a few soft-float
//! operations per sample; [`Simplex`](super::Simplex) is the cheaper noise there.
//!
//! **Batches** ([`Noise::fill_grid`](crate::Noise::fill_grid), `fill_points`): both noises in
//! 2D and 3D run their vertices over 16 points at once, each step a loop over the points so
//! that the compiler vectorises what it can; every vertex (3D OpenSimplex2S: every candidate)
//! of every point is computed, one out of reach adding an exact 0 where a point sample skips
//! it and one not chosen adding nothing, so batches are `sample`'s bits (3D OpenSimplex2S on
//! x86 and AArch64 only, where branches cost more than its extra candidates). 4D, whose
//! vertex choices branch per point over more candidates, samples point by point.
//!
//! **No periodic variant**: the rotated and diagonal-offset lattices have no period along the
//! axes (psrdnoise, Gustavson & McEwan 2022, builds a periodic 2D simplex lattice instead).
//!
//! # Examples
//!
//! ```
//! use bandnoise::{I16F16, Noise, simplex::{Improve, OpenSimplex2, OpenSimplex2S}};
//!
//! let fast = OpenSimplex2::new(0);
//! let v: f64 = fast.sample([0.3, 4.7, 1.5]);
//! assert!(v.abs() <= f64::from(fast.amplitude_bound::<3>()));
//! // Terrain with z up: the xy plane is the isotropic one.
//! let terrain = OpenSimplex2S::new(-7).improving(Improve::XY);
//! let h: f32 = terrain.sample([12.5, -3.25, 0.5]);
//! let q: I16F16 = terrain.sample([12.5, -3.25, 0.5].map(I16F16::from_num));
//! assert!((q.to_num::<f32>() - h).abs() < 1e-3);
//! ```

use crate::Real;
use crate::batch::LANES;
use crate::real::sealed::Sealed;

use super::OUT_OF_ORDER;

/// The primes that hash a vertex's cell, by axis.
const PRIME: [i64; 4] = [
    0x5205_402B_9270_C86F,
    0x598C_D327_0038_17B5,
    0x5BCC_226E_9FA0_BACB,
    0x56CC_5227_E58F_554B,
];
/// The multiplier that mixes a vertex's hash.
const HASH_MULTIPLIER: i64 = 0x53A3_F72D_EEC5_46F5;
/// The seed of 3D's second cubic lattice is the seed `⊕` this.
const SEED_FLIP_3D: i64 = -0x52D5_47B2_E96E_D629;
/// The seeds of 4D OpenSimplex2's five lattice copies differ by this.
const SEED_OFFSET_4D: i64 = 0x0E83_DC3E_0DA7_164D;

/// `U = (1/√3 − 1)/2`, the 2D unskew (offsets from skewed fractions: `dₐ = fₐ + U·Σf`).
const UNSKEW_2D: f64 = -0.211_324_865_405_187_13;
/// The 4D unskew of OpenSimplex2's A₄* lattice, `(√5 − 1)/4`.
const UNSKEW_4D_FAST: f64 = 0.309_016_994_374_947;
/// The 4D unskew of OpenSimplex2S's A₄ lattice, `(1/√5 − 1)/4`.
const UNSKEW_4D_SMOOTH: f64 = -0.138_196_601_125_011;
/// The offset between 4D OpenSimplex2's lattice copies along each skewed axis.
const LATTICE_STEP_4D: f64 = 0.2;

/// One variant's kernel in one dimension: `r²` and the reference's normaliser (the value is
/// `Σ (r² − |d|²)⁴ (g·d) / normaliser` for unit-scale gradients `g`).
struct Kernel {
    /// `1/r²`: the kernel is computed as `τ = 1 − |d|²/r²`, in `[0, 1]` where it counts.
    inverse_radius: f64,
    /// `r⁸ / normaliser`: the value is this times `Σ τ⁴ (g·d)`.
    scale: f64,
    /// `r`'s bound on one vertex's contribution: `max (1 − x²/r²)⁴ x` over `x` (at `x = r/3`,
    /// `(8/9)⁴ r/3`) times the longest gradient and the scale, times the most vertices in
    /// reach, in `f32` (the amplitude bound, proved; see [`OpenSimplex2`]).
    bound: f32,
}

impl Kernel {
    const fn new(r2: f64, normaliser: f64, longest_gradient: f64, vertices: u32) -> Self {
        let scale = r2 * r2 * r2 * r2 / normaliser;
        // √r2 by Newton's method (const fn has no sqrt): r2 is in [½, 1].
        let mut r = 1.0;
        let mut i = 0;
        while i < 8 {
            r = 0.5 * (r + r2 / r);
            i += 1;
        }
        let peak = 0.624_295_077_379_972_5 * r / 3.0; // (8/9)⁴ = 0.6242950773799725
        let bound = peak * longest_gradient * scale * vertices as f64;
        Self {
            inverse_radius: 1.0 / r2,
            scale,
            // Rounding in the number types stays far below the slack of this bound.
            bound: (bound * 1.001) as f32,
        }
    }
}

/// The longest gradient in each dimension's set, rounded up (the 3D set is not normalised:
/// its longest is 3.30136).
const LONGEST: [f64; 5] = [0.0, 0.0, 1.0, 3.3014, 1.0];

/// OpenSimplex2's kernels, by dimension: the reference's `r²` and normalisers, and the most
/// vertices that contribute (3 corners; 2 per cubic lattice; 1 per lattice copy).
const FAST: [Kernel; 5] = [
    Kernel::new(0.5, 0.010_016_341_213_657_12, 1.0, 3),
    Kernel::new(0.5, 0.010_016_341_213_657_12, 1.0, 3),
    Kernel::new(0.5, 0.010_016_341_213_657_12, LONGEST[2], 3),
    Kernel::new(0.6, 0.079_698_376_689_353_31, LONGEST[3], 4),
    Kernel::new(0.6, 0.022_006_593_324_189_7, LONGEST[4], 5),
];

/// OpenSimplex2S's kernels, by dimension (vertices: 4 in 2D; in 3D `v₀`, `v₁` and at most two
/// more per axis ([`smooth_3d`]), 8; in 4D the candidates of [`SMOOTH_4D`], a loose count: no
/// tighter count of the vertices in reach at once is proved yet).
const SMOOTH: [Kernel; 5] = [
    Kernel::new(2.0 / 3.0, 0.054_818_664_956_251_18, 1.0, 4),
    Kernel::new(2.0 / 3.0, 0.054_818_664_956_251_18, 1.0, 4),
    Kernel::new(2.0 / 3.0, 0.054_818_664_956_251_18, LONGEST[2], 4),
    Kernel::new(0.75, 0.278_192_611_752_718_6, LONGEST[3], 8),
    Kernel::new(
        0.8,
        0.111_274_018_899_455_51,
        LONGEST[4],
        SMOOTH_4D.len() as u32,
    ),
];

/// Which plane of the input the lattice is turned to serve best (the reference's "Improve"
/// orientations). The noise's statistics are the same in every orientation; what changes is
/// which slices of it look most isotropic.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Improve {
    /// The reference's standard lattice orientation: 2D `noise2`, 3D `noise3_Fallback`, 4D
    /// `noise4_Fallback`.
    #[default]
    Standard,
    /// `z` (or time) is the different axis and the `xy` plane the isotropic one: terrain with
    /// `z` up, or a 2D image animated along `z`. 2D: as `Standard`; 3D `noise3_ImproveXY`;
    /// 4D `noise4_ImproveXYZ_ImproveXY`.
    XY,
    /// `y` is the different axis and the `xz` plane the isotropic one: terrain with `y` up.
    /// 2D `noise2_ImproveX` (`y` along a lattice diagonal); 3D `noise3_ImproveXZ`; 4D
    /// `noise4_ImproveXYZ_ImproveXZ`.
    XZ,
}

impl Improve {
    /// The isotropic plane's axes `u`, `v` and the different axis `h`, for `XY` and `XZ`.
    const fn axes(self) -> (usize, usize, usize) {
        match self {
            Improve::XZ => (0, 2, 1),
            _ => (0, 1, 2),
        }
    }
}

/// OpenSimplex2 ("fast"): simplex noise in 2D, two closest vertices per cubic lattice on the
/// body-centred cubic lattice in 3D, five lattice copies in 4D (module docs), reproducing the
/// `opensimplex2` crate's `fast` module.
///
/// * **Dimensions**: 2D–4D as the reference; 1D is the 2D noise along the line `y = 0`.
/// * **Seed**: any `i64`, as the reference's.
/// * **Range**: about `[−1, 1]` (the reference's normalisers; largest `|n|` found over
///   2·10⁵ random points: 1.000, 0.991, 0.947 in 2D–4D, `tests/tests/opensimplex.rs`).
///   [`Noise::amplitude_bound`] is proved and loose: every vertex that can contribute at its
///   kernel's peak `(8/9)⁴ r/3` along the longest gradient (2.76, 3.47, 4.75).
/// * **Reference**: `f64` is the reference's algorithm within 1.2·10⁻⁹ (its code with `f64`
///   for its internal `f32`, `tests/reference/`). The published crate rounds its offsets and
///   gradients to `f32`, which moves its values by up to 2.1·10⁻⁶ (2D; 99.2% of points within
///   10⁻⁶), 0.9·10⁻⁶ (3D, all within) and 1.5·10⁻⁶ (4D, 99.99% within); `f64` is never
///   farther from it than that rounding. `f32` follows `f64` within 1.5·10⁻⁶ and I16F16
///   within 6·10⁻⁴ (measured, `|x| < 200`).
/// * **Continuity**: 2D is continuous. 3D and 4D take a fixed number of vertices rather than
///   every one in reach, so they jump where the choice changes while a vertex left out is
///   still in reach: by up to 3.9·10⁻³ (3D) and 2.8·10⁻³ (4D), found by bisection along 3000
///   random segments. The reference jumps identically (same test); [`OpenSimplex2S`] in 2D
///   and 4D, and [`Simplex`](super::Simplex), are continuous.
/// * **Gradient** ([`NoiseGradient`](crate::NoiseGradient)): analytic, the kernels'
///   derivatives taken back through the turn by the chain rule; within 10⁻⁷ of central
///   differences in `f64`, I16F16 within 4·10⁻³ of `f64`'s (away from the jumps below).
/// * **Bad input**: a non-finite coordinate is 0; a turned coordinate whose cell lies outside
///   `i32` has its cell wrapped modulo 2³² (the reference saturates it).
///
/// [`Noise::amplitude_bound`]: crate::Noise::amplitude_bound
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct OpenSimplex2 {
    seed: i64,
    improve: Improve,
}

/// OpenSimplex2S ("smooth", formerly SuperSimplex): the same lattices as [`OpenSimplex2`] with
/// wider kernels (`r² = ⅔`, `¾`, `0.8` in 2D–4D) and more vertices, smoother and less
/// grid-aligned at about twice the cost; the reference recommends it for ridged noise.
/// Reproduces the `opensimplex2` crate's `smooth` module.
///
/// * **Dimensions**: 2D–4D as the reference; 1D is the 2D noise along the line `y = 0`.
/// * **Seed**: any `i64`, as the reference's.
/// * **Range**: about `[−1, 1]` (largest `|n|` found: 0.995, 0.988, 0.932 in 2D–4D).
///   [`Noise::amplitude_bound`] is proved as [`OpenSimplex2`]'s, counting the vertices that
///   can contribute (2.45, 5.42; in 4D every candidate, 70: loose).
/// * **Reference**: `f64` within 10⁻⁹ of the reference's algorithm; the published crate's
///   `f32` rounding moves it by up to 1.3·10⁻⁶ (2D, 99.99% of points within 10⁻⁶) and
///   0.6·10⁻⁶ (3D, 4D: all within). 4D evaluates every vertex in reach (the reference narrows
///   the candidates with a table; the values agree).
/// * **Continuity**: 2D and 4D are continuous; 3D takes the reference's choice of vertices,
///   which leaves some in reach out, and jumps by up to 2·10⁻³ as the reference does.
/// * **Gradient** and **bad input**: as [`OpenSimplex2`].
///
/// [`Noise::amplitude_bound`]: crate::Noise::amplitude_bound
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct OpenSimplex2S {
    seed: i64,
    improve: Improve,
}

macro_rules! open_simplex_common {
    ($t:ident) => {
        impl $t {
            /// The noise for `seed`, in the standard orientation.
            #[must_use]
            pub const fn new(seed: i64) -> Self {
                Self {
                    seed,
                    improve: Improve::Standard,
                }
            }

            /// The same noise with its lattice turned for `improve`.
            #[must_use]
            pub const fn improving(mut self, improve: Improve) -> Self {
                self.improve = improve;
                self
            }

            /// The seed.
            #[must_use]
            pub const fn seed(&self) -> i64 {
                self.seed
            }

            /// The orientation.
            #[must_use]
            pub const fn improve(&self) -> Improve {
                self.improve
            }
        }
    };
}

open_simplex_common!(OpenSimplex2);
open_simplex_common!(OpenSimplex2S);

/// The point `p` turned onto the lattice, in `f64` (module docs). Non-finite coordinates are
/// 0 first, so that one does not spread to the other axes.
#[inline]
fn turn<R: Real, const D: usize>(p: [R; D], improve: Improve, smooth: bool) -> [f64; D] {
    // On the out-of-order targets, finite coordinates (nearly always) skip the zeroing: a
    // branch the predictor follows, where masking each coordinate put three dependent
    // operations on every sample's chain (`bench/README.md`: 2D points −8%). Elsewhere, and
    // with the `small` feature (a second copy of the turn), and in the lane bodies, which
    // vectorise it, each coordinate is masked ([`turn_masked`]).
    if super::OUT_OF_ORDER && !cfg!(feature = "small") {
        let q = p.map(|x| x.to_f64());
        if q.iter().all(|x| x.is_finite()) {
            return turn_f64(q, improve, smooth);
        }
    }
    turn_masked(p, improve, smooth)
}

/// [`turn`] with every coordinate masked, no branch: for the lane bodies.
#[inline]
fn turn_masked<R: Real, const D: usize>(p: [R; D], improve: Improve, smooth: bool) -> [f64; D] {
    turn_f64(p.map(|x| x.to_f64().finite_or_zero()), improve, smooth)
}

/// The reference's transforms onto the lattice: linear maps (rotations, and the skew of the
/// 2D and 4D lattices).
#[inline]
fn turn_f64<const D: usize>(p: [f64; D], improve: Improve, smooth: bool) -> [f64; D] {
    let mut t = [0.0; D];
    match (D, improve) {
        (2, Improve::Standard | Improve::XY) => {
            let s = 0.366_025_403_784_439 * (p[0] + p[1]);
            t[0] = p[0] + s;
            t[1] = p[1] + s;
        }
        (2, Improve::XZ) => {
            let xx = p[0] * core::f64::consts::FRAC_1_SQRT_2;
            let yy =
                p[1] * (core::f64::consts::FRAC_1_SQRT_2 * (1.0 + 2.0 * 0.366_025_403_784_439));
            t[0] = yy + xx;
            t[1] = yy - xx;
        }
        (3, Improve::Standard) => {
            let r = 2.0 / 3.0 * (p[0] + p[1] + p[2]);
            for a in 0..3 {
                t[a] = r - p[a];
            }
        }
        (3, Improve::XY | Improve::XZ) => {
            let (u, v, h) = improve.axes();
            let uv = p[u] + p[v];
            let s2 = uv * -0.211_324_865_405_187_13;
            let hh = p[h] * 0.577_350_269_189_626;
            t[u] = p[u] + s2 + hh;
            t[v] = p[v] + s2 + hh;
            t[h] = uv * -0.577_350_269_189_626 + hh;
        }
        (4, Improve::Standard) => {
            // The reference keeps this skew in `f32` (0.309016994374947 and
            // -0.138196601125011 rounded to `f32`).
            let skew = if smooth {
                0.309_017_f32
            } else {
                -0.138_196_6_f32
            };
            let s = f64::from(skew) * (p[0] + p[1] + p[2] + p[3]);
            for a in 0..4 {
                t[a] = p[a] + s;
            }
        }
        (4, Improve::XY | Improve::XZ) => {
            let (u, v, h) = improve.axes();
            let uv = p[u] + p[v];
            let s2 = uv * -0.211_324_865_405_187;
            let hh = p[h] * 0.288_675_134_594_812_9;
            let ww = p[3]
                * if smooth {
                    1.118_033_988_749_894
                } else {
                    0.223_606_797_749_978_8
                };
            t[u] = p[u] + (hh + ww + s2);
            t[v] = p[v] + (hh + ww + s2);
            t[h] = uv * -0.577_350_269_189_626 + (hh + ww);
            t[3] = p[h] * -0.866_025_403_784_439 + ww;
        }
        _ => {}
    }
    t
}

/// `v` rounded to `R`. Out of line with the `small` feature (fixed point's conversion is
/// long, and a sample makes a dozen).
#[cfg_attr(feature = "small", inline(never))]
#[cfg_attr(not(feature = "small"), inline)]
fn real<R: Real>(v: f64) -> R {
    R::from_f64_nearest(v)
}

/// A turned coordinate's cell (its floor) and the offset within it, in `R`.
#[inline(always)]
fn floor_split<R: Real>(v: f64) -> (i32, R) {
    let (cell, frac) = Real::split(v);
    (cell, real::<R>(frac))
}

/// A turned coordinate's nearest integer (halves away from zero, as the reference's
/// `fastRound`) and the offset from it, in `[−½, ½]`, in `R`.
#[inline(always)]
fn round_split<R: Real>(v: f64) -> (i32, R) {
    let (cell, frac) = Real::split(round_input(v));
    round_output(v, cell, frac)
}

/// What [`round_split`] splits: `½ − v` (v < 0) or `v + ½`. Each choice here and in
/// [`round_output`] is a select rather than a branch (the sign of a turned coordinate is a
/// coin flip for the predictor), and the lane bodies split 16 of these at once.
#[inline(always)]
fn round_input(v: f64) -> f64 {
    if v < 0.0 { 0.5 - v } else { v + 0.5 }
}

/// [`round_split`]'s cell and offset from the split `(cell, frac)` of [`round_input`]`(v)`.
#[inline(always)]
fn round_output<R: Real>(v: f64, cell: i32, frac: f64) -> (i32, R) {
    let below = v < 0.0;
    let cell = if below { cell.wrapping_neg() } else { cell };
    (cell, real::<R>(if below { 0.5 - frac } else { frac - 0.5 }))
}

/// A sample's running sum over its vertices: `Σ τ⁴ (g·d)` with `τ = 1 − |d|²/r²` and, with
/// `GRADIENT`, its gradient with respect to the offset `d` (the vertices of a sample share the
/// space their offsets are measured in).
struct Sum<R, const D: usize, const GRADIENT: bool> {
    value: R,
    gradient: [R; D],
    /// `1/r²`.
    inverse_radius: R,
}

impl<R: Real, const D: usize, const GRADIENT: bool> Sum<R, D, GRADIENT> {
    #[inline(always)]
    fn new(kernel: &Kernel) -> Self {
        Self {
            value: R::ZERO,
            gradient: [R::ZERO; D],
            inverse_radius: real::<R>(kernel.inverse_radius),
        }
    }

    /// Adds the vertex of hash key `key` ([`key`]) at offset `d` if it is within reach (else
    /// computes no hash), and says whether it was. Out of line with the `small`
    /// feature: 3D OpenSimplex2S alone has 14 vertex sites.
    #[cfg_attr(feature = "small", inline(never))]
    #[cfg_attr(not(feature = "small"), inline)]
    fn add(&mut self, key: i64, d: [R; D]) -> bool {
        let tau = reach(d, self.inverse_radius);
        if tau <= R::ZERO {
            return false;
        }
        let (g, dot) = hash_dot(key, d);
        let tau2 = tau.mul_fraction(tau);
        let tau4 = tau2.mul_fraction(tau2);
        self.value = self.value + tau4.mul_fraction(dot);
        if GRADIENT {
            // ∂/∂d [τ⁴ (g·d)] = τ⁴ g − 8τ³ (g·d) d / r²; 8·τ³·|g·d|/r² < 500 in range.
            let radial = tau2
                .mul_fraction(tau)
                .mul_fraction(dot)
                .mul_fraction(self.inverse_radius);
            let radial = radial + radial;
            let radial = radial + radial;
            let radial = radial + radial;
            for a in 0..D {
                self.gradient[a] =
                    self.gradient[a] + tau4.mul_fraction(g[a]) - radial.mul_fraction(d[a]);
            }
        }
        true
    }

    /// [`add`](Self::add) where the caller needs no answer.
    #[inline(always)]
    fn vertex(&mut self, key: i64, d: [R; D]) {
        self.add(key, d);
    }
}

/// `τ = 1 − |d|²/r²` of a vertex at offset `d`: it is in reach where `τ > 0`.
#[inline(always)]
fn reach<R: Real, const D: usize>(d: [R; D], inverse_radius: R) -> R {
    // |dₐ| < 2: the squares, their sum and its product with 1/r² ≤ 2 fit every type.
    let mut q = R::ZERO;
    for x in d {
        q = q + x.mul_fraction(x);
    }
    R::ONE - q.mul_fraction(inverse_radius)
}

/// The hash key of the vertex `cell` for `seed`: `seed` xor each coordinate times its
/// axis's prime (the key's parts per axis can be computed apart and joined by xor).
#[inline(always)]
fn key<const D: usize>(seed: i64, cell: [i64; D]) -> i64 {
    let mut h = seed;
    for (a, &c) in cell.iter().enumerate() {
        h ^= share(a, c);
    }
    h
}

/// Axis `a`'s part of a vertex's hash [`key`].
#[inline(always)]
fn share(a: usize, c: i64) -> i64 {
    c.wrapping_mul(PRIME[a])
}

/// The gradient `g` of the vertex of hash key `key` and its dot product `g·d` with the
/// offset `d`.
#[inline(always)]
fn hash_dot<R: Real, const D: usize>(key: i64, d: [R; D]) -> ([R; D], R) {
    let g = gradient::<R, D>(key.wrapping_mul(HASH_MULTIPLIER));
    // [`dot_of`] from the first term, not from 0 (one addition fewer; the lane bodies keep
    // `dot_of`, whose form the compiler vectorises): `0 + t` is `t` but for a zero's sign,
    // which changes no sum it enters but a zero one, and a sample's value and gradient are
    // canonicalised.
    let mut dot = d[0].mul_fraction(g[0]);
    for a in 1..D {
        dot = dot + d[a].mul_fraction(g[a]);
    }
    (g, dot)
}

/// `g·d` in axis order. |g| ≤ 3.4 and |d| < 2: the dot product stays below 30.
#[inline(always)]
fn dot_of<R: Real, const D: usize>(g: [R; D], d: [R; D]) -> R {
    let mut dot = R::ZERO;
    for a in 0..D {
        dot = dot + d[a].mul_fraction(g[a]);
    }
    dot
}

/// A vertex's term `τ⁴ (g·d)` as [`Sum::add`] adds it, and an exact 0 out of reach (where
/// `add` adds nothing: a sum starts at +0 and so is never −0, and adding ±0 to it changes
/// nothing). For the lane bodies, which compute every vertex of every lane.
#[inline(always)]
fn term<R: Real, const D: usize>(key: i64, d: [R; D], inverse_radius: R) -> R {
    term_of(
        gradient(key.wrapping_mul(HASH_MULTIPLIER)),
        d,
        inverse_radius,
    )
}

/// [`term`] of the vertex whose gradient is `g`.
#[inline(always)]
fn term_of<R: Real, const D: usize>(g: [R; D], d: [R; D], inverse_radius: R) -> R {
    term_at(g, d, reach(d, inverse_radius))
}

/// [`term_of`] where `tau` is the vertex's [`reach`].
#[inline(always)]
fn term_at<R: Real, const D: usize>(g: [R; D], d: [R; D], tau: R) -> R {
    let tau = if tau > R::ZERO { tau } else { R::ZERO };
    let dot = dot_of(g, d);
    let tau2 = tau.mul_fraction(tau);
    tau2.mul_fraction(tau2).mul_fraction(dot)
}

/// The gradient for the mixed hash `h`: its top bits folded onto its low bits index the
/// reference's table of the dimension's set cycled to 128 (2D), 256 (3D) or 512 (4D) entries.
#[inline(always)]
fn gradient<R: Real, const D: usize>(h: i64) -> [R; D] {
    // `f32` reads the tables already converted (without the `small` feature, which counts
    // their 6.5 KiB): a conversion and a product fewer per vertex, the same numbers.
    let converted = R::BINARY32 && !cfg!(feature = "small");
    match D {
        2 => {
            let i = ((h ^ (h >> 58)) >> 1) as usize & 127;
            if converted {
                return f32_row(&CYCLED2_F32[i]);
            }
            q29_row(if cfg!(feature = "small") {
                &GRAD2[i % 24]
            } else {
                &CYCLED2[i]
            })
        }
        3 => {
            if converted {
                return f32_row(&CYCLED3_F32[index_3d(h) as usize]);
            }
            q29_row(&row_3d(h))
        }
        _ => {
            let i = (((h ^ (h >> 57)) >> 2) as usize & 511) % 160;
            if converted {
                return f32_row(&GRAD4_F32[i]);
            }
            q29_row(&GRAD4[i])
        }
    }
}

/// The first `D` numbers of a row of `f32`, as `R`.
#[inline(always)]
fn f32_row<R: Real, const D: usize>(row: &[f32]) -> [R; D] {
    let mut g = [R::ZERO; D];
    for a in 0..D {
        g[a] = R::from_f32(row[a]);
    }
    g
}

/// The first `D` numbers of a row in units of 2⁻²⁹, as `R`.
#[inline(always)]
fn q29_row<R: Real, const D: usize>(row: &[i32]) -> [R; D] {
    let mut g = [R::ZERO; D];
    for a in 0..D {
        g[a] = R::from_ratio(row[a], 29);
    }
    g
}

/// [`gradient`]'s 3D row for the mixed hash `h`, in units of 2⁻²⁹ (the lane bodies convert
/// the rows of 16 lanes together).
#[inline(always)]
fn row_3d(h: i64) -> [i32; 3] {
    let i = index_3d(h);
    if cfg!(feature = "small") {
        GRAD3[(i % 48) as usize]
    } else {
        CYCLED3[i as usize]
    }
}

/// The index of [`CYCLED3`]'s row for the mixed hash `h`.
#[inline(always)]
fn index_3d(h: i64) -> u32 {
    ((h ^ (h >> 58)) >> 2) as u32 & 255
}

/// The offset from the 2D skewed lattice vertex `cell + step` of a point whose unskewed offset
/// from `cell` is `d0`: `d0 − (step + U·Σstep)`.
#[inline(always)]
fn unskewed<R: Real, const D: usize>(d0: [R; D], step: [i32; D], unskew: R) -> [R; D] {
    let along: i32 = step.iter().sum();
    // |Σstep| ≤ 8 and |U| < ⅓: the product fits 64 bits, and Q30 keeps it below 2³¹.
    let diagonal = unskew.mul_fraction(R::from_i32(along));
    let mut d = d0;
    for a in 0..D {
        d[a] = d0[a] - R::from_i32(step[a]) - diagonal;
    }
    d
}

/// The cell of the vertex `cell + step`, for hashing.
#[inline(always)]
fn plus<const D: usize>(cell: [i32; D], step: [i32; D]) -> [i64; D] {
    let mut v = [0i64; D];
    for a in 0..D {
        v[a] = i64::from(cell[a]) + i64::from(step[a]);
    }
    v
}

/// The 2D noise at the skewed point `t`: the corners `(0, 0)` and `(1, 1)` of its skewed cell
/// and, fast, the third corner of its triangle; smooth, the two vertices beyond the two edges
/// nearest the point (the reference's choices, which hold every vertex in reach).
#[inline(always)]
fn body_2d<R: Real, const G: bool>(seed: i64, t: [f64; 2], smooth: bool, sum: &mut Sum<R, 2, G>) {
    let (cx, fx) = floor_split::<R>(t[0]);
    let (cy, fy) = floor_split::<R>(t[1]);
    let cell = [cx, cy];
    let unskew = real::<R>(UNSKEW_2D);
    let d0 = unskewed_base(fx, fy, unskew);
    let mut corner =
        |step: [i32; 2]| sum.vertex(key(seed, plus(cell, step)), unskewed(d0, step, unskew));
    corner([0, 0]);
    corner([1, 1]);
    if !smooth {
        corner(third_2d(fx, fy));
    } else {
        let [third, fourth] = beyond_2d(fx, fy);
        corner(third);
        corner(fourth);
    }
}

/// 2D OpenSimplex2S's third and fourth vertices, after `(0, 0)` and `(1, 1)`: the reference's
/// nested choices on the skewed fractions, the vertex beyond each of the two edges of the
/// point's triangle nearest it.
#[inline(always)]
fn beyond_2d<R: Real>(fx: R, fy: R) -> [[i32; 2]; 2] {
    let xmy = fx - fy;
    if fx + fy > R::ONE {
        [
            if fx + xmy > R::ONE { [2, 1] } else { [0, 1] },
            if fy - xmy > R::ONE { [1, 2] } else { [1, 0] },
        ]
    } else {
        [
            if fx + xmy < R::ZERO { [-1, 0] } else { [1, 0] },
            if fy < xmy { [0, -1] } else { [0, 1] },
        ]
    }
}

/// The unskewed offset from the skewed cell's base vertex of a point with skewed fractions
/// `fx`, `fy`; `Σf < 2` and `|U| < ¼`.
#[inline(always)]
fn unskewed_base<R: Real>(fx: R, fy: R, unskew: R) -> [R; 2] {
    let shift = unskew.mul_fraction(fx + fy);
    [fx + shift, fy + shift]
}

/// 2D OpenSimplex2's third corner, after `(0, 0)` and `(1, 1)`: the one of the point's
/// triangle, `(0, 1)` if `fy > fx`, else `(1, 0)`.
#[inline(always)]
fn third_2d<R: Real>(fx: R, fy: R) -> [i32; 2] {
    let up = i32::from(fy > fx);
    [1 - up, up]
}

/// The 2D noise at [`LANES`] points (OpenSimplex2, or OpenSimplex2S if `smooth`), bit for
/// bit [`evaluate`] at each: the same operations on each lane in the same order, each step a
/// loop over the lanes so that the compiler vectorises what it can. Every vertex of every lane
/// is computed, out of reach as an exact 0 ([`term`]).
#[inline]
fn lanes_2d<R: Real, const S: bool>(
    seed: i64,
    improve: Improve,
    p: &[[R; LANES]; 2],
    out: &mut [R; LANES],
) {
    let smooth = S;
    let kernel = if smooth { &SMOOTH[2] } else { &FAST[2] };
    let mut t = [[0.0f64; LANES]; 2];
    for l in 0..LANES {
        let turned = turn_masked([p[0][l], p[1][l]], improve, smooth);
        t[0][l] = turned[0];
        t[1][l] = turned[1];
    }
    let mut cell = [[0i32; LANES]; 2];
    let mut frac = [[0.0f64; LANES]; 2];
    for a in 0..2 {
        f64::split_lanes(&t[a], &mut cell[a], &mut frac[a]);
    }
    let inverse_radius = real::<R>(kernel.inverse_radius);
    let unskew = real::<R>(UNSKEW_2D);
    // By axis, lane innermost (as the lanes' other numbers; an array per lane took 3% more
    // instructions). The vertices after (0, 0) and (1, 1): fast, the third (the fourth
    // unused); smooth, the third and the fourth.
    let mut d0 = [[R::ZERO; LANES]; 2];
    let mut steps = [[[0i32; LANES]; 2]; 2];
    for l in 0..LANES {
        let (fx, fy) = (real::<R>(frac[0][l]), real::<R>(frac[1][l]));
        [d0[0][l], d0[1][l]] = unskewed_base(fx, fy, unskew);
        let chosen = if smooth {
            beyond_2d(fx, fy)
        } else {
            [third_2d(fx, fy), [0, 0]]
        };
        for (v, step) in chosen.into_iter().enumerate() {
            [steps[v][0][l], steps[v][1][l]] = step;
        }
    }
    let mut value = [R::ZERO; LANES];
    for corner in 0..3 + usize::from(smooth) {
        for l in 0..LANES {
            let step = match corner {
                0 => [0, 0],
                1 => [1, 1],
                v => [steps[v - 2][0][l], steps[v - 2][1][l]],
            };
            let cell = plus([cell[0][l], cell[1][l]], step);
            let d = unskewed([d0[0][l], d0[1][l]], step, unskew);
            value[l] = value[l] + term(key(seed, cell), d, inverse_radius);
        }
    }
    finish_lanes(&value, kernel, out);
}

/// [`turn`] of [`LANES`] 3D points, by axis.
#[inline(always)]
#[allow(
    clippy::needless_range_loop,
    reason = "the turned points are stored by axis with the lanes innermost"
)]
fn turn_3d_lanes<R: Real>(
    p: &[[R; LANES]; 3],
    improve: Improve,
    smooth: bool,
) -> [[f64; LANES]; 3] {
    let mut t = [[0.0f64; LANES]; 3];
    for l in 0..LANES {
        let turned = turn_masked([p[0][l], p[1][l], p[2][l]], improve, smooth);
        for a in 0..3 {
            t[a][l] = turned[a];
        }
    }
    t
}

/// OpenSimplex2's 3D noise at [`LANES`] points, bit for bit [`evaluate`] at each
/// ([`fast_3d`]'s vertices in its order, each lane's through [`term_of`]). Each step is a
/// loop over the lanes with the lanes innermost and selects for `fast_3d`'s branches, so
/// that the compiler vectorises the splits, the offsets, the choice of the second vertex and
/// the terms; only the 64-bit hashes (the key's parts per axis, [`share`], and the gradient's
/// row) are scalar.
#[inline]
#[allow(
    clippy::needless_range_loop,
    reason = "each step loops over the lanes innermost, indexing the axis arrays, so that it vectorises"
)]
fn fast_3d_lanes<R: Real>(seed: i64, improve: Improve, p: &[[R; LANES]; 3], out: &mut [R; LANES]) {
    let kernel = &FAST[3];
    let inverse_radius = real::<R>(kernel.inverse_radius);
    let half = R::from_ratio(1, 1);
    let t = turn_3d_lanes(p, improve, false);
    // `nearest_3d`: per axis the nearest vertex's key part, the offset from it, and the side
    // of it the point lies on as `side` = ±1 (+1: toward `cell + 1`); `round_split` of 16
    // coordinates.
    let mut part = [[0i64; LANES]; 3];
    let mut d = [[R::ZERO; LANES]; 3];
    let mut side = [[R::ZERO; LANES]; 3];
    for a in 0..3 {
        let w = t[a].map(round_input);
        let mut cell = [0i32; LANES];
        let mut frac = [0.0f64; LANES];
        f64::split_lanes(&w, &mut cell, &mut frac);
        for l in 0..LANES {
            let (c, x) = round_output::<R>(t[a][l], cell[l], frac[l]);
            part[a][l] = share(a, i64::from(c));
            d[a][l] = x;
            side[a][l] = if x >= R::ZERO { R::ONE } else { -R::ONE };
        }
    }
    let mut value = [R::ZERO; LANES];
    for lattice in 0..2 {
        let seed = if lattice == 0 {
            seed
        } else {
            seed ^ SEED_FLIP_3D
        };
        // `pair_3d`'s second vertex: one step toward the point (`x − side`, which is `x − 1`
        // or `x + 1` exactly) along the first axis of the largest offset.
        let mut axis = [0i32; LANES];
        let mut e = d;
        for l in 0..LANES {
            let [ax, ay, az] = [d[0][l].abs(), d[1][l].abs(), d[2][l].abs()];
            let y = ay > ax;
            let z = az > if y { ay } else { ax };
            axis[l] = if z { 2 } else { i32::from(y) };
            let chosen = [!y && !z, y && !z, z];
            for a in 0..3 {
                let x = d[a][l];
                e[a][l] = if chosen[a] { x - side[a][l] } else { x };
            }
        }
        // The two vertices' gradients ((c ± 1)·P = c·P ± P, wrapping: the second vertex's
        // key from the nearest's), and `other_lattice_3d`'s key parts.
        let mut rows = [[[0i32; LANES]; 3]; 2];
        for l in 0..LANES {
            let near = seed ^ part[0][l] ^ part[1][l] ^ part[2][l];
            let a = axis[l] as usize % 3;
            let up = side[a][l] > R::ZERO;
            let step = if up {
                PRIME[a]
            } else {
                PRIME[a].wrapping_neg()
            };
            let next = near ^ part[a][l] ^ part[a][l].wrapping_add(step);
            for (v, key) in [near, next].into_iter().enumerate() {
                let row = row_3d(key.wrapping_mul(HASH_MULTIPLIER));
                for b in 0..3 {
                    rows[v][b][l] = row[b];
                }
            }
            if lattice == 0 {
                for b in 0..3 {
                    if side[b][l] > R::ZERO {
                        part[b][l] = part[b][l].wrapping_add(PRIME[b]);
                    }
                }
            }
        }
        for (v, offset) in [&d, &e].into_iter().enumerate() {
            for l in 0..LANES {
                let gl = [0, 1, 2].map(|b| R::from_ratio(rows[v][b][l], 29));
                let dl = [offset[0][l], offset[1][l], offset[2][l]];
                value[l] = value[l] + term_of(gl, dl, inverse_radius);
            }
        }
        if lattice == 0 {
            // `other_lattice_3d`'s offsets and sides: `x ∓ ½` toward the other lattice's
            // nearest vertex, whose side is the other one.
            for a in 0..3 {
                for l in 0..LANES {
                    let up = side[a][l] > R::ZERO;
                    d[a][l] = d[a][l] - if up { half } else { -half };
                    side[a][l] = -side[a][l];
                }
            }
        }
    }
    finish_lanes(&value, kernel, out);
}

/// OpenSimplex2S's 3D noise at [`LANES`] points, bit for bit [`evaluate`] at each
/// ([`smooth_3d`]'s choices in its order): [`Choices::around`] by axis with the lanes
/// innermost, then each of the 14 candidate vertices of every lane (hashed in a scalar loop,
/// its term over the lanes), added where `smooth_3d` adds it (a select, not a branch: its
/// choices follow whether earlier vertices are in reach, a coin flip per point).
#[inline]
#[allow(
    clippy::needless_range_loop,
    reason = "each step loops over the lanes innermost, indexing the axis arrays, so that it vectorises"
)]
fn smooth_3d_lanes<R: Real>(
    seed: i64,
    improve: Improve,
    p: &[[R; LANES]; 3],
    out: &mut [R; LANES],
) {
    let kernel = &SMOOTH[3];
    let inverse_radius = real::<R>(kernel.inverse_radius);
    let half = R::from_ratio(1, 1);
    let t = turn_3d_lanes(p, improve, true);
    // `Choices::around`: per set (corners, centres), axis and choice, each lane's key part
    // and offset.
    let mut keys = [[[[0i64; LANES]; 2]; 3]; 2];
    let mut offsets = [[[[R::ZERO; LANES]; 2]; 3]; 2];
    for a in 0..3 {
        let mut cell = [0i32; LANES];
        let mut frac = [0.0f64; LANES];
        f64::split_lanes(&t[a], &mut cell, &mut frac);
        for l in 0..LANES {
            // `Choices::around`'s, with selects for its branch (written apart: through one
            // function for both, the point sample took 3–4% more time).
            let f = real::<R>(frac[l]);
            // (c + s)·P = c·P + s·P, wrapping.
            let p0 = share(a, i64::from(cell[l]));
            let p1 = p0.wrapping_add(PRIME[a]);
            let p2 = p1.wrapping_add(PRIME[a]);
            let centred = f - half;
            let upper = f >= half;
            keys[0][a][0][l] = if upper { p1 } else { p0 };
            keys[0][a][1][l] = if upper { p0 } else { p1 };
            offsets[0][a][0][l] = if upper { f - R::ONE } else { f };
            offsets[0][a][1][l] = if upper { f } else { f - R::ONE };
            keys[1][a][0][l] = p1;
            keys[1][a][1][l] = if upper { p2 } else { p0 };
            offsets[1][a][0][l] = centred;
            offsets[1][a][1][l] = if upper {
                centred - R::ONE
            } else {
                centred + R::ONE
            };
        }
    }
    let seeds = [seed, seed ^ SEED_FLIP_3D];
    // A candidate's term in every lane (an exact 0 out of reach) and whether it is in reach.
    let candidate = |set: usize, pick: [usize; 3]| {
        let mut rows = [[0i32; LANES]; 3];
        for l in 0..LANES {
            let k = &keys[set];
            let key = seeds[set] ^ k[0][pick[0]][l] ^ k[1][pick[1]][l] ^ k[2][pick[2]][l];
            let row = row_3d(key.wrapping_mul(HASH_MULTIPLIER));
            for b in 0..3 {
                rows[b][l] = row[b];
            }
        }
        let mut terms = [R::ZERO; LANES];
        let mut inside = [false; LANES];
        for l in 0..LANES {
            let o = &offsets[set];
            let d = [o[0][pick[0]][l], o[1][pick[1]][l], o[2][pick[2]][l]];
            let g = [0, 1, 2].map(|b| R::from_ratio(rows[b][l], 29));
            let tau = reach(d, inverse_radius);
            inside[l] = tau > R::ZERO;
            terms[l] = term_at(g, d, tau);
        }
        (terms, inside)
    };
    // Adds `terms` where `taken` (+0 elsewhere: a sum that starts at +0 never becomes −0).
    let add = |value: &mut [R; LANES], terms: &[R; LANES], taken: &[bool; LANES]| {
        for l in 0..LANES {
            value[l] = value[l] + if taken[l] { terms[l] } else { R::ZERO };
        }
    };
    let every = [true; LANES];
    let mut value = [R::ZERO; LANES];
    add(&mut value, &candidate(0, NONE).0, &every);
    add(&mut value, &candidate(1, NONE).0, &every);
    let mut moved_alone = [[false; LANES]; 3];
    for a in 0..3 {
        let (terms, flipped) = candidate(0, ALONG[a]);
        add(&mut value, &terms, &every);
        let not_flipped = flipped.map(|f| !f);
        add(&mut value, &candidate(0, OTHERS[a]).0, &not_flipped);
        let (terms, inside) = candidate(1, ALONG[a]);
        add(&mut value, &terms, &not_flipped);
        for l in 0..LANES {
            moved_alone[a][l] = not_flipped[l] && inside[l];
        }
    }
    for a in 0..3 {
        let not_moved = moved_alone[a].map(|m| !m);
        add(&mut value, &candidate(1, OTHERS[a]).0, &not_moved);
    }
    finish_lanes(&value, kernel, out);
}

/// [`evaluate`]'s scaling of the sums, lane by lane.
#[inline(always)]
fn finish_lanes<R: Real>(value: &[R; LANES], kernel: &Kernel, out: &mut [R; LANES]) {
    let scale = real::<R>(kernel.scale);
    for l in 0..LANES {
        out[l] = value[l].mul_rn(scale).canonical();
    }
}

/// The first index of the largest of `v` (the reference's tie order).
#[inline(always)]
fn largest<R: Real, const D: usize>(v: [R; D]) -> usize {
    let mut best = 0;
    for a in 1..D {
        if v[a] > v[best] {
            best = a;
        }
    }
    best
}

/// 3D OpenSimplex2 at the turned point `t`: on each cubic lattice, the nearest vertex and the
/// next one along the axis of the largest offset.
#[inline(always)]
fn fast_3d<R: Real, const G: bool>(seed: i64, t: [f64; 3], sum: &mut Sum<R, 3, G>) {
    let (mut cell, mut d, mut up) = nearest_3d::<R>(t);
    let mut seed = seed;
    for lattice in 0..2 {
        for (c, e) in pair_3d(cell, d, &up) {
            sum.vertex(key(seed, c), e);
        }
        if lattice == 1 {
            break;
        }
        other_lattice_3d(&mut cell, &mut d, &mut up);
        seed ^= SEED_FLIP_3D;
    }
}

/// The nearest vertex of the first cubic lattice to the turned point `t`, the offset from it,
/// and per axis the side of the vertex the point lies on (`true`: toward `cell + 1`).
#[inline(always)]
fn nearest_3d<R: Real>(t: [f64; 3]) -> ([i64; 3], [R; 3], [bool; 3]) {
    let mut cell = [0i64; 3];
    let mut d = [R::ZERO; 3];
    let mut up = [true; 3];
    for a in 0..3 {
        let (c, f) = round_split::<R>(t[a]);
        cell[a] = i64::from(c);
        d[a] = f;
        up[a] = f >= R::ZERO;
    }
    (cell, d, up)
}

/// [`fast_3d`]'s two vertices of one cubic lattice, with the offsets from them: the nearest
/// (`cell`, `d`) and the next one toward the point along the axis of the largest offset.
#[inline(always)]
fn pair_3d<R: Real>(cell: [i64; 3], d: [R; 3], up: &[bool; 3]) -> [([i64; 3], [R; 3]); 2] {
    let axis = largest(d.map(Real::abs));
    let (mut next, mut e) = (cell, d);
    // One step toward the point along `axis`: `x − 1`, or `x − (−1) = x + 1`. Each axis
    // takes or keeps its step by selects: indexed by `axis`, the compiler branched three
    // ways on it, a coin flip for the predictor.
    for a in 0..3 {
        let chosen = a == axis;
        let up = up[a];
        next[a] += if chosen { if up { 1 } else { -1 } } else { 0 };
        let x = e[a];
        e[a] = if chosen {
            x - if up { R::ONE } else { -R::ONE }
        } else {
            x
        };
    }
    [(cell, d), (next, e)]
}

/// Moves [`nearest_3d`]'s vertex, offset and sides to the other cubic lattice, offset by
/// (½, ½, ½): its vertex at position c − ½ is hashed as c, and its nearest vertex lies
/// toward the point on every axis.
#[inline(always)]
fn other_lattice_3d<R: Real>(cell: &mut [i64; 3], d: &mut [R; 3], up: &mut [bool; 3]) {
    let half = R::from_ratio(1, 1);
    for a in 0..3 {
        if up[a] {
            cell[a] += 1;
            d[a] = d[a] - half;
        } else {
            d[a] = d[a] + half;
        }
        up[a] = !up[a];
    }
}

/// 3D OpenSimplex2S at the turned point `t`: the nearest corner `v₀` of the point's cube in
/// the first cubic lattice and the vertex `v₁` at the cube's centre in the second, then the
/// reference's choices among their neighbours toward the point: per axis, `v₀` flipped along
/// it if in reach, else `v₀` flipped along the other two and `v₁` moved along it; then `v₁`
/// moved along each pair of axes whose single move was not taken.
///
/// These choices are the reference's, not every vertex in reach: where `v₀` flipped along an
/// axis is barely in reach, `v₁` moved along that axis can be in reach too and is left out, so
/// the reference (and this) has small jumps (`tests/tests/opensimplex.rs` measures them).
#[inline(always)]
fn smooth_3d<R: Real, const G: bool>(seed: i64, t: [f64; 3], sum: &mut Sum<R, 3, G>) {
    let [corners, centres] = Choices::around(seed, t);
    let (key, d) = corners.vertex(NONE);
    sum.vertex(key, d);
    let (key, d) = centres.vertex(NONE);
    sum.vertex(key, d);
    // Per axis: whether `v₁` moved along it alone was taken.
    let mut moved_alone = [false; 3];
    for (a, moved) in moved_alone.iter_mut().enumerate() {
        let (key, d) = corners.vertex(ALONG[a]);
        if !sum.add(key, d) {
            let (key, d) = corners.vertex(OTHERS[a]);
            sum.vertex(key, d);
            let (key, d) = centres.vertex(ALONG[a]);
            // The reference then skips `v₁` moved along the other two axes.
            *moved = sum.add(key, d);
        }
    }
    for (a, moved) in moved_alone.into_iter().enumerate() {
        if !moved {
            let (key, d) = centres.vertex(OTHERS[a]);
            sum.vertex(key, d);
        }
    }
}

/// No axis, each axis alone, and each pair of axes (the other two than an axis's), as the
/// index (0 or 1) of the per-axis choice of [`Choices`].
const NONE: [usize; 3] = [0; 3];
const ALONG: [[usize; 3]; 3] = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
const OTHERS: [[usize; 3]; 3] = [[0, 1, 1], [1, 0, 1], [1, 1, 0]];

/// Two vertices per axis to choose from, as a hash key's part ([`share`]) and an offset from
/// the point, so that a vertex is three choices joined; [`smooth_3d`] has two sets.
#[derive(Clone, Copy)]
struct Choices<R> {
    /// The lattice's seed.
    seed: i64,
    /// Per axis: the key parts of the first and second choice.
    keys: [[i64; 2]; 3],
    /// Per axis: their offsets.
    offsets: [[R; 2]; 3],
}

impl<R: Real> Choices<R> {
    /// The choices around the turned point `t`, each axis's computed once: in the first cubic
    /// lattice `v₀` (the point's cube's corner nearest it) and that corner flipped to the
    /// cube's other side; in the second, `v₁` (the vertex at the cube's centre, hashed as
    /// cell + 1) and `v₁` moved toward the point.
    #[inline(always)]
    fn around(seed: i64, t: [f64; 3]) -> [Self; 2] {
        let half = R::from_ratio(1, 1);
        let mut choices = [seed, seed ^ SEED_FLIP_3D].map(|seed| Self {
            seed,
            keys: [[0; 2]; 3],
            offsets: [[R::ZERO; 2]; 3],
        });
        for (a, &t) in t.iter().enumerate() {
            let (cell, f) = floor_split::<R>(t);
            let part = |step: i64| share(a, i64::from(cell) + step);
            // In the upper half of its cube, `v₀` is the upper corner and `v₁`'s neighbour
            // toward the point the upper one.
            let centred = f - half;
            let [corners, centres] = &mut choices;
            if f >= half {
                (corners.keys[a], corners.offsets[a]) = ([part(1), part(0)], [f - R::ONE, f]);
                (centres.keys[a], centres.offsets[a]) =
                    ([part(1), part(2)], [centred, centred - R::ONE]);
            } else {
                (corners.keys[a], corners.offsets[a]) = ([part(0), part(1)], [f, f - R::ONE]);
                (centres.keys[a], centres.offsets[a]) =
                    ([part(1), part(0)], [centred, centred + R::ONE]);
            }
        }
        choices
    }

    /// The hash key of the vertex of choice `pick[a]` along each axis `a`, and its offset.
    #[inline(always)]
    fn vertex(&self, pick: [usize; 3]) -> (i64, [R; 3]) {
        let k = &self.keys;
        (
            self.seed ^ k[0][pick[0]] ^ k[1][pick[1]] ^ k[2][pick[2]],
            core::array::from_fn(|a| self.offsets[a][pick[a]]),
        )
    }
}

/// 4D OpenSimplex2 at the skewed point `t`: one vertex from each of five copies of the lattice
/// offset by `0.2` along the main diagonal, starting with the copy whose base simplex surely
/// holds a contributing vertex (the reference's walk).
#[inline(always)]
fn fast_4d<R: Real, const G: bool>(seed: i64, t: [f64; 4], sum: &mut Sum<R, 4, G>) {
    let step = real::<R>(LATTICE_STEP_4D);
    let unskew = real::<R>(UNSKEW_4D_FAST);
    let mut cell = [0i64; 4];
    let mut f = [R::ZERO; 4];
    let mut total = R::ZERO;
    for a in 0..4 {
        let (c, x) = floor_split::<R>(t[a]);
        cell[a] = i64::from(c);
        f[a] = x;
        total = total + x;
    }
    // ⌊1.25 · Σf⌋: the first copy, 0 to 4.
    let mut start = 0;
    for k in 1..=4 {
        if total >= real::<R>(0.8 * f64::from(k)) {
            start = k;
        }
    }
    let mut seed = seed.wrapping_add(i64::from(start).wrapping_mul(SEED_OFFSET_4D));
    let back = real::<R>(LATTICE_STEP_4D * f64::from(start));
    for x in &mut f {
        *x = *x - back;
    }
    for copy in 0..5 {
        // The vertex of this copy's simplex nearest the point: the base vertex, or one step
        // along the axis of the largest offset if that is nearer.
        let total = f[0] + f[1] + f[2] + f[3];
        let axis = largest(f);
        if f[axis] >= R::ONE - total {
            cell[axis] += 1;
            f[axis] = f[axis] - R::ONE;
        }
        let s = (f[0] + f[1] + f[2] + f[3]).mul_fraction(unskew);
        let d = f.map(|x| x + s);
        sum.vertex(key(seed, cell), d);
        if copy == 4 {
            break;
        }
        for x in &mut f {
            *x = *x + step;
        }
        seed = seed.wrapping_sub(SEED_OFFSET_4D);
        if copy == start {
            for c in &mut cell {
                *c -= 1;
            }
            seed = seed.wrapping_add(SEED_OFFSET_4D.wrapping_mul(5));
        }
    }
}

/// `c = 2U + 4U²` for 4D OpenSimplex2S's unskew `U`: a vertex at skewed offset `e` from the
/// point lies at `|d|² = |e|² + c·(Σe)²` (`c = −0.2`).
const SMOOTH_4D_METRIC: f64 = {
    let u = -0.138_196_601_125_011;
    2.0 * u + 4.0 * u * u
};

/// The smallest `|d|²` from the vertex at skewed cell offset `v` to a point of the skewed
/// cell `[0, 1]⁴`: a convex quadratic over a box, so its minimum is the stationary point of one
/// face (each coordinate at 0, at 1 or free; free ones all equal `−c·Σe`) that lies in the box.
const fn nearest(v: [i32; 4]) -> f64 {
    let c = SMOOTH_4D_METRIC;
    let mut best = f64::MAX;
    let mut pattern = 0;
    while pattern < 81 {
        let mut digits = pattern;
        let mut e = [0.0; 4];
        let mut free = [false; 4];
        let mut fixed = 0.0;
        let mut k = 0;
        let mut a = 0;
        while a < 4 {
            match digits % 3 {
                0 => e[a] = -(v[a] as f64),
                1 => e[a] = 1.0 - v[a] as f64,
                _ => {
                    free[a] = true;
                    k += 1;
                }
            }
            if !free[a] {
                fixed += e[a];
            }
            digits /= 3;
            a += 1;
        }
        let s = fixed / (1.0 + c * k as f64);
        let mut inside = true;
        let mut g = c * s * s;
        a = 0;
        while a < 4 {
            if free[a] {
                e[a] = -c * s;
                let f = e[a] + v[a] as f64;
                if f < 0.0 || f > 1.0 {
                    inside = false;
                }
            }
            g += e[a] * e[a];
            a += 1;
        }
        if inside && g < best {
            best = g;
        }
        pattern += 1;
    }
    best
}

/// The skewed offset in `{−1, 0, 1, 2}⁴` with base-4 code `code` (`0..256`), if some point of
/// a cell has it within reach of 4D OpenSimplex2S's kernel (`r² = 0.8`).
const fn candidate(code: i32) -> Option<[i32; 4]> {
    let v = [
        code % 4 - 1,
        code / 4 % 4 - 1,
        code / 16 % 4 - 1,
        code / 64 - 1,
    ];
    if nearest(v) < 0.8 { Some(v) } else { None }
}

/// Every [`candidate`], in the order of their codes.
const SMOOTH_4D: [[i8; 4]; smooth_4d_count()] = {
    let mut out = [[0i8; 4]; smooth_4d_count()];
    let mut n = 0;
    let mut code = 0;
    while code < 256 {
        if let Some(v) = candidate(code) {
            out[n] = [v[0] as i8, v[1] as i8, v[2] as i8, v[3] as i8];
            n += 1;
        }
        code += 1;
    }
    out
};

/// How many vertices [`SMOOTH_4D`] holds.
const fn smooth_4d_count() -> usize {
    let mut n = 0;
    let mut code = 0;
    while code < 256 {
        if candidate(code).is_some() {
            n += 1;
        }
        code += 1;
    }
    n
}

/// 4D OpenSimplex2S at the skewed point `t`: every vertex of [`SMOOTH_4D`], each counted where
/// it is within reach (the reference narrows the candidates with a table over 4⁴ sub-cells).
#[inline(always)]
fn smooth_4d<R: Real, const G: bool>(seed: i64, t: [f64; 4], sum: &mut Sum<R, 4, G>) {
    let unskew = real::<R>(UNSKEW_4D_SMOOTH);
    let mut cell = [0i32; 4];
    let mut f = [R::ZERO; 4];
    for a in 0..4 {
        (cell[a], f[a]) = floor_split::<R>(t[a]);
    }
    let s = (f[0] + f[1] + f[2] + f[3]).mul_fraction(unskew);
    let d0 = f.map(|x| x + s);
    for v in &SMOOTH_4D {
        let step = v.map(i32::from);
        sum.vertex(key(seed, plus(cell, step)), unskewed(d0, step, unskew));
    }
}

/// The lattice body of each dimension.
struct Dim;

trait Body<const D: usize> {
    /// Adds the vertices around the turned point `t` to `sum`.
    fn body<R: Real, const G: bool>(seed: i64, t: [f64; D], smooth: bool, sum: &mut Sum<R, D, G>);
}

impl Body<2> for Dim {
    #[inline(always)]
    fn body<R: Real, const G: bool>(seed: i64, t: [f64; 2], smooth: bool, sum: &mut Sum<R, 2, G>) {
        body_2d(seed, t, smooth, sum);
    }
}

impl Body<3> for Dim {
    #[inline(always)]
    fn body<R: Real, const G: bool>(seed: i64, t: [f64; 3], smooth: bool, sum: &mut Sum<R, 3, G>) {
        if smooth {
            smooth_3d(seed, t, sum);
        } else {
            fast_3d(seed, t, sum);
        }
    }
}

impl Body<4> for Dim {
    #[inline(always)]
    fn body<R: Real, const G: bool>(seed: i64, t: [f64; 4], smooth: bool, sum: &mut Sum<R, 4, G>) {
        if smooth {
            smooth_4d(seed, t, sum);
        } else {
            fast_4d(seed, t, sum);
        }
    }
}

/// The noise at `p` and, with `G`, its gradient: the vertices' sum scaled by `r⁸/normaliser`,
/// and the gradient taken from the offsets' space back to the input's by the chain rule
/// (`∇ₚ = Jᵀ ∇_d` for the linear map `J` from the input to the unskewed offsets: the turn,
/// then in 2D and 4D the lattice's unskew).
// Out of line with the `small` feature: each entry point of each number type would otherwise
// hold its own copy of the lattice body (16 KB of the demo's wasm module).
#[cfg_attr(feature = "small", inline(never))]
#[cfg_attr(not(feature = "small"), inline)]
fn evaluate<R: Real, const D: usize, const G: bool, const S: bool>(
    seed: i64,
    improve: Improve,
    smooth: bool,
    p: [R; D],
) -> (R, [R; D])
where
    Dim: Body<D>,
{
    // OpenSimplex2S (`smooth`) or OpenSimplex2, known at compile time from `S` ([`body_for`]).
    let smooth = if cfg!(feature = "small") { smooth } else { S };
    let kernel = if smooth { &SMOOTH[D] } else { &FAST[D] };
    let mut sum = Sum::<R, D, G>::new(kernel);
    Dim::body(seed, turn(p, improve, smooth), smooth, &mut sum);
    let scale = real::<R>(kernel.scale);
    // |Σ| ≤ the bound / scale: the products stay within the bound (below 70).
    let value = sum.value.mul_rn(scale).canonical();
    let mut gradient = [R::ZERO; D];
    if G {
        for a in 0..D {
            sum.gradient[a] = sum.gradient[a].mul_rn(scale);
        }
        for (i, out) in gradient.iter_mut().enumerate() {
            let unit: [f64; D] = core::array::from_fn(|j| f64::from(u8::from(i == j)));
            let column = offsets_of(unit, improve, smooth);
            let mut g = R::ZERO;
            for (&d, &j) in sum.gradient.iter().zip(&column) {
                g = g.saturating_add(d.mul_rn(real::<R>(j)));
            }
            *out = g.canonical();
        }
    }
    (value, gradient)
}

/// The `S` of [`evaluate`] for a noise: each noise its own body, with its constants folded
/// (a program sampling both would otherwise share one, told apart at run time: 10–30% more
/// instructions per sample), except with the `small` feature (one body for both, 3.5 KB less
/// of the demo's module).
const fn body_for(smooth: bool) -> bool {
    smooth && !cfg!(feature = "small")
}

/// The unskewed offset space's coordinates of the input vector `v`: the turn, then the
/// unskew of the 2D and 4D lattices (3D's lattice is not skewed).
fn offsets_of<const D: usize>(v: [f64; D], improve: Improve, smooth: bool) -> [f64; D] {
    let t = turn_f64(v, improve, smooth);
    let unskew = match D {
        2 => UNSKEW_2D,
        4 if smooth => UNSKEW_4D_SMOOTH,
        4 => UNSKEW_4D_FAST,
        _ => 0.0,
    };
    let s: f64 = t.iter().sum::<f64>() * unskew;
    t.map(|x| x + s)
}

macro_rules! open_simplex_impls {
    ($t:ident, $smooth:expr, $kernels:ident) => {
        impl<R: Real> crate::Noise<R, 1> for $t {
            #[inline]
            fn sample(&self, p: [R; 1]) -> R {
                let q = [p[0], R::ZERO];
                evaluate::<R, 2, false, { body_for($smooth) }>(self.seed, self.improve, $smooth, q).0
            }
            fn amplitude_bound(&self) -> f32 {
                $kernels[1].bound
            }
        }
        impl<R: Real> crate::NoiseGradient<R, 1> for $t {
            #[inline]
            fn sample_with_gradient(&self, p: [R; 1]) -> (R, [R; 1]) {
                let q = [p[0], R::ZERO];
                let (v, g) =
                    evaluate::<R, 2, true, { body_for($smooth) }>(self.seed, self.improve, $smooth, q);
                (v, [g[0]])
            }
        }
        open_simplex_impls!(@dim $t, $smooth, $kernels, 2);
        open_simplex_impls!(@dim $t, $smooth, $kernels, 3);
        open_simplex_impls!(@dim $t, $smooth, $kernels, 4);
        crate::noise::inherent_amplitude_bound!($t, []);
    };
    (@dim $t:ident, $smooth:expr, $kernels:ident, $d:literal) => {
        impl<R: Real> crate::Noise<R, $d> for $t {
            #[inline]
            fn sample(&self, p: [R; $d]) -> R {
                evaluate::<R, $d, false, { body_for($smooth) }>(self.seed, self.improve, $smooth, p).0
            }
            #[inline]
            fn sample_lanes(&self, p: &[[R; LANES]; $d], out: &mut [R; LANES]) {
                // Lane bodies where `has_lanes` says; elsewhere point by point (4D's vertex
                // choices branch per point).
                if let Ok(p) = <&[[R; LANES]; 2]>::try_from(&p[..]) {
                    return lanes_2d::<R, { $smooth }>(self.seed, self.improve, p, out);
                }
                if let (true, Ok(p)) = (has_lanes($smooth, 3), <&[[R; LANES]; 3]>::try_from(&p[..])) {
                    return if $smooth {
                        smooth_3d_lanes(self.seed, self.improve, p, out)
                    } else {
                        fast_3d_lanes(self.seed, self.improve, p, out)
                    };
                }
                for (l, o) in out.iter_mut().enumerate() {
                    *o = self.sample(crate::batch::lane(p, l));
                }
            }
            fn fill_grid(
                &self,
                grid: &crate::batch::Grid<R, $d>,
                out: &mut [R],
            ) -> Result<(), crate::Error> {
                if has_lanes($smooth, $d) {
                    crate::batch::fill_grid(self, grid, out)
                } else {
                    // Its lanes are point samples: a plain loop of them is faster
                    // (`fill_grid_pointwise`; bench/README.md, "OpenSimplex2S 3D and 4D
                    // grids point by point", measured before 3D had lanes).
                    crate::batch::fill_grid_pointwise(self, grid, out)
                }
            }
            fn fill_points(&self, points: [&[R]; $d], out: &mut [R]) -> Result<(), crate::Error> {
                if has_lanes($smooth, $d) {
                    crate::batch::fill_points(self, points, out)
                } else {
                    crate::batch::fill_points_pointwise(self, points, out)
                }
            }
            fn amplitude_bound(&self) -> f32 {
                $kernels[$d].bound
            }
        }
        impl<R: Real> crate::NoiseGradient<R, $d> for $t {
            #[inline]
            fn sample_with_gradient(&self, p: [R; $d]) -> (R, [R; $d]) {
                evaluate::<R, $d, true, { body_for($smooth) }>(self.seed, self.improve, $smooth, p)
            }
        }
    };
}

/// Whether `sample_lanes` of the noise (`smooth`: OpenSimplex2S) in `dims` dimensions has a
/// lane body (`lanes_2d`, `fast_3d_lanes`, `smooth_3d_lanes`) rather than a loop of point
/// samples. 3D OpenSimplex2S's lanes compute all 14 candidate vertices where a point takes
/// about half of them: faster only where branches are costly (`OUT_OF_ORDER`; on the
/// microcontrollers, with floats in software, the candidates would cost twice the points).
const fn has_lanes(smooth: bool, dims: usize) -> bool {
    dims == 2 || dims == 3 && (!smooth || OUT_OF_ORDER)
}

open_simplex_impls!(OpenSimplex2, false, FAST);
open_simplex_impls!(OpenSimplex2S, true, SMOOTH);

/// The 2D and 3D gradient sets cycled to 128 and 256 entries, as the reference's tables are:
/// entry `i` is the set's `i mod n` (a load instead of a division by 24 or 48 per vertex;
/// with the `small` feature the division, 4 KB less).
static CYCLED2: [[i32; 2]; 128] = cycled(&GRAD2);
static CYCLED3: [[i32; 3]; 256] = cycled(&GRAD3);

/// [`CYCLED2`], [`CYCLED3`] and [`GRAD4`] as `f32` (each entry `f32::from_ratio(x, 29)`, the
/// conversion rounded once and an exact product by 2⁻²⁹, as at run time).
static CYCLED2_F32: [[f32; 2]; 128] = converted(&CYCLED2);
static CYCLED3_F32: [[f32; 3]; 256] = converted(&CYCLED3);
static GRAD4_F32: [[f32; 4]; 160] = converted(&GRAD4);

/// A Q29 table's entries as `f32`.
const fn converted<const D: usize, const N: usize>(t: &[[i32; D]; N]) -> [[f32; D]; N] {
    let mut out = [[0.0; D]; N];
    let mut i = 0;
    while i < N {
        let mut a = 0;
        while a < D {
            out[i][a] = t[i][a] as f32 * (1.0 / 536_870_912.0);
            a += 1;
        }
        i += 1;
    }
    out
}

/// `set` repeated to `N` entries.
const fn cycled<const D: usize, const M: usize, const N: usize>(
    set: &[[i32; D]; M],
) -> [[i32; D]; N] {
    let mut t = [[0; D]; N];
    let mut i = 0;
    while i < N {
        t[i] = set[i % M];
        i += 1;
    }
    t
}

#[rustfmt::skip]
/// The 2D gradient set: 24 unit vectors, Q29.
static GRAD2: [[i32; 2]; 24] = [
    [205451603, 496004047],
    [496004047, 205451603],
    [496004047, -205451603],
    [205451603, -496004047],
    [-205451603, -496004047],
    [-496004047, -205451603],
    [-496004047, 205451603],
    [-205451603, 496004047],
    [70075716, 532277907],
    [326826304, 425928331],
    [425928331, 326826304],
    [532277907, 70075716],
    [532277907, -70075716],
    [425928331, -326826304],
    [326826304, -425928331],
    [70075716, -532277907],
    [-70075716, -532277907],
    [-326826304, -425928331],
    [-425928331, -326826304],
    [-532277907, -70075716],
    [-532277907, 70075716],
    [-425928331, 326826304],
    [-326826304, 425928331],
    [-70075716, 532277907],
];

#[rustfmt::skip]
/// The 3D gradient set: 48 vectors (not normalised), Q29.
static GRAD3: [[i32; 3]; 48] = [
    [1194400808, 1194400808, -536870912],
    [1194400808, 1194400808, 536870912],
    [1656926694, 629293960, 0],
    [629293960, 1656926694, 0],
    [-1194400808, 1194400808, -536870912],
    [-1194400808, 1194400808, 536870912],
    [-629293960, 1656926694, 0],
    [-1656926694, 629293960, 0],
    [-536870912, -1194400808, -1194400808],
    [536870912, -1194400808, -1194400808],
    [0, -1656926694, -629293960],
    [0, -629293960, -1656926694],
    [-536870912, -1194400808, 1194400808],
    [536870912, -1194400808, 1194400808],
    [0, -629293960, 1656926694],
    [0, -1656926694, 629293960],
    [-1194400808, -1194400808, -536870912],
    [-1194400808, -1194400808, 536870912],
    [-1656926694, -629293960, 0],
    [-629293960, -1656926694, 0],
    [-1194400808, -536870912, -1194400808],
    [-1194400808, 536870912, -1194400808],
    [-629293960, 0, -1656926694],
    [-1656926694, 0, -629293960],
    [-1194400808, -536870912, 1194400808],
    [-1194400808, 536870912, 1194400808],
    [-1656926694, 0, 629293960],
    [-629293960, 0, 1656926694],
    [-536870912, 1194400808, -1194400808],
    [536870912, 1194400808, -1194400808],
    [0, 629293960, -1656926694],
    [0, 1656926694, -629293960],
    [-536870912, 1194400808, 1194400808],
    [536870912, 1194400808, 1194400808],
    [0, 1656926694, 629293960],
    [0, 629293960, 1656926694],
    [1194400808, -1194400808, -536870912],
    [1194400808, -1194400808, 536870912],
    [629293960, -1656926694, 0],
    [1656926694, -629293960, 0],
    [1194400808, -536870912, -1194400808],
    [1194400808, 536870912, -1194400808],
    [1656926694, 0, -629293960],
    [629293960, 0, -1656926694],
    [1194400808, -536870912, 1194400808],
    [1194400808, 536870912, 1194400808],
    [629293960, 0, 1656926694],
    [1656926694, 0, 629293960],
];

#[rustfmt::skip]
/// The 4D gradient set: 160 unit vectors, Q29.
static GRAD4: [[i32; 4]; 160] = [
    [-361854190, -173938003, -173938003, 311099765],
    [-402915383, -214999195, 82122385, 270038572],
    [-402915383, 82122385, -214999195, 270038572],
    [-473958332, 43834057, 43834057, 244440232],
    [-244440232, -43834057, -43834057, 473958332],
    [-270038572, -82122385, 214999195, 402915383],
    [-270038572, 214999195, -82122385, 402915383],
    [-311099765, 173938003, 173938003, 361854190],
    [-361854190, -173938003, 311099765, -173938003],
    [-402915383, -214999195, 270038572, 82122385],
    [-402915383, 82122385, 270038572, -214999195],
    [-473958332, 43834057, 244440232, 43834057],
    [-244440232, -43834057, 473958332, -43834057],
    [-270038572, -82122385, 402915383, 214999195],
    [-270038572, 214999195, 402915383, -82122385],
    [-311099765, 173938003, 361854190, 173938003],
    [-361854190, 311099765, -173938003, -173938003],
    [-402915383, 270038572, -214999195, 82122385],
    [-402915383, 270038572, 82122385, -214999195],
    [-473958332, 244440232, 43834057, 43834057],
    [-244440232, 473958332, -43834057, -43834057],
    [-270038572, 402915383, -82122385, 214999195],
    [-270038572, 402915383, 214999195, -82122385],
    [-311099765, 361854190, 173938003, 173938003],
    [311099765, -361854190, -173938003, -173938003],
    [270038572, -402915383, -214999195, 82122385],
    [270038572, -402915383, 82122385, -214999195],
    [244440232, -473958332, 43834057, 43834057],
    [473958332, -244440232, -43834057, -43834057],
    [402915383, -270038572, -82122385, 214999195],
    [402915383, -270038572, 214999195, -82122385],
    [361854190, -311099765, 173938003, 173938003],
    [-404446879, -203840704, -203840704, -203840704],
    [-419923485, -232007298, -232007298, 65114282],
    [-419923485, -232007298, 65114282, -232007298],
    [-419923485, 65114282, -232007298, -232007298],
    [-460984678, -273068491, 24053090, 24053090],
    [-460984678, 24053090, -273068491, 24053090],
    [-460984678, 24053090, 24053090, -273068491],
    [-535949049, -18156661, -18156661, -18156661],
    [-203840704, -404446879, -203840704, -203840704],
    [-232007298, -419923485, -232007298, 65114282],
    [-232007298, -419923485, 65114282, -232007298],
    [65114282, -419923485, -232007298, -232007298],
    [-273068491, -460984678, 24053090, 24053090],
    [24053090, -460984678, -273068491, 24053090],
    [24053090, -460984678, 24053090, -273068491],
    [-18156661, -535949049, -18156661, -18156661],
    [-203840704, -203840704, -404446879, -203840704],
    [-232007298, -232007298, -419923485, 65114282],
    [-232007298, 65114282, -419923485, -232007298],
    [65114282, -232007298, -419923485, -232007298],
    [-273068491, 24053090, -460984678, 24053090],
    [24053090, -273068491, -460984678, 24053090],
    [24053090, 24053090, -460984678, -273068491],
    [-18156661, -18156661, -535949049, -18156661],
    [-203840704, -203840704, -203840704, -404446879],
    [-232007298, -232007298, 65114282, -419923485],
    [-232007298, 65114282, -232007298, -419923485],
    [65114282, -232007298, -232007298, -419923485],
    [-273068491, 24053090, 24053090, -460984678],
    [24053090, -273068491, 24053090, -460984678],
    [24053090, 24053090, -273068491, -460984678],
    [-18156661, -18156661, -18156661, -535949049],
    [-173938003, -361854190, -173938003, 311099765],
    [-214999195, -402915383, 82122385, 270038572],
    [82122385, -402915383, -214999195, 270038572],
    [43834057, -473958332, 43834057, 244440232],
    [-43834057, -244440232, -43834057, 473958332],
    [-82122385, -270038572, 214999195, 402915383],
    [214999195, -270038572, -82122385, 402915383],
    [173938003, -311099765, 173938003, 361854190],
    [-173938003, -173938003, -361854190, 311099765],
    [-214999195, 82122385, -402915383, 270038572],
    [82122385, -214999195, -402915383, 270038572],
    [43834057, 43834057, -473958332, 244440232],
    [-43834057, -43834057, -244440232, 473958332],
    [-82122385, 214999195, -270038572, 402915383],
    [214999195, -82122385, -270038572, 402915383],
    [173938003, 173938003, -311099765, 361854190],
    [-173938003, -361854190, 311099765, -173938003],
    [-214999195, -402915383, 270038572, 82122385],
    [82122385, -402915383, 270038572, -214999195],
    [43834057, -473958332, 244440232, 43834057],
    [-43834057, -244440232, 473958332, -43834057],
    [-82122385, -270038572, 402915383, 214999195],
    [214999195, -270038572, 402915383, -82122385],
    [173938003, -311099765, 361854190, 173938003],
    [-173938003, -173938003, 311099765, -361854190],
    [-214999195, 82122385, 270038572, -402915383],
    [82122385, -214999195, 270038572, -402915383],
    [43834057, 43834057, 244440232, -473958332],
    [-43834057, -43834057, 473958332, -244440232],
    [-82122385, 214999195, 402915383, -270038572],
    [214999195, -82122385, 402915383, -270038572],
    [173938003, 173938003, 361854190, -311099765],
    [-173938003, 311099765, -361854190, -173938003],
    [-214999195, 270038572, -402915383, 82122385],
    [82122385, 270038572, -402915383, -214999195],
    [43834057, 244440232, -473958332, 43834057],
    [-43834057, 473958332, -244440232, -43834057],
    [-82122385, 402915383, -270038572, 214999195],
    [214999195, 402915383, -270038572, -82122385],
    [173938003, 361854190, -311099765, 173938003],
    [-173938003, 311099765, -173938003, -361854190],
    [-214999195, 270038572, 82122385, -402915383],
    [82122385, 270038572, -214999195, -402915383],
    [43834057, 244440232, 43834057, -473958332],
    [-43834057, 473958332, -43834057, -244440232],
    [-82122385, 402915383, 214999195, -270038572],
    [214999195, 402915383, -82122385, -270038572],
    [173938003, 361854190, 173938003, -311099765],
    [311099765, -173938003, -361854190, -173938003],
    [270038572, -214999195, -402915383, 82122385],
    [270038572, 82122385, -402915383, -214999195],
    [244440232, 43834057, -473958332, 43834057],
    [473958332, -43834057, -244440232, -43834057],
    [402915383, -82122385, -270038572, 214999195],
    [402915383, 214999195, -270038572, -82122385],
    [361854190, 173938003, -311099765, 173938003],
    [311099765, -173938003, -173938003, -361854190],
    [270038572, -214999195, 82122385, -402915383],
    [270038572, 82122385, -214999195, -402915383],
    [244440232, 43834057, 43834057, -473958332],
    [473958332, -43834057, -43834057, -244440232],
    [402915383, -82122385, 214999195, -270038572],
    [402915383, 214999195, -82122385, -270038572],
    [361854190, 173938003, 173938003, -311099765],
    [18156661, 18156661, 18156661, 535949049],
    [-24053090, -24053090, 273068491, 460984678],
    [-24053090, 273068491, -24053090, 460984678],
    [-65114282, 232007298, 232007298, 419923485],
    [273068491, -24053090, -24053090, 460984678],
    [232007298, -65114282, 232007298, 419923485],
    [232007298, 232007298, -65114282, 419923485],
    [203840704, 203840704, 203840704, 404446879],
    [18156661, 18156661, 535949049, 18156661],
    [-24053090, 24053090, 460984678, 273068491],
    [-24053090, 273068491, 460984678, -24053090],
    [-65114282, 232007298, 419923485, 232007298],
    [273068491, -24053090, 460984678, -24053090],
    [232007298, -65114282, 419923485, 232007298],
    [232007298, 232007298, 419923485, -65114282],
    [203840704, 203840704, 404446879, 203840704],
    [18156661, 535949049, 18156661, 18156661],
    [-24053090, 460984678, -24053090, 273068491],
    [-24053090, 460984678, 273068491, -24053090],
    [-65114282, 419923485, 232007298, 232007298],
    [273068491, 460984678, -24053090, -24053090],
    [232007298, 419923485, -65114282, 232007298],
    [232007298, 419923485, 232007298, -65114282],
    [203840704, 404446879, 203840704, 203840704],
    [535949049, 18156661, 18156661, 18156661],
    [460984678, -24053090, -24053090, 273068491],
    [460984678, -24053090, 273068491, -24053090],
    [419923485, -65114282, 232007298, 232007298],
    [460984678, 273068491, -24053090, -24053090],
    [419923485, 232007298, -65114282, 232007298],
    [419923485, 232007298, 232007298, -65114282],
    [404446879, 203840704, 203840704, 203840704],
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{I16F16, Noise};

    /// The `f32` tables hold `f32::from_ratio` of every entry, bit for bit: the compile-time
    /// conversion is the run-time one.
    #[test]
    fn converted_tables_are_the_run_time_conversion() {
        fn check<const D: usize, const N: usize>(ints: &[[i32; D]; N], floats: &[[f32; D]; N]) {
            for (row, converted) in ints.iter().zip(floats) {
                for (&x, &f) in row.iter().zip(converted) {
                    assert_eq!(f.to_bits(), f32::from_ratio(x, 29).to_bits(), "{x}");
                }
            }
        }
        check(&CYCLED2, &CYCLED2_F32);
        check(&CYCLED3, &CYCLED3_F32);
        check(&GRAD4, &GRAD4_F32);
    }

    /// The lane bodies (`sample_lanes`, 2D and 3D, OpenSimplex2 and OpenSimplex2S) give
    /// `sample`'s bits at each lane, for every orientation, several seeds and every number
    /// type: random points near and far from the origin, points on the lattices' edges and
    /// vertices (multiples of ¼, also on the main diagonal), and non-finite ones.
    #[test]
    fn lanes_are_the_point_samples() {
        fn check<R: Real, const D: usize, N: Noise<R, D>>(noise: &N, p: &[[f32; LANES]; D]) {
            let p = p.map(|axis| axis.map(R::from_f32));
            let mut got = [R::ZERO; LANES];
            noise.sample_lanes(&p, &mut got);
            for l in 0..LANES {
                let point: [R; D] = core::array::from_fn(|a| p[a][l]);
                let want = noise.sample(point);
                assert_eq!(
                    got[l].to_f64().to_bits(),
                    want.to_f64().to_bits(),
                    "{point:?}: {got:?}"
                );
            }
        }
        fn all_types<const D: usize, N>(noise: &N, p: &[[f32; LANES]; D])
        where
            N: Noise<f32, D> + Noise<f64, D> + Noise<I16F16, D>,
        {
            check::<f32, D, N>(noise, p);
            check::<f64, D, N>(noise, p);
            check::<I16F16, D, N>(noise, p);
        }
        let mut next = crate::testing::xorshift32(0x2545_F491);
        let mut unit = move || f64::from(next()) / f64::from(u32::MAX);
        let specials = crate::testing::SPECIAL_COORDINATES;
        let mut coordinate = |round: usize| match round % 4 {
            0 => ((unit() - 0.5) * 600.0) as f32,
            1 => ((unit() - 0.5) * 4e6) as f32,
            2 => ((unit() * 64.0).floor() / 4.0 - 8.0) as f32,
            _ => specials[(unit() * specials.len() as f64) as usize % specials.len()],
        };
        for seed in [0, -7, i64::MAX, 0x1234_5678_9ABC] {
            for improve in [Improve::Standard, Improve::XY, Improve::XZ] {
                let noise = OpenSimplex2::new(seed).improving(improve);
                let smooth = OpenSimplex2S::new(seed).improving(improve);
                for round in 0..400 {
                    let p2: [[f32; LANES]; 2] =
                        core::array::from_fn(|_| core::array::from_fn(|_| coordinate(round)));
                    all_types(&noise, &p2);
                    all_types(&smooth, &p2);
                    let p3: [[f32; LANES]; 3] =
                        core::array::from_fn(|_| core::array::from_fn(|_| coordinate(round)));
                    all_types(&noise, &p3);
                    all_types(&smooth, &p3);
                    if round % 4 == 2 {
                        // On the main diagonal at multiples of ¼, where turned offsets are
                        // exactly ½ (standard: (−½, −½, −½) turns to itself).
                        let v: [f32; LANES] = core::array::from_fn(|_| coordinate(round));
                        all_types(&noise, &[v; 3]);
                        all_types(&smooth, &[v; 3]);
                    }
                }
            }
        }
    }
}
