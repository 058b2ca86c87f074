//! The npm package's wasm module (`bandnoise` on npm): any noise of the crate, named by its
//! runtime description ([`bandnoise::spec`], its text form), built in 1–4D and sampled from
//! JavaScript point by point, with gradients, or over a grid into the caller's `Float32Array`.
//!
//! This crate only crosses the boundary: it parses and builds the description with
//! [`Spec`] and samples the [`SpecNoise`] it builds, so a JavaScript value is the crate's value
//! bit for bit (the package's tests compare the crate's checksums). Every bad input is a
//! JavaScript `Error` with the crate's message, never a panic. `js/index.js` wraps the exported
//! class in the package's API (a class per noise, `fromSpec`, `fillGrid`'s checks); its
//! documentation is `js/README.md`.
//!
//! Wavelet and multiband noise use the quantized tiles ([`I16Tiles`], 72 KiB instead of 144 KiB
//! of `f32`): the module is downloaded by every page that uses it. Their values differ from the
//! `f32` tiles' by the quantization (at most 1.2e-4: [`bandnoise::wavelet`]'s docs), and equal
//! those of the C library's firmware builds and of `bandnoise-checks`.

use bandnoise::batch::Grid;
use bandnoise::lattice::{OriginalPerlin, TabledPerlin, ValueNoise};
use bandnoise::simplex::Simplex;
use bandnoise::spec::{Base, I16Tiles, Spec, SpecNoise};
use bandnoise::{Noise, NoiseGradient};
use js_sys::Float32Array;
use wasm_bindgen::prelude::*;

/// A built noise of one dimension.
#[derive(Clone, Debug)]
enum Built {
    D1(SpecNoise<1, I16Tiles>),
    D2(SpecNoise<2, I16Tiles>),
    D3(SpecNoise<3, I16Tiles>),
    D4(SpecNoise<4, I16Tiles>),
}

/// A plain noise that a point sample reaches without the description's dispatch: a base whose
/// only setting is its seed, with no sum, warp or period, built as the description builds it
/// (the same values bit for bit: a test compares them). Their kernels are short enough that
/// the dispatch (`SpecNoise`'s nested `match`es, out of line in WebAssembly) is a large share
/// of a call (`bench/README.md`). Grids take the batch kernels through the description, where
/// the dispatch is once per grid row.
#[derive(Clone, Debug)]
#[allow(
    clippy::large_enum_variant,
    reason = "one per noise, in the heap (wasm-bindgen boxes RawNoise); a box more would be a load more per sample"
)]
enum Direct {
    /// Perlin noise with its per-seed table (`TabledPerlin`: 32.5 KiB in the module's memory,
    /// one dependent lookup fewer per sample), and sampled inline in the exported methods: the
    /// common case of sampling point by point.
    Perlin(TabledPerlin),
    OriginalPerlin(OriginalPerlin),
    Value(ValueNoise),
    Simplex(Simplex),
}

impl Direct {
    /// The direct form of `spec`, if it has one.
    fn of(spec: &Spec) -> Option<Direct> {
        if spec.fractal().is_some() || spec.warp().is_some() || spec.period().is_some() {
            return None;
        }
        let seed = spec.seed();
        Some(match spec.base() {
            Base::Perlin => Direct::Perlin(TabledPerlin::new(seed)),
            Base::OriginalPerlin => Direct::OriginalPerlin(OriginalPerlin::new(seed)),
            Base::Value => Direct::Value(ValueNoise::new(seed)),
            Base::Simplex => Direct::Simplex(Simplex::new(seed)),
            _ => return None,
        })
    }

    /// The value at `p`.
    #[inline]
    fn sample<const D: usize>(&self, p: [f32; D]) -> f32
    where
        TabledPerlin: Noise<f32, D>,
        OriginalPerlin: Noise<f32, D>,
        ValueNoise: Noise<f32, D>,
        Simplex: Noise<f32, D>,
    {
        match self {
            Direct::Perlin(n) => n.sample(p),
            Direct::OriginalPerlin(n) => n.sample(p),
            Direct::Value(n) => n.sample(p),
            Direct::Simplex(n) => n.sample(p),
        }
    }
}

/// The values a grid's rows are computed into before they are copied to the caller's array:
/// at most this many `f32`s (64 KiB), or one row when a row is longer.
const CHUNK: usize = 16 * 1024;

/// A noise built from its description in 1 to 4 dimensions (`js/index.js` wraps it as the
/// package's `Noise`).
#[wasm_bindgen]
#[derive(Debug)]
pub struct RawNoise {
    spec: Spec,
    built: Built,
    direct: Option<Direct>,
    /// Rows of a grid on their way to the caller's array (kept between calls).
    scratch: Vec<f32>,
}

fn error(message: impl core::fmt::Display) -> JsError {
    JsError::new(&message.to_string())
}

#[wasm_bindgen]
impl RawNoise {
    /// Parses `text` and builds it in `dims` dimensions.
    ///
    /// # Errors
    ///
    /// The parser's message (the byte position and what was expected there), a dimension
    /// outside 1..=4, or the build's refusal (a noise without that dimension).
    #[wasm_bindgen(constructor)]
    pub fn new(text: &str, dims: u32) -> Result<RawNoise, JsError> {
        let spec: Spec = text
            .parse()
            .map_err(|e| error(format_args!("bad noise description \"{text}\": {e}")))?;
        let built = match dims {
            1 => spec.build_with::<1, I16Tiles>().map(Built::D1),
            2 => spec.build_with::<2, I16Tiles>().map(Built::D2),
            3 => spec.build_with::<3, I16Tiles>().map(Built::D3),
            4 => spec.build_with::<4, I16Tiles>().map(Built::D4),
            _ => return Err(error(format_args!("dims must be 1, 2, 3 or 4, not {dims}"))),
        }
        .map_err(|e| error(format_args!("\"{text}\" in {dims}D: {e}")))?;
        Ok(RawNoise {
            direct: Direct::of(&spec),
            spec,
            built,
            scratch: Vec::new(),
        })
    }

    /// The number of dimensions it was built in.
    #[wasm_bindgen(getter)]
    pub fn dims(&self) -> u32 {
        match self.built {
            Built::D1(_) => 1,
            Built::D2(_) => 2,
            Built::D3(_) => 3,
            Built::D4(_) => 4,
        }
    }

    /// The description in full: every setting written out, defaults included, so that it
    /// keeps its meaning if a default changes (parsing it gives the same noise).
    #[wasm_bindgen(getter)]
    pub fn text(&self) -> String {
        self.spec.to_string()
    }

    /// The value at `x` of a 1D noise (`NaN` for another dimension: the wrapper calls the
    /// method of the noise's dimension).
    pub fn sample1(&self, x: f32) -> f32 {
        match (&self.direct, &self.built) {
            (Some(Direct::Perlin(n)), Built::D1(_)) => n.sample([x]),
            (_, Built::D1(n)) => self.sample_other(n, [x]),
            _ => f32::NAN,
        }
    }

    /// The value at `(x, y)` of a 2D noise (`NaN` for another dimension).
    pub fn sample2(&self, x: f32, y: f32) -> f32 {
        match (&self.direct, &self.built) {
            (Some(Direct::Perlin(n)), Built::D2(_)) => n.sample([x, y]),
            (_, Built::D2(n)) => self.sample_other(n, [x, y]),
            _ => f32::NAN,
        }
    }

    /// The value at `(x, y, z)` of a 3D noise (`NaN` for another dimension).
    pub fn sample3(&self, x: f32, y: f32, z: f32) -> f32 {
        match (&self.direct, &self.built) {
            (Some(Direct::Perlin(n)), Built::D3(_)) => n.sample([x, y, z]),
            (_, Built::D3(n)) => self.sample_other(n, [x, y, z]),
            _ => f32::NAN,
        }
    }

    /// The value at `(x, y, z, w)` of a 4D noise (`NaN` for another dimension).
    pub fn sample4(&self, x: f32, y: f32, z: f32, w: f32) -> f32 {
        match (&self.direct, &self.built) {
            (Some(Direct::Perlin(n)), Built::D4(_)) => n.sample([x, y, z, w]),
            (_, Built::D4(n)) => self.sample_other(n, [x, y, z, w]),
            _ => f32::NAN,
        }
    }

    /// A point sample of any noise but Perlin's direct form (which the `sample` methods take
    /// inline): out of line, so that the exported methods need no stack frame on their
    /// common path (about 1 ns of a 13 ns call in Chromium, `bench/README.md`).
    #[inline(never)]
    fn sample_other<const D: usize>(&self, n: &SpecNoise<D, I16Tiles>, p: [f32; D]) -> f32
    where
        SpecNoise<D, I16Tiles>: Noise<f32, D>,
        TabledPerlin: Noise<f32, D>,
        OriginalPerlin: Noise<f32, D>,
        ValueNoise: Noise<f32, D>,
        Simplex: Noise<f32, D>,
    {
        match &self.direct {
            Some(direct) => direct.sample(p),
            None => n.sample(p),
        }
    }

    /// The value and gradient at the first `dims` coordinates of `p`: `[value, ∂x, ∂y, …]`.
    ///
    /// # Errors
    ///
    /// Fewer than `dims` coordinates.
    pub fn gradient(&self, p: &[f32]) -> Result<Vec<f32>, JsError> {
        fn one<const D: usize>(n: &SpecNoise<D, I16Tiles>, p: &[f32]) -> Vec<f32>
        where
            SpecNoise<D, I16Tiles>: NoiseGradient<f32, D>,
        {
            let (v, g) = n.sample_with_gradient(core::array::from_fn(|a| p[a]));
            core::iter::once(v).chain(g).collect()
        }
        let dims = self.dims() as usize;
        if p.len() < dims {
            return Err(error(format_args!(
                "a {dims}D noise's gradient needs {dims} coordinates, not {}",
                p.len()
            )));
        }
        Ok(match &self.built {
            Built::D1(n) => one(n, p),
            Built::D2(n) => one(n, p),
            Built::D3(n) => one(n, p),
            Built::D4(n) => one(n, p),
        })
    }

    /// Fills `out` with the grid's values, axis 0 fastest: point `(i, j, …)` is
    /// `origin + (i·step₀, j·step₁, …)`, its value at index `i + size₀·(j + size₁·…)`, equal bit
    /// for bit to the point's sample. The values are computed by the crate's batch kernels row
    /// by row into a bounded buffer of this module and copied into `out` (never `out` into the
    /// module: no memory grows with the grid).
    ///
    /// # Errors
    ///
    /// Lengths of `origin`, `step` or `size` other than `dims`, a size that is not a
    /// whole number below 2³², or an `out` whose length is not the grid's point count.
    pub fn fill_grid(
        &mut self,
        out: &Float32Array,
        origin: &[f32],
        step: &[f32],
        size: &[f64],
    ) -> Result<(), JsError> {
        let dims = self.dims() as usize;
        for (name, len) in [
            ("origin", origin.len()),
            ("step", step.len()),
            ("size", size.len()),
        ] {
            if len != dims {
                return Err(error(format_args!(
                    "a {dims}D grid's {name} has {dims} numbers, not {len}"
                )));
            }
        }
        let mut sizes = [0usize; 4];
        for (s, &v) in sizes.iter_mut().zip(size) {
            // Below 2³², so that the cast is exact where `usize` has 32 bits.
            if !(v.fract() == 0.0 && (0.0..4_294_967_296.0).contains(&v)) {
                return Err(error(format_args!(
                    "a grid's size is a whole number of points below 2^32, not {v}"
                )));
            }
            *s = v as usize;
        }
        let len = sizes[..dims]
            .iter()
            .try_fold(1usize, |n, &s| n.checked_mul(s))
            .filter(|&n| n <= u32::MAX as usize);
        let Some(len) = len.filter(|&n| n == out.length() as usize) else {
            return Err(error(format_args!(
                "the array for a {} grid has {} values, not {}",
                sizes[..dims]
                    .iter()
                    .map(|s| s.to_string())
                    .collect::<Vec<_>>()
                    .join("×"),
                len.map_or_else(|| "2^32 or more".to_string(), |n| n.to_string()),
                out.length()
            )));
        };
        if len == 0 {
            return Ok(());
        }
        let scratch = &mut self.scratch;
        match &self.built {
            Built::D1(n) => fill(n, scratch, out, origin, step, &sizes),
            Built::D2(n) => fill(n, scratch, out, origin, step, &sizes),
            Built::D3(n) => fill(n, scratch, out, origin, step, &sizes),
            Built::D4(n) => fill(n, scratch, out, origin, step, &sizes),
        }
    }
}

/// [`RawNoise::fill_grid`] for a checked, non-empty grid: row by row ([`Grid::row`], the full
/// grid's values bit for bit), gathered in `scratch` up to [`CHUNK`] values per copy to `out`.
fn fill<const D: usize>(
    noise: &SpecNoise<D, I16Tiles>,
    scratch: &mut Vec<f32>,
    out: &Float32Array,
    origin: &[f32],
    step: &[f32],
    sizes: &[usize; 4],
) -> Result<(), JsError>
where
    SpecNoise<D, I16Tiles>: Noise<f32, D>,
{
    let grid = Grid::new(
        core::array::from_fn(|a| origin[a]),
        core::array::from_fn(|a| step[a]),
        core::array::from_fn(|a| sizes[a]),
    );
    let (row, rows) = (grid.size[0], grid.rows());
    let per_copy = (CHUNK / row).max(1);
    scratch.resize(per_copy * row, 0.0);
    let mut r = 0;
    while r < rows {
        let count = per_copy.min(rows - r);
        for (k, chunk) in scratch[..count * row].chunks_exact_mut(row).enumerate() {
            noise.fill_grid(&grid.row(r + k), chunk).map_err(error)?;
        }
        let at = (r * row) as u32;
        out.subarray(at, at + (count * row) as u32)
            .copy_from(&scratch[..count * row]);
        r += count;
    }
    Ok(())
}

/// The names of every noise, separated by spaces, in the crate's order ([`Base::ALL`]): the
/// package has a class for each.
#[wasm_bindgen]
pub fn bases() -> String {
    Base::ALL.map(Base::name).join(" ")
}

/// The dimensions a noise has a form in, as a bit mask (bit `d - 1` for `d`D), or 0 for an
/// unknown name.
#[wasm_bindgen(js_name = dimensionMask)]
pub fn dimension_mask(name: &str) -> u32 {
    Base::ALL
        .into_iter()
        .find(|b| b.name() == name)
        .map_or(0, |b| {
            (1..=4u32)
                .filter(|&d| b.has_dimension(d as usize))
                .map(|d| 1 << (d - 1))
                .sum()
        })
}

#[cfg(test)]
mod tests {
    use super::{Direct, RawNoise};
    use bandnoise::Noise;
    use bandnoise::spec::{I16Tiles, Spec, SpecNoise};

    /// Points off the lattice, on it, negative, far and non-finite.
    fn points<const D: usize>() -> Vec<[f32; D]> {
        let xs = [
            0.37,
            -1.5,
            0.0,
            -0.0,
            3.999_999_8,
            1e-30,
            -2.25e5,
            7.3e9,
            f32::NAN,
            f32::INFINITY,
        ];
        let mut state = 0x2545_f491u32;
        let mut random = || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            (state >> 8) as f32 / 65_536.0 - 128.0
        };
        (0..2000)
            .map(|k| {
                core::array::from_fn(|a| {
                    if k < 100 {
                        xs[(k + 3 * a) % 10]
                    } else {
                        random()
                    }
                })
            })
            .collect()
    }

    /// A plain seed-only description samples through its direct form, a layered one does not,
    /// and both give the description's values bit for bit in 1–4D.
    #[test]
    fn direct_samples_are_the_description_values() {
        fn case<const D: usize>(text: &str, direct: bool)
        where
            SpecNoise<D, I16Tiles>: Noise<f32, D>,
        {
            let spec: Spec = text.parse().unwrap();
            assert_eq!(Direct::of(&spec).is_some(), direct, "{text}");
            let expected = spec.build_with::<D, I16Tiles>().unwrap();
            let raw = RawNoise::new(text, D as u32).unwrap();
            for p in points::<D>() {
                let got = match D {
                    1 => raw.sample1(p[0]),
                    2 => raw.sample2(p[0], p[1]),
                    3 => raw.sample3(p[0], p[1], p[2]),
                    _ => raw.sample4(p[0], p[1], p[2], p[3]),
                };
                let want = expected.sample(p);
                assert_eq!(got.to_bits(), want.to_bits(), "{text} {D}D {p:?}");
            }
        }
        for (text, direct) in [
            ("perlin seed=7", true),
            ("original seed=7", true),
            ("value seed=7", true),
            ("simplex seed=7", true),
            ("value seed=7 fbm octaves=3", false),
            ("simplex seed=7 warp=0.5", false),
            ("cellular seed=7", false),
        ] {
            case::<1>(text, direct);
            case::<2>(text, direct);
            case::<3>(text, direct);
            case::<4>(text, direct);
        }
        case::<2>("perlin seed=7 period=4,4", false);
    }
}
