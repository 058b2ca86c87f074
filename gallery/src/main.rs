//! Renders every bandnoise noise to grey-scale PNG files (the textures in colour), so a
//! newcomer can see them.
//!
//! ```text
//! cargo run --release -p bandnoise-gallery -- [--size N] [--scale S] [--seed K] [--out DIR]
//!     [--spec TEXT] [--textures]
//! ```
//!
//! Each image samples a noise on an `N × N` grid covering `S` lattice cells per side and maps
//! `[-bound, bound]` (the noise's documented amplitude bound) to black..white. The noises come
//! from the runtime description (`bandnoise::spec`): every base in 2D, in `f32` (`NAME-2d.png`)
//! and in fixed point (`NAME-2d-fixed.png`), then fractal sums and periodic tiles written in
//! its text form; then one wavelet band with each tiling, wavelet noise plain and filtered by
//! the pixel's footprint, infinite wavelet noise at four zooms, and the textures in colour.
//! `--spec TEXT` renders one description of your own instead (`spec.png`); `--textures` only
//! the textures (the README's images are `--textures --size 128`, in `docs/textures/`).

use std::fs::{self, File};
use std::io::BufWriter;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use bandnoise::prelude::*;
use bandnoise::spec::{Base, Spec, SpecNoise};

struct Options {
    size: u32,
    scale: f32,
    seed: u32,
    out: PathBuf,
    spec: Option<Spec>,
    textures: bool,
}

fn parse_args() -> Result<Options, String> {
    let mut o = Options {
        size: 256,
        scale: 8.0,
        seed: 0,
        out: PathBuf::from("gallery-out"),
        spec: None,
        textures: false,
    };
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        let mut value = || args.next().ok_or_else(|| format!("{flag} needs a value"));
        match flag.as_str() {
            "--size" => {
                o.size = value()?.parse().map_err(|e| format!("--size: {e}"))?;
                if !(1..=4096).contains(&o.size) {
                    return Err("--size must be in 1..=4096".into());
                }
            }
            "--scale" => {
                o.scale = value()?.parse().map_err(|e| format!("--scale: {e}"))?;
                if !(o.scale.is_finite() && o.scale > 0.0) {
                    return Err("--scale must be a positive number".into());
                }
            }
            "--seed" => o.seed = value()?.parse().map_err(|e| format!("--seed: {e}"))?,
            "--out" => o.out = PathBuf::from(value()?),
            "--spec" => {
                let text = value()?;
                o.spec = Some(text.parse().map_err(|e| format!("--spec {text:?}: {e}"))?);
            }
            "--textures" => o.textures = true,
            "-h" | "--help" => {
                return Err(
                    "usage: bandnoise-gallery [--size N] [--scale S] [--seed K] [--out DIR] \
                     [--spec TEXT] [--textures]"
                        .into(),
                );
            }
            other => return Err(format!("unknown argument {other}")),
        }
    }
    Ok(o)
}

/// Samples `noise` over the grid and writes it as an 8-bit grey PNG.
fn render<R: Real, N: Noise<R, 2>>(o: &Options, name: &str, noise: &N) -> Result<(), String> {
    render_scaled(o, name, noise, noise.amplitude_bound())
}

/// Samples `noise` over the grid mapping `[-bound, bound]` to black..white.
fn render_scaled<R: Real, N: Noise<R, 2>>(
    o: &Options,
    name: &str,
    noise: &N,
    bound: f32,
) -> Result<(), String> {
    let f = |p: [f32; 2], _| noise.sample(p.map(R::from_f32)).to_f32();
    render_with(o, name, bound, 1.0, f)
}

/// Writes `f(p, footprint)` over the grid, zoomed in `zoom` times about its centre, mapping
/// `[-bound, bound]` to black..white. `footprint` is the distance between pixels.
fn render_with(
    o: &Options,
    name: &str,
    bound: f32,
    zoom: f32,
    f: impl Fn([f32; 2], f32) -> f32,
) -> Result<(), String> {
    let n = o.size as usize;
    let step = o.scale / o.size as f32 / zoom;
    let centre = 0.5 * o.scale;
    let mut pixels = Vec::with_capacity(n * n);
    for j in 0..n {
        for i in 0..n {
            let at = |k: usize| centre + (k as f32 - 0.5 * n as f32) * step;
            let v = f([at(i), at(j)], step) / bound;
            pixels.push(((v * 0.5 + 0.5).clamp(0.0, 1.0) * 255.0).round() as u8);
        }
    }
    write_png(&o.out.join(format!("{name}.png")), o.size, &pixels)
}

/// Wavelet noise rendered as a pixel sees it (Cook & DeRose §4.1, §5.4): ten bands of equal
/// weight, most of them finer than the pixels, sampled plainly (aliased) and filtered by the
/// pixel's footprint; and infinite noise zoomed in 1, 16, 256 and 4096 times.
fn render_wavelet_filtering(o: &Options) -> Result<(), String> {
    use bandnoise::wavelet::{Bands, Distribution, Multiband, TILE2};
    let bands = Bands::new(-1, &[1.0; 10]).map_err(|e| e.to_string())?;
    let m = Multiband::new(o.seed, &TILE2, bands, Distribution::Gaussian);
    let bound = 3.0; // three standard deviations
    render_with(o, "wavelet-10-bands-plain", bound, 1.0, |p, _| m.sample(p))?;
    render_with(o, "wavelet-10-bands-filtered", bound, 1.0, |p, w| {
        m.sample_filtered(p, [w, 0.0], [0.0, w])
    })?;
    // Six halving bands relative to a footprint of 1, the finest at ¼ coefficient per pixel.
    let bands = Bands::fractal(-8, 6, 0.5).map_err(|e| e.to_string())?;
    let infinite = Multiband::new(o.seed, &TILE2, bands, Distribution::Gaussian);
    for zoom in [1u32, 16, 256, 4096] {
        render_with(
            o,
            &format!("wavelet-infinite-zoom-{zoom}"),
            bound,
            zoom as f32,
            |p, w| infinite.sample_infinite(p, w),
        )?;
    }
    Ok(())
}

fn write_png(path: &Path, size: u32, pixels: &[u8]) -> Result<(), String> {
    write_png_as(path, size, pixels, png::ColorType::Grayscale)
}

fn write_png_as(
    path: &Path,
    size: u32,
    pixels: &[u8],
    color: png::ColorType,
) -> Result<(), String> {
    let file = File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut encoder = png::Encoder::new(BufWriter::new(file), size, size);
    encoder.set_color(color);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| e.to_string())?;
    writer.write_image_data(pixels).map_err(|e| e.to_string())?;
    println!("wrote {}", path.display());
    Ok(())
}

/// Composed descriptions: fractal sums, cubic value noise over Gaussian values, and a tile of
/// 4 × 4 cells with its fBm (lacunarity 2 keeps the period: the image repeats), with the
/// gallery's seed.
const COMPOSED: [(&str, &str); 8] = [
    ("perlin-fbm-2d", "perlin fbm"),
    ("perlin-turbulence-2d", "perlin turbulence"),
    ("perlin-ridged-2d", "perlin ridged"),
    ("mnoise-fbm-2d", "mnoise fbm"),
    ("value-cubic-fbm-2d", "value-cubic fbm"),
    (
        "value-cubic-gaussian-2d",
        "value-cubic distribution=gaussian",
    ),
    ("perlin-periodic-2d", "perlin period=4,4"),
    (
        "perlin-periodic-fbm-2d",
        "perlin period=4,4 fbm octaves=6 lacunarity=2 gain=0.5",
    ),
];

fn build(spec: &Spec) -> Result<SpecNoise<2>, String> {
    spec.build::<2>().map_err(|e| format!("{spec}: {e}"))
}

fn run(o: &Options) -> Result<(), String> {
    fs::create_dir_all(&o.out).map_err(|e| format!("{}: {e}", o.out.display()))?;
    if let Some(spec) = &o.spec {
        return render::<f32, _>(o, "spec", &build(spec)?);
    }
    if o.textures {
        return render_textures(o);
    }
    for base in Base::ALL.into_iter().filter(|b| b.has_dimension(2)) {
        let noise = build(&Spec::new(base, o.seed))?;
        if base == Base::Cellular {
            // Distances from 0: black at the feature points.
            render_from_zero::<f32>(o, &format!("{base}-2d"), &noise, 1.0)?;
            render_from_zero::<I16F16>(o, &format!("{base}-2d-fixed"), &noise, 1.0)?;
        } else if base.is_texture() && base != Base::Windy {
            // Patterns in [0, 1]; wrinkled's turbulence mostly below 1.5.
            let top = if base == Base::Wrinkled { 1.5 } else { 1.0 };
            render_from_zero::<f32>(o, &format!("{base}-2d"), &noise, top)?;
            render_from_zero::<I16F16>(o, &format!("{base}-2d-fixed"), &noise, top)?;
        } else if base.is_impulse() || base == Base::Wiener {
            // Variance 1 and a bound far above what occurs: show ±3σ.
            render_scaled::<f32, _>(o, &format!("{base}-2d"), &noise, 3.0)?;
            render_scaled::<I16F16, _>(o, &format!("{base}-2d-fixed"), &noise, 3.0)?;
        } else {
            render::<f32, _>(o, &format!("{base}-2d"), &noise)?;
            render::<I16F16, _>(o, &format!("{base}-2d-fixed"), &noise)?;
        }
    }
    for (name, text) in COMPOSED {
        let spec: Spec = text.parse().map_err(|e| format!("{text:?}: {e}"))?;
        render::<f32, _>(o, name, &build(&spec.with_seed(o.seed))?)?;
    }
    render_wavelet_tilings(o)?;
    render_sparse_densities(o)?;
    render_wiener_covariances(o)?;
    render_gabor_variants(o)?;
    render_curl(o)?;
    render_flow_and_warp(o)?;
    render_cellular_variants(o)?;
    render_textures(o)?;
    render_wavelet_filtering(o)
}

/// Writes the colour `f(p)` over the grid (the same grid as [`render_with`]) as an RGB PNG.
fn render_rgb(o: &Options, name: &str, f: impl Fn([f32; 2]) -> [u8; 3]) -> Result<(), String> {
    let n = o.size as usize;
    let step = o.scale / o.size as f32;
    let centre = 0.5 * o.scale;
    let mut pixels = Vec::with_capacity(3 * n * n);
    for j in 0..n {
        for i in 0..n {
            let at = |k: usize| centre + (k as f32 - 0.5 * n as f32) * step;
            pixels.extend_from_slice(&f([at(i), at(j)]));
        }
    }
    write_png_as(
        &o.out.join(format!("{name}.png")),
        o.size,
        &pixels,
        png::ColorType::Rgb,
    )
}

/// The textures (`bandnoise::texture`) in colour, in `f32` and (`-fixed`) in I16F16: pbrt's
/// windy waves, wrinkled, marble and polka dots, Lewis's wood, Olano's wood and marble, in 2D
/// (the plane z = 0 of the solid textures); the wood's trunk (the z axis) is at the image's
/// centre.
fn render_textures(o: &Options) -> Result<(), String> {
    render_texture(o, "texture-windy", &Windy::new(o.seed), [0.0; 2])?;
    render_texture(o, "texture-wrinkled", &Wrinkled::new(o.seed), [0.0; 2])?;
    render_texture(o, "texture-marble-pbrt", &Marble::new(o.seed), [0.0; 2])?;
    render_texture(o, "texture-marble-olano", &Marble::olano(o.seed), [0.0; 2])?;
    render_texture(o, "texture-polka-dots", &PolkaDots::new(o.seed), [0.0; 2])?;
    let trunk = [0.5 * o.scale; 2];
    render_texture(o, "texture-wood-lewis", &Wood::new(o.seed), trunk)?;
    render_texture(o, "texture-wood-olano", &Wood::olano(o.seed), trunk)
}

/// One texture in `f32` and in I16F16, moved by `-origin`.
fn render_texture<T: Texture<f32, 2> + Texture<I16F16, 2>>(
    o: &Options,
    name: &str,
    texture: &T,
    origin: [f32; 2],
) -> Result<(), String> {
    let at = |p: [f32; 2]| [p[0] - origin[0], p[1] - origin[1]];
    render_rgb(o, name, |p| texture.color_rgb8(at(p)))?;
    render_rgb(o, &format!("{name}-fixed"), |p| {
        texture.color_rgb8(at(p).map(I16F16::from_num))
    })
}

/// Samples `noise` over the grid mapping `[0, top]` to black..white (cellular distances).
fn render_from_zero<R: Real>(
    o: &Options,
    name: &str,
    noise: &SpecNoise<2>,
    top: f32,
) -> Result<(), String> {
    render_with(o, name, top, 1.0, |p, _| {
        2.0 * Noise::<R, 2>::sample(noise, p.map(R::from_f32)).to_f32() - top
    })
}

/// Cellular noise (Worley 1996) beyond its default (`cellular-2d`: F1, Euclidean): the cell
/// borders (F2 − F1), F2, the cells' values (a Voronoi diagram), the Manhattan and Chebyshev
/// metrics, and a jitter of 0.5 (an even tiling).
fn render_cellular_variants(o: &Options) -> Result<(), String> {
    let variants = [
        ("cellular-f2-f1-2d", "output=f2-f1", 0.8),
        ("cellular-f2-2d", "output=f2", 1.3),
        ("cellular-value-2d", "output=value", 0.0),
        ("cellular-manhattan-2d", "metric=manhattan", 1.4),
        ("cellular-chebyshev-2d", "metric=chebyshev", 0.9),
        ("cellular-jitter-0.5-2d", "jitter=0.5", 0.9),
    ];
    for (name, settings, top) in variants {
        let text = format!("cellular seed={} {settings}", o.seed);
        let spec: Spec = text.parse().map_err(|e| format!("{text:?}: {e}"))?;
        let noise = build(&spec)?;
        if top == 0.0 {
            render::<f32, _>(o, name, &noise)?;
        } else {
            render_from_zero::<f32>(o, name, &noise, top)?;
        }
    }
    Ok(())
}

/// Curl noise (Bridson et al. 2007) over simplex noise: the field's two components (its
/// potential's gradient turned a quarter turn), each mapped from ±3.
fn render_curl(o: &Options) -> Result<(), String> {
    let flow = Curl2::new(Simplex::new(o.seed));
    render_with(o, "curl-2d-x", 3.0, 1.0, |p, _| flow.sample_vector(p)[0])?;
    render_with(o, "curl-2d-y", 3.0, 1.0, |p, _| flow.sample_vector(p)[1])
}

/// Flow noise (Perlin and Neyret 2001) at three angles of its rotating gradients (the
/// features swirl in place) and its fBm with pseudo-advection, domain warping (Lewis's stochastic deformation) of Perlin noise
/// by two simplex noises, OpenSimplex2 and OpenSimplex2S, and Olano's 4-octave turbulence of
/// mNoise (3D, the slice z = 0.37).
fn render_flow_and_warp(o: &Options) -> Result<(), String> {
    // Through the description: flow noise at three angles, and its fBm advected.
    let flow = [
        ("flow-2d-angle-0", "angle=0", 1.0),
        ("flow-2d-angle-0.125", "angle=0.125", 1.0),
        ("flow-2d-angle-0.25", "angle=0.25", 1.0),
        (
            "flow-fbm-advected-2d",
            "fbm octaves=5 lacunarity=2 gain=0.5 advection=0.5",
            1.5,
        ),
    ];
    for (name, settings, top) in flow {
        let text = format!("flow seed={} {settings}", o.seed);
        let spec: Spec = text.parse().map_err(|e| format!("{text:?}: {e}"))?;
        let noise = build(&spec)?;
        render_with(o, name, top, 1.0, |p, _| Noise::<f32, 2>::sample(&noise, p))?;
    }
    let field = Components::new([Simplex::new(o.seed ^ 1), Simplex::new(o.seed ^ 2)]);
    let warp = Warp::new(Perlin::new(o.seed), field, 1.0).map_err(|e| e.to_string())?;
    render_with(o, "warp-perlin-2d", 1.0, 1.0, |p, _| warp.sample(p))?;
    // OpenSimplex2S in 3D turned for a vertical z (the slice z = 0.37; its 2D images come
    // from the description).
    let terrain = OpenSimplex2S::new(i64::from(o.seed)).improving(Improve::XY);
    render_with(o, "opensimplex2s-3d-improve-xy", 1.0, 1.0, |p, _| {
        terrain.sample([p[0], p[1], 0.37])
    })?;
    let turbulence = MixedTurbulence::<4>::new(o.seed);
    // |n| ≥ 0 with mean about 0.35: map [0, 1.2] to black..white.
    render_with(o, "mnoise-turbulence-3d", 0.6, 1.0, |p, _| {
        turbulence.sample([p[0], p[1], 0.37]) - 0.6
    })
}

/// Gabor noise (Lagae et al. 2009) beyond its default (`gabor-2d`: anisotropic along x): the
/// isotropic variant, narrow-band stripes at 45°, a wide band, and the paper's truncated
/// envelope, ±3σ.
fn render_gabor_variants(o: &Options) -> Result<(), String> {
    let variants = [
        ("gabor-isotropic-2d", "orientation=isotropic"),
        (
            "gabor-narrow-45-2d",
            "frequency=2 bandwidth=0.4 direction=1,1",
        ),
        ("gabor-wide-2d", "frequency=1 bandwidth=2"),
        ("gabor-truncated-2d", "envelope=truncated"),
    ];
    for (name, settings) in variants {
        let text = format!("gabor seed={} {settings}", o.seed);
        let spec: Spec = text.parse().map_err(|e| format!("{text:?}: {e}"))?;
        render_scaled::<f32, _>(o, name, &build(&spec)?, 3.0)?;
    }
    Ok(())
}

/// Sparse convolution noise at 1, 3, 10 and 30 impulses per kernel volume, with Lewis's and
/// Peachey's kernels (Lewis 1989 §4: below a few impulses per kernel the noise is lumpy; at ten
/// and more it is convolved white noise), ±3σ, features a few pixels wide at the default size.
fn render_sparse_densities(o: &Options) -> Result<(), String> {
    for kernel in ["cosine", "catmull-rom"] {
        for density in ["1", "3", "10", "30"] {
            let text = format!("sparse seed={} kernel={kernel} density={density}", o.seed);
            let spec: Spec = text.parse().map_err(|e| format!("{text:?}: {e}"))?;
            let noise = build(&spec)?;
            let name = format!("sparse-{kernel}-{density}");
            render_scaled::<f32, _>(o, &name, &noise, 3.0)?;
        }
    }
    Ok(())
}

/// Wiener-interpolated noise (Lewis 1989 §3) with the band-pass covariance, ±3σ (the
/// low-pass default is `wiener-2d`).
fn render_wiener_covariances(o: &Options) -> Result<(), String> {
    let text = format!("wiener seed={} covariance=band-pass", o.seed);
    let spec: Spec = text.parse().map_err(|e| format!("{text:?}: {e}"))?;
    render_scaled::<f32, _>(o, "wiener-band-pass-2d", &build(&spec)?, 3.0)
}

/// One 2D wavelet band over four of its 64² tiles (128 coefficients across the image, whatever
/// `--scale`) with each tiling: `periodic` repeats, `varied` shows block borders
/// (some mirrored), `blended` (the default) neither.
fn render_wavelet_tilings(o: &Options) -> Result<(), String> {
    use bandnoise::wavelet::{TILE2, Tiling, Wavelet};
    for (name, tiling) in [
        ("periodic", Tiling::Periodic),
        ("varied", Tiling::Varied),
        ("blended", Tiling::Blended),
    ] {
        let band = Wavelet::new(o.seed, &TILE2).with_tiling(tiling);
        // Three standard deviations of a 2D band (its variance is about 0.27).
        let bound = 1.6;
        let zoom = o.scale / 128.0;
        render_with(o, &format!("wavelet-tiling-{name}"), bound, zoom, |p, _| {
            band.sample(p)
        })?;
    }
    Ok(())
}

fn main() -> ExitCode {
    match parse_args().and_then(|o| run(&o)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("bandnoise-gallery: {e}");
            ExitCode::FAILURE
        }
    }
}
