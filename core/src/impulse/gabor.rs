//! Gabor noise (Lagae, Lefebvre, Drettakis and Dutré 2009; the survey, Lagae et al. 2010,
//! §3.3; random phases as in Lagae and Drettakis 2011, §3.3): [`Gabor`], whose docs give the
//! kernel, the variants, the envelopes and the normalisation.

use super::{Impulses, PerCell, Weights, walk, walk_lanes};
use crate::batch::{self, LANES};
use crate::hash::{CellHash, CellRng};
use crate::radial::{GAUSSIAN_RATE, Profile, Table, ball_volume, knots, power_in, powers};
use crate::special::{cis_turns_f64, cos_turn_f64, q30};
use crate::wavelet::constmath;
use crate::wavelet::unit_normal;
use crate::{Error, I16F16, Noise, NoiseGradient, ProjectedNoise, Real};

/// How the impulses' kernels are oriented ([`Gabor`]'s variants).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// Every kernel along the noise's direction: two spectral lobes at `±F₀ ω`.
    #[default]
    Anisotropic,
    /// Each kernel along a direction of its own, uniform on the circle or sphere: a ring or
    /// shell of radius `F₀`.
    Isotropic,
    /// Each kernel along a direction of its own, uniform in the xy plane
    /// (OpenShadingLanguage's hybrid noise; the same as isotropic in 1D and 2D).
    Hybrid,
}

/// The kernel's envelope ([`Gabor`]'s envelope and truncation).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Envelope {
    /// The Gaussian times Hann's window in `d²`: `C¹`, 0 at the kernel's radius.
    #[default]
    Hann,
    /// The Gaussian cut at 5% of its peak (Lagae et al. 2009): a jump of 5% at the radius.
    Truncated,
}

impl Envelope {
    /// The envelope as a radial profile.
    const fn profile(self) -> Profile {
        match self {
            Envelope::Hann => Profile::GaussianHann,
            Envelope::Truncated => Profile::Gaussian,
        }
    }

    /// The envelope at squared distance `s` in cell units (kernel radii) and its derivative
    /// in `s`, in `f64`, from its formula: what the tables hold, and what tests compare with.
    #[must_use]
    pub const fn exact(self, s: f64) -> (f64, f64) {
        self.profile().exact(s)
    }

    /// The table of the envelope.
    fn table(self) -> &'static Table {
        match self {
            Envelope::Hann => &HANN,
            Envelope::Truncated => &GAUSSIAN,
        }
    }

    /// `∫ e(|x|)² dx` over the unit ball in `d` dimensions (1 to 3), from a table built at
    /// compile time.
    fn power_of(self, d: usize) -> f64 {
        const HANN_POWERS: [f64; 4] = powers(Profile::GaussianHann);
        const GAUSSIAN_POWERS: [f64; 4] = powers(Profile::Gaussian);
        match self {
            Envelope::Hann => power_in(&HANN_POWERS, d),
            Envelope::Truncated => power_in(&GAUSSIAN_POWERS, d),
        }
    }
}

/// The envelopes' tables: 65 knots, `Δ = 1/64` (errors below 3e-7: `tests` in this module).
static HANN: Table = Table::new(Profile::GaussianHann, &HANN_KNOTS);
static HANN_KNOTS: [[i32; 2]; 65] = knots(Profile::GaussianHann);
static GAUSSIAN: Table = Table::new(Profile::Gaussian, &GAUSSIAN_KNOTS);
static GAUSSIAN_KNOTS: [[i32; 2]; 65] = knots(Profile::Gaussian);

/// The kernel's radius times `a`: `√(ln 20 / π)`, where the Gaussian is 5% of its peak.
pub const RADIUS_TIMES_BANDWIDTH: f64 = constmath::sqrt(GAUSSIAN_RATE / core::f64::consts::PI);

/// A setting in floats and in fixed point, rounded once from `f64`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Setting {
    float: f32,
    fixed: I16F16,
}

impl Setting {
    fn of(v: f64) -> Self {
        Self {
            float: v as f32,
            fixed: I16F16::from_f32(v as f32),
        }
    }

    #[inline]
    fn get<R: Real>(self) -> R {
        R::from_setting(self.float, self.fixed)
    }

    /// `[cos 2πk, sin 2πk]` for this setting `k` in turns, each type's from its own rounding
    /// of `k` (so that a kernel's harmonic is the same seen from either cell within the
    /// type's precision).
    #[inline(never)]
    fn turn(self) -> [Self; 2] {
        let f = cis_turns_f64(self.float as f64);
        let q = cis_turns_f64(self.fixed.to_num::<f64>());
        let of = |i: usize| Self {
            fixed: Self::of(q[i]).fixed,
            ..Self::of(f[i])
        };
        [of(0), of(1)]
    }
}

/// Gabor noise's parameters, for building it in one step from a description (a chain of
/// builders would move the noise, 480 bytes, through the stack at each step: more than a
/// microcontroller's checksum program has).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Parameters {
    pub(crate) frequency: f32,
    pub(crate) bandwidth: f32,
    /// Up to 3 components; a noise in `D` dimensions takes the first `D`.
    pub(crate) direction: [f32; 3],
    pub(crate) orientation: Orientation,
    pub(crate) envelope: Envelope,
    pub(crate) magnitude: f32,
}

impl Parameters {
    /// The defaults of [`Gabor::new`].
    pub(crate) const DEFAULT: Self = Self {
        frequency: DEFAULT_FREQUENCY,
        bandwidth: DEFAULT_BANDWIDTH,
        direction: [1.0, 0.0, 0.0],
        orientation: Orientation::Anisotropic,
        envelope: Envelope::Hann,
        magnitude: 1.0,
    };

    /// Checks the spectrum: [`Gabor::with_spectrum`]'s errors.
    pub(crate) fn check_spectrum(frequency: f32, bandwidth: f32) -> Result<(), Error> {
        if !(MIN_BANDWIDTH..=MAX_BANDWIDTH).contains(&bandwidth) {
            return Err(Error::Bandwidth(bandwidth));
        }
        if !(0.0..=MAX_FREQUENCY_RATIO * bandwidth).contains(&frequency) {
            return Err(Error::Frequency {
                frequency,
                bandwidth,
                max_ratio: MAX_FREQUENCY_RATIO,
            });
        }
        Ok(())
    }

    /// Checks the magnitude: [`Gabor::with_magnitude`]'s error.
    pub(crate) fn check_magnitude(magnitude: f32) -> Result<(), Error> {
        if (-MAX_MAGNITUDE..=MAX_MAGNITUDE).contains(&magnitude) {
            Ok(())
        } else {
            Err(Error::Magnitude(magnitude))
        }
    }

    /// The unit direction from the first `D` components: [`Gabor::with_direction`]'s error.
    pub(crate) fn unit_direction<const D: usize>(&self) -> Result<[f32; D], Error> {
        let d: [f32; D] = core::array::from_fn(|a| self.direction.get(a).copied().unwrap_or(0.0));
        let length = libm::sqrt(d.iter().map(|&c| c as f64 * c as f64).sum::<f64>());
        // Finite components give a finite length; NaN fails the range test.
        if !d.iter().all(|c| c.is_finite()) || !(1e-30..).contains(&length) {
            return Err(Error::Direction);
        }
        Ok(d.map(|c| (c as f64 / length) as f32))
    }
}

const DEFAULT_FREQUENCY: f32 = 1.0;
const DEFAULT_BANDWIDTH: f32 = 0.8;
const MIN_BANDWIDTH: f32 = 1.0 / 256.0;
const MAX_BANDWIDTH: f32 = 256.0;
const MAX_FREQUENCY_RATIO: f32 = 64.0;
const MAX_MAGNITUDE: f32 = 1024.0;

/// An impulse's own random parameters, in cell units: its harmonic's wave vector (turns per
/// kernel radius along each axis) and its phase (turns).
struct Params<R, const D: usize> {
    wave: [R; D],
    /// The phase in turns relative to the impulse's position, for kernels of their own
    /// direction (0 for kernels along the noise's, whose phase is `cis`).
    phase: R,
    /// `cos 2πφ` and `sin 2πφ` of the phase relative to the cell's corner, for kernels along
    /// the noise's direction (from [`PHASES`]; `[1, 0]` for the others).
    cis: [R; 2],
    /// The unit direction (the wave vector over `F₀ r`), for surface noise.
    direction: [R; D],
}

/// Gabor noise in `D` dimensions, 1 to 3 (Lagae, Lefebvre, Drettakis and Dutré 2009,
/// "Procedural Noise using Sparse Gabor Convolution"; the survey, Lagae et al. 2010, §3.3,
/// eqs. 7–9), in its random-phase
/// form (Lagae and Drettakis 2011, "Filtering Solid Gabor Noise", §3.3, as OpenShadingLanguage
/// implements it):
///
/// ```text
/// g(x) = K e^{−π a² |x|²} cos(2π F₀ ω·x + φ)          N(x) = Σ_i w_i g_i(x − x_i)
/// ```
///
/// a Gaussian envelope of inverse width `a` (the bandwidth) times a harmonic of frequency `F₀`
/// along the unit direction `ω`, with a random phase `φ` per impulse, summed over the random
/// impulses `x_i` of the [impulse walk](crate::impulse) (sparse convolution with a Gabor kernel). Its
/// power spectrum is the kernel's: two Gaussian lobes of width `a` at `±F₀ ω` (eq. 8), so the
/// three parameters place the noise's energy where the user wants it: principal frequency,
/// orientation and bandwidth.
///
/// # Variants
///
/// * [`Orientation::Anisotropic`]: every impulse has the noise's direction (the survey's
///   anisotropic noise: two lobes).
/// * [`Orientation::Isotropic`]: each impulse draws its own direction, uniform on the circle
///   (2D) or the sphere (3D): the spectrum is a ring (2D) or a shell (3D) of radius `F₀`.
/// * [`Orientation::Hybrid`] (OpenShadingLanguage's): each impulse's direction is uniform in
///   the xy plane: isotropic within every plane `z = const` of 3D noise, unchanging along z
///   (in 1D and 2D it is the isotropic variant).
///
/// # Envelope and truncation
///
/// The Gaussian is cut where it falls to 5% of its peak, at `r = √(ln 20 / π) / a` (Lagae et
/// al. 2009's "kernel radius"); cells are `r` wide, so the `3^D` cells around a point hold
/// every impulse in reach. [`Envelope::Truncated`] is that kernel, which jumps by 5% of its
/// peak at `r`: the noise has small discontinuities (the paper's). [`Envelope::Hann`] (the
/// default) multiplies the Gaussian by Hann's window in `d² = |x|²/r²`, `½ + ½ cos(π d²)`, as
/// Blender's Gabor texture does: the kernel and the noise are `C¹`, at the price of a slightly
/// narrower envelope, so lobes wider than `a` says (by a fifth: measured in
/// `tests/tests/gabor.rs`). Both envelopes are read from a table of `d²` (65 knots, Q2.30,
/// cubic Hermite: within 3e-7 of their formulas, [`Envelope::exact`]), the harmonic from
/// [`Real::cos_turns`]: per impulse for kernels of their own direction; per sample and cell
/// for kernels along the noise's direction (see [Random numbers](Self#random-numbers)).
///
/// # Normalisation
///
/// With random phases `E[cos²] = ½` whatever `F₀` and `ω`, so Campbell's theorem gives the
/// variance in closed form, `Var N = λ E[w²] · ½ ∫ e(x)² dx` (`λ` impulses per unit volume,
/// `e` the envelope; the integral is computed at compile time for each envelope), and the noise
/// is scaled by `K / √Var`: variance `K²`, mean 0, for every frequency, bandwidth, orientation,
/// density and dimension (the 2009 paper's `(1 + e^{−2πF₀²/a²})` interference term of a
/// phase-free kernel does not arise).
///
/// # Random numbers
///
/// Per impulse, after the walk's position draw (and uniform weight), one 32-bit draw:
///
/// * Kernels along the noise's direction `k` (the anisotropic variant, and every variant in
///   1D): the top 6 bits give the phase `φ` relative to the corner `c` of the impulse's
///   cell, one of 64 bin centres `(2j + 1)/128` turns, so the harmonic is `cos 2π(k·(p − c) +
///   φ)`. That is the kernel `cos 2π(k·(p − x_i) + φ_i)` of the phase `φ_i = φ + k·(x_i − c)`
///   relative to the impulse at `x_i`, which is uniform and independent of the impulse's
///   position as `φ` is: the same random-phase noise, whose `cos` and `sin` of `2π k·(p − c)`
///   are computed once per cell and sample (two [`Real::cos_turns`] per axis, turned by
///   `±2π k_a` for the neighbouring cells), so that an impulse costs two products with its
///   phase's `cos` and `sin` (a table of 64 in Q2.30) instead of a cosine. With 64 phases
///   `E[cos²]` is exactly ½ and the spectrum is the continuous phases' (the covariance of a
///   kernel with itself averages `cos 2π(θ + φ) cos 2π(θ′ + φ)` over the phases, `½ cos
///   2π(θ − θ′)` for any 3 or more equally spaced phases).
/// * Kernels of their own direction (isotropic and hybrid): the top 16 bits give the phase
///   relative to the impulse and the low 16 bits the direction's angle (bin centres `(2k +
///   1)/2¹⁷` turns: exact in every number type); in 3D isotropic noise a second draw's top 16
///   bits give the direction's `z` (uniform in `(−1, 1)`, which makes the direction uniform on
///   the sphere, Archimedes).
///
/// # Surface noise
///
/// `Gabor<3>` is a [`ProjectedNoise`]: `sample_projected(p, normal)` is the noise on the
/// surface through `p`, each kernel's direction turned into the tangent plane (Lagae et al.
/// 2009's surface noise without set-up), band-limited on the surface where a slice of the
/// solid noise is not (the impl's docs say how).
///
/// # Filtering
///
/// `Gabor<2>` is a [`FilteredNoise`](crate::FilteredNoise): `sample_filtered(p, dpdx, dpdy)`
/// filters each kernel analytically by the Gaussian of the sample's footprint (Lagae et al.
/// 2009 §5, anisotropic: the impl's docs say how), so a render needs no supersampling.
///
/// # Parameters
///
/// Coordinates are in the user's units: the frequency `F₀` is in cycles per unit, the
/// bandwidth `a` in the same units' inverse (the envelope is `e^{−π a² |x|²}`). The defaults
/// are `F₀ = 1`, `a = 0.8` (the ratio of Lagae et al.'s example, `F₀ = 0.0625`, `a = 0.05`),
/// the anisotropic variant along the x axis, the `C¹` [`Envelope::Hann`], 16 impulses per
/// kernel volume (OpenShadingLanguage's default) with Poisson counts and ±1 weights, and
/// magnitude `K = 1` (variance 1).
///
/// # Fixed point
///
/// A point is taken to cell units, `p / r`, before the walk. In I16F16 that product wraps
/// modulo 2¹⁶ cells ([`Real::wrapping_mul`], as octave frequencies do): where `|p| / r` reaches
/// 2¹⁵ (32768 kernel radii: `|p| ≥ 32768 · 0.977 / a`, so only for bandwidths above 0.977, whose
/// radius is under a unit; at `a = 2`, from 16,000 units) the fixed-point noise reads another
/// cell than `f32` does: a defined value of the same noise, but not `f32`'s. Below that, fixed
/// point follows the noise within the tables' and roundings' error (`tests/tests/gabor.rs`:
/// within 2e-3 of `f64` up to the limit, where `f32`'s own rounding of `p / r` is 2⁻⁹ cells).
///
/// # Amplitude
///
/// Variance `K²` and mean 0 (see [Normalisation](Self#normalisation)). Each of the `3^D` cells holds at
/// most [`Impulses::cap`] impulses of weight at most 1, and a kernel is at most 1, so
/// `|N| ≤ 3^D · cap · |K| / σ` ([`amplitude_bound`](Noise::amplitude_bound)): a proved
/// bound, far above what occurs.
///
/// # Examples
///
/// ```
/// use bandnoise::{Error, I16F16, Noise, impulse::{Gabor, Orientation}};
///
/// // Stripes at 45°, two cycles per unit, fairly narrow-band.
/// let stripes = Gabor::<2>::new(7)
///     .with_frequency(2.0)?
///     .with_bandwidth(0.5)?
///     .with_angle(core::f32::consts::FRAC_PI_4)?;
/// let v: f32 = stripes.sample([0.5, 1.25]);
/// assert!(v.abs() <= stripes.amplitude_bound());
///
/// // Isotropic solid noise, in fixed point too.
/// let solid = Gabor::<3>::new(7).with_orientation(Orientation::Isotropic);
/// let p = [0.5f32, 1.25, -2.0];
/// let q: I16F16 = solid.sample(p.map(I16F16::from_num));
/// assert!((q.to_num::<f32>() - solid.sample(p)).abs() < 2e-3);
/// # Ok::<(), Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Gabor<const D: usize> {
    hash: CellHash,
    impulses: Impulses,
    orientation: Orientation,
    envelope: Envelope,
    magnitude: f32,
    frequency: f32,
    bandwidth: f32,
    /// The unit direction of the anisotropic variant.
    direction: [f32; D],
    /// `1/r`: coordinates times this are in cell units.
    to_cells: Setting,
    /// `F₀ r`: the harmonic's turns per kernel radius.
    turns: Setting,
    /// `F₀ r ω`: the anisotropic wave vector in turns per kernel radius.
    wave: [Setting; D],
    /// `[cos 2π k_a, sin 2π k_a]` for each component `k_a` of `wave` as each type rounds it.
    turn: [[Setting; 2]; D],
    /// `K/σ`.
    scale: Setting,
}

impl<const D: usize> Gabor<D> {
    /// The default frequency `F₀`, cycles per unit.
    pub const DEFAULT_FREQUENCY: f32 = DEFAULT_FREQUENCY;
    /// The default bandwidth `a`.
    pub const DEFAULT_BANDWIDTH: f32 = DEFAULT_BANDWIDTH;
    /// The default density, impulses per kernel volume.
    pub const DEFAULT_DENSITY: f32 = 16.0;
    /// The smallest bandwidth (a kernel 250 units wide).
    pub const MIN_BANDWIDTH: f32 = MIN_BANDWIDTH;
    /// The largest bandwidth (a kernel 1/260 unit wide).
    pub const MAX_BANDWIDTH: f32 = MAX_BANDWIDTH;
    /// The largest ratio `F₀ / a` (62 cycles within a kernel's radius: a nearly pure tone).
    pub const MAX_FREQUENCY_RATIO: f32 = MAX_FREQUENCY_RATIO;
    /// The largest magnitude `K`.
    pub const MAX_MAGNITUDE: f32 = MAX_MAGNITUDE;

    /// The noise for `seed`, with the defaults above.
    #[must_use]
    pub fn new(seed: u32) -> Self {
        let impulses =
            Impulses::poisson_checked(Self::per_cell(Self::DEFAULT_DENSITY), Weights::Sign);
        let direction = core::array::from_fn(|a| if a == 0 { 1.0 } else { 0.0 });
        Self::assemble(seed, &Parameters::DEFAULT, direction, impulses)
    }

    /// The noise for `seed` with `parameters` (checked here) and `impulses` (checked by the
    /// caller: [`check_density`](Self::check_density)), in one step.
    pub(crate) fn build(
        seed: u32,
        parameters: &Parameters,
        impulses: Impulses,
    ) -> Result<Self, Error> {
        Parameters::check_spectrum(parameters.frequency, parameters.bandwidth)?;
        Parameters::check_magnitude(parameters.magnitude)?;
        let direction = parameters.unit_direction::<D>()?;
        Ok(Self::assemble(seed, parameters, direction, impulses))
    }

    /// The noise from checked parts.
    fn assemble(
        seed: u32,
        parameters: &Parameters,
        direction: [f32; D],
        impulses: Impulses,
    ) -> Self {
        const { assert!(D >= 1 && D <= 3, "Gabor noise has 1 to 3 dimensions") };
        Self {
            hash: CellHash::new(seed),
            impulses,
            orientation: parameters.orientation,
            envelope: parameters.envelope,
            magnitude: parameters.magnitude,
            frequency: parameters.frequency,
            bandwidth: parameters.bandwidth,
            direction,
            to_cells: Setting::default(),
            turns: Setting::default(),
            wave: [Setting::default(); D],
            turn: [[Setting::default(); 2]; D],
            scale: Setting::default(),
        }
        .derive()
    }

    /// `1/r` rounded to a multiple of 2⁻¹⁶, so that `f32`, `f64` and I16F16 scale coordinates
    /// by the same number (a fixed-point scale rounded on its own would shift the cells of
    /// points far from the origin by up to `|p| · 2⁻¹⁷`, hence the harmonic's phase): the
    /// kernel's radius as used, within `2⁻¹⁷ r` of `√(ln 20/π)/a` (0.2% at the smallest
    /// bandwidth, 10⁻⁵ at the default).
    fn to_cells_exact(&self) -> f64 {
        let exact = self.bandwidth as f64 / RADIUS_TIMES_BANDWIDTH;
        libm::round(exact * 65536.0).max(1.0) / 65536.0
    }

    /// Computes the derived settings from the parameters.
    fn derive(mut self) -> Self {
        let to_cells = self.to_cells_exact();
        let turns = self.frequency as f64 / to_cells;
        self.to_cells = Setting::of(to_cells);
        self.turns = Setting::of(turns);
        self.wave = core::array::from_fn(|a| Setting::of(turns * self.direction[a] as f64));
        for (turn, k) in self.turn.iter_mut().zip(&self.wave) {
            *turn = k.turn();
        }
        self.scale = Setting::of(self.magnitude as f64 / self.sigma());
        self
    }

    /// The mean count per cell (of volume 1 in kernel radii) for `density` per kernel volume.
    pub(crate) fn per_cell(density: f32) -> f32 {
        (density as f64 / ball_volume(D)) as f32
    }

    /// The largest density in `D` dimensions: 32 impulses per cell on average, `32 · V_D` per
    /// kernel volume (64 in 1D, 100.5 in 2D, 134 in 3D).
    #[must_use]
    pub fn max_density() -> f32 {
        (32.0 * ball_volume(D)) as f32
    }

    /// [`with_density`](Self::with_density)'s check.
    pub(crate) fn check_density(density: f32) -> Result<(), Error> {
        let max = Self::max_density();
        if (super::MIN_DENSITY..=max).contains(&density) {
            Ok(())
        } else {
            Err(Error::Density {
                density,
                min: super::MIN_DENSITY,
                max,
            })
        }
    }

    /// The same noise at frequency `F₀` cycles per unit.
    ///
    /// # Errors
    ///
    /// [`Error::Frequency`] unless `0 ≤ F₀ ≤ MAX_FREQUENCY_RATIO · a` (to raise both far, use
    /// [`with_spectrum`](Self::with_spectrum)).
    pub fn with_frequency(self, frequency: f32) -> Result<Self, Error> {
        let bandwidth = self.bandwidth;
        self.with_spectrum(frequency, bandwidth)
    }

    /// The same noise with bandwidth `a` (the envelope `e^{−π a² |x|²}`; lobes of that width
    /// in frequency).
    ///
    /// # Errors
    ///
    /// [`Error::Bandwidth`] unless `a` is in `[MIN_BANDWIDTH, MAX_BANDWIDTH]`;
    /// [`Error::Frequency`] if the frequency would exceed `MAX_FREQUENCY_RATIO · a`.
    pub fn with_bandwidth(self, bandwidth: f32) -> Result<Self, Error> {
        let frequency = self.frequency;
        self.with_spectrum(frequency, bandwidth)
    }

    /// The same noise with frequency `F₀` and bandwidth `a` together (so that neither is
    /// checked against the other's old value).
    ///
    /// # Errors
    ///
    /// [`Error::Bandwidth`] unless `a` is in `[MIN_BANDWIDTH, MAX_BANDWIDTH]`;
    /// [`Error::Frequency`] unless `0 ≤ F₀ ≤ MAX_FREQUENCY_RATIO · a`.
    pub fn with_spectrum(mut self, frequency: f32, bandwidth: f32) -> Result<Self, Error> {
        Parameters::check_spectrum(frequency, bandwidth)?;
        self.frequency = frequency;
        self.bandwidth = bandwidth;
        Ok(self.derive())
    }

    /// The same noise with the anisotropic direction `direction` (any finite non-zero vector;
    /// it is normalised).
    ///
    /// # Errors
    ///
    /// [`Error::Direction`] if a component is not finite or the vector is zero (or too small
    /// to normalise).
    pub fn with_direction(mut self, direction: [f32; D]) -> Result<Self, Error> {
        let parameters = Parameters {
            direction: core::array::from_fn(|a| direction.get(a).copied().unwrap_or(0.0)),
            ..Parameters::DEFAULT
        };
        self.direction = parameters.unit_direction::<D>()?;
        Ok(self.derive())
    }

    /// The same noise with the anisotropic direction at `angle` radians from the x axis
    /// towards y (the paper's `ω₀`); in 3D, in the xy plane. In 1D only the direction's sign
    /// along x counts.
    ///
    /// # Errors
    ///
    /// [`Error::Direction`] if `angle` is not finite (or, in 1D, at right angles to x).
    pub fn with_angle(self, angle: f32) -> Result<Self, Error> {
        if !angle.is_finite() {
            return Err(Error::Direction);
        }
        let (s, c) = (
            libm::sin(angle as f64) as f32,
            libm::cos(angle as f64) as f32,
        );
        self.with_direction(core::array::from_fn(|a| match a {
            0 => c,
            1 => s,
            _ => 0.0,
        }))
    }

    /// The same noise with kernels oriented as `orientation` says.
    #[must_use]
    pub fn with_orientation(mut self, orientation: Orientation) -> Self {
        self.orientation = orientation;
        self
    }

    /// The same noise with the envelope `envelope`.
    #[must_use]
    pub fn with_envelope(self, envelope: Envelope) -> Self {
        Self { envelope, ..self }.derive()
    }

    /// The same noise with magnitude `K` (its standard deviation; negative flips the sign).
    ///
    /// # Errors
    ///
    /// [`Error::Magnitude`] unless `|K| ≤ MAX_MAGNITUDE`.
    pub fn with_magnitude(self, magnitude: f32) -> Result<Self, Error> {
        Parameters::check_magnitude(magnitude)?;
        Ok(Self { magnitude, ..self }.derive())
    }

    /// The same noise with `density` impulses per kernel volume on average (Poisson counts),
    /// keeping the weights. More is closer to Gaussian and slower (the cost is about
    /// proportional).
    ///
    /// # Errors
    ///
    /// [`Error::Density`] unless `density` is in `[MIN_DENSITY, max_density()]`.
    pub fn with_density(self, density: f32) -> Result<Self, Error> {
        Self::check_density(density)?;
        let impulses = Impulses::poisson_checked(Self::per_cell(density), self.impulses.weights());
        Ok(Self { impulses, ..self }.derive())
    }

    /// The same noise with exactly `per_cell` impulses in every cell, keeping the weights:
    /// with ±1 weights, the fast normalised process of Tavernier et al. 2019 (no count to
    /// draw; `per_cell · V_D` impulses per kernel volume).
    ///
    /// # Errors
    ///
    /// [`Error::ImpulseCount`] unless `1 ≤ per_cell ≤` [`MAX_FIXED`](super::MAX_FIXED).
    pub fn with_fixed_count(self, per_cell: u32) -> Result<Self, Error> {
        let impulses = Impulses::fixed(per_cell)?.with_weights(self.impulses.weights());
        Ok(Self { impulses, ..self }.derive())
    }

    /// The same noise with impulse weights drawn as `weights` says.
    #[must_use]
    pub fn with_weights(self, weights: Weights) -> Self {
        let impulses = self.impulses.clone().with_weights(weights);
        Self { impulses, ..self }.derive()
    }

    /// The frequency `F₀`, cycles per unit.
    #[must_use]
    pub fn frequency(&self) -> f32 {
        self.frequency
    }

    /// The bandwidth `a`.
    #[must_use]
    pub fn bandwidth(&self) -> f32 {
        self.bandwidth
    }

    /// The anisotropic direction (a unit vector).
    #[must_use]
    pub fn direction(&self) -> [f32; D] {
        self.direction
    }

    /// The orientation variant.
    #[must_use]
    pub fn orientation(&self) -> Orientation {
        self.orientation
    }

    /// The envelope.
    #[must_use]
    pub fn envelope(&self) -> Envelope {
        self.envelope
    }

    /// The magnitude `K`.
    #[must_use]
    pub fn magnitude(&self) -> f32 {
        self.magnitude
    }

    /// The impulses per cell.
    #[must_use]
    pub fn impulses(&self) -> &Impulses {
        &self.impulses
    }

    /// The mean number of impulses per kernel volume.
    #[must_use]
    pub fn density(&self) -> f32 {
        (self.impulses.per_cell() as f64 * ball_volume(D)) as f32
    }

    /// The kernel's radius `r = √(ln 20 / π) / a`, in units: the cells' width (`1/r` rounded
    /// to a multiple of 2⁻¹⁶, the same in every number type).
    #[must_use]
    pub fn radius(&self) -> f64 {
        1.0 / self.to_cells_exact()
    }

    /// The standard deviation of the unscaled sum in cell units, `√(λ E[w²] ½ ∫e²)`
    /// ([Normalisation](Self#normalisation)), which the noise divides by.
    #[must_use]
    pub fn sigma(&self) -> f64 {
        libm::sqrt(self.impulses.variance(self.envelope.power_of(D)) / 2.0)
    }

    /// The bound on `|sample(p)|` in every number type (see [Amplitude](Self#amplitude)).
    #[must_use]
    pub fn amplitude_bound(&self) -> f32 {
        let cells = 3u32.pow(D as u32) as f64;
        let scale = (self.scale.float.abs() as f64).max(self.scale.fixed.to_num::<f64>().abs());
        // A little above: the roundings of the sum and of the scale.
        (cells * self.impulses.cap() as f64 * scale * (1.0 + 1e-3) + 1e-3) as f32
    }

    /// Extra draws per impulse: the phase and an isotropic or hybrid angle share one; 3D
    /// isotropic directions take a second for `z`.
    fn extra(&self) -> u32 {
        if D == 3 && self.orientation == Orientation::Isotropic {
            2
        } else {
            1
        }
    }

    /// An impulse's phase and wave vector from its extra draws.
    #[inline]
    fn params<R: Real>(&self, rng: &mut CellRng) -> Params<R, D> {
        let draw = rng.next_u32();
        if self.shared() {
            // One of the PHASES' bins, relative to the cell's corner.
            let j = (draw >> (32 - PHASE_BITS)) as usize;
            return Params {
                wave: self.wave.map(Setting::get),
                phase: R::ZERO,
                cis: phase_cis(j),
                direction: self.direction.map(R::from_f32),
            };
        }
        // Bin centres of 2^16 bins: (2k + 1)/2^17 turns.
        let turn = |bits: u32| R::from_ratio((2 * bits + 1) as i32, 17);
        let phase = turn(draw >> 16);
        let theta = turn(draw & 0xFFFF);
        let (c, s) = (theta.cos_turns(), (theta - R::from_ratio(1, 2)).cos_turns());
        let turns = self.turns.get::<R>();
        // The direction's z and the length of its xy part (a plane direction: 0 and 1).
        let (z, rho) = if D == 3 && self.orientation == Orientation::Isotropic {
            let k = (rng.next_u32() >> 16) as i32 - (1 << 15);
            let z = R::from_ratio(2 * k + 1, 16);
            (z, (R::ONE - z.mul_rn(z)).sqrt())
        } else {
            (R::ZERO, R::ONE)
        };
        let direction: [R; D] = core::array::from_fn(|a| match a {
            0 => rho.mul_rn(c),
            1 => rho.mul_rn(s),
            _ => z,
        });
        let wave = direction.map(|d| turns.mul_rn(d));
        Params {
            wave,
            phase,
            cis: [R::ONE, R::ZERO],
            direction,
        }
    }

    /// Whether every kernel runs along the noise's direction (the anisotropic variant, and
    /// every variant in 1D), so that its harmonic is computed per cell ([`Harmonics`]).
    #[inline]
    fn shared(&self) -> bool {
        D == 1 || self.orientation == Orientation::Anisotropic
    }

    /// The per-cell harmonics.
    #[inline]
    fn harmonics(&self) -> Harmonics<'_, D> {
        Harmonics {
            on: self.shared(),
            wave: &self.wave,
            turn: &self.turn,
        }
    }

    /// Calls `kernel(delta, d², w, params, cell)` for each impulse within reach of `p` (the
    /// [impulse walk](crate::impulse) in cell units, each impulse's phase and direction drawn,
    /// its cell's [`Harmonic`]).
    #[inline]
    fn each_kernel<R: Real>(
        &self,
        p: [R; D],
        kernel: impl FnMut([R; D], R, R, &Params<R, D>, &Harmonic<R>),
    ) {
        let prepare = |rng: &mut CellRng| self.params::<R>(rng);
        walk(
            &self.hash,
            &self.impulses,
            self.to_cells(p),
            (self.extra(), prepare),
            &self.harmonics(),
            kernel,
        );
    }

    /// The point in cell units.
    #[inline]
    fn to_cells<R: Real>(&self, p: [R; D]) -> [R; D] {
        let k = self.to_cells.get::<R>();
        p.map(|x| x.wrapping_mul(k))
    }
}

/// The harmonic's argument in turns, `wave · delta + phase`, of a kernel with a direction of
/// its own.
#[inline]
fn argument<R: Real, const D: usize>(params: &Params<R, D>, delta: &[R; D]) -> R {
    let mut t = params.phase;
    for (k, d) in params.wave.iter().zip(delta) {
        t = t + k.mul_rn(*d);
    }
    t
}

/// Bits of a phase relative to the cell's corner: [`PHASES`] has `2^PHASE_BITS` bins.
const PHASE_BITS: u32 = 6;

/// `cos 2πφ` at the centres of 64 equal bins of the phase, `φ = (2j + 1)/128` turns, in
/// Q2.30; `sin 2πφ` is the entry a quarter turn before.
static PHASES: [i32; 1 << PHASE_BITS] = {
    const N: usize = 1 << PHASE_BITS;
    let q30 = (1u64 << 30) as f64;
    let mut t = [0i32; N];
    let mut j = 0;
    while j < N {
        let v = cos_turn_f64((2 * j + 1) as f64 / (2 * N) as f64);
        // Rounded to nearest, half away from 0 (symmetric about the zeros).
        let magnitude = ((if v < 0.0 { -v } else { v }) * q30 + 0.5) as i32;
        t[j] = if v < 0.0 { -magnitude } else { magnitude };
        j += 1;
    }
    t
};

/// `[cos 2πφ, sin 2πφ]` of phase bin `j` (below `2^PHASE_BITS`).
#[inline]
fn phase_cis<R: Real>(j: usize) -> [R; 2] {
    const MASK: usize = (1 << PHASE_BITS) - 1;
    let quarter = 1 << (PHASE_BITS - 2);
    [
        q30(PHASES[j & MASK]),
        q30(PHASES[j.wrapping_sub(quarter) & MASK]),
    ]
}

/// A kernel's harmonic along the noise's direction `k` at a cell: `cos` and `sin` of
/// `2π k·(p − c)` for the point `p` and the cell's corner `c`.
#[derive(Clone, Copy, Debug, Default)]
struct Harmonic<R> {
    cos: R,
    sin: R,
}

impl<R: Real> Harmonic<R> {
    /// The harmonic plus another (the angles added).
    #[inline]
    fn plus(self, other: Self) -> Self {
        Self {
            cos: self.cos.mul_rn(other.cos) - self.sin.mul_rn(other.sin),
            sin: self.sin.mul_rn(other.cos) + self.cos.mul_rn(other.sin),
        }
    }

    /// `cos 2π(θ + φ)` and `sin 2π(θ + φ)` for this harmonic's angle `θ` and an impulse's
    /// phase `φ` given as `[cos 2πφ, sin 2πφ]`.
    #[inline]
    fn at(&self, cis: &[R; 2]) -> (R, R) {
        (
            self.cos.mul_rn(cis[0]) - self.sin.mul_rn(cis[1]),
            self.sin.mul_rn(cis[0]) + self.cos.mul_rn(cis[1]),
        )
    }

    /// `cos 2π(θ + φ + u)`: [`at`](Self::at) turned by `u` turns more (the filtered and the
    /// surface kernels, whose wave differs from the cells' by `u/δ`).
    #[inline]
    fn shifted(&self, cis: &[R; 2], u: R) -> R {
        let (c, s) = self.at(cis);
        c.mul_rn(u.cos_turns()) - s.mul_rn((u - R::from_ratio(1, 2)).cos_turns())
    }
}

/// The harmonics of kernels along the noise's direction, per cell (Gabor noise's
/// [`PerCell`]). An impulse's phase `φ` is drawn relative to its cell's corner `c`: its
/// kernel's harmonic is `cos 2π(k·(p − c) + φ)`, which is `cos 2π(k·(p − x_i) + φ_i)` for the
/// phase `φ_i = φ + k·(x_i − c)` relative to the impulse `x_i`, uniform as `φ` is and
/// independent of the impulse's position: the same noise (Lagae and Drettakis 2011's random
/// phases). So `cos` and `sin` of `2π k·(p − c)` are computed once per cell (per axis, from
/// the point's fraction `f`: two `cos_turns` for the point's own cell, then turned by
/// `±2π k_a` for the cells either side, then added over the axes), and each impulse only
/// combines them with its phase's, read from [`PHASES`].
struct Harmonics<'a, const D: usize> {
    /// Off for kernels with directions of their own.
    on: bool,
    /// `k`, turns per kernel radius.
    wave: &'a [Setting; D],
    /// `[cos 2π k_a, sin 2π k_a]` per axis.
    turn: &'a [[Setting; 2]; D],
}

impl<R: Real, const D: usize> PerCell<R, D> for Harmonics<'_, D> {
    type Share = Harmonic<R>;

    // Out of line in the demo's size-bound build (each walk would inline two `cos_turns`).
    #[cfg_attr(feature = "small", inline(never))]
    #[cfg_attr(not(feature = "small"), inline)]
    fn axis(&self, a: usize, f: R) -> [Harmonic<R>; 3] {
        let (Some(k), Some([c, s])) = (self.wave.get(a), self.turn.get(a)) else {
            return [Harmonic::default(); 3];
        };
        if !self.on {
            return [Harmonic::default(); 3];
        }
        let (k, c, s) = (k.get::<R>(), c.get::<R>(), s.get::<R>());
        let t = k.mul_rn(f);
        let (cos, sin) = (t.cos_turns(), (t - R::from_ratio(1, 2)).cos_turns());
        // The point is at f + 1 from the corner of the cell below, f − 1 from the one above:
        // the angle turned by +2πk and −2πk (the products shared; `Harmonic::plus` would
        // compute the same numbers).
        let (cc, ss, sc, cs) = (cos.mul_rn(c), sin.mul_rn(s), sin.mul_rn(c), cos.mul_rn(s));
        [
            Harmonic {
                cos: cc - ss,
                sin: sc + cs,
            },
            Harmonic { cos, sin },
            Harmonic {
                cos: cc + ss,
                sin: sc - cs,
            },
        ]
    }

    #[inline]
    fn join(&self, before: Harmonic<R>, share: Harmonic<R>) -> Harmonic<R> {
        if self.on { before.plus(share) } else { before }
    }
}

/// `cos 2π(k·δ + φ)`, the harmonic of a kernel at offset `δ` (`cell` the harmonic of its
/// cell when the kernels share the noise's direction).
#[inline]
fn harmonic<R: Real, const D: usize>(
    shared: bool,
    params: &Params<R, D>,
    delta: &[R; D],
    cell: &Harmonic<R>,
) -> R {
    if shared {
        cell.at(&params.cis).0
    } else {
        argument(params, delta).cos_turns()
    }
}

impl<R: Real, const D: usize> Noise<R, D> for Gabor<D> {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        let table = self.envelope.table();
        let shared = self.shared();
        let mut total = R::ZERO;
        self.each_kernel(p, |delta, d2, w, params, cell| {
            let h = table.at(d2).mul_rn(harmonic(shared, params, &delta, cell));
            total = total + w.mul_rn(h);
        });
        total.mul_rn(self.scale.get()).canonical()
    }

    fn amplitude_bound(&self) -> f32 {
        Gabor::amplitude_bound(self)
    }

    /// Lanes near each other (a grid's chunk) share the walk: each cell's impulses are
    /// generated, and each impulse's phase and direction drawn, once for all of them;
    /// scattered lanes are walked one by one. Bit-identical to [`sample`](Noise::sample)
    /// either way.
    fn sample_lanes(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) {
        let table = self.envelope.table();
        let mut totals = [R::ZERO; LANES];
        let k = self.to_cells.get::<R>();
        let cells = p.map(|axis| axis.map(|x| x.wrapping_mul(k)));
        let prepare = |rng: &mut CellRng| self.params::<R>(rng);
        let along = self.shared();
        let walked = walk_lanes(
            &self.hash,
            &self.impulses,
            &cells,
            (self.extra(), prepare),
            &self.harmonics(),
            |l, delta, d2, w, params, cell| {
                if let Some(t) = totals.get_mut(l) {
                    let h = table.at(d2).mul_rn(harmonic(along, params, &delta, cell));
                    *t = *t + w.mul_rn(h);
                }
            },
        );
        if walked {
            let scale = self.scale.get::<R>();
            for (o, t) in out.iter_mut().zip(totals) {
                *o = t.mul_rn(scale).canonical();
            }
        } else {
            for (l, o) in out.iter_mut().enumerate() {
                *o = self.sample(batch::lane(p, l));
            }
        }
    }
}

/// The analytic gradient: for each impulse, `w (e′(d²) 2δ cos 2πt − e(d²) 2π k sin 2πt)` in
/// cell units (`δ` the offset, `k` the wave vector, `t` the harmonic's argument), times `1/r`
/// and the scale; the value is [`sample`](Noise::sample)'s bit for bit. Sums saturate in fixed
/// point (a term reaches `2π · 64` at the largest frequency ratio).
impl<R: Real, const D: usize> NoiseGradient<R, D> for Gabor<D> {
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        let table = self.envelope.table();
        let mut total = R::ZERO;
        let mut gradient = [R::ZERO; D];
        let tau = R::from_f32(core::f32::consts::TAU);
        let shared = self.shared();
        self.each_kernel(p, |delta, d2, w, params, cell| {
            let (e, slope) = table.at_with_slope(d2);
            let (c, s) = if shared {
                cell.at(&params.cis)
            } else {
                let t = argument(params, &delta);
                (t.cos_turns(), (t - R::from_ratio(1, 2)).cos_turns())
            };
            total = total + w.mul_rn(e.mul_rn(c));
            let radial = w.mul_rn(slope.mul_rn(c));
            let along = w.mul_rn(e.mul_rn(s)).mul_rn(tau);
            for ((g, d), k) in gradient.iter_mut().zip(delta).zip(&params.wave) {
                let term = (radial + radial).mul_rn(d) - along.saturating_mul(*k);
                *g = g.saturating_add(term);
            }
        });
        let scale = self.scale.get::<R>();
        let chain = scale.saturating_mul(self.to_cells.get());
        (
            total.mul_rn(scale).canonical(),
            gradient.map(|g| g.saturating_mul(chain).canonical()),
        )
    }
}

/// Surface noise without set-up (Lagae et al. 2009, §5 "surface noise"; the survey §5.1.3):
/// the noise on the surface through `p` with normal `n` needs only `p` and `n`. Each impulse
/// keeps its 3D position and envelope (`e(|δ|²)`, the 3D distance), and its kernel's harmonic
/// runs along its direction turned into the tangent plane, at the full frequency:
/// `cos(2π F₀ (ω_t/|ω_t|)·δ + φ)`, `ω_t = ω − (ω·n) n`. On the surface each kernel is then a
/// 2D Gabor kernel of frequency `F₀`, so the noise keeps its band (a ring at `F₀` for the
/// isotropic variant), where a plain slice of solid noise (`sample` on the surface) sees each
/// kernel's frequency shortened to `F₀ |ω_t|` and fills the disc below `F₀`
/// (`tests/tests/gabor.rs` prints the power below `F₀/2` of both).
///
/// * Anisotropic: the noise's direction turned into the plane; undefined where it is normal
///   to the surface (a combed sphere has two such points: Brouwer's hairy ball). Within
///   `2⁻⁸` of the normal (0.2°) the direction is left unnormalised, so the kernels' frequency
///   falls to its projection there.
/// * Isotropic and hybrid: each kernel's weight is multiplied by `|ω_t|²`, which makes the
///   noise smooth in `n` (a kernel whose direction meets the normal fades out instead of
///   spinning), and the variance is restored exactly: `E[(1 − (ω·n)²)²]` is `8/15` for
///   directions uniform on the sphere and `1 − ρ² + 3ρ⁴/8` (`ρ²` the normal's xy part) for
///   directions uniform in the xy plane.
///
/// Variance `K²` on every surface (tested). A normal that is zero or not finite is the z
/// axis ([`unit_normal`](crate::wavelet::unit_normal)).
impl<R: Real> ProjectedNoise<R> for Gabor<3> {
    fn sample_projected(&self, p: [R; 3], normal: [R; 3]) -> R {
        let n = unit_normal(normal);
        let table = self.envelope.table();
        let turns = self.turns.get::<R>();
        let dot = |v: &[R; 3]| v[0].mul_rn(n[0]) + v[1].mul_rn(n[1]) + v[2].mul_rn(n[2]);
        // The direction in the tangent plane, and its squared length before normalising.
        let tangent = |v: &[R; 3]| -> ([R; 3], R) {
            let a = dot(v);
            let t: [R; 3] = core::array::from_fn(|i| v[i] - a.mul_rn(n[i]));
            let m2 = t[0].mul_rn(t[0]) + t[1].mul_rn(t[1]) + t[2].mul_rn(t[2]);
            if m2 < R::from_ratio(1, 16) {
                return (t, m2);
            }
            let m = m2.sqrt();
            (t.map(|c| c.div(m)), m2)
        };
        let anisotropic = self.orientation == Orientation::Anisotropic;
        // The anisotropic kernels' phase is relative to their cell's corner (`Harmonics`):
        // their argument is `k·(p − c) + φ + (k_t − k)·δ` in turns, with `k_t` the wave
        // turned into the plane.
        let fixed = tangent(&self.direction.map(R::from_f32))
            .0
            .map(|c| turns.mul_rn(c));
        let wave = self.wave.map(Setting::get::<R>);
        let change: [R; 3] = core::array::from_fn(|a| fixed[a] - wave[a]);
        let mut total = R::ZERO;
        self.each_kernel(p, |delta, d2, w, params, cell| {
            let dot = |wave: &[R; 3]| {
                let mut u = R::ZERO;
                for (k, d) in wave.iter().zip(&delta) {
                    u = u + k.mul_rn(*d);
                }
                u
            };
            let (harmonic, weight) = if anisotropic {
                (cell.shifted(&params.cis, dot(&change)), R::ONE)
            } else {
                let (t, m2) = tangent(&params.direction);
                let wave = t.map(|c| turns.mul_rn(c));
                ((params.phase + dot(&wave)).cos_turns(), m2)
            };
            let h = table.at(d2).mul_rn(harmonic);
            total = total + w.mul_rn(weight).mul_rn(h);
        });
        let gain = match self.orientation {
            Orientation::Anisotropic => R::ONE,
            // √(15/8).
            Orientation::Isotropic => R::from_f32(1.369_306_4),
            Orientation::Hybrid => {
                let rho2 = n[0].mul_rn(n[0]) + n[1].mul_rn(n[1]);
                let mean = R::ONE - rho2 + R::from_ratio(3, 3).mul_rn(rho2.mul_rn(rho2));
                R::ONE.div(mean.sqrt())
            }
        };
        total.mul_rn(self.scale.get()).mul_rn(gain).canonical()
    }

    /// [`amplitude_bound`](Noise::amplitude_bound) times the largest variance correction:
    /// `√(15/8)` (isotropic), `√(8/3)` (hybrid).
    fn projected_bound(&self) -> f32 {
        let gain = match self.orientation {
            Orientation::Anisotropic => 1.0,
            Orientation::Isotropic => 1.3694,
            Orientation::Hybrid => 1.633,
        };
        self.amplitude_bound() * gain * 1.001
    }
}

/// The filter of a sample's footprint, in cell units, as the filtered kernels need it
/// (Lagae et al. 2009 §5; Lagae and Drettakis 2011, eq. 10): the pixel is a Gaussian of the
/// footprint box's covariance `Σ = (dx dxᵀ + dy dyᵀ)/12`; with the kernel's envelope
/// `e^{−½ xᵀ A x}`, `A = 2 ln 20 · I`, and `B = A⁻¹ + Σ`, a filtered kernel is
/// `amp · e^{−½ δᵀ P δ} cos(2π m·δ + φ)` with `P = B⁻¹`, `m = P A⁻¹ k`,
/// `amp = e^{−2π² kᵀ(A⁻¹ − A⁻¹ P A⁻¹)k} / √det(I + AΣ)`.
struct Footprint<R> {
    /// `P / 2`, the filtered envelope's quadratic form (symmetric: `[p00, p01, p11]`).
    half_precision: [R; 3],
    /// `P A⁻¹`, which turns a wave vector into the filtered one (`[m00, m01, m11]`).
    shift: [R; 3],
    /// `2π² (A⁻¹ − A⁻¹ P A⁻¹)`, the attenuation's quadratic form (`[q00, q01, q11]`).
    attenuation: [R; 3],
    /// `1 / √det(I + AΣ)`.
    gain: R,
}

impl<R: Real> Footprint<R> {
    /// The filter of the footprint `dx`, `dy` in cell units, computed in `f32` (the same
    /// numbers in every type, as the wavelet bands' footprints are): `None` when it is too
    /// small to change a kernel (every entry of `Σ` below 2⁻²⁴), so that the caller samples
    /// the plain noise, bit for bit.
    fn new(dx: [f32; 2], dy: [f32; 2]) -> Option<Self> {
        // Non-finite components count as 0; huge ones are capped (a footprint of 2²⁰ kernel
        // radii leaves nothing of a kernel anyway).
        let tame = |v: f32| {
            if v.is_finite() {
                v.clamp(-1048576.0, 1048576.0)
            } else {
                0.0
            }
        };
        let (dx, dy) = (dx.map(tame), dy.map(tame));
        let sigma = [
            (dx[0] * dx[0] + dy[0] * dy[0]) / 12.0,
            (dx[0] * dx[1] + dy[0] * dy[1]) / 12.0,
            (dx[1] * dx[1] + dy[1] * dy[1]) / 12.0,
        ];
        if sigma.iter().all(|s| s.abs() < 1.0 / 16_777_216.0) {
            return None;
        }
        let inv_a = (0.5 / GAUSSIAN_RATE) as f32;
        let b = [inv_a + sigma[0], sigma[1], inv_a + sigma[2]];
        // det B = (A⁻¹)² + A⁻¹ tr Σ + det Σ, and det Σ = (dx × dy)²/144: every term is at
        // least 0, so det B ≥ (A⁻¹)² whatever the rounding (`b₀b₂ − b₁²` cancels
        // catastrophically for a long, thin footprint; found by the fuzz target `impulse`).
        let cross = dx[0] * dy[1] - dx[1] * dy[0];
        let det = inv_a * inv_a + inv_a * (sigma[0] + sigma[2]) + cross * cross / 144.0;
        // P = B⁻¹ lies between 0 and A = 2 ln 20 · I: its entries within ±A, its diagonal
        // at least 0 (clamped against rounding).
        let top = (2.0 * GAUSSIAN_RATE) as f32;
        let p = [
            (b[2] / det).clamp(0.0, top),
            (-b[1] / det).clamp(-top, top),
            (b[0] / det).clamp(0.0, top),
        ];
        let m = p.map(|x| x * inv_a);
        let q = [
            (inv_a - inv_a * inv_a * p[0]).max(0.0),
            -inv_a * inv_a * p[1],
            (inv_a - inv_a * inv_a * p[2]).max(0.0),
        ];
        let pi2 = 2.0 * core::f32::consts::PI * core::f32::consts::PI;
        let gain = 1.0 / (libm::sqrtf(det) / inv_a);
        let r = |v: f32| R::from_f32(v);
        Some(Self {
            half_precision: p.map(|x| r(0.5 * x)),
            shift: m.map(r),
            attenuation: q.map(|x| r(pi2 * x)),
            gain: r(gain),
        })
    }

    /// `xᵀ S y` for the symmetric `S = [s00, s01, s11]`. The sum saturates in fixed point:
    /// the attenuation's form over a wave vector of 62 turns per radius reaches 4·10⁴, beyond
    /// I16F16, where `e^{−x}` is 0 anyway (found by the fuzz target `impulse`).
    #[inline]
    fn form(s: &[R; 3], x: [R; 2], y: [R; 2]) -> R {
        let cross = s[1].saturating_mul(x[0].mul_rn(y[1]) + x[1].mul_rn(y[0]));
        s[0].mul_rn(x[0])
            .saturating_mul(y[0])
            .saturating_add(cross)
            .saturating_add(s[2].mul_rn(x[1]).saturating_mul(y[1]))
    }
}

/// Analytic anisotropic filtering (Lagae et al. 2009 §5; the survey §5.2.1): each kernel is a
/// Gaussian in frequency, and so is the pixel's filter, so the filtered kernel is again a
/// Gabor kernel, with a wider (anisotropic) envelope, a frequency pulled towards 0 across the
/// footprint and an amplitude that falls as the footprint covers more of a period ([`Gabor`]'s
/// `Footprint`, Lagae and Drettakis 2011's eq. 10 in the plane). The pixel is the Gaussian with
/// the footprint box's covariance, `(dpdx dpdxᵀ + dpdy dpdyᵀ)/12`. Only impulses within the
/// kernel's radius are summed (the filtered envelope reaches further, but its amplitude falls
/// faster), and the envelope keeps the kernel's window (Hann's, or the truncation), so a
/// footprint that shrinks to nothing gives the plain noise: below 2⁻²⁴ cell² it is `sample`,
/// bit for bit. A footprint with non-finite components counts them as 0.
///
/// Against a 16×16-supersampled box-filtered reference, one filtered sample per pixel is many
/// times closer than a plain one (`tests/tests/gabor.rs`).
impl<R: Real> crate::FilteredNoise<R, 2> for Gabor<2> {
    fn sample_filtered(&self, p: [R; 2], dpdx: [R; 2], dpdy: [R; 2]) -> R {
        let k = self.to_cells.float;
        let cells = |v: [R; 2]| v.map(|c| c.to_f32() * k);
        let Some(filter) = Footprint::<R>::new(cells(dpdx), cells(dpdy)) else {
            return self.sample(p);
        };
        let window = match self.envelope {
            Envelope::Hann => Some(&HANN_WINDOW),
            Envelope::Truncated => None,
        };
        let shared = self.shared();
        let mut total = R::ZERO;
        self.each_kernel(p, |delta, d2, w, params, cell| {
            let k = params.wave;
            let m = [
                filter.shift[0].mul_rn(k[0]) + filter.shift[1].mul_rn(k[1]),
                filter.shift[1].mul_rn(k[0]) + filter.shift[2].mul_rn(k[1]),
            ];
            let fade = Footprint::form(&filter.attenuation, k, k).exp_neg();
            let spread = Footprint::form(&filter.half_precision, delta, delta).exp_neg();
            let envelope = match window {
                Some(table) => spread.mul_rn(table.at(d2)),
                None => spread,
            };
            // A phase relative to the cell's corner (`Harmonics`): the argument `k·(p − c) +
            // φ + (m − k)·δ`; relative to the impulse, `φ + m·δ`.
            let harmonic = if shared {
                let u = (m[0] - k[0]).mul_rn(delta[0]) + (m[1] - k[1]).mul_rn(delta[1]);
                cell.shifted(&params.cis, u)
            } else {
                (params.phase + m[0].mul_rn(delta[0]) + m[1].mul_rn(delta[1])).cos_turns()
            };
            let h = envelope.mul_rn(fade).mul_rn(harmonic);
            total = total + w.mul_rn(h);
        });
        total
            .mul_rn(filter.gain)
            .mul_rn(self.scale.get())
            .canonical()
    }
}

/// Hann's window `½ + ½ cos(π d²)` alone (the filtered kernels' window), 33 knots.
static HANN_WINDOW: Table = Table::new(Profile::HannWindow, &HANN_WINDOW_KNOTS);
static HANN_WINDOW_KNOTS: [[i32; 2]; 33] = knots(Profile::HannWindow);

#[cfg(test)]
mod tests {
    use super::*;

    /// The envelopes' tables against their formulas, in `f64` and `f32`.
    #[test]
    fn envelope_tables_follow_their_formulas() {
        for envelope in [Envelope::Hann, Envelope::Truncated] {
            let mut worst = [0.0f64; 2];
            for i in 0..=10_000 {
                let s = i as f64 / 10_000.0 * 0.9999;
                let (want, slope) = envelope.exact(s);
                let got = envelope.table().at(s);
                let (_, got_slope) = envelope.table().at_with_slope(s);
                worst[0] = worst[0].max((got - want).abs());
                worst[1] = worst[1].max((got_slope - slope).abs());
                let f = envelope.table().at(s as f32) as f64;
                assert!((f - want).abs() < 1e-6, "{envelope:?} f32 at {s}");
            }
            assert!(
                worst[0] < 3e-7 && worst[1] < 2e-4,
                "{envelope:?}: {worst:?}"
            );
        }
        // The truncated envelope is 5% of its peak just inside the rim, 0 from it on.
        assert!((Envelope::Truncated.table().at(0.999_999f64) - 0.05).abs() < 1e-6);
        assert_eq!(Envelope::Truncated.table().at(1.0f64), 0.0);
        assert_eq!(Envelope::Hann.table().at(1.0f64), 0.0);
    }

    /// The phase table holds `cos` and `sin` of its bin centres.
    #[test]
    fn phases_are_the_bin_centres() {
        for j in 0..1 << PHASE_BITS {
            let phase = (2 * j + 1) as f64 / (2 << PHASE_BITS) as f64 * core::f64::consts::TAU;
            let [c, s] = phase_cis::<f64>(j);
            assert!((c - libm::cos(phase)).abs() < 1e-9, "{j}");
            assert!((s - libm::sin(phase)).abs() < 1e-9, "{j}");
        }
    }

    /// Each cell's harmonic, turned from the point's own cell, is `2π k·(p − c)`'s cosine and
    /// sine computed directly, in every dimension and for wave vectors up to the largest.
    #[test]
    fn cell_harmonics_are_the_direct_ones() {
        fn case<const D: usize>(wave: [f64; D], next: &mut impl FnMut() -> u32) {
            // Waves exact in f32 (the settings' float); turns rounded to f32 from f64.
            let setting = |v: f64| Setting {
                float: v as f32,
                fixed: I16F16::ZERO,
            };
            let turn = wave.map(|k| cis_turns_f64(k).map(setting));
            let wave_settings = wave.map(setting);
            let h = Harmonics::<D> {
                on: true,
                wave: &wave_settings,
                turn: &turn,
            };
            for _ in 0..2000 {
                let f: [f64; D] = core::array::from_fn(|_| next() as f64 / 4_294_967_296.0);
                let shares: [[Harmonic<f64>; 3]; D] = core::array::from_fn(|a| h.axis(a, f[a]));
                for n in 0..3usize.pow(D as u32) {
                    let digit: [usize; D] = core::array::from_fn(|a| n / 3usize.pow(a as u32) % 3);
                    let mut cell: Harmonic<f64> = shares[0][digit[0]];
                    for a in 1..D {
                        cell = h.join(cell, shares[a][digit[a]]);
                    }
                    // The point relative to the cell's corner: f + 1, f, f − 1.
                    let turns: f64 = (0..D)
                        .map(|a| wave[a] * (f[a] + 1.0 - digit[a] as f64))
                        .sum();
                    let angle = core::f64::consts::TAU * turns;
                    // cos_turns' own error (2e-8) and the turn's rounding to f32 (6e-8),
                    // per axis.
                    let tolerance = 2e-7 * D as f64;
                    assert!(
                        (cell.cos - libm::cos(angle)).abs() < tolerance,
                        "{f:?} {digit:?}"
                    );
                    assert!(
                        (cell.sin - libm::sin(angle)).abs() < tolerance,
                        "{f:?} {digit:?}"
                    );
                }
            }
        }
        let mut next = crate::testing::xorshift32(7);
        for wave in [0.0, 0.375, 1.0, 1.2109375, -7.875, 62.5] {
            case::<1>([wave], &mut next);
            case::<2>([wave, 0.5 - wave], &mut next);
            case::<3>([wave, -0.25, wave / 4.0], &mut next);
        }
    }

    /// The noise is continuous across the cells' borders (in `f64`, within 1e-6 over a step
    /// of 1e-9 cell): each kernel's harmonic is the same on both sides whichever cell the
    /// point lies in, in every dimension and orientation.
    #[test]
    fn noise_is_continuous_across_cells() {
        fn case<const D: usize>(noise: &Gabor<D>, next: &mut impl FnMut() -> u32) {
            let r = noise.radius();
            for _ in 0..300 {
                let mut p: [f64; D] =
                    core::array::from_fn(|_| (next() as f64 / 4_294_967_296.0 - 0.5) * 20.0 * r);
                // Onto a cell border along one axis, then a step either side.
                let a = next() as usize % D;
                p[a] = libm::round(p[a] / r) * r;
                let (mut lo, mut hi) = (p, p);
                lo[a] -= 1e-9 * r;
                hi[a] += 1e-9 * r;
                let (u, v): (f64, f64) = (noise.sample(lo), noise.sample(hi));
                assert!((u - v).abs() < 1e-6, "{p:?} along {a}: {u} against {v}");
            }
        }
        let mut next = crate::testing::xorshift32(11);
        for orientation in [Orientation::Anisotropic, Orientation::Isotropic] {
            let at = |g: Gabor<2>| g.with_orientation(orientation);
            case(&Gabor::<1>::new(3).with_frequency(2.5).unwrap(), &mut next);
            case(&at(Gabor::<2>::new(3).with_angle(0.4).unwrap()), &mut next);
            case(
                &Gabor::<3>::new(3)
                    .with_orientation(orientation)
                    .with_direction([0.3, -0.5, 0.8])
                    .unwrap(),
                &mut next,
            );
        }
    }

    /// `∫e²` from the tables against the 2D closed form of the truncated Gaussian:
    /// `π (1 − e^{−2c}) / (2c)` over the unit disc.
    #[test]
    fn truncated_power_is_the_closed_form() {
        let c = GAUSSIAN_RATE;
        let want = core::f64::consts::PI * (1.0 - libm::exp(-2.0 * c)) / (2.0 * c);
        let got = Envelope::Truncated.power_of(2);
        assert!((got - want).abs() < 1e-9, "{got} against {want}");
    }
}
