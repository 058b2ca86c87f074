//! The 8-bit output of `bandnoise::levels` beside FastLED's `inoise8` (issue 16, point 2): how
//! many distinct levels a 256² grid takes, and the longest run of one level along a line.
//! Defaults a user gets: `Levels::symmetric(amplitude_bound)`, a grid whose step is not a
//! power-of-two fraction of a cell and whose origin is off the lattice, fixed point (what
//! firmware runs) and f32.

use bandnoise::levels::Levels;
use bandnoise::prelude::*;
use bandnoise::spec::{Base, Spec};

/// Grid step (cells) and origin: off the lattice, not a power-of-two fraction.
const STEP: f32 = 0.0731;
const ORIGIN: [f32; 2] = [0.37, 11.19];
/// The line's step: about 1/244 of a cell (an LED animation moves a little per frame).
const LINE_STEP: f32 = 0.0041;
const LINE: usize = 65_536;

struct Figures {
    levels: usize,
    flat_run: usize,
    /// The longest run of one `u16` level along the same line.
    flat_run_u16: usize,
    /// The longest run of one value (to within 2⁻¹⁶) of the noise itself along the line.
    flat_run_noise: usize,
}

/// The longest run of equal consecutive values.
fn longest_run<T: PartialEq>(values: impl Iterator<Item = T>) -> usize {
    let (mut longest, mut run, mut last) = (0, 0, None);
    for v in values {
        run = if last.as_ref() == Some(&v) {
            run + 1
        } else {
            1
        };
        last = Some(v);
        longest = longest.max(run);
    }
    longest
}

fn figures<N: Noise<I16F16, 2> + Noise<f32, 2>>(noise: &N, fixed: bool) -> Figures {
    let levels = Levels::symmetric(Noise::<f32, 2>::amplitude_bound(noise)).unwrap();
    let at16 = |x: f32, y: f32| -> u16 {
        if fixed {
            levels.u16(Noise::<I16F16, 2>::sample(
                noise,
                [I16F16::from_num(x), I16F16::from_num(y)],
            ))
        } else {
            levels.u16(Noise::<f32, 2>::sample(noise, [x, y]))
        }
    };
    let at = |x: f32, y: f32| (at16(x, y) >> 8) as u8;
    let mut seen = [false; 256];
    for j in 0..256 {
        for i in 0..256 {
            let v = at(ORIGIN[0] + i as f32 * STEP, ORIGIN[1] + j as f32 * STEP);
            seen[usize::from(v)] = true;
        }
    }
    let line: Vec<u16> = (0..LINE)
        .map(|i| at16(ORIGIN[0] + i as f32 * LINE_STEP, ORIGIN[1]))
        .collect();
    Figures {
        levels: seen.iter().filter(|&&s| s).count(),
        flat_run: longest_run(line.iter().map(|v| v >> 8)),
        flat_run_u16: longest_run(line.iter()),
        flat_run_noise: longest_run((0..LINE).map(|i| {
            let p = [ORIGIN[0] + i as f32 * LINE_STEP, ORIGIN[1]];
            (Noise::<f32, 2>::sample(noise, p) * 65536.0).round() as i32
        })),
    }
}

/// Every lattice noise, as a user sets it up: 200 levels or more of 256 (FastLED's `inoise8`
/// takes 129), the same in f32 and fixed point; runs of one `u16` level of at most 32 samples
/// (1/8 of a cell) unless the noise itself is that flat. Improved Perlin noise is: where both
/// ends of a cell edge along the line take the same gradient across it (`(0, ±1)`, a third of
/// the 2D gradients), the noise is constant along the whole edge, so its 8-bit run is about a
/// cell long (figures in `bench/README.md`).
#[test]
fn eight_bit_output_keeps_the_noise() {
    for base in Base::ALL.into_iter().filter(|b| b.is_lattice()) {
        let n = Spec::new(base, 7).build::<2>().unwrap();
        let [fixed, float] = [true, false].map(|fixed| figures(&n, fixed));
        for (f, what) in [(&fixed, "I16F16"), (&float, "f32")] {
            println!(
                "{base} {what}: {} levels of 256; longest run of one level along a line: {} \
                 samples (u16: {}, the noise within 2^-16: {}; {} samples per cell)",
                f.levels,
                f.flat_run,
                f.flat_run_u16,
                f.flat_run_noise,
                (1.0 / LINE_STEP).round()
            );
            assert!(f.levels >= 200, "{base} {what}: {} levels", f.levels);
            assert!(
                f.flat_run_u16 <= 32 || f.flat_run_noise * 10 >= f.flat_run_u16 * 9,
                "{base} {what}: a u16 run of {} where the noise runs {}",
                f.flat_run_u16,
                f.flat_run_noise
            );
        }
        assert!(fixed.levels.abs_diff(float.levels) <= 2, "{base}");
    }
}
