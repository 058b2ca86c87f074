//! The `bandnoise` command on small sizes: its files decode to what was asked for, a periodic
//! noise's image tiles, the analysis's numbers are a density and a spectrum where the noise
//! puts its energy, and bad input is an error naming the problem.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use bandnoise::spec::Spec;
use bandnoise::{Noise, batch::Grid};

fn bandnoise(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_bandnoise"))
        .args(args)
        .output()
        .expect("runs")
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir
}

fn ok(out: &Output) {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The PNG's size, colour type and bit depth.
fn png_info(path: &Path) -> (u32, u32, png::ColorType, png::BitDepth) {
    let decoder = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(path).expect("written"),
    ));
    let reader = decoder.read_info().expect("a PNG");
    let info = reader.info();
    (info.width, info.height, info.color_type, info.bit_depth)
}

#[test]
fn help_has_examples() {
    let out = bandnoise(&["--help"]);
    ok(&out);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("Examples:") && text.contains("bandnoise render"),
        "{text}"
    );
    let out = bandnoise(&["analyse", "--help"]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("--numbers"));
}

#[test]
fn renders_16_bit_grey_and_colour() {
    let dir = scratch("render");
    let grey = dir.join("grey.png");
    ok(&bandnoise(&[
        "render",
        "perlin seed=7 fbm octaves=4",
        "--size",
        "48",
        "--out",
        grey.to_str().unwrap(),
    ]));
    assert_eq!(
        png_info(&grey),
        (48, 48, png::ColorType::Grayscale, png::BitDepth::Sixteen)
    );
    // Negative coordinates and ranges read as values.
    ok(&bandnoise(&[
        "render",
        "perlin",
        "--origin",
        "-3.5,-2",
        "--slice",
        "-0.5",
        "--range",
        "-1,1",
        "--size",
        "8",
        "--out",
        dir.join("negative.png").to_str().unwrap(),
    ]));
    let colour = dir.join("marble.png");
    ok(&bandnoise(&[
        "render",
        "marble seed=1",
        "--colors",
        "marble",
        "--size",
        "40",
        "--fixed",
        "--progress",
        "--out",
        colour.to_str().unwrap(),
    ]));
    assert_eq!(
        png_info(&colour),
        (40, 40, png::ColorType::Rgb, png::BitDepth::Sixteen)
    );
}

/// Raw f32 output is the noise's batch values over the frame, bit for bit, and a periodic
/// noise's default frame is one period: the next period's first column is the image's first.
#[test]
fn raw_f32_is_the_noise_and_periodic_output_tiles() {
    let dir = scratch("raw");
    let path = dir.join("tile.f32");
    let text = "value-cubic seed=4 period=6,6";
    ok(&bandnoise(&[
        "render",
        text,
        "--size",
        "48",
        "--format",
        "f32",
        "--out",
        path.to_str().unwrap(),
    ]));
    let bytes = std::fs::read(&path).expect("written");
    let values: Vec<f32> = bytes
        .chunks(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    assert_eq!(values.len(), 48 * 48);
    let noise = text.parse::<Spec>().unwrap().build::<2>().unwrap();
    // One period across: the step is 6/48 = 1/8, exact.
    let grid = Grid::new([0.0f32, 0.0], [0.125, 0.125], [48, 48]);
    let mut expected = vec![0.0f32; grid.len()];
    noise.fill_grid(&grid, &mut expected).unwrap();
    assert_eq!(
        values.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        expected.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
    );
    for row in 0..48 {
        let y = row as f32 * 0.125;
        assert_eq!(noise.sample([6.0, y]), values[row * 48], "row {row}");
        assert_eq!(noise.sample([y, 6.0]), values[row], "column {row}");
    }
}

/// The analysis of one wavelet band: the histogram is a density close to N(0, 1), and the
/// radial spectrum has its peak inside the band, far above the lowest frequencies.
#[test]
fn analyse_writes_images_and_numbers() {
    let dir = scratch("analyse");
    ok(&bandnoise(&[
        "analyse",
        "multiband seed=5 bands=0,1,0",
        "--size",
        "128",
        "--block",
        "32",
        "--numbers",
        "json",
        "--out",
        dir.to_str().unwrap(),
    ]));
    for name in [
        "image.png",
        "periodogram.png",
        "spectrum.png",
        "histogram.png",
    ] {
        assert!(dir.join(name).exists(), "{name}");
    }
    assert_eq!(png_info(&dir.join("periodogram.png")).0, 32);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("analysis.json")).unwrap())
            .expect("valid JSON");
    let histogram = json["histogram"].as_array().unwrap();
    let width = 8.0 / histogram.len() as f64;
    let mass: f64 = histogram
        .iter()
        .map(|h| h[1].as_f64().unwrap() * width)
        .sum();
    let outside = json["outside"].as_f64().unwrap() / (128.0 * 128.0);
    assert!((mass + outside - 1.0).abs() < 1e-9, "{mass} {outside}");
    // Standardised, the middle bin is near the normal density 0.399.
    let middle = &histogram[histogram.len() / 2];
    assert!(
        (middle[1].as_f64().unwrap() - 0.399).abs() < 0.1,
        "{middle:?}"
    );
    let spectrum: Vec<(f64, f64)> = json["spectrum"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| (s[0].as_f64().unwrap(), s[1].as_f64().unwrap()))
        .collect();
    let peak = spectrum
        .iter()
        .copied()
        .fold((0.0, 0.0), |a, s| if s.1 > a.1 { s } else { a });
    // Band 1 of multiband noise (first=0, the second weight): about one cycle per unit.
    assert!((0.5..2.0).contains(&peak.0), "{peak:?}");
    assert!(spectrum[0].1 < peak.1 / 5.0, "{spectrum:?}");
    let csv = scratch("analyse-csv");
    ok(&bandnoise(&[
        "analyse",
        "white seed=1",
        "--size",
        "64",
        "--block",
        "16",
        "--numbers",
        "csv",
        "--out",
        csv.to_str().unwrap(),
    ]));
    let text = std::fs::read_to_string(csv.join("spectrum.csv")).unwrap();
    assert!(
        text.starts_with("frequency,power\n") && text.lines().count() == 9,
        "{text}"
    );
}

#[test]
fn bad_input_is_an_error_naming_the_problem() {
    for (args, says) in [
        (vec!["render", "perlin seed=-1"], "at byte 12"),
        (vec!["render", "perlin", "--size", "1"], "--size 1"),
        (vec!["render", "perlin", "--range", "1,0"], "--range"),
        (vec!["render", "flow", "--slice", "0.5"], "no 3D form"),
        (vec!["analyse", "perlin", "--block", "48"], "--block 48"),
        (vec!["render", "perlin", "--step", "-1"], "--step"),
        (vec!["render", "perlin", "--origin", "1"], "--origin"),
    ] {
        let out = bandnoise(&args);
        assert!(!out.status.success(), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(says), "{args:?}: {err}");
    }
}
