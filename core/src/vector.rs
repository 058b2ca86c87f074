//! Vector noise: curl noise (Bridson, Hourihan and Nordenstam, "Curl-Noise for Procedural
//! Fluid Flow", SIGGRAPH 2007, §2–§3).
//!
//! A velocity field that is the curl of a potential has no divergence: particles advected by it
//! neither bunch up nor thin out, which is what makes it look like incompressible flow. Bridson
//! et al. build the potential from noise: in 2D a scalar `ψ`, whose curl is its gradient turned
//! a quarter turn, `(∂ψ/∂y, −∂ψ/∂x)`; in 3D a vector `(ψ₁, ψ₂, ψ₃)` of three uncorrelated noises,
//! whose curl is `(∂ψ₃/∂y − ∂ψ₂/∂z, ∂ψ₁/∂z − ∂ψ₃/∂x, ∂ψ₂/∂x − ∂ψ₁/∂y)`.
//!
//! bandnoise takes the potentials' derivatives from their analytic gradients
//! ([`NoiseGradient`]), not from finite differences as the paper's implementation does, so the
//! field is divergence-free up to rounding (`tests/tests/vector.rs` measures the divergence by
//! central differences) and costs one gradient sample per potential. Any noise with a
//! gradient can be a potential, in any number type: a fractal sum of simplex noise for
//! turbulent flow, one band of wavelet noise for a flow of one scale.
//!
//! # Examples
//!
//! ```
//! use bandnoise::prelude::*;
//! use bandnoise::vector::{Curl2, Curl3, VectorNoise};
//!
//! // 2D: the gradient of simplex noise turned a quarter turn.
//! let flow = Curl2::new(Simplex::new(1));
//! let [u, v]: [f32; 2] = flow.sample_vector([0.3, 4.7]);
//! let (_, g): (f32, [f32; 2]) = Simplex::new(1).sample_with_gradient([0.3, 4.7]);
//! assert_eq!([u, v], [g[1], -g[0]]);
//!
//! // 3D: three uncorrelated potentials (here three seeds).
//! let flow = Curl3::new(Perlin::new(1), Perlin::new(2), Perlin::new(3));
//! let w: [f32; 3] = flow.sample_vector([0.3, 4.7, -1.2]);
//! assert!(w.iter().all(|c| c.is_finite()));
//! ```

use crate::{NoiseGradient, Real};

/// A noise whose value at a point is a vector of `D` components.
pub trait VectorNoise<R: Real, const D: usize> {
    /// The vector at `p`. Defined for every input as the potentials' gradients are (a
    /// non-finite coordinate samples the origin's cell for the lattice noises).
    #[must_use]
    fn sample_vector(&self, p: [R; D]) -> [R; D];
}

/// 2D curl noise: the curl `(∂ψ/∂y, −∂ψ/∂x)` of the scalar potential `ψ`, its analytic gradient
/// turned a quarter turn (so exactly the gradient's components, one negated).
///
/// * **Divergence**: zero up to rounding wherever `ψ` is twice differentiable (every gradient
///   noise of the crate: the quintic fade, simplex noise's fourth-power kernel, B-splines).
/// * **Range**: each component within the potential's largest gradient component.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Curl2<N> {
    potential: N,
}

impl<N> Curl2<N> {
    /// Curl noise of the potential `potential`.
    #[must_use]
    pub const fn new(potential: N) -> Self {
        Self { potential }
    }

    /// The potential.
    #[must_use]
    pub const fn potential(&self) -> &N {
        &self.potential
    }
}

impl<R: Real, N: NoiseGradient<R, 2>> VectorNoise<R, 2> for Curl2<N> {
    #[inline]
    fn sample_vector(&self, p: [R; 2]) -> [R; 2] {
        let (_, g) = self.potential.sample_with_gradient(p);
        [g[1], negate(g[0])]
    }
}

/// 3D curl noise: the curl of the vector potential `(ψ₁, ψ₂, ψ₃)`,
/// `(∂ψ₃/∂y − ∂ψ₂/∂z, ∂ψ₁/∂z − ∂ψ₃/∂x, ∂ψ₂/∂x − ∂ψ₁/∂y)`, from each potential's analytic
/// gradient.
///
/// The three potentials should be uncorrelated (three seeds of one noise, as in the example
/// of the [module](self)): correlated ones cancel in the differences and weaken the flow.
///
/// * **Divergence**: zero up to rounding wherever the potentials are twice differentiable.
/// * **Range**: each component within twice the potentials' largest gradient component
///   (fixed point sums them with saturation).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Curl3<A, B = A, C = A> {
    potentials: (A, B, C),
}

impl<A, B, C> Curl3<A, B, C> {
    /// Curl noise of the potential `(first, second, third)`.
    #[must_use]
    pub const fn new(first: A, second: B, third: C) -> Self {
        Self {
            potentials: (first, second, third),
        }
    }

    /// The three potentials.
    #[must_use]
    pub const fn potentials(&self) -> &(A, B, C) {
        &self.potentials
    }
}

impl<R, A, B, C> VectorNoise<R, 3> for Curl3<A, B, C>
where
    R: Real,
    A: NoiseGradient<R, 3>,
    B: NoiseGradient<R, 3>,
    C: NoiseGradient<R, 3>,
{
    #[inline]
    fn sample_vector(&self, p: [R; 3]) -> [R; 3] {
        let (_, g1) = self.potentials.0.sample_with_gradient(p);
        let (_, g2) = self.potentials.1.sample_with_gradient(p);
        let (_, g3) = self.potentials.2.sample_with_gradient(p);
        let curl = |a: R, b: R| a.saturating_add(negate(b)).canonical();
        [curl(g3[1], g2[2]), curl(g1[2], g3[0]), curl(g2[0], g1[1])]
    }
}

/// `−x`, total: fixed point's most negative value (which has no negation) gives the largest
/// value; `-0.0` gives `+0.0`.
#[inline]
fn negate<R: Real>(x: R) -> R {
    (-x.clamp_to(-R::MAX, R::MAX)).canonical()
}
