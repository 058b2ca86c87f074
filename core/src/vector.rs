//! Vector noise: curl noise (Bridson, Hourihan and Nordenstam, "Curl-Noise for Procedural
//! Fluid Flow", SIGGRAPH 2007, §2–§3), vectors of independent noises, and domain warping by
//! them (Lewis 1989, "Algorithms for Solid Noise Synthesis", §5.3: stochastic deformation).
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

use crate::{Error, I16F16, Noise, NoiseGradient, Real};

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

/// A vector noise of `D` independent scalar noises, one per component: Lewis's vector noise
/// for stochastic deformation ("three independent scalar solid noises form the components of
/// the vector field", §5.3), or any displacement field.
///
/// The components should be uncorrelated, as different seeds of one noise are; one noise in
/// every component would displace along the diagonal only.
///
/// * **Range**: each component within its noise's bound.
///
/// ```
/// use bandnoise::{Noise, lattice::Perlin, vector::{Components, VectorNoise}};
///
/// let v = Components::new([Perlin::new(1), Perlin::new(2)]);
/// let [a, b]: [f32; 2] = v.sample_vector([0.3, 4.7]);
/// assert_eq!(a, Perlin::new(1).sample([0.3f32, 4.7]));
/// # let _ = b;
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Components<N, const D: usize> {
    noises: [N; D],
}

impl<N, const D: usize> Components<N, D> {
    /// The vector noise whose component `a` is `noises[a]`.
    #[must_use]
    pub const fn new(noises: [N; D]) -> Self {
        Self { noises }
    }

    /// The components' noises.
    #[must_use]
    pub const fn noises(&self) -> &[N; D] {
        &self.noises
    }
}

impl<R: Real, N: Noise<R, D>, const D: usize> VectorNoise<R, D> for Components<N, D> {
    #[inline]
    fn sample_vector(&self, p: [R; D]) -> [R; D] {
        core::array::from_fn(|a| self.noises[a].sample(p))
    }
}

/// Domain warping: `noise(p + amplitude · displacement(p))`, Lewis's stochastic deformation
/// (§5.3: he perturbs a model's vertices by a vector of independent noises;
/// [`displace`](Self::displace) is that perturbation) applied to a noise's domain. Any [`VectorNoise`] displaces:
/// [`Components`] of independent noises (Lewis's), or curl noise ([`Curl2`], [`Curl3`]) for a
/// warp that neither compresses nor stretches the domain on average.
///
/// * **Amplitude**: how far a point moves, in the noise's units, per unit of displacement;
///   validated finite and within ±1024, exact in floats and rounded once to 2⁻¹⁶ in fixed
///   point. 0 gives the noise itself.
/// * **Range**: the noise's: the warp moves points, never values.
/// * **Fixed point**: the displaced coordinate saturates at I16F16's range.
/// * **Batches**: point by point (the displacement depends on each point).
///
/// ```
/// use bandnoise::{Noise, lattice::Perlin, simplex::Simplex, vector::{Components, Warp}};
///
/// let warp = Components::new([Simplex::new(11), Simplex::new(12)]);
/// let marble = Warp::new(Perlin::new(1), warp, 0.8).unwrap();
/// let v: f32 = marble.sample([0.3, 4.7]);
/// assert!(v.abs() <= marble.amplitude_bound::<2>());
/// assert!(Warp::new(Perlin::new(1), Components::new([Simplex::new(1), Simplex::new(2)]), f32::NAN)
///     .is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Warp<N, V> {
    noise: N,
    displacement: V,
    amplitude: f32,
    amplitude_fixed: I16F16,
}

impl<N, V> Warp<N, V> {
    /// The largest amplitude's magnitude.
    pub const MAX_AMPLITUDE: f32 = 1024.0;

    /// `noise` warped by `amplitude · displacement`.
    ///
    /// # Errors
    ///
    /// [`Error::WarpAmplitude`] unless `amplitude` is finite and `|amplitude| ≤ 1024`.
    pub fn new(noise: N, displacement: V, amplitude: f32) -> Result<Self, Error> {
        if amplitude.is_nan() || amplitude.abs() > Self::MAX_AMPLITUDE {
            return Err(Error::WarpAmplitude(amplitude));
        }
        Ok(Self {
            noise,
            displacement,
            amplitude,
            amplitude_fixed: I16F16::from_f32(amplitude),
        })
    }

    /// `noise` warped by this displacement and amplitude.
    pub(crate) fn with_noise<M>(&self, noise: M) -> Warp<M, V>
    where
        V: Clone,
    {
        Warp {
            noise,
            displacement: self.displacement.clone(),
            amplitude: self.amplitude,
            amplitude_fixed: self.amplitude_fixed,
        }
    }

    /// The noise warped.
    #[must_use]
    pub const fn noise(&self) -> &N {
        &self.noise
    }

    /// The displacement field.
    #[must_use]
    pub const fn displacement(&self) -> &V {
        &self.displacement
    }

    /// The amplitude.
    #[must_use]
    pub const fn amplitude(&self) -> f32 {
        self.amplitude
    }

    /// Lewis's stochastic deformation of the point `p`: `p + amplitude · displacement(p)`
    /// (saturating at I16F16's range), the point the warped noise samples at `p`. For a model,
    /// deform its vertices.
    #[inline]
    #[must_use]
    pub fn displace<R: Real, const D: usize>(&self, p: [R; D]) -> [R; D]
    where
        V: VectorNoise<R, D>,
    {
        let amplitude = R::from_setting(self.amplitude, self.amplitude_fixed);
        let v = self.displacement.sample_vector(p);
        core::array::from_fn(|a| p[a].saturating_add(amplitude.saturating_mul(v[a])))
    }
}

impl<R, N, V, const D: usize> Noise<R, D> for Warp<N, V>
where
    R: Real,
    N: Noise<R, D>,
    V: VectorNoise<R, D>,
{
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        self.noise.sample(self.displace(p))
    }

    fn amplitude_bound(&self) -> f32 {
        self.noise.amplitude_bound()
    }
}

/// The gradient by the chain rule, where the displacement is [`Components`] of noises with
/// gradients: `∇(n∘q)(p) = J_qᵀ ∇n(q)` with `J_q = I + amplitude · J_v`, row `a` of `J_v` the
/// gradient of component `a`. The value is [`sample`](Noise::sample)'s, bit for bit.
impl<R, N, M, const D: usize> NoiseGradient<R, D> for Warp<N, Components<M, D>>
where
    R: Real,
    N: NoiseGradient<R, D>,
    M: NoiseGradient<R, D>,
{
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        let amplitude = R::from_setting(self.amplitude, self.amplitude_fixed);
        let components = self
            .displacement
            .noises
            .each_ref()
            .map(|n| n.sample_with_gradient(p));
        let q: [R; D] = core::array::from_fn(|a| {
            p[a].saturating_add(amplitude.saturating_mul(components[a].0))
        });
        let (value, g) = self.noise.sample_with_gradient(q);
        let gradient = core::array::from_fn(|b| {
            let mut chain = R::ZERO;
            for (ga, (_, dv)) in g.iter().zip(&components) {
                chain = chain.saturating_add(ga.saturating_mul(dv[b]));
            }
            g[b].saturating_add(amplitude.saturating_mul(chain))
                .canonical()
        });
        (value, gradient)
    }
}

crate::noise::inherent_amplitude_bound!(Warp<N, V>, [N, V]);

/// `−x`, total: fixed point's most negative value (which has no negation) gives the largest
/// value; `-0.0` gives `+0.0`.
#[inline]
fn negate<R: Real>(x: R) -> R {
    (-x.clamp_to(-R::MAX, R::MAX)).canonical()
}
