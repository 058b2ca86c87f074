//! Perlin's improved noise (Perlin 2002, "Improving Noise"; pbrt §10.6.1).
//!
//! Gradient noise on the integer lattice with Perlin's quintic fade and his permutation hash
//! `p[p[p[x] + y] + z]`. In 3D the gradient is chosen from the 12 edges of the cube (with 4
//! repeated to make 16) exactly as in Perlin's reference `grad`, so that with seed 0 the f64 noise
//! reproduces his reference values bit for bit.
//!
//! In `f32` on x86-64, 2D and 3D sampling runs an SSE2 version of the same kernel
//! (`perlin_sse2.rs`) with the same values; see [`Perlin`]'s performance notes.

use super::kernel::{MAX_CORNERS, Quintic, sum_of_products};
use super::periodic::WrapCorners;
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
use super::perlin_sse2;
use super::{GradientLattice, gradient_noise_impls, half_dims, sample_gradient, signed};
use crate::Real;
use crate::hash::chain::{self, ChainHash, Doubled, Order, Wrap};

/// Perlin's improved noise in 1 to 4 dimensions.
///
/// * **Hash**: the [`Permutation`](crate::hash::Permutation) of the seed (seed 0 is Perlin's 2002 table), folded with x
///   innermost: `p[(p[(p[x] + y) & 255] + z) & 255]`, each cell reduced mod 256 (period 256).
/// * **Gradients**: 3D uses Perlin's reference selection from `h & 15` (the 12 cube edges).
///   2D uses the same function with `z = 0` (edges projected onto the plane: diagonals and axes).
///   1D uses the 8 slopes `±¼, ±½, ±¾, ±1` from `h & 7`. 4D uses the 32 edges of the
///   tesseract (one zero component, three ±1) from `h & 31`.
/// * **Speed**: in `f32` on x86-64, 2D and 3D `sample` run an SSE2 kernel (same values, bit
///   for bit): about 70 and 105 instructions per sample. For many samples, the batch API
///   ([`Noise::fill_grid`](crate::Noise::fill_grid)) is 5–8× faster still.
/// * **Size**: 512 bytes (the permutation, doubled); on x86-64 16.5 KiB, with the SSE2
///   kernel's table of gradient pairs. Build it once and share it: sampling takes `&self`.
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
#[derive(Clone)]
pub struct Perlin {
    /// The seed's [`Permutation`](crate::hash::Permutation) repeated twice, as in Perlin's reference code (`p[i + 256] =
    /// p[i]`): the hash chain's indices `p[x] + y + 1` stay below 512 without a `& 255`.
    p: Doubled,
    /// The SSE2 kernel's gradients of neighbouring hash values (16 KiB), derived from `p`.
    #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
    pairs: perlin_sse2::GradientPairs,
}

/// Two noises are equal when their permutations are (the rest is derived from it).
impl PartialEq for Perlin {
    fn eq(&self, other: &Self) -> bool {
        self.p == other.p
    }
}

impl Eq for Perlin {}

impl Perlin {
    /// Improved noise for `seed`; seed 0 is Perlin's reference noise. `const`, so
    /// `static NOISE: Perlin = Perlin::new(7);` builds the table at compile time.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        let p = Doubled::new(seed);
        Self {
            #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
            pairs: perlin_sse2::GradientPairs::new(&p.0),
            p,
        }
    }

    /// The SSE2 kernel over this seed's tables.
    #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
    #[inline]
    pub(super) fn kernel(&self) -> perlin_sse2::Kernel<'_> {
        perlin_sse2::Kernel {
            p: &self.p.0,
            pairs: &self.pairs,
        }
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
        let (lower, upper) = wrap.corners(cell, [0; D]);
        chain::corners(Order::XFirst, 0, lower, upper, |h, c| {
            Wrap::<D>::fold(&self.p, h, c)
        })
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

/// Whether 2D and 3D sampling in `R` take the SSE2 kernel: `f32` on x86-64.
#[inline]
fn has_vector_kernel<R: Real>() -> bool {
    cfg!(all(target_arch = "x86_64", target_feature = "sse2"))
        && core::any::TypeId::of::<R>() == core::any::TypeId::of::<f32>()
}

/// `f32`, seen as `R`, when `R` is `f32`: the point kernels with a vector version for `f32`
/// only take it this way (the comparison of type ids is a constant; the conversions are the
/// identity).
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[inline]
fn as_f32<R: Real, const D: usize>(p: [R; D]) -> Option<[f32; D]> {
    has_vector_kernel::<R>().then(|| p.map(R::to_f32))
}

/// The shared kernel in `f32`, for the coordinates the SSE2 kernel leaves to it (beyond ±2³¹,
/// not finite, or a tiny negative whose fraction rounds to 1): out of line, so that the vector
/// kernel stays small enough to inline.
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[cold]
#[inline(never)]
fn shared_kernel<const D: usize>(perlin: &Perlin, p: [f32; D]) -> f32
where
    Perlin: GradientLattice<D>,
{
    sample_gradient(perlin, p)
}

impl Default for Perlin {
    fn default() -> Self {
        Self::new(0)
    }
}

/// Perlin's reference `grad(hash, x, y, z)`, the definition [`GRAD3`] is checked against.
#[cfg(test)]
fn grad3<R: Real>(h: u32, x: R, y: R, z: R) -> R {
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
pub(super) const GRAD3: [[i8; 3]; 16] = [
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
            let mut a = 0;
            while a < 3 {
                table[i][a] = match GRAD3[i][a] {
                    1 => R::ONE,
                    -1 => R::NEG_ONE,
                    _ => R::ZERO,
                };
                a += 1;
            }
            i += 1;
        }
        table
    };
}

impl GradientLattice<1> for Perlin {
    type Fade = Quintic;
    fn corner_hashes(&self, cell: [i32; 1]) -> [u32; MAX_CORNERS] {
        self.corners(cell)
    }
    #[inline]
    fn dot<R: Real>(&self, h: u32, d: &[R; 1]) -> R {
        d[0].mul_rn(<Self as GradientLattice<1>>::gradient::<R>(self, h)[0])
    }
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; 1] {
        [signed(h, 2, R::from_ratio((h & 3) as i32 + 1, 2))]
    }
}

impl GradientLattice<2> for Perlin {
    type Fade = Quintic;
    fn corner_hashes(&self, cell: [i32; 2]) -> [u32; MAX_CORNERS] {
        self.corners(cell)
    }
    #[inline]
    fn sample_point<R: Real>(&self, p: [R; 2]) -> R {
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        if let Some([x, y]) = as_f32(p) {
            let v = self.kernel().sample2(x, y);
            return R::from_f32(v.unwrap_or_else(|| shared_kernel(self, [x, y])));
        }
        sample_gradient(self, p)
    }
    #[inline]
    fn point_kernel_for_scattered_lanes<R: Real>() -> bool {
        has_vector_kernel::<R>()
    }
    #[inline]
    fn dot<R: Real>(&self, h: u32, d: &[R; 2]) -> R {
        self.dot_with(&self.gradient(h), d)
    }
    #[inline]
    fn dot_with<R: Real>(&self, g: &[R; 2], d: &[R; 2]) -> R {
        sum_of_products(d, g, R::mul_unit)
    }
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; 2] {
        let g = &Grad3::<R>::TABLE[(h & 15) as usize];
        [g[0], g[1]]
    }
}

impl GradientLattice<3> for Perlin {
    type Fade = Quintic;
    fn corner_hashes(&self, cell: [i32; 3]) -> [u32; MAX_CORNERS] {
        self.corners(cell)
    }
    #[inline]
    fn sample_point<R: Real>(&self, p: [R; 3]) -> R {
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        if let Some([x, y, z]) = as_f32(p) {
            let v = self.kernel().sample3(x, y, z);
            return R::from_f32(v.unwrap_or_else(|| shared_kernel(self, [x, y, z])));
        }
        sample_gradient(self, p)
    }
    #[inline]
    fn point_kernel_for_scattered_lanes<R: Real>() -> bool {
        has_vector_kernel::<R>()
    }
    #[inline]
    fn dot<R: Real>(&self, h: u32, d: &[R; 3]) -> R {
        self.dot_with(&self.gradient(h), d)
    }
    #[inline]
    fn dot_with<R: Real>(&self, g: &[R; 3], d: &[R; 3]) -> R {
        sum_of_products(d, g, R::mul_unit)
    }
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; 3] {
        Grad3::<R>::TABLE[(h & 15) as usize]
    }
}

impl GradientLattice<4> for Perlin {
    type Fade = Quintic;
    fn corner_hashes(&self, cell: [i32; 4]) -> [u32; MAX_CORNERS] {
        self.corners(cell)
    }
    #[inline]
    fn dot<R: Real>(&self, h: u32, d: &[R; 4]) -> R {
        // Axis (h >> 3) & 3 is zero; bits 0..3 give the signs of the other three in order.
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
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; 4] {
        let zero = (h >> 3 & 3) as usize;
        let mut g = [R::ZERO; 4];
        let mut bit = 0;
        for (a, ga) in g.iter_mut().enumerate() {
            if a != zero {
                *ga = signed(h, bit, R::ONE);
                bit += 1;
            }
        }
        g
    }
}

gradient_noise_impls!(Perlin, [], |_, d| half_dims(d));
crate::noise::inherent_amplitude_bound!(Perlin, []);

#[cfg(test)]
mod tests {
    use super::{GRAD3, grad3};

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
