//! Renders every bandnoise noise to grey-scale PNG files, so a newcomer can see them.
//!
//! ```text
//! cargo run --release -p bandnoise-gallery -- [--size N] [--scale S] [--seed K] [--out DIR]
//!     [--spec TEXT]
//! ```
//!
//! Each image samples a noise on an `N × N` grid covering `S` lattice cells per side and maps
//! `[-bound, bound]` (the noise's documented amplitude bound) to black..white. The noises come
//! from the runtime description (`bandnoise::spec`): every base in 2D, in `f32` (`NAME-2d.png`)
//! and in fixed point (`NAME-2d-fixed.png`), then fractal sums and periodic tiles written in
//! its text form. `--spec TEXT` renders one description of your own instead (`spec.png`).

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
}

fn parse_args() -> Result<Options, String> {
    let mut o = Options {
        size: 256,
        scale: 8.0,
        seed: 0,
        out: PathBuf::from("gallery-out"),
        spec: None,
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
            "-h" | "--help" => {
                return Err(
                    "usage: bandnoise-gallery [--size N] [--scale S] [--seed K] [--out DIR] \
                     [--spec TEXT]"
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
    let n = o.size as usize;
    let bound = noise.amplitude_bound();
    let step = o.scale / o.size as f32;
    let mut pixels = Vec::with_capacity(n * n);
    for j in 0..n {
        for i in 0..n {
            let p = [R::from_f32(i as f32 * step), R::from_f32(j as f32 * step)];
            let v = noise.sample(p).to_f32() / bound;
            pixels.push(((v * 0.5 + 0.5).clamp(0.0, 1.0) * 255.0).round() as u8);
        }
    }
    write_png(&o.out.join(format!("{name}.png")), o.size, &pixels)
}

fn write_png(path: &Path, size: u32, pixels: &[u8]) -> Result<(), String> {
    let file = File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut encoder = png::Encoder::new(BufWriter::new(file), size, size);
    encoder.set_color(png::ColorType::Grayscale);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| e.to_string())?;
    writer.write_image_data(pixels).map_err(|e| e.to_string())?;
    println!("wrote {}", path.display());
    Ok(())
}

/// Composed descriptions: fractal sums, and a tile of 4 × 4 cells with its fBm (lacunarity 2
/// keeps the period: the image repeats), with the gallery's seed.
const COMPOSED: [(&str, &str); 6] = [
    ("perlin-fbm-2d", "perlin fbm"),
    ("perlin-turbulence-2d", "perlin turbulence"),
    ("perlin-ridged-2d", "perlin ridged"),
    ("mnoise-fbm-2d", "mnoise fbm"),
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
    for base in Base::ALL.into_iter().filter(|b| b.has_dimension(2)) {
        let noise = build(&Spec::new(base, o.seed))?;
        render::<f32, _>(o, &format!("{base}-2d"), &noise)?;
        render::<I16F16, _>(o, &format!("{base}-2d-fixed"), &noise)?;
    }
    for (name, text) in COMPOSED {
        let spec: Spec = text.parse().map_err(|e| format!("{text:?}: {e}"))?;
        render::<f32, _>(o, name, &build(&spec.with_seed(o.seed))?)?;
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
