//! PNG output: 16-bit grey and colour images of a noise, and small line and bar plots.

use std::fs::File;
use std::io::BufWriter;
use std::path::Path;

/// Writes `width × height` samples, 1 (grey) or 3 (RGB) channels of 16 bits.
pub fn write_png16(
    path: &Path,
    width: usize,
    height: usize,
    channels: usize,
    samples: &[u16],
) -> Result<(), String> {
    let color = if channels == 3 {
        png::ColorType::Rgb
    } else {
        png::ColorType::Grayscale
    };
    let bytes: Vec<u8> = samples.iter().flat_map(|s| s.to_be_bytes()).collect();
    write(path, width, height, color, png::BitDepth::Sixteen, &bytes)
}

/// Writes an 8-bit RGB image.
pub fn write_rgb8(path: &Path, width: usize, height: usize, rgb: &[u8]) -> Result<(), String> {
    write(
        path,
        width,
        height,
        png::ColorType::Rgb,
        png::BitDepth::Eight,
        rgb,
    )
}

fn write(
    path: &Path,
    width: usize,
    height: usize,
    color: png::ColorType,
    depth: png::BitDepth,
    data: &[u8],
) -> Result<(), String> {
    let file = File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut encoder = png::Encoder::new(BufWriter::new(file), width as u32, height as u32);
    encoder.set_color(color);
    encoder.set_depth(depth);
    let mut writer = encoder
        .write_header()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    writer
        .write_image_data(data)
        .map_err(|e| format!("{}: {e}", path.display()))
}

/// A white RGB canvas for plots, with a frame: `x` and `y` map to the plot area inside a
/// margin, `y` upwards.
pub struct Plot {
    pub width: usize,
    pub height: usize,
    pub rgb: Vec<u8>,
    margin: usize,
}

impl Plot {
    pub fn new(width: usize, height: usize) -> Self {
        let mut plot = Self {
            width,
            height,
            rgb: vec![255; width * height * 3],
            margin: 8,
        };
        let m = plot.margin as f64;
        let (w, h) = ((width - 1) as f64, (height - 1) as f64);
        for (a, b) in [
            ((m, m), (w - m, m)),
            ((m, m), (m, h - m)),
            ((w - m, m), (w - m, h - m)),
            ((m, h - m), (w - m, h - m)),
        ] {
            plot.line_px(a, b, [160, 160, 160]);
        }
        plot
    }

    /// The pixel of the unit-square point `(u, v)` (`v` upwards).
    fn at(&self, (u, v): (f64, f64)) -> (f64, f64) {
        let m = self.margin as f64;
        let (w, h) = (
            (self.width - 1) as f64 - 2.0 * m,
            (self.height - 1) as f64 - 2.0 * m,
        );
        (m + u.clamp(0.0, 1.0) * w, m + (1.0 - v.clamp(0.0, 1.0)) * h)
    }

    fn dot(&mut self, x: f64, y: f64, color: [u8; 3]) {
        let (x, y) = (x.round(), y.round());
        if x >= 0.0 && y >= 0.0 && (x as usize) < self.width && (y as usize) < self.height {
            let i = (y as usize * self.width + x as usize) * 3;
            self.rgb[i..i + 3].copy_from_slice(&color);
        }
    }

    fn line_px(&mut self, (x0, y0): (f64, f64), (x1, y1): (f64, f64), color: [u8; 3]) {
        let steps = (x1 - x0).abs().max((y1 - y0).abs()).ceil().max(1.0) as usize;
        for s in 0..=steps {
            let t = s as f64 / steps as f64;
            self.dot(x0 + (x1 - x0) * t, y0 + (y1 - y0) * t, color);
        }
    }

    /// A polyline through unit-square points.
    pub fn polyline(&mut self, points: &[(f64, f64)], color: [u8; 3]) {
        for pair in points.windows(2) {
            let (a, b) = (self.at(pair[0]), self.at(pair[1]));
            self.line_px(a, b, color);
        }
    }

    /// A bar from `u0` to `u1` of height `v` (unit square), filled.
    pub fn bar(&mut self, u0: f64, u1: f64, v: f64, color: [u8; 3]) {
        let (a, b) = (self.at((u0, 0.0)), self.at((u1, v)));
        for x in a.0.round() as usize..=b.0.round() as usize {
            for y in b.1.round() as usize..=a.1.round() as usize {
                self.dot(x as f64, y as f64, color);
            }
        }
    }
}
