//! One frame: sample the chosen noise over the view, colour it, and keep what the page shows.

use std::sync::OnceLock;

use bandnoise::batch::Grid;
use bandnoise::fractal::Fractal;
use bandnoise::spec::{Base, Tiles};
use bandnoise::wavelet::{
    DEFAULT_TILE_SEED, Multiband, QuantizedTile2, QuantizedTile3, TILE2_I16, Tile3, Wavelet,
};
use bandnoise::{FilteredNoise, I16F16, Noise, ProjectedNoise, Real};
use wasm_bindgen::Clamped;
use wasm_bindgen::prelude::*;
use web_sys::{CanvasRenderingContext2d, ImageData};

use crate::fft::log_spectrum;
use crate::palette::color;
use crate::params::{Filter, Params};

/// The demo's 3D wavelet tile: the crate's `TILE3_I16` (32³ `i16` coefficients, the tile of
/// the npm package that samples the plane views), generated when a wavelet noise first needs
/// it rather than stored in the module: its 64 KiB would not fit the module's budget, its
/// generator's code takes 4 KB. `Tile3::generate` is a `const fn` of plain `f64` and `f32`
/// arithmetic, which gives the same bits at compile time and at run time, so the tile equals
/// the stored one bit for bit (the end-to-end test compares the two paths' frames).
static WEB_TILE3: OnceLock<QuantizedTile3<32>> = OnceLock::new();

fn web_tile3() -> &'static QuantizedTile3<32> {
    WEB_TILE3.get_or_init(|| QuantizedTile3::quantize(&Tile3::generate(DEFAULT_TILE_SEED)))
}

/// The wavelet tiles the demo's specs are built over: the crate's quantized tiles
/// (`I16Tiles`'s), the 3D one generated at its first use.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct WebTiles;

impl Tiles for WebTiles {
    type Two = QuantizedTile2<64>;
    type Three = QuantizedTile3<32>;
    fn two() -> &'static QuantizedTile2<64> {
        &TILE2_I16
    }
    fn three() -> &'static QuantizedTile3<32> {
        web_tile3()
    }
}

/// The side of the spectrum's square: the frame's centre, at most this many pixels across
/// (a 512² transform takes 14 ms in Chromium here, a 256² one 3 ms: the spectrum's
/// frequency range is the frame's, its resolution half that of the whole frame).
pub const SPECTRUM_SIDE: usize = 256;

/// Histogram bins over `[-4σ, 4σ]` of the frame's standardised values.
pub const HISTOGRAM_BINS: usize = 64;

/// A square frame of `size × size` samples and the buffers the page draws from, reused from
/// frame to frame.
#[wasm_bindgen]
pub struct Demo {
    size: usize,
    values: Vec<f32>,
    rgba: Vec<u8>,
    spectrum: Vec<u8>,
    spectrum_rgba: Vec<u8>,
    histogram: Vec<u32>,
    mean: f32,
    std_dev: f32,
}

/// Samples `noise` at every pixel of the view into `values`.
fn fill<R: Real, N: Noise<R, 3>>(noise: &N, p: &Params, size: usize, values: &mut [f32]) {
    fill_with(&|q| noise.sample(q), p, size, values)
}

/// The plane view's grid of `size × size` pixels: its first pixel's `(x, y)` and the step
/// between pixels, in `f32`, centred on the pan. Pixel `(i, j)` is at `origin + (i, j)·step`
/// computed in `f32` by `bandnoise::batch::Grid`, so the batch path (the npm package's
/// `fillGrid` on this grid) and [`fill_with`] (its `Grid::point`) sample the same points.
fn plane(p: &Params, size: usize) -> ([f32; 2], f32) {
    let step = 1.0 / p.zoom;
    let half = size as f32 / 2.0;
    ([p.pan[0] - half * step, p.pan[1] - half * step], step)
}

/// [`fill`] through a `dyn` closure: one loop per number type rather than one per noise type
/// keeps the module small, for an indirect call per sample.
fn fill_with<R: Real>(sample: &dyn Fn([R; 3]) -> R, p: &Params, size: usize, values: &mut [f32]) {
    let (origin, step) = plane(p, size);
    let grid = Grid::new(origin, [step; 2], [size, values.len() / size.max(1)]);
    let t = R::from_f32(p.time);
    for (j, row) in values.chunks_mut(size).enumerate() {
        for (i, v) in row.iter_mut().enumerate() {
            let [x, y] = grid.point([i, j]).map(R::from_f32);
            *v = sample([x, y, t]).to_f32();
        }
    }
}

/// Wavelet noise projected along z (the time axis) as a 3D `Noise`: one type for both
/// wavelet bases, so each fill loop is compiled once for them.
#[allow(
    clippy::large_enum_variant,
    reason = "one value per frame, on the stack"
)]
enum Projected {
    Wavelet(Wavelet<'static, QuantizedTile3<32>>),
    Multiband(Multiband<'static, QuantizedTile3<32>>),
}

impl<R: Real> Noise<R, 3> for Projected {
    fn sample(&self, p: [R; 3]) -> R {
        let z = [R::ZERO, R::ZERO, R::ONE];
        match self {
            Projected::Wavelet(n) => n.sample_projected(p, z),
            Projected::Multiband(n) => n.sample_projected(p, z),
        }
    }
    fn amplitude_bound(&self) -> f32 {
        match self {
            Projected::Wavelet(n) => ProjectedNoise::<R>::projected_bound(n),
            Projected::Multiband(n) => ProjectedNoise::<R>::projected_bound(n),
        }
    }
}

impl Projected {
    /// The band projected onto the plane through `p` with normal `normal`.
    fn at<R: Real>(&self, p: [R; 3], normal: [R; 3]) -> R {
        match self {
            Projected::Wavelet(n) => n.sample_projected(p, normal),
            Projected::Multiband(n) => n.sample_projected(p, normal),
        }
    }
}

/// The noise on a sphere that fills the view (its radius half the view's width, its centre at
/// the view's centre and the time): a solid texture, sampled at each surface point, or with
/// the page's projection, wavelet noise projected onto each point's tangent plane (Cook &
/// DeRose §3.7: the band limit kept on the surface, which a solid texture's slices lose).
/// Pixels off the sphere are NaN. The projected noise is the band or multiband noise alone
/// (no fractal sum); filtering and infinite zoom apply to the plane view only.
fn fill_sphere<R: Real>(p: &Params, size: usize, values: &mut [f32]) {
    let s = p.noise.spec();
    let projected = match s.base() {
        Base::Wavelet if p.projected => Some(Projected::Wavelet(
            Wavelet::new(s.seed(), web_tile3()).with_tiling(s.tiling()),
        )),
        Base::Multiband if p.projected => Some(Projected::Multiband(
            Multiband::new(s.seed(), web_tile3(), s.bands(), s.distribution())
                .with_tiling(s.tiling()),
        )),
        _ => None,
    };
    let half = size as f32 / 2.0;
    let radius = half / p.zoom;
    for (j, row) in values.chunks_mut(size).enumerate() {
        let v = 1.0 - (j as f32 + 0.5) / half;
        for (i, out) in row.iter_mut().enumerate() {
            let u = (i as f32 + 0.5) / half - 1.0;
            let w2 = 1.0 - u * u - v * v;
            if w2 <= 0.0 {
                *out = f32::NAN;
                continue;
            }
            let n = [u, v, w2.sqrt()];
            let q = [
                p.pan[0] + radius * n[0],
                p.pan[1] - radius * n[1],
                p.time + radius * n[2],
            ]
            .map(R::from_f32);
            *out = match &projected {
                Some(band) => band.at(q, n.map(R::from_f32)),
                None => p.noise.sample(q),
            }
            .to_f32();
        }
    }
}

/// The page's zoom (pixels per unit) at which infinite noise shows the band weights as set:
/// its footprint is this over the zoom, so zooming keeps the bands where they are on screen.
const INFINITE_AT_ZOOM: f32 = 64.0;

fn fill_any<R: Real>(p: &Params, size: usize, values: &mut [f32]) {
    let s = p.noise.spec();
    // The pixel's footprint in noise space: one pixel along x and along y, none along time.
    let step = R::from_f32(1.0 / p.zoom);
    let (dx, dy) = ([step, R::ZERO, R::ZERO], [R::ZERO, step, R::ZERO]);
    let wavelet = || Wavelet::new(s.seed(), web_tile3()).with_tiling(s.tiling());
    let multiband = || {
        Multiband::new(s.seed(), web_tile3(), s.bands(), s.distribution()).with_tiling(s.tiling())
    };
    if p.infinite {
        let (noise, footprint) = (multiband(), R::from_f32(INFINITE_AT_ZOOM / p.zoom));
        return fill_with(&|q| noise.sample_infinite(q, footprint), p, size, values);
    }
    match &p.filter {
        Filter::None => {}
        Filter::Octaves(sum) => {
            return fill_with(&|q| sum.sample_filtered(q, dx, dy), p, size, values);
        }
        Filter::Band if s.base() == Base::Wavelet => {
            let noise = wavelet();
            return fill_with(&|q| noise.sample_filtered(q, dx, dy), p, size, values);
        }
        Filter::Band => {
            let noise = multiband();
            return fill_with(&|q| noise.sample_filtered(q, dx, dy), p, size, values);
        }
    }
    // Projection is a way of sampling, not a noise of its own: the spec names the noise.
    let projected = match s.base() {
        Base::Wavelet if p.projected => Projected::Wavelet(wavelet()),
        Base::Multiband if p.projected => Projected::Multiband(multiband()),
        _ => return fill::<R, _>(&p.noise, p, size, values),
    };
    match s.fractal() {
        None => fill::<R, _>(&projected, p, size, values),
        Some((kind, octaves)) => {
            fill::<R, _>(&Fractal::new(projected, octaves, kind), p, size, values)
        }
    }
}

#[wasm_bindgen]
impl Demo {
    /// A frame of `size × size` samples; `size` must be a power of two from 16 to 1024.
    ///
    /// # Errors
    ///
    /// A message if `size` is not such a power of two.
    #[wasm_bindgen(constructor)]
    pub fn new(size: u32) -> Result<Demo, JsValue> {
        if !(16..=1024).contains(&size) || !size.is_power_of_two() {
            return Err(JsValue::from_str(&format!(
                "size must be a power of two from 16 to 1024, not {size}"
            )));
        }
        let n = (size * size) as usize;
        let spectrum = SPECTRUM_SIDE.min(size as usize).pow(2);
        Ok(Demo {
            size: size as usize,
            values: vec![0.0; n],
            rgba: vec![255; n * 4],
            spectrum: vec![0; spectrum],
            spectrum_rgba: vec![255; spectrum * 4],
            histogram: vec![0; HISTOGRAM_BINS],
            mean: 0.0,
            std_dev: 0.0,
        })
    }

    /// Renders one frame for `params`: samples, statistics, colours, histogram.
    pub fn render(&mut self, params: &Params) {
        if params.fixed {
            fill_any::<I16F16>(params, self.size, &mut self.values);
        } else {
            fill_any::<f32>(params, self.size, &mut self.values);
        }
        self.finish(params);
    }

    /// The plane view's grid for `params`, for a batch sampler: `[x, y, time, step]`, the
    /// first pixel's coordinates and the step between pixels along x and y (the values
    /// [`render`](Self::render) samples at, in `f32`).
    pub fn grid(&self, params: &Params) -> Vec<f32> {
        let (origin, step) = plane(params, self.size);
        vec![origin[0], origin[1], params.time, step]
    }

    /// Where the frame's values are in this module's memory: `size²` `f32`s from this byte
    /// address, row by row. The page's batch path fills them there (the npm package's
    /// `fillGrid` of [`grid`](Self::grid) with [`Params::batch_text`](crate::Params::batch_text)
    /// into a `Float32Array` over the module's memory, made anew for each frame since the
    /// memory may grow), then calls [`render_values`](Self::render_values): no copy.
    pub fn values_address(&self) -> usize {
        self.values.as_ptr() as usize
    }

    /// Finishes a frame whose values were written at
    /// [`values_address`](Self::values_address) as [`render`](Self::render) finishes its own:
    /// statistics, colours, histogram.
    pub fn render_values(&mut self, params: &Params) {
        self.finish(params);
    }

    /// Renders the noise of `params` on a sphere that fills the frame (sliced as a solid
    /// texture, or projected onto each point's tangent plane when `params` projects): the
    /// paper's Figure 1. Pixels off the sphere are the page's background and count in no
    /// statistic.
    pub fn render_sphere(&mut self, params: &Params) {
        if params.fixed {
            fill_sphere::<I16F16>(params, self.size, &mut self.values);
        } else {
            fill_sphere::<f32>(params, self.size, &mut self.values);
        }
        self.finish(params);
    }

    /// Statistics, colours and histogram of the frame's finite values (others: background).
    fn finish(&mut self, params: &Params) {
        // One pass: count, sum and sum of squares in f64 (the values are noise, within a few
        // units, so E[v²] − mean² loses nothing that shows).
        let (mut n, mut sum, mut squares) = (0u32, 0.0f64, 0.0f64);
        for &v in self.values.iter().filter(|v| v.is_finite()) {
            let v = v as f64;
            (n, sum, squares) = (n + 1, sum + v, squares + v * v);
        }
        let n = n.max(1) as f64;
        let mean = sum / n;
        let var = (squares / n - mean * mean).max(0.0);
        (self.mean, self.std_dev) = (mean as f32, var.sqrt() as f32);
        // Colours: mean ± 3σ spans the palette (a constant frame is mid-grey).
        let scale = if self.std_dev > 0.0 {
            1.0 / (6.0 * self.std_dev)
        } else {
            0.0
        };
        self.histogram.iter_mut().for_each(|b| *b = 0);
        for (v, px) in self.values.iter().zip(self.rgba.chunks_mut(4)) {
            if !v.is_finite() {
                px[..3].copy_from_slice(&[250, 250, 250]);
                continue;
            }
            let z = (v - self.mean) * scale; // in units of 6σ
            let [r, g, b] = color(0.5 + z, params.marble);
            px[..3].copy_from_slice(&[r, g, b]);
            let bin = ((z * 6.0 + 4.0) / 8.0 * HISTOGRAM_BINS as f32).floor();
            if (0.0..HISTOGRAM_BINS as f32).contains(&bin) {
                self.histogram[bin as usize] += 1;
            }
        }
    }

    /// Draws the frame on `ctx` at (0, 0).
    ///
    /// # Errors
    ///
    /// The canvas's own error if it refuses the image.
    pub fn draw(&self, ctx: &CanvasRenderingContext2d) -> Result<(), JsValue> {
        put_rgba(ctx, &self.rgba, self.size)
    }

    /// Computes the power spectrum (log magnitude, DC centred) of the frame's central
    /// [`SPECTRUM_SIDE`]² pixels (all of a smaller frame) and draws it on `ctx`.
    ///
    /// # Errors
    ///
    /// The canvas's own error if it refuses the image.
    pub fn draw_spectrum(&mut self, ctx: &CanvasRenderingContext2d) -> Result<(), JsValue> {
        let side = SPECTRUM_SIDE.min(self.size);
        let at = (self.size - side) / 2;
        let centre: Vec<f32> = self.values[at * self.size..]
            .chunks(self.size)
            .take(side)
            .flat_map(|row| &row[at..at + side])
            .copied()
            .collect();
        log_spectrum(&centre, side, &mut self.spectrum);
        for (s, px) in self.spectrum.iter().zip(self.spectrum_rgba.chunks_mut(4)) {
            px[..3].copy_from_slice(&[*s, *s, *s]);
        }
        put_rgba(ctx, &self.spectrum_rgba, side)
    }

    /// The histogram of the frame's values, standardised, in [`HISTOGRAM_BINS`] bins over
    /// `[-4σ, 4σ]`.
    pub fn histogram(&self) -> Vec<u32> {
        self.histogram.clone()
    }

    /// The frame's mean value.
    pub fn mean(&self) -> f32 {
        self.mean
    }

    /// The frame's standard deviation.
    pub fn std_dev(&self) -> f32 {
        self.std_dev
    }

    /// Samples per frame.
    pub fn samples(&self) -> u32 {
        self.values.len() as u32
    }

    /// The spectrum as computed by the last [`draw_spectrum`](Self::draw_spectrum)
    /// ([`SPECTRUM_SIDE`]² values, or the frame's size if smaller).
    pub fn spectrum(&self) -> Vec<u8> {
        self.spectrum.clone()
    }
}

/// Draws a `size × size` RGBA buffer on `ctx` at (0, 0) with one `ImageData`.
fn put_rgba(ctx: &CanvasRenderingContext2d, rgba: &[u8], size: usize) -> Result<(), JsValue> {
    let image =
        ImageData::new_with_u8_clamped_array_and_sh(Clamped(rgba), size as u32, size as u32)?;
    ctx.put_image_data(&image, 0.0, 0.0)
}
