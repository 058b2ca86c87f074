//! `bandnoise`: render any noise description (`bandnoise::spec`) to a PNG or raw `f32`, and
//! analyse it as the survey's §6 does (periodogram, radially averaged power spectrum,
//! histogram against the standard normal). `bandnoise --help` lists the commands and
//! examples.

mod image;

use bandnoise_analysis as analysis;

use std::fmt::Write as _;
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use bandnoise::batch::Grid;
use bandnoise::spec::Spec;
use bandnoise::texture::ColorMap;
use bandnoise::{I16F16, Noise, Real};
use clap::{Arg, ArgAction, ArgMatches, Command};

const EXAMPLES: &str = "\
Examples:
  bandnoise render \"perlin seed=7 fbm octaves=6\" --out perlin.png
  bandnoise render \"marble seed=1\" --colors marble --size 512 --out marble.png
  bandnoise render \"perlin seed=3 period=8,8\" --out tile.png      (one period: tiles seamlessly)
  bandnoise render \"wavelet seed=3\" --slice 0.5 --format f32 --out band.f32
  bandnoise analyse \"multiband seed=5 bands=0,1,0\" --out analysis --numbers json

A description is a base noise and its settings, as bandnoise::spec prints them (see the crate
docs): perlin, original, value, cnoise, mnoise, mnoise4093, wavelet, multiband, sparse,
wiener, gabor, simplex, opensimplex2, opensimplex2s, flow, cellular, white, value-cubic,
windy, wrinkled, marble, marble-olano, wood, wood-olano, polka-dots; then seed=, period=,
fbm/turbulence/ridged octaves= lacunarity= gain=, warp= and the noise's own settings.";

fn command() -> Command {
    let spec = Arg::new("spec")
        .required(true)
        .value_name("DESCRIPTION")
        .help("the noise, e.g. \"perlin seed=7 fbm octaves=6\"");
    let common = [
        Arg::new("size")
            .long("size")
            .value_name("PIXELS")
            .default_value("256")
            .help("width and height in samples"),
        Arg::new("step")
            .long("step")
            .allow_negative_numbers(true)
            .value_name("UNITS")
            .help("distance between samples [default: 1/32 for render, 0.1 for analyse; one period across the image for a periodic noise]"),
        Arg::new("origin")
            .long("origin")
            .allow_hyphen_values(true)
            .value_name("X,Y")
            .help("the first sample's coordinates [default: 0,0 for render and periodic noises, 0.31,0.57 for analyse]"),
        Arg::new("slice")
            .long("slice")
            .allow_negative_numbers(true)
            .value_name("Z")
            .help("sample the 3D noise on the plane z = Z instead of the 2D noise"),
        Arg::new("fixed")
            .long("fixed")
            .action(ArgAction::SetTrue)
            .help("sample in 16.16 fixed point (I16F16) instead of f32"),
        Arg::new("progress")
            .long("progress")
            .action(ArgAction::SetTrue)
            .help("show a progress bar (shown anyway for large images on a terminal)"),
    ];
    Command::new("bandnoise")
        .about("Render and analyse band-limited procedural noise (bandnoise)")
        .after_help(EXAMPLES)
        .subcommand_required(true)
        .arg_required_else_help(true)
        .subcommand(
            Command::new("render")
                .about("Render a noise to a 16-bit PNG (grey or a colour map) or raw f32")
                .after_help(EXAMPLES)
                .arg(spec.clone())
                .args(common.clone())
                .arg(
                    Arg::new("out")
                        .long("out")
                        .short('o')
                        .value_name("FILE")
                        .default_value("noise.png"),
                )
                .arg(
                    Arg::new("format")
                        .long("format")
                        .value_parser(["png", "f32"])
                        .default_value("png")
                        .help("png: 16-bit; f32: little-endian floats, row by row"),
                )
                .arg(
                    Arg::new("range")
                        .long("range")
                        .allow_hyphen_values(true)
                        .value_name("auto|bound|MIN,MAX")
                        .default_value("auto")
                        .help("values mapped to black..white: auto (mean ± 3σ), bound (± the amplitude bound) or MIN,MAX"),
                )
                .arg(
                    Arg::new("colors")
                        .long("colors")
                        .value_parser(["grey", "marble", "wood", "water", "dots"])
                        .default_value("grey")
                        .help("a colour map (bandnoise::texture::ColorMap) over the range"),
                ),
        )
        .subcommand(
            Command::new("analyse")
                .about("The survey's §6 analysis: image, periodogram, radial power spectrum, histogram against N(0, 1)")
                .after_help(EXAMPLES)
                .arg(spec)
                .args(common)
                .arg(
                    Arg::new("out")
                        .long("out")
                        .short('o')
                        .value_name("DIR")
                        .default_value("analysis")
                        .help("directory for image.png, periodogram.png, spectrum.png, histogram.png"),
                )
                .arg(
                    Arg::new("block")
                        .long("block")
                        .value_name("SAMPLES")
                        .default_value("64")
                        .help("Bartlett's blocks: the periodogram is averaged over (size/block)² of them"),
                )
                .arg(
                    Arg::new("numbers")
                        .long("numbers")
                        .value_parser(["csv", "json"])
                        .help("also write the numbers: spectrum.csv and histogram.csv, or analysis.json"),
                ),
        )
}

/// A parsed number option.
fn number<T: std::str::FromStr>(m: &ArgMatches, name: &str) -> Result<Option<T>, String> {
    m.get_one::<String>(name)
        .map(|s| {
            s.parse()
                .map_err(|_| format!("--{name}: \"{s}\" is not a number"))
        })
        .transpose()
}

/// A `step` given as a decimal or a fraction `a/b`.
fn step(m: &ArgMatches) -> Result<Option<f64>, String> {
    let Some(s) = m.get_one::<String>("step") else {
        return Ok(None);
    };
    let v = match s.split_once('/') {
        Some((a, b)) => a
            .trim()
            .parse::<f64>()
            .ok()
            .zip(b.trim().parse::<f64>().ok())
            .map(|(a, b)| a / b),
        None => s.parse().ok(),
    };
    match v {
        Some(v) if v.is_finite() && v > 0.0 => Ok(Some(v)),
        _ => Err(format!("--step: \"{s}\" is not a positive number")),
    }
}

fn pair(m: &ArgMatches, name: &str) -> Result<Option<[f64; 2]>, String> {
    let Some(s) = m.get_one::<String>(name) else {
        return Ok(None);
    };
    two_numbers(s)
        .map(Some)
        .ok_or_else(|| format!("--{name}: \"{s}\" is not two numbers X,Y"))
}

/// Where and how densely to sample.
struct Frame {
    size: usize,
    origin: [f64; 2],
    step: f64,
    slice: Option<f64>,
    fixed: bool,
    progress: bool,
}

fn frame(m: &ArgMatches, spec: &Spec, analyse: bool) -> Result<Frame, String> {
    let size: usize = number(m, "size")?.unwrap_or(256);
    if !(2..=16384).contains(&size) {
        return Err(format!("--size {size}: must be from 2 to 16384"));
    }
    // A periodic noise: one period across (the image tiles seamlessly).
    let period = spec.period().and_then(|p| p.first().copied());
    let default_step = match (period, analyse) {
        (Some(p), _) => f64::from(p) / size as f64,
        (None, false) => 1.0 / 32.0,
        (None, true) => 0.1,
    };
    let default_origin = if analyse && period.is_none() {
        [0.31, 0.57]
    } else {
        [0.0, 0.0]
    };
    let slice = number::<f64>(m, "slice")?;
    if slice.is_some_and(|z| !z.is_finite()) {
        return Err("--slice: must be finite".into());
    }
    let big = size * size >= 1 << 20 && std::io::stderr().is_terminal();
    Ok(Frame {
        size,
        origin: pair(m, "origin")?.unwrap_or(default_origin),
        step: step(m)?.unwrap_or(default_step),
        slice,
        fixed: m.get_flag("fixed"),
        progress: m.get_flag("progress") || big,
    })
}

/// The noise sampled over the frame, row by row through the batch API, as `f32`; and its
/// amplitude bound.
fn sample(spec: &Spec, f: &Frame) -> Result<(Vec<f32>, f32), String> {
    fn fill<R: Real, const D: usize, N: Noise<R, D>>(
        noise: &N,
        f: &Frame,
        origin: [f64; D],
        step: [f64; D],
        out: &mut [f32],
    ) -> Result<(), String> {
        let n = f.size;
        let mut size = [1usize; D];
        size[0] = n;
        size[1] = n;
        let whole = Grid::<R, D>::new(
            origin.map(|v| R::from_f32(v as f32)),
            step.map(|v| R::from_f32(v as f32)),
            size,
        );
        let mut row = vec![R::ZERO; n];
        for (j, chunk) in out.chunks_mut(n).enumerate() {
            noise
                .fill_grid(&whole.row(j), &mut row)
                .map_err(|e| e.to_string())?;
            for (o, v) in chunk.iter_mut().zip(&row) {
                *o = v.to_f32();
            }
            if f.progress && (j % 16 == 15 || j + 1 == n) {
                progress((j + 1) as f64 / n as f64);
            }
        }
        if f.progress {
            eprintln!();
        }
        Ok(())
    }
    let mut out = vec![0.0f32; f.size * f.size];
    let bound;
    if let Some(z) = f.slice {
        let noise = spec.build::<3>().map_err(|e| format!("{spec}: {e}"))?;
        let (origin, step) = ([f.origin[0], f.origin[1], z], [f.step, f.step, 0.0]);
        bound = Noise::<f32, 3>::amplitude_bound(&noise);
        if f.fixed {
            fill::<I16F16, 3, _>(&noise, f, origin, step, &mut out)?;
        } else {
            fill::<f32, 3, _>(&noise, f, origin, step, &mut out)?;
        }
    } else {
        let noise = spec.build::<2>().map_err(|e| format!("{spec}: {e}"))?;
        bound = Noise::<f32, 2>::amplitude_bound(&noise);
        if f.fixed {
            fill::<I16F16, 2, _>(&noise, f, f.origin, [f.step; 2], &mut out)?;
        } else {
            fill::<f32, 2, _>(&noise, f, f.origin, [f.step; 2], &mut out)?;
        }
    }
    Ok((out, bound))
}

/// A progress bar on standard error, redrawn in place.
fn progress(done: f64) {
    let filled = (done * 40.0).round() as usize;
    let mut err = std::io::stderr();
    let _ = write!(
        err,
        "\r[{}{}] {:3.0}%",
        "#".repeat(filled),
        ".".repeat(40 - filled),
        done * 100.0
    );
    let _ = err.flush();
}

/// Mean ± 3σ (± 1 for a constant image).
fn three_sigma(mean: f64, sd: f64) -> (f64, f64) {
    if sd > 0.0 {
        (mean - 3.0 * sd, mean + 3.0 * sd)
    } else {
        (mean - 1.0, mean + 1.0)
    }
}

/// Two comma-separated finite numbers.
fn two_numbers(text: &str) -> Option<[f64; 2]> {
    let (a, b) = text.split_once(',')?;
    let (a, b) = (a.trim().parse::<f64>().ok()?, b.trim().parse::<f64>().ok()?);
    (a.is_finite() && b.is_finite()).then_some([a, b])
}

/// `[low, high]` for the image: mean ± 3σ, ± the bound, or given.
fn range(text: &str, values: &[f32], bound: f32) -> Result<(f64, f64), String> {
    match text {
        "auto" => {
            let (mean, sd) = analysis::mean_and_std_dev(values);
            Ok(three_sigma(mean, sd))
        }
        "bound" => Ok((-f64::from(bound), f64::from(bound))),
        _ => match two_numbers(text) {
            Some([a, b]) if a < b => Ok((a, b)),
            _ => Err(format!(
                "--range: \"{text}\" is not auto, bound or MIN,MAX with MIN < MAX"
            )),
        },
    }
}

fn color_map(name: &str) -> Option<ColorMap> {
    match name {
        "marble" => Some(ColorMap::MARBLE),
        "wood" => Some(ColorMap::WOOD),
        "water" => Some(ColorMap::WATER),
        "dots" => Some(ColorMap::DOTS),
        _ => None,
    }
}

/// The values as 16-bit samples over `[low, high]`, grey or through `colors`.
fn to_png16(values: &[f32], (low, high): (f64, f64), colors: Option<ColorMap>) -> Vec<u16> {
    let unit = |v: f32| ((f64::from(v) - low) / (high - low)).clamp(0.0, 1.0);
    let q = |t: f64| (t * 65535.0).round() as u16;
    match colors {
        None => values.iter().map(|&v| q(unit(v))).collect(),
        Some(map) => values
            .iter()
            .flat_map(|&v| map.map(unit(v)).map(|c| q(c.clamp(0.0, 1.0))))
            .collect(),
    }
}

fn render(m: &ArgMatches, spec: &Spec) -> Result<(), String> {
    let f = frame(m, spec, false)?;
    let (values, bound) = sample(spec, &f)?;
    let out = PathBuf::from(
        m.get_one::<String>("out")
            .map_or("noise.png", String::as_str),
    );
    if m.get_one::<String>("format").map(String::as_str) == Some("f32") {
        let bytes: Vec<u8> = values.iter().flat_map(|v| v.to_le_bytes()).collect();
        return std::fs::write(&out, bytes).map_err(|e| format!("{}: {e}", out.display()));
    }
    let r = range(
        m.get_one::<String>("range").map_or("auto", String::as_str),
        &values,
        bound,
    )?;
    let colors = color_map(m.get_one::<String>("colors").map_or("grey", String::as_str));
    let samples = to_png16(&values, r, colors);
    let channels = if colors.is_some() { 3 } else { 1 };
    image::write_png16(&out, f.size, f.size, channels, &samples)
}

fn analyse(m: &ArgMatches, spec: &Spec) -> Result<(), String> {
    let f = frame(m, spec, true)?;
    let block: usize = number(m, "block")?.unwrap_or(64);
    if !block.is_power_of_two() || block < 4 || block > f.size {
        return Err(format!(
            "--block {block}: must be a power of two from 4 to the size {}",
            f.size
        ));
    }
    let (values, _) = sample(spec, &f)?;
    let dir = PathBuf::from(
        m.get_one::<String>("out")
            .map_or("analysis", String::as_str),
    );
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let a = analysis::analyse(&values, f.size, f.step, block, 64);
    let r = three_sigma(a.mean, a.std_dev);
    image::write_png16(
        &dir.join("image.png"),
        f.size,
        f.size,
        1,
        &to_png16(&values, r, None),
    )?;
    write_periodogram(&dir.join("periodogram.png"), &a)?;
    write_spectrum_plot(&dir.join("spectrum.png"), &a)?;
    write_histogram_plot(&dir.join("histogram.png"), &a)?;
    match m.get_one::<String>("numbers").map(String::as_str) {
        Some("csv") => write_csv(&dir, &a),
        Some(_) => write_json(&dir.join("analysis.json"), spec, &f, &a),
        None => Ok(()),
    }
}

/// `log(1 + P/max P)` of the periodogram, DC in the centre, as grey.
fn write_periodogram(path: &Path, a: &analysis::Analysis) -> Result<(), String> {
    let max = a
        .periodogram
        .iter()
        .copied()
        .fold(0.0f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let top = (1.0f64 + 1e6).ln();
    let samples: Vec<u16> = a
        .periodogram
        .iter()
        .map(|p| ((1.0 + 1e6 * p / max).ln() / top * 65535.0).round() as u16)
        .collect();
    image::write_png16(path, a.block, a.block, 1, &samples)
}

/// Power against frequency: log₁₀ of the power over 8 decades below the largest.
fn write_spectrum_plot(path: &Path, a: &analysis::Analysis) -> Result<(), String> {
    let mut plot = image::Plot::new(320, 200);
    let max = a
        .spectrum
        .iter()
        .map(|s| s.1)
        .fold(f64::MIN_POSITIVE, f64::max);
    let f_max = a.spectrum.last().map_or(1.0, |s| s.0);
    let points: Vec<(f64, f64)> = a
        .spectrum
        .iter()
        .map(|&(freq, p)| (freq / f_max, 1.0 + (p.max(max * 1e-8) / max).log10() / 8.0))
        .collect();
    plot.polyline(&points, [200, 40, 40]);
    image::write_rgb8(path, plot.width, plot.height, &plot.rgb)
}

/// The histogram's bars and the standard normal density over `[-4, 4]`.
fn write_histogram_plot(path: &Path, a: &analysis::Analysis) -> Result<(), String> {
    let mut plot = image::Plot::new(320, 200);
    let top = a
        .histogram
        .iter()
        .map(|h| h.1.max(h.2))
        .fold(0.0f64, f64::max)
        .max(1e-9);
    let n = a.histogram.len() as f64;
    for (i, h) in a.histogram.iter().enumerate() {
        plot.bar(
            i as f64 / n,
            (i as f64 + 0.8) / n,
            h.1 / top,
            [90, 120, 220],
        );
    }
    let curve: Vec<(f64, f64)> = a
        .histogram
        .iter()
        .enumerate()
        .map(|(i, h)| ((i as f64 + 0.5) / n, h.2 / top))
        .collect();
    plot.polyline(&curve, [200, 40, 40]);
    image::write_rgb8(path, plot.width, plot.height, &plot.rgb)
}

fn write_csv(dir: &Path, a: &analysis::Analysis) -> Result<(), String> {
    let mut spectrum = String::from("frequency,power\n");
    for (f, p) in &a.spectrum {
        let _ = writeln!(spectrum, "{f},{p}");
    }
    let mut histogram = String::from("z,density,normal\n");
    for (z, d, n) in &a.histogram {
        let _ = writeln!(histogram, "{z},{d},{n}");
    }
    for (name, text) in [("spectrum.csv", spectrum), ("histogram.csv", histogram)] {
        let path = dir.join(name);
        std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(())
}

fn write_json(path: &Path, spec: &Spec, f: &Frame, a: &analysis::Analysis) -> Result<(), String> {
    let mut s = String::new();
    let quoted = spec.to_string().replace('\\', "\\\\").replace('"', "\\\"");
    let _ = write!(
        s,
        "{{\"spec\":\"{quoted}\",\"size\":{},\"step\":{},\"origin\":[{},{}],\"mean\":{},\"std_dev\":{},\"outside\":{},\"spectrum\":[",
        f.size, f.step, f.origin[0], f.origin[1], a.mean, a.std_dev, a.outside
    );
    for (i, (fr, p)) in a.spectrum.iter().enumerate() {
        let _ = write!(s, "{}[{fr},{p}]", if i > 0 { "," } else { "" });
    }
    s.push_str("],\"histogram\":[");
    for (i, (z, d, n)) in a.histogram.iter().enumerate() {
        let _ = write!(s, "{}[{z},{d},{n}]", if i > 0 { "," } else { "" });
    }
    s.push_str("]}\n");
    std::fs::write(path, s).map_err(|e| format!("{}: {e}", path.display()))
}

fn run() -> Result<(), String> {
    let matches = command().get_matches();
    let (name, m) = matches.subcommand().ok_or("a command: render or analyse")?;
    let text = m.get_one::<String>("spec").map_or("", String::as_str);
    let spec: Spec = text.parse().map_err(|e| format!("\"{text}\": {e}"))?;
    match name {
        "render" => render(m, &spec),
        _ => analyse(m, &spec),
    }
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("bandnoise: {e}");
            ExitCode::FAILURE
        }
    }
}
