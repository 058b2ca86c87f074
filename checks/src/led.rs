//! A realistic firmware job: an animated strip of 60 RGB LEDs showing fire, from fixed-point fBm
//! (no FPU), one frame per call, on the fastest path the crate offers a strip: 2D noise (the
//! strip's axis and time; a third axis would double the cost and add nothing a strip can
//! show) of improved Perlin noise, the cheapest fixed-point lattice noise on the Cortex-M0
//! (`bench/README.md`), and integer arithmetic from the sum to the colour.

use bandnoise::fractal::{Fractal, Octaves};
use bandnoise::lattice::Perlin;
use bandnoise::{I16F16, Noise};

/// LEDs on the strip.
pub const LEDS: usize = 60;

/// The fire: fBm of improved Perlin noise, 4 octaves.
pub struct Fire {
    noise: Fractal<Perlin>,
}

impl Default for Fire {
    fn default() -> Self {
        Self::new()
    }
}

impl Fire {
    /// The fire effect (seed 7).
    pub fn new() -> Self {
        let octaves = Octaves::new(4, 2.0, 0.5).unwrap_or_default();
        Self {
            noise: Fractal::fbm(Perlin::new(7), octaves),
        }
    }

    /// Renders frame `t` (frames are 1/50 s apart) into `strip`.
    pub fn render(&self, t: u32, strip: &mut [[u8; 3]; LEDS]) {
        let time = I16F16::from_bits((t as i32).wrapping_mul(1311)); // 0.02 per frame
        // Flames rise: the pattern moves up the strip (1.5 cells per second) and changes as it
        // goes (time on the second axis).
        let rise = time.wrapping_mul(I16F16::from_bits(3 << 15));
        for (i, led) in strip.iter_mut().enumerate() {
            let x = I16F16::from_bits(i as i32 * 9830); // 0.15 per LED
            let n = self.noise.sample([x.wrapping_sub(rise), time]);
            // Heat in [0, 1): fBm ~ [-0.9, 0.9] mapped, hotter at the strip's start.
            let base = I16F16::ONE - I16F16::from_bits(i as i32 * 1092); // 1 → 0 along the strip
            let heat = (n + base).clamp(I16F16::ZERO, I16F16::ONE - I16F16::DELTA);
            *led = palette(heat);
        }
    }
}

/// Black → red → yellow → white, in integer arithmetic.
fn palette(heat: I16F16) -> [u8; 3] {
    let h = (heat.to_bits() as u32 * 768) >> 16; // 0..768
    match h {
        0..=255 => [h as u8, 0, 0],
        256..=511 => [255, (h - 256) as u8, 0],
        _ => [255, 255, (h - 512) as u8],
    }
}

/// FNV-1a of `frames` frames' bytes.
pub fn checksum(frames: u32) -> u32 {
    let fire = Fire::new();
    let mut strip = [[0u8; 3]; LEDS];
    let mut h = 0x811C_9DC5u32;
    for t in 0..frames {
        fire.render(t, &mut strip);
        for b in strip.iter().flatten() {
            h = (h ^ *b as u32).wrapping_mul(0x0100_0193);
        }
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fire_moves_and_glows() {
        let fire = Fire::new();
        let (mut a, mut b) = ([[0u8; 3]; LEDS], [[0u8; 3]; LEDS]);
        fire.render(0, &mut a);
        fire.render(25, &mut b);
        assert_ne!(a, b, "frames half a second apart are identical");
        // Hot at the start of the strip, darker at its end.
        let heat = |s: &[[u8; 3]]| {
            s.iter()
                .map(|p| p.iter().map(|&c| c as u32).sum::<u32>())
                .sum::<u32>()
        };
        assert!(heat(&a[..10]) > heat(&a[50..]));
        assert!(a.iter().any(|p| p[0] > 0));
    }
}
