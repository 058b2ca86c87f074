//! The analysis on known inputs: a sine's power in one ring of the spectrum, the histogram a
//! density. (Tests here, not in the library: a test-mode copy of the library instantiates
//! rustfft again, about half a minute of build for two tests.)

use std::f64::consts::PI;

use bandnoise_analysis::analyse;

#[test]
fn a_sine_puts_its_power_in_one_ring() {
    // 4 cycles across a 64-sample block at step 1/16: 1 cycle per unit.
    let side = 64;
    let values: Vec<f32> = (0..side * side)
        .map(|i| (2.0 * PI * 4.0 * (i % side) as f64 / side as f64).sin() as f32)
        .collect();
    let a = analyse(&values, side, 1.0 / 16.0, 64, 32);
    let (f, p) = a
        .spectrum
        .iter()
        .copied()
        .fold((0.0, 0.0), |best, s| if s.1 > best.1 { s } else { best });
    assert!((f - 1.0).abs() < 1e-9, "{f}");
    // Parseval: the cells' mean is the variance ½ (white noise would be flat at it), all
    // of it in the two cells at ±1 cycle per unit, so the ring's mean is positive.
    let mean = a.periodogram.iter().sum::<f64>() / (64.0 * 64.0);
    // (Within f32 rounding of the sine: the values are f32.)
    assert!((mean - 0.5).abs() < 1e-6 && p > 0.0, "{mean} {p}");
}

#[test]
fn the_histogram_is_a_density() {
    let values: Vec<f32> = (0..4096).map(|i| ((i * 7919) % 4096) as f32).collect();
    let a = analyse(&values, 64, 0.1, 32, 64);
    let width = 8.0 / 64.0;
    let mass: f64 = a.histogram.iter().map(|h| h.1 * width).sum();
    assert!((mass - 1.0).abs() < 1e-9 && a.outside == 0, "{mass}");
}
