//! Perlin's improved noise (Perlin 2002, "Improving Noise"; pbrt §10.6.1).
//!
//! Gradient noise on the integer lattice with Perlin's quintic fade and his permutation hash
//! `p[p[p[x] + y] + z]`. In 3D the gradient is chosen from the 12 edges of the cube (with 4
//! repeated to make 16) exactly as in Perlin's reference `grad`, so that with seed 0 the f64 noise
//! reproduces his reference values bit for bit.
//!
//! In `f32`, 2D, 3D and 4D sampling runs the target's vector kernel where [`arch`] has
//! one (x86-64; wasm32 with `simd128`), with the same values; see [`Perlin`]'s performance
//! notes.

use super::kernel::{MAX_CORNERS, Quintic};
use super::periodic::WrapCorners;
use super::{Lattice, gradient_corners, half_dims, lattice_noise_impls, sample_lattice, signed};
use crate::Real;
use crate::arch;
use crate::hash::chain::{self, ChainHash, Doubled, Order, Wrap};

/// Perlin's improved noise in 1 to 4 dimensions.
///
/// * **Hash**: the [`Permutation`](crate::hash::Permutation) of the seed (seed 0 is Perlin's 2002 table), folded with x
///   innermost: `p[(p[(p[x] + y) & 255] + z) & 255]`, each cell reduced mod 256 (period 256).
/// * **Gradients**: 3D uses Perlin's reference selection from `h & 15` (the 12 cube edges).
///   2D uses the same function with `z = 0` (edges projected onto the plane: diagonals and axes).
///   1D uses the 8 slopes `±¼, ±½, ±¾, ±1` from `h & 7`. 4D uses the 32 edges of the
///   tesseract (one zero component, three ±1) from `h & 31`.
/// * **Speed**: in `f32` on x86-64 and in WebAssembly built with `simd128` (without the
///   `small` feature), 2D, 3D and 4D `sample` run a 4-lane vector kernel (same values, bit for
///   bit). For many samples, the batch API ([`Noise::fill_grid`](crate::Noise::fill_grid))
///   is several times faster still (`bench/README.md`).
/// * **Size**: 512 bytes on every target (the permutation, doubled), so it is cheap to copy,
///   but sampling takes `&self`: build it once and share it.
/// * **Range**: `|n| ≤ D/2` (+2⁻¹⁰ for rounding; module docs of [`lattice`](super)); 0 at
///   every lattice point. Measured maxima over 2·10⁶ random points (`tests/tests/statistics.rs`):
///   1D 0.500, 2D 0.999, 3D 0.998, 4D 1.118.
///
/// # Examples
///
/// ```
/// use bandnoise::{I16F16, Noise, lattice::Perlin};
///
/// let p = Perlin::new(0);
/// assert_eq!(p.sample([3.14f64, 42.0, 7.0]), 0.13691995878400012);
/// assert_eq!(p.sample([1.0f32, 2.0, 3.0]), 0.0); // zero on the lattice
/// let fixed: I16F16 = p.sample([I16F16::from_num(3.14), I16F16::from_num(42), I16F16::from_num(7)]);
/// assert!((fixed.to_num::<f64>() - 0.136919958784).abs() < 1e-3);
/// ```
#[derive(Clone, PartialEq, Eq)]
pub struct Perlin {
    /// The seed's [`Permutation`](crate::hash::Permutation) repeated twice, as in Perlin's reference code (`p[i + 256] =
    /// p[i]`): the hash chain's indices `p[x] + y + 1` stay below 512 without a `& 255`.
    p: Doubled,
}

impl Perlin {
    /// Improved noise for `seed`; seed 0 is Perlin's reference noise. `const`, so
    /// `static NOISE: Perlin = Perlin::new(7);` builds the table at compile time.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self {
            p: Doubled::new(seed),
        }
    }

    /// The doubled permutation, for the target kernels of [`arch`].
    #[inline]
    pub(crate) fn doubled(&self) -> &[u8; 512] {
        &self.p.0
    }

    #[inline]
    fn corners<const D: usize>(&self, cell: [i32; D]) -> [u32; MAX_CORNERS] {
        let (lower, upper) = chain::natural::<Doubled, D>(cell);
        chain::corners(Order::XFirst, 0, lower, upper, |h, c| self.p.step(h, c))
    }
}

impl<const D: usize> WrapCorners<D> for Perlin {
    #[inline]
    fn corner_hashes_wrapped(&self, cell: [i32; D], wrap: &Wrap<D>) -> [u32; MAX_CORNERS] {
        wrap.corner_hashes(&self.p, Order::XFirst, 0, cell, [0; D])
    }
}

impl core::fmt::Debug for Perlin {
    /// The permutation, once.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Perlin")
            .field("perm", &&self.p.0[..256])
            .finish()
    }
}

/// Whether 2D, 3D and 4D sampling in `R` take the target's vector kernel: `f32` where
/// [`arch`] has one (a constant after monomorphisation).
#[inline]
fn has_vector_kernel<R: Real>() -> bool {
    arch::PERLIN_POINT && R::BINARY32
}

/// A point sample: the target's vector `kernel` in `f32` where there is one (falling back to the
/// shared kernel for the coordinates it leaves), else the shared kernel in `R`.
#[inline]
fn sample_point<R: Real, const D: usize>(
    perlin: &Perlin,
    p: [R; D],
    kernel: impl FnOnce([f32; D]) -> Option<f32>,
) -> R
where
    Perlin: Lattice<D>,
{
    if has_vector_kernel::<R>() {
        let f = p.map(R::to_f32);
        let at = |a: usize| if a < D { f[a] } else { 0.0 };
        return R::from_f32(
            kernel(f).unwrap_or_else(|| shared_kernel::<D>(perlin, at(0), at(1), at(2), at(3))),
        );
    }
    sample_lattice(perlin, p)
}

/// The shared kernel in `f32`, for the coordinates the vector kernel leaves to it (beyond ±2³¹,
/// not finite, or a tiny negative whose fraction rounds to 1): out of line, so that the vector
/// kernel stays small enough to inline. The first `D` of `x, y, z, w` are the point, passed
/// one by one: passed as an array, the point stayed in memory, and the 4D vector kernel
/// loaded its four lanes from the array's four separate stores, which the processor cannot
/// forward to one load (a stall at the start of every sample; bench/README.md).
#[cold]
#[inline(never)]
fn shared_kernel<const D: usize>(perlin: &Perlin, x: f32, y: f32, z: f32, w: f32) -> f32
where
    Perlin: Lattice<D>,
{
    let all = [x, y, z, w];
    sample_lattice(perlin, core::array::from_fn(|a| all[a]))
}

impl Default for Perlin {
    fn default() -> Self {
        Self::new(0)
    }
}

/// [`Perlin`] with per-seed tables for the point kernels: the same noise bit for bit, faster
/// where the target's vector kernel can use the tables, at the cost of their size.
///
/// On x86-64 (and in WebAssembly with `simd128`), 2D, 3D and 4D point sampling in `f32` look
/// up the gradients of two neighbouring corners in one entry of a table (the gradients that
/// Perlin's `grad` picks for `p[b]` and `p[b + 1]`, for every `b`: 16 KiB for 2D and 3D,
/// 16 KiB for 4D), one dependent lookup fewer than [`Perlin`], whose kernel first reads
/// `p[b]` and `p[b + 1]` and then static gradient tables. How much that saves depends on the
/// core and the dimension: on an AMD Zen 4 a 2D point sample about 4%, a 3D one about 13% and
/// a 4D one about 18% (on a recent Intel core 3% and 10% in 2D and 3D; `bench/README.md`).
/// Other number types, dimensions and targets sample exactly as [`Perlin`]; there the tables
/// are empty.
///
/// * **Size**: 32.5 KiB where the vector kernel is (x86-64, WebAssembly with `simd128`), 512
///   bytes elsewhere. Build it once (`static` works: `new` is
///   `const`) and share it.
/// * Everything else (range, gradients, periodic wrapping, batches) is [`Perlin`]'s.
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, lattice::{Perlin, TabledPerlin}};
///
/// static NOISE: TabledPerlin = TabledPerlin::new(7);
/// let p = [0.3f32, 4.7, -2.2];
/// assert_eq!(NOISE.sample(p).to_bits(), Perlin::new(7).sample(p).to_bits());
/// assert_eq!(NOISE.perlin(), &Perlin::new(7));
/// ```
#[derive(Clone)]
pub struct TabledPerlin {
    perlin: Perlin,
    pairs: arch::PerlinPairs,
}

impl TabledPerlin {
    /// [`Perlin::new`]`(seed)` with its table.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self::from_perlin(Perlin::new(seed))
    }

    /// `perlin` with its table.
    #[must_use]
    pub const fn from_perlin(perlin: Perlin) -> Self {
        let pairs = arch::PerlinPairs::new(&perlin.p.0);
        Self { perlin, pairs }
    }

    /// The noise without the table.
    #[must_use]
    pub const fn perlin(&self) -> &Perlin {
        &self.perlin
    }
}

/// Two noises are equal when their permutations are (the table is derived from it).
impl PartialEq for TabledPerlin {
    fn eq(&self, other: &Self) -> bool {
        self.perlin == other.perlin
    }
}

impl Eq for TabledPerlin {}

impl Default for TabledPerlin {
    fn default() -> Self {
        Self::new(0)
    }
}

impl core::fmt::Debug for TabledPerlin {
    /// The permutation, once.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("TabledPerlin")
            .field("perm", &&self.perlin.p.0[..256])
            .finish()
    }
}

/// `TabledPerlin` is `Perlin` in every method but the point kernels (`$point`).
macro_rules! forward_to_perlin {
    ($d:literal $(, $point:ident)?) => {
        impl Lattice<$d> for TabledPerlin {
            type Fade = Quintic;
            #[inline]
            fn corner_hashes(&self, cell: [i32; $d]) -> [u32; MAX_CORNERS] {
                self.perlin.corners(cell)
            }
            type Corner<R: Real> = [R; $d];
            #[inline]
            fn corner<R: Real>(&self, h: u32) -> [R; $d] {
                Lattice::<$d>::corner(&self.perlin, h)
            }
            #[inline]
            fn contribution<R: Real>(&self, g: &[R; $d], d: &[R; $d]) -> R {
                Lattice::<$d>::contribution(&self.perlin, g, d)
            }
            #[inline]
            fn gradient<R: Real>(&self, h: u32) -> [R; $d] {
                Lattice::<$d>::gradient(&self.perlin, h)
            }
            #[inline]
            fn dot<R: Real>(&self, h: u32, d: &[R; $d]) -> R {
                Lattice::<$d>::dot(&self.perlin, h, d)
            }
            #[inline]
            fn point_kernel_for_scattered_lanes<R: Real>() -> bool {
                <Perlin as Lattice<$d>>::point_kernel_for_scattered_lanes::<R>()
            }
            $(
                #[inline]
                fn sample_point<R: Real>(&self, p: [R; $d]) -> R {
                    sample_point(&self.perlin, p, |f| $point(&self.perlin, &self.pairs, f))
                }
            )?
        }

        impl WrapCorners<$d> for TabledPerlin {
            #[inline]
            fn corner_hashes_wrapped(&self, cell: [i32; $d], wrap: &Wrap<$d>) -> [u32; MAX_CORNERS] {
                self.perlin.corner_hashes_wrapped(cell, wrap)
            }
        }
    };
}

/// The 2D point kernel with the table.
#[inline]
fn paired2(perlin: &Perlin, pairs: &arch::PerlinPairs, [x, y]: [f32; 2]) -> Option<f32> {
    arch::perlin2_paired(perlin.doubled(), pairs, x, y)
}

/// The 3D point kernel with the table.
#[inline]
fn paired3(perlin: &Perlin, pairs: &arch::PerlinPairs, [x, y, z]: [f32; 3]) -> Option<f32> {
    arch::perlin3_paired(perlin.doubled(), pairs, x, y, z)
}

/// The 4D point kernel with the table.
#[inline]
fn paired4(perlin: &Perlin, pairs: &arch::PerlinPairs, [x, y, z, w]: [f32; 4]) -> Option<f32> {
    arch::perlin4_paired(perlin.doubled(), pairs, x, y, z, w)
}

forward_to_perlin!(1);
forward_to_perlin!(2, paired2);
forward_to_perlin!(3, paired3);
forward_to_perlin!(4, paired4);
lattice_noise_impls!(TabledPerlin, [], |_, d| half_dims(d));
crate::noise::inherent_amplitude_bound!(TabledPerlin, []);

/// Perlin's reference `grad(hash, x, y, z)`, the definition [`GRAD3`] is checked against;
/// its data-dependent choices vectorise as selects over lanes (simplex noise's batches).
#[inline(always)]
pub(crate) fn grad3<R: Real>(h: u32, x: R, y: R, z: R) -> R {
    let h = h & 15;
    let u = if h < 8 { x } else { y };
    let v = if h < 4 {
        y
    } else if h == 12 || h == 14 {
        x
    } else {
        z
    };
    signed(h, 0, u) + signed(h, 1, v)
}

/// The gradient Perlin's reference `grad(hash, x, y, z)` dots with for `hash & 15`: the 12
/// edges of the cube and 4 of them repeated (checked against `grad3` by a test).
pub(crate) const GRAD3: [[i8; 3]; 16] = [
    [1, 1, 0],
    [-1, 1, 0],
    [1, -1, 0],
    [-1, -1, 0],
    [1, 0, 1],
    [-1, 0, 1],
    [1, 0, -1],
    [-1, 0, -1],
    [0, 1, 1],
    [0, -1, 1],
    [0, 1, -1],
    [0, -1, -1],
    [1, 1, 0],
    [0, -1, 1],
    [-1, 1, 0],
    [0, -1, -1],
];

/// [`GRAD3`] in the number type `R`, built at compile time, so a gradient component is one
/// load (no conversion) that a multiplication can take as its memory operand. 2D and 3D take
/// their dot products with these rows through `mul_unit` (branch-free, where `grad3`'s
/// data-dependent choices cost about three times as many instructions); the value is
/// `grad3`'s but for the sign of a zero, which sampling canonicalises.
struct Grad3<R>(core::marker::PhantomData<R>);

impl<R: Real> Grad3<R> {
    const TABLE: [[R; 3]; 16] = {
        let mut table = [[R::ZERO; 3]; 16];
        let mut i = 0;
        while i < 16 {
            table[i] = in_type(GRAD3[i]);
            i += 1;
        }
        table
    };
}

/// A gradient of components 0 and ±1 in the number type `R` (exact in every one).
const fn in_type<R: Real, const N: usize>(g: [i8; N]) -> [R; N] {
    let mut v = [R::ZERO; N];
    let mut a = 0;
    while a < N {
        v[a] = match g[a] {
            1 => R::ONE,
            -1 => R::NEG_ONE,
            _ => R::ZERO,
        };
        a += 1;
    }
    v
}

// `corner_hashes` is inlined in WebAssembly builds without `small` (the npm package's, the
// browser benchmark's): left out of line there, its 16 hashes go through memory and a 2D point
// sample takes 1.6× the time (bench/README.md, "the npm package in Chromium"). Elsewhere the
// compiler decides (the firmware's flash, the demo's module budget).
impl Lattice<1> for Perlin {
    type Fade = Quintic;
    #[cfg_attr(all(target_arch = "wasm32", not(feature = "small")), inline)]
    fn corner_hashes(&self, cell: [i32; 1]) -> [u32; MAX_CORNERS] {
        self.corners(cell)
    }
    gradient_corners!(1, mul_rn);
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; 1] {
        [signed(h, 2, R::from_ratio((h & 3) as i32 + 1, 2))]
    }
}

impl Lattice<2> for Perlin {
    type Fade = Quintic;
    #[cfg_attr(all(target_arch = "wasm32", not(feature = "small")), inline)]
    fn corner_hashes(&self, cell: [i32; 2]) -> [u32; MAX_CORNERS] {
        self.corners(cell)
    }
    #[inline]
    fn sample_point<R: Real>(&self, p: [R; 2]) -> R {
        sample_point(self, p, |[x, y]| arch::perlin2(self.doubled(), x, y))
    }
    #[inline]
    fn point_kernel_for_scattered_lanes<R: Real>() -> bool {
        has_vector_kernel::<R>()
    }
    gradient_corners!(2, mul_unit);
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; 2] {
        let g = &Grad3::<R>::TABLE[(h & 15) as usize];
        [g[0], g[1]]
    }
}

impl Lattice<3> for Perlin {
    type Fade = Quintic;
    #[cfg_attr(all(target_arch = "wasm32", not(feature = "small")), inline)]
    fn corner_hashes(&self, cell: [i32; 3]) -> [u32; MAX_CORNERS] {
        self.corners(cell)
    }
    #[inline]
    fn sample_point<R: Real>(&self, p: [R; 3]) -> R {
        sample_point(self, p, |[x, y, z]| arch::perlin3(self.doubled(), x, y, z))
    }
    #[inline]
    fn point_kernel_for_scattered_lanes<R: Real>() -> bool {
        has_vector_kernel::<R>()
    }
    type Corner<R: Real> = [R; 3];
    #[inline]
    fn corner<R: Real>(&self, h: u32) -> [R; 3] {
        self.gradient(h)
    }
    /// `d·g` as `d_x·g_x + (d_y·g_y + d_z·g_z)`. Each of Perlin's gradients has a zero
    /// component, whose product is a zero, so this is the axis-order sum
    /// `(d_x·g_x + d_y·g_y) + d_z·g_z` but for the sign of a zero (canonicalised by sampling;
    /// in fixed point both are exact). Along a grid row the corner, `d_y` and `d_z` are fixed,
    /// so the bracket is one number per corner and row, and each point adds once, not twice.
    #[inline]
    fn contribution<R: Real>(&self, g: &[R; 3], d: &[R; 3]) -> R {
        d[0].mul_unit(g[0]) + (d[1].mul_unit(g[1]) + d[2].mul_unit(g[2]))
    }
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; 3] {
        Grad3::<R>::TABLE[(h & 15) as usize]
    }
}

impl Lattice<4> for Perlin {
    type Fade = Quintic;
    gradient_corners!(4, mul_unit);
    #[cfg_attr(all(target_arch = "wasm32", not(feature = "small")), inline)]
    fn corner_hashes(&self, cell: [i32; 4]) -> [u32; MAX_CORNERS] {
        self.corners(cell)
    }
    #[inline]
    fn sample_point<R: Real>(&self, p: [R; 4]) -> R {
        sample_point(self, p, |[x, y, z, w]| {
            arch::perlin4(self.doubled(), x, y, z, w)
        })
    }
    #[inline]
    fn point_kernel_for_scattered_lanes<R: Real>() -> bool {
        has_vector_kernel::<R>()
    }
    /// The signed sum of the three offsets [`grad4`] selects: for a point sample, fewer
    /// instructions than the table's four products (`bench/README.md`).
    #[inline]
    fn dot<R: Real>(&self, h: u32, d: &[R; 4]) -> R {
        grad4_dot(h, d)
    }
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; 4] {
        // A reference, so the table is promoted to a static rather than built on the stack.
        let g: &[R; 4] = &Grad4::<R>::TABLE[(h & 31) as usize];
        *g
    }
}

/// Perlin's gradient in `D` dimensions for the low bits of `h` (1D slopes, [`GRAD3`]'s rows,
/// 2D their x and y, [`grad4`]'s rows), as [`Lattice::gradient`] of [`Perlin`], for noises
/// that pick Perlin's gradients with another hash (simplex noise). (Perlin's own impls keep
/// their per-dimension bodies: through this function the Cortex-M0's 2D Perlin took 2 more
/// instructions per sample.)
#[inline(always)]
pub(crate) fn gradient_of<R: Real, const D: usize>(h: u32) -> [R; D] {
    // References, so the tables are promoted to statics; `min` keeps the (constant) index
    // visibly in the row.
    match D {
        1 => core::array::from_fn(|_| signed(h, 2, R::from_ratio((h & 3) as i32 + 1, 2))),
        2 | 3 => {
            let row: &[R; 3] = &Grad3::<R>::TABLE[(h & 15) as usize];
            core::array::from_fn(|a| row[a.min(2)])
        }
        _ => {
            let row: &[R; 4] = &Grad4::<R>::TABLE[(h & 31) as usize];
            core::array::from_fn(|a| row[a.min(3)])
        }
    }
}

/// `g·d` for [`grad4`]'s gradient of `h`: the signed sum of the three offsets it selects (for
/// a point sample, fewer instructions than the table's four products, `bench/README.md`).
/// The table's products give the same value but for the sign of a zero, which sampling
/// canonicalises.
#[inline(always)]
pub(crate) fn grad4_dot<R: Real>(h: u32, d: &[R; 4]) -> R {
    let zero = (h >> 3 & 3) as usize;
    let mut sum = R::ZERO;
    let mut bit = 0;
    for (a, x) in d.iter().enumerate() {
        if a != zero {
            sum = sum + signed(h, bit, *x);
            bit += 1;
        }
    }
    sum
}

/// The 4D gradient of hash `h`: one of the 32 edges of the tesseract, its zero axis
/// `(h >> 3) & 3` and bits 0, 1, 2 the signs of the other three axes in order.
const fn grad4(h: u32) -> [i8; 4] {
    let zero = (h >> 3 & 3) as usize;
    let mut g = [0i8; 4];
    let mut bit = 0;
    let mut a = 0;
    while a < 4 {
        if a != zero {
            g[a] = if h >> bit & 1 == 0 { 1 } else { -1 };
            bit += 1;
        }
        a += 1;
    }
    g
}

/// [`grad4`] of every hash in the number type `R`, built at compile time, for the same reason
/// as [`Grad3`]: a dot product is then four `mul_unit`s of loaded components, branch-free.
pub(crate) struct Grad4<R>(core::marker::PhantomData<R>);

impl<R: Real> Grad4<R> {
    pub(crate) const TABLE: [[R; 4]; 32] = {
        let mut table = [[R::ZERO; 4]; 32];
        let mut h = 0;
        while h < 32 {
            table[h] = in_type(grad4(h as u32));
            h += 1;
        }
        table
    };
}

lattice_noise_impls!(Perlin, [], |_, d| half_dims(d));
crate::noise::inherent_amplitude_bound!(Perlin, []);

#[cfg(test)]
mod tests {
    use super::{GRAD3, Grad4, Lattice, Perlin, grad3};

    #[test]
    fn gradient_table_4d_is_the_vector_the_signed_sum_dots_with() {
        let perlin = Perlin::new(0);
        for h in 0..64u32 {
            let picked: [f64; 4] = core::array::from_fn(|a| {
                let d: [f64; 4] = core::array::from_fn(|b| if a == b { 1.0 } else { 0.0 });
                Lattice::<4>::dot(&perlin, h, &d)
            });
            assert_eq!(Grad4::<f64>::TABLE[(h & 31) as usize], picked, "h = {h}");
            assert_eq!(Lattice::<4>::gradient::<f64>(&perlin, h), picked, "h = {h}");
        }
    }

    #[test]
    fn gradient_table_is_the_vector_grad3_dots_with() {
        // Unit coordinates pick each component out of grad3's dot product.
        for h in 0..16u32 {
            let picked = [
                grad3(h, 1.0f64, 0.0, 0.0),
                grad3(h, 0.0, 1.0, 0.0),
                grad3(h, 0.0, 0.0, 1.0),
            ];
            assert_eq!(GRAD3[h as usize].map(f64::from), picked, "h = {h}");
        }
    }
}
