//! What the page asks for, checked, as a [`Spec`]: the noises the page offers are the
//! description's bases ([`kinds`]), so a noise added to `bandnoise::spec` appears in the demo.

use core::cell::Cell;

use bandnoise::fractal::{Fractal, Kind, Octaves};
use bandnoise::impulse::{Envelope, Kernel, Orientation};
use bandnoise::simplex::{Flow, FlowSum};
use bandnoise::spec::{Base, Spec, SpecNoise};
use bandnoise::wavelet::{Bands, Distribution, Tiling};
use bandnoise::wiener::Covariance;
use bandnoise::{Error, Noise, Real};
use wasm_bindgen::prelude::*;

use crate::render::WebTiles;

/// Whether the page shows `base`: every noise with a 3D form (the page's third axis is time),
/// and flow noise (2D only: time turns its gradients).
fn shown(base: Base) -> bool {
    base.has_dimension(3) || base == Base::Flow
}

/// The names of the noises the demo can show, separated by spaces, in the description's
/// order: every [`Base`] with a 3D form and flow noise. One string, not an array:
/// wasm-bindgen's array of strings costs the module 1 KB.
#[wasm_bindgen]
pub fn kinds() -> String {
    let mut names = String::new();
    for base in Base::ALL.into_iter().filter(|&b| shown(b)) {
        if !names.is_empty() {
            names.push(' ');
        }
        names.push_str(base.name());
    }
    names
}

fn kind(name: &str) -> Result<Base, String> {
    Base::ALL
        .into_iter()
        .find(|&b| shown(b) && b.name() == name)
        .ok_or_else(|| format!("unknown noise kind \"{name}\" (see kinds())"))
}

/// Time units per turn of flow noise's gradients on the page (animating time adds 0.05 a
/// frame: a turn in 160 frames).
const FLOW_TIME_PER_TURN: f32 = 8.0;

/// The noise a frame samples at `(x, y, time)`.
#[derive(Clone, Debug)]
#[allow(
    clippy::large_enum_variant,
    reason = "one per frame's settings, built once"
)]
pub(crate) enum Sampled {
    /// A noise with a 3D form: time is its third axis.
    Solid(SpecNoise<3, WebTiles>),
    /// Flow noise (Perlin and Neyret 2001), which has only a 2D form: time turns its
    /// gradients, one turn every [`FLOW_TIME_PER_TURN`] units from the description's angle.
    /// Built from the typed noises (the description's 2D dispatch would bring every 2D noise
    /// into the module), as the description builds it.
    Flow(Spec, FlowNoise),
}

/// Flow noise as the description builds it: plain, its own fBm (each octave turned further
/// and advected), or a plain turbulence or ridged sum of one angle.
#[derive(Clone, Debug)]
#[allow(
    clippy::large_enum_variant,
    reason = "one per frame's settings, built once"
)]
pub(crate) enum FlowNoise {
    Plain(Flow),
    Fbm(FlowSum),
    Sum(Fractal<Flow>),
}

impl Sampled {
    /// The description the page asked for.
    pub(crate) fn spec(&self) -> &Spec {
        match self {
            Sampled::Solid(n) => n.spec(),
            Sampled::Flow(spec, _) => spec,
        }
    }
}

impl<R: Real> Noise<R, 3> for Sampled {
    fn sample(&self, p: [R; 3]) -> R {
        let q = [p[0], p[1]];
        match self {
            Sampled::Solid(n) => n.sample(p),
            Sampled::Flow(_, FlowNoise::Plain(n)) => n.sample(q),
            Sampled::Flow(_, FlowNoise::Fbm(n)) => n.sample(q),
            Sampled::Flow(_, FlowNoise::Sum(n)) => n.sample(q),
        }
    }
    fn amplitude_bound(&self) -> f32 {
        match self {
            Sampled::Solid(n) => Noise::<R, 3>::amplitude_bound(n),
            Sampled::Flow(_, FlowNoise::Plain(n)) => Noise::<R, 2>::amplitude_bound(n),
            Sampled::Flow(_, FlowNoise::Fbm(n)) => Noise::<R, 2>::amplitude_bound(n),
            Sampled::Flow(_, FlowNoise::Sum(n)) => Noise::<R, 2>::amplitude_bound(n),
        }
    }
}

/// The angle of flow noise's gradients at `time`: the description's, turned by time.
fn turned_angle(spec: &Spec, time: f32) -> f32 {
    spec.flow()[0] + time / FLOW_TIME_PER_TURN
}

/// Flow noise at `time` as `spec` (with its sum, if any) describes it.
fn flow_noise(spec: &Spec, time: f32) -> Result<FlowNoise, Error> {
    let [_, spin, advection] = spec.flow();
    let flow = Flow::new(spec.seed()).with_angle(turned_angle(spec, time))?;
    Ok(match spec.fractal() {
        None => FlowNoise::Plain(flow),
        Some((Kind::Fbm, octaves)) => FlowNoise::Fbm(
            FlowSum::new(flow, octaves)
                .with_spin(spin)?
                .with_advection(advection)?,
        ),
        Some((kind, octaves)) => FlowNoise::Sum(Fractal::new(flow, octaves, kind)),
    })
}

/// How a frame's samples are filtered by the pixel's footprint (`bandnoise::FilteredNoise`).
#[derive(Clone, Debug)]
pub(crate) enum Filter {
    /// Point samples.
    None,
    /// Wavelet or multiband noise's own filtering: each band averaged over the footprint.
    Band,
    /// A fractal sum's octaves clamped to the footprint (pbrt): the spec's sum, taken here
    /// over its noise so that it can filter.
    Octaves(Box<Fractal<SpecNoise<3, WebTiles>>>),
}

/// The settings of one frame, built and validated from JavaScript.
#[wasm_bindgen]
#[derive(Clone, Debug)]
pub struct Params {
    /// The noise, its seed, period, bands and fractal sum, built once over the demo's tiles.
    pub(crate) noise: Sampled,
    pub(crate) fixed: bool,
    pub(crate) zoom: f32,
    pub(crate) pan: [f32; 2],
    pub(crate) time: f32,
    /// Wavelet noise projected along the time axis rather than sliced.
    pub(crate) projected: bool,
    /// Whether and how samples are filtered by the pixel's footprint.
    pub(crate) filter: Filter,
    /// Multiband noise with its band weights following the zoom (infinite noise).
    pub(crate) infinite: bool,
    pub(crate) marble: bool,
}

/// A refused setting: the page's field it came from (its element's id; empty for the pan) and
/// why. JavaScript receives it thrown, and shows the message next to the field.
#[wasm_bindgen]
#[derive(Debug)]
pub struct BadField {
    field: &'static str,
    message: String,
}

#[wasm_bindgen]
impl BadField {
    /// The id of the page's field whose value is refused (`""` for the pan, which has none).
    #[wasm_bindgen(getter)]
    pub fn field(&self) -> String {
        self.field.into()
    }

    /// Why, in words.
    #[wasm_bindgen(getter)]
    pub fn message(&self) -> String {
        self.message.clone()
    }
}

fn finite(name: &str, v: f64) -> Result<f32, String> {
    if v.is_finite() && v.abs() <= 1e30 {
        Ok(v as f32)
    } else {
        Err(format!("{name} must be a finite number, not {}", num(v)))
    }
}

/// A number in a message. In the browser JavaScript formats it (`Number.prototype.toString`),
/// so core's float formatting (about 15 KB of code) stays out of the module; on the host (the
/// unit tests) Rust's `Display` does.
fn num(v: f64) -> String {
    #[cfg(target_arch = "wasm32")]
    {
        js_sys::Number::from(v)
            .to_string_with_radix(10)
            .map(String::from)
            .unwrap_or_default()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        format!("{v}")
    }
}

/// The core's refusal as a message: the core's wording, with [`num`] for the numbers (the
/// core's `Display` would bring float formatting back in).
fn describe(e: Error) -> String {
    match e {
        Error::OctaveCount { count, max } => format!("octave count {count} is outside 1..={max}"),
        Error::Lacunarity(v) => {
            format!("lacunarity {} must be finite and in (0, 16]", num(v.into()))
        }
        Error::Gain(v) => format!("gain {} must be finite and in [-1, 1]", num(v.into())),
        Error::TooManyBands { count, max } => {
            format!("{count} wavelet bands given, at most {max} are allowed")
        }
        Error::BandWeight { index, value } => format!(
            "band weight {} at {index} must be finite and at most 1e6 in magnitude",
            num(value.into())
        ),
        Error::Period { axis, period } => {
            format!("period {period} along axis {axis} is outside 1..=65536 cells")
        }
        Error::NotPeriodic(noise) => {
            format!("{noise} noise is not on the integer lattice and cannot be wrapped to a period")
        }
        Error::Bandwidth(a) => format!(
            "Gabor bandwidth {} must be finite and in [1/256, 256]",
            num(a.into())
        ),
        Error::Frequency {
            frequency,
            bandwidth,
            max_ratio,
        } => format!(
            "Gabor frequency {} must be finite and in [0, {} × bandwidth {}]",
            num(frequency.into()),
            num(max_ratio.into()),
            num(bandwidth.into())
        ),
        Error::Direction => "Gabor direction must not be zero".into(),
        Error::Density { density, min, max } => format!(
            "impulse density {} must be finite and in [{}, {}] impulses per kernel volume",
            num(density.into()),
            num(min.into()),
            num(max.into())
        ),
        Error::TextureSetting {
            name,
            value,
            min,
            max,
        } => format!(
            "texture {name} {} must be finite and in [{}, {}]",
            num(value.into()),
            num(min.into()),
            num(max.into())
        ),
        Error::WarpAmplitude(a) => format!(
            "warp amplitude {} must be finite and within ±1024",
            num(a.into())
        ),
        Error::WarpedPeriod => {
            "a warped noise does not repeat: a warp and a period cannot be combined".into()
        }
        // The page asks the core only for what is refused above (its kinds have a 3D form, or
        // are flow noise, built in 2D; its period has 3 axes, so building the spec in 3D is
        // not refused).
        _ => "invalid settings".into(),
    }
}

#[wasm_bindgen]
impl Params {
    /// The plane view's noise as a description, for a batch sampler (the page passes it to
    /// the npm package's `fromSpec` in [`dims`](Self::dims) dimensions and fills
    /// [`Demo::grid`](crate::Demo::grid) with it): the frame [`Demo::render`](crate::Demo::render)
    /// would sample, bit for bit. `None` where the view needs this module's own sampling:
    /// fixed point, filtering, infinite zoom and projection.
    pub fn batch_text(&self) -> Option<String> {
        if self.fixed || self.infinite || self.projected || !matches!(self.filter, Filter::None) {
            return None;
        }
        match &self.noise {
            Sampled::Solid(n) => Some(n.spec().to_string()),
            Sampled::Flow(spec, _) => spec
                .with_angle(turned_angle(spec, self.time))
                .ok()
                .map(|s| s.to_string()),
        }
    }

    /// The dimensions of [`batch_text`](Self::batch_text)'s noise: 2 for flow noise (time
    /// turns it), 3 for the others (time is their third axis).
    #[wasm_bindgen(getter)]
    pub fn dims(&self) -> u32 {
        match self.noise {
            Sampled::Solid(_) => 3,
            Sampled::Flow(..) => 2,
        }
    }

    /// Checks and builds the settings.
    ///
    /// `period` is the period in cells of every axis (time included, so an animation loops),
    /// or 0 for none.
    ///
    /// # Errors
    ///
    /// A message naming the first bad field: an unknown kind (see [`kinds`]), fractal, number
    /// type, distribution or palette; a zoom that is not a positive finite number (at most
    /// 1e6); a non-finite pan, time, lacunarity or gain; octaves outside 1..=16; a period that
    /// is not a whole number in 0..=65536, or given for wavelet noise; band weights that are
    /// not finite, too many, or all zero for multiband noise; a tiling other than varied,
    /// blended or periodic (used by wavelet and multiband noise, ignored by the others); a
    /// density (impulses per kernel volume) outside the core's range or a kernel other than
    /// cosine or catmull-rom (used by sparse noise, ignored by the others); a covariance other
    /// than low-pass or band-pass (used by Wiener noise, ignored by the others); a Gabor
    /// frequency, bandwidth or direction the core refuses, an orientation other than
    /// anisotropic, isotropic or hybrid, an envelope other than hann or truncated (used by
    /// Gabor noise, ignored by the others); texture settings (two numbers, `NaN` for the
    /// texture's default) or a warp amplitude (0: none) the core refuses, or a warp with a
    /// period;
    /// projection asked for a lattice noise; filtering asked for a lattice noise without a
    /// fractal sum, or with projection; infinite zoom asked for another noise than multiband,
    /// or with projection, a fractal sum or filtering; and the core's own errors. Each is a
    /// [`BadField`] naming the page's field it came from (JavaScript receives it thrown).
    #[wasm_bindgen(constructor)]
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        kind_name: &str,
        number: &str,
        seed: f64,
        zoom: f64,
        pan_x: f64,
        pan_y: f64,
        time: f64,
        period: f64,
        fractal: &str,
        octaves: f64,
        lacunarity: f64,
        gain: f64,
        band_weights: &[f32],
        distribution: &str,
        tiling: &str,
        density: f64,
        kernel: &str,
        covariance: &str,
        frequency: f64,
        bandwidth: f64,
        direction_x: f64,
        direction_y: f64,
        orientation: &str,
        envelope: &str,
        texture: &[f64],
        warp: f64,
        projected: bool,
        filtered: bool,
        infinite: bool,
        palette: &str,
    ) -> Result<Params, BadField> {
        // The field the checks are at: a refusal is tagged with it.
        let field = Cell::new("kind");
        let built = (|| -> Result<Params, String> {
            let base = kind(kind_name)?;
            field.set("number");
            let fixed = match number {
                "f32" => false,
                "fixed" => true,
                _ => {
                    return Err(format!(
                        "number type must be \"f32\" or \"fixed\", not \"{number}\""
                    ));
                }
            };
            field.set("seed");
            if !(seed.is_finite() && seed >= 0.0 && seed <= u32::MAX as f64 && seed.fract() == 0.0)
            {
                return Err(format!(
                    "seed must be a whole number from 0 to {}, not {}",
                    u32::MAX,
                    num(seed)
                ));
            }
            let mut spec = Spec::new(base, seed as u32);
            field.set("zoom");
            let zoom = finite("zoom", zoom)?;
            if !(zoom > 0.0 && zoom <= 1e6) {
                return Err(format!(
                    "zoom must be positive and at most 1e6, not {}",
                    num(zoom.into())
                ));
            }
            field.set("");
            let pan = [finite("pan x", pan_x)?, finite("pan y", pan_y)?];
            field.set("time");
            let time = finite("time", time)?;
            field.set("period");
            if !(period.is_finite() && (0.0..=65536.0).contains(&period) && period.fract() == 0.0) {
                return Err(format!(
                    "period must be a whole number of cells from 1 to 65536 (0: none), not {}",
                    num(period)
                ));
            }
            if period > 0.0 {
                spec = spec.with_period(&[period as u32; 3]).map_err(describe)?;
            }
            field.set("fractal");
            let kind = match fractal {
                "none" => None,
                "fbm" => Some(Kind::Fbm),
                "turbulence" => Some(Kind::Turbulence),
                "ridged" => Some(Kind::Ridged),
                _ => {
                    return Err(format!(
                        "fractal must be none, fbm, turbulence or ridged, not \"{fractal}\""
                    ));
                }
            };
            field.set("octaves");
            if !(octaves.is_finite() && (1.0..=16.0).contains(&octaves) && octaves.fract() == 0.0) {
                return Err(format!(
                    "octaves must be a whole number from 1 to 16, not {}",
                    num(octaves)
                ));
            }
            field.set("lacunarity");
            let lacunarity = finite("lacunarity", lacunarity)?;
            field.set("gain");
            let gain = finite("gain", gain)?;
            // The core checks the ranges and says why.
            let octaves = Octaves::new(octaves as u32, lacunarity, gain).map_err(|e| {
                field.set(match e {
                    Error::Lacunarity(_) => "lacunarity",
                    Error::Gain(_) => "gain",
                    _ => "octaves",
                });
                describe(e)
            })?;
            field.set("distribution");
            let distribution = match distribution {
                "gaussian" => Distribution::Gaussian,
                "uniform" => Distribution::Uniform,
                _ => {
                    return Err(format!(
                        "distribution must be gaussian or uniform, not \"{distribution}\""
                    ));
                }
            };
            field.set("tiling");
            let tiling = match tiling {
                "varied" => Tiling::Varied,
                "blended" => Tiling::Blended,
                "periodic" => Tiling::Periodic,
                _ => {
                    return Err(format!(
                        "tiling must be varied, blended or periodic, not \"{tiling}\""
                    ));
                }
            };
            if base.is_wavelet() {
                spec = spec.with_tiling(tiling).map_err(describe)?;
            }
            field.set("kernel");
            let kernel = match kernel {
                "cosine" => Kernel::Cosine,
                "catmull-rom" => Kernel::CatmullRom,
                _ => {
                    return Err(format!(
                        "kernel must be cosine or catmull-rom, not \"{kernel}\""
                    ));
                }
            };
            field.set("density");
            let density = finite("density", density)?;
            if base.is_impulse() {
                // The core checks the range and says why.
                spec = spec.with_density(density).map_err(describe)?;
            }
            if base == Base::Sparse {
                // Accepted for sparse noise (refused only for other bases).
                spec = spec.with_kernel(kernel).unwrap_or(spec);
            }
            field.set("orientation");
            let orientation = match orientation {
                "anisotropic" => Orientation::Anisotropic,
                "isotropic" => Orientation::Isotropic,
                "hybrid" => Orientation::Hybrid,
                _ => {
                    return Err(format!(
                        "orientation must be anisotropic, isotropic or hybrid, not \"{orientation}\""
                    ));
                }
            };
            field.set("envelope");
            let envelope = match envelope {
                "hann" => Envelope::Hann,
                "truncated" => Envelope::Truncated,
                _ => {
                    return Err(format!(
                        "envelope must be hann or truncated, not \"{envelope}\""
                    ));
                }
            };
            field.set("frequency");
            let frequency = finite("frequency", frequency)?;
            field.set("bandwidth");
            let bandwidth = finite("bandwidth", bandwidth)?;
            field.set("angle");
            let direction = [
                finite("direction x", direction_x)?,
                finite("direction y", direction_y)?,
            ];
            if base == Base::Gabor {
                // The core checks the ranges and says why.
                spec = spec
                    .with_spectrum(frequency, bandwidth)
                    .and_then(|s| s.with_direction(&direction))
                    .and_then(|s| s.with_orientation(orientation))
                    .and_then(|s| s.with_envelope(envelope))
                    .map_err(|e| {
                        field.set(match e {
                            Error::Bandwidth(_) => "bandwidth",
                            Error::Direction => "angle",
                            _ => "frequency",
                        });
                        describe(e)
                    })?;
            }
            field.set("covariance");
            let covariance = match covariance {
                "low-pass" => Covariance::LowPass,
                "band-pass" => Covariance::BandPass,
                _ => {
                    return Err(format!(
                        "covariance must be low-pass or band-pass, not \"{covariance}\""
                    ));
                }
            };
            if base == Base::Wiener {
                // Accepted for Wiener noise (refused only for other bases).
                spec = spec.with_covariance(covariance).unwrap_or(spec);
            }
            // The textures' two settings (`NaN`: the texture's default), for the textures only.
            field.set("texture1");
            if base.is_texture() && texture.len() == 2 && texture.iter().any(|v| !v.is_nan()) {
                let current = spec.texture();
                let mut settings = [0.0f32; 2];
                let names = [
                    ("texture setting 1", "texture1"),
                    ("texture setting 2", "texture2"),
                ];
                for ((s, &v), (&d, (name, id))) in settings
                    .iter_mut()
                    .zip(texture)
                    .zip(current.iter().zip(names))
                {
                    field.set(id);
                    *s = if v.is_nan() { d } else { finite(name, v)? };
                }
                // The core names the setting it refuses, in the texture's order of settings.
                spec = spec.with_texture(settings).map_err(|e| {
                    if let Error::TextureSetting { name, .. } = e {
                        let first = base.texture_settings().and_then(|n| n.first().copied());
                        field.set(if first == Some(name) {
                            "texture1"
                        } else {
                            "texture2"
                        });
                    }
                    describe(e)
                })?;
            }
            field.set("bands");
            let bands = Bands::new(-3, band_weights).map_err(describe)?;
            if base == Base::Multiband {
                if band_weights.iter().all(|w| *w == 0.0) {
                    return Err("every band weight is zero: raise at least one band".into());
                }
                spec = spec
                    .with_bands(bands)
                    .and_then(|s| s.with_distribution(distribution))
                    .map_err(describe)?;
            }
            field.set("warp");
            let warp = finite("warp", warp)?;
            if warp != 0.0 && base == Base::Flow {
                return Err("the warp applies to noises with a 3D form, not flow noise".into());
            }
            if warp != 0.0 {
                spec = spec.with_warp(warp).map_err(describe)?;
            }
            // Filtering a fractal sum filters its octaves: the sum is then taken in `render.rs`.
            let unsummed = spec;
            if let Some(kind) = kind {
                spec = spec.with_fractal(kind, octaves);
            }
            field.set("projected");
            if projected && !base.is_wavelet() {
                return Err(format!(
                    "projection applies to wavelet and multiband noise, not {base}"
                ));
            }
            field.set("filtered");
            if filtered && projected {
                return Err("filtering applies to sliced noise, not projected".into());
            }
            if filtered && kind.is_none() && !base.is_wavelet() {
                return Err(format!(
                    "filtering applies to wavelet and multiband noise and to fractal sums, not to \
                     {base} alone"
                ));
            }
            if filtered && base == Base::Flow {
                return Err("filtering applies to wavelet and multiband noise and to fractal sums of noises with a 3D form, not to flow noise".into());
            }
            field.set("infinite");
            if infinite && base != Base::Multiband {
                return Err(format!(
                    "infinite zoom applies to multiband noise, not {base}"
                ));
            }
            if infinite && (projected || kind.is_some() || filtered) {
                return Err(
                    "infinite zoom is multiband noise on its own: no projection, fractal sum or \
                     filtering"
                        .into(),
                );
            }
            field.set("palette");
            let marble = match palette {
                "grey" => false,
                "marble" => true,
                _ => return Err(format!("palette must be grey or marble, not \"{palette}\"")),
            };
            field.set("kind");
            Ok(Params {
                noise: if base == Base::Flow {
                    Sampled::Flow(spec, flow_noise(&spec, time).map_err(describe)?)
                } else {
                    Sampled::Solid(spec.build_with::<3, WebTiles>().map_err(describe)?)
                },
                fixed,
                zoom,
                pan,
                time,
                projected,
                filter: match (filtered, kind) {
                    (false, _) => Filter::None,
                    (true, None) => Filter::Band,
                    (true, Some(kind)) => {
                        let noise = unsummed.build_with().map_err(describe)?;
                        Filter::Octaves(Box::new(Fractal::new(noise, octaves, kind)))
                    }
                },
                infinite,
                marble,
            })
        })();
        built.map_err(|message| BadField {
            field: field.get(),
            message,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::{FLOW_TIME_PER_TURN, flow_noise};
    use bandnoise::Noise;
    use bandnoise::spec::Spec;

    /// The page builds flow noise from the typed noises rather than the description (see
    /// [`super::Sampled::Flow`]); at each time it is the description's 2D noise with the
    /// angle turned by `time / 8`, bit for bit, plain and with each sum.
    #[test]
    fn flow_noise_is_the_description_turned_by_time() {
        for text in [
            "flow seed=5 angle=0.1",
            "flow seed=5 angle=0.1 fbm octaves=4 spin=1.5 advection=0.3",
            "flow seed=5 turbulence octaves=3",
            "flow seed=5 ridged octaves=2",
        ] {
            let spec: Spec = text.parse().unwrap();
            for time in [0.0f32, 1.3, -7.9, 100.0] {
                let page = flow_noise(&spec, time).unwrap();
                let turned = spec
                    .with_angle(spec.flow()[0] + time / FLOW_TIME_PER_TURN)
                    .unwrap()
                    .build::<2>()
                    .unwrap();
                for k in 0..400 {
                    let p = [k as f32 * 0.173 - 31.0, (k * 7 % 41) as f32 * 0.291 - 5.0];
                    let q = [p[0], p[1], time];
                    let got: f32 = super::Sampled::Flow(spec, page.clone()).sample(q);
                    let want: f32 = turned.sample(p);
                    assert_eq!(got.to_bits(), want.to_bits(), "{text} at {time}: {p:?}");
                }
            }
        }
    }
}
