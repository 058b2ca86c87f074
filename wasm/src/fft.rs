//! A radix-2 FFT for the spectrum view (sizes are powers of two).

/// In-place forward FFT of `re`, `im` (length a power of two).
pub(crate) fn fft(re: &mut [f32], im: &mut [f32]) {
    let n = re.len();
    debug_assert!(n.is_power_of_two() && im.len() == n);
    // Bit reversal.
    let mut j = 0;
    for i in 1..n {
        let mut bit = n >> 1;
        while j & bit != 0 {
            j ^= bit;
            bit >>= 1;
        }
        j |= bit;
        if i < j {
            re.swap(i, j);
            im.swap(i, j);
        }
    }
    // The twiddle e^(-2πi/len) of each pass, by halving the angle from len = 2 (cos and sin
    // would link libm's argument reduction, about 7 KB, into the module).
    let (mut twiddle_r, mut twiddle_i) = (-1.0f64, 0.0f64);
    let mut len = 2;
    while len <= n {
        let (wr, wi) = (twiddle_r as f32, twiddle_i as f32);
        // Half the angle: cos = √((1 + c)/2); sin = s / (2 cos), or -1 from angle -π.
        let half_r = ((1.0 + twiddle_r) / 2.0).sqrt();
        twiddle_i = if len == 2 {
            -1.0
        } else {
            twiddle_i / (2.0 * half_r)
        };
        twiddle_r = half_r;
        for start in (0..n).step_by(len) {
            let (mut cr, mut ci) = (1.0f32, 0.0f32);
            for k in 0..len / 2 {
                let (a, b) = (start + k, start + k + len / 2);
                let tr = re[b] * cr - im[b] * ci;
                let ti = re[b] * ci + im[b] * cr;
                re[b] = re[a] - tr;
                im[b] = im[a] - ti;
                re[a] += tr;
                im[a] += ti;
                (cr, ci) = (cr * wr - ci * wi, cr * wi + ci * wr);
            }
        }
        len <<= 1;
    }
}

/// `log(1 + |F|²)` of a square `side × side` grid, DC in the centre, scaled to 0..=255.
///
/// The grid is windowed first by `(1 − u²)²` along each axis (`u` from −1 to 1 across it: a
/// polynomial close to Hann's `cos²(πu/2)`, without `cos`, which would link libm's argument
/// reduction), so the frame's edges, where the noise does not wrap, do not leak power along
/// the axes: without it a cross through DC hides a band-limited noise's empty centre.
pub(crate) fn log_spectrum(values: &[f32], side: usize, out: &mut [u8]) {
    let mut re: Vec<f32> = values.to_vec();
    let mean = re.iter().sum::<f32>() / re.len() as f32;
    let window = |i: usize| {
        let u = (2 * i + 1) as f32 / side as f32 - 1.0;
        (1.0 - u * u) * (1.0 - u * u)
    };
    for (j, row) in re.chunks_mut(side).enumerate() {
        let wy = window(j);
        for (i, v) in row.iter_mut().enumerate() {
            *v = (*v - mean) * window(i) * wy;
        }
    }
    let mut im = vec![0.0f32; re.len()];
    for (r, i) in re.chunks_mut(side).zip(im.chunks_mut(side)) {
        fft(r, i);
    }
    let (mut cr, mut ci) = (vec![0.0; side], vec![0.0; side]);
    for x in 0..side {
        for y in 0..side {
            cr[y] = re[y * side + x];
            ci[y] = im[y * side + x];
        }
        fft(&mut cr, &mut ci);
        for y in 0..side {
            re[y * side + x] = cr[y];
            im[y * side + x] = ci[y];
        }
    }
    let mut power: Vec<f32> = re
        .iter()
        .zip(&im)
        .map(|(r, i)| (1.0 + r * r + i * i).ln())
        .collect();
    let max = power.iter().cloned().fold(0.0f32, f32::max).max(1e-6);
    power.iter_mut().for_each(|p| *p /= max);
    let h = side / 2;
    for y in 0..side {
        for x in 0..side {
            let (sx, sy) = ((x + h) % side, (y + h) % side);
            out[y * side + x] = (power[sy * side + sx] * 255.0) as u8;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every pass's twiddle is right: the FFT equals the direct sum for 1024 points.
    #[test]
    fn fft_matches_the_direct_transform() {
        let n = 1024;
        let x: Vec<f32> = (0..n)
            .map(|i| ((i * 7919 % 1000) as f32 / 500.0) - 1.0)
            .collect();
        let (mut re, mut im) = (x.clone(), vec![0.0; n]);
        fft(&mut re, &mut im);
        for k in [1, 3, 100, 511, 512, 700, 1023] {
            let (mut sr, mut si) = (0.0f64, 0.0f64);
            for (j, v) in x.iter().enumerate() {
                let a = -2.0 * core::f64::consts::PI * (k * j % n) as f64 / n as f64;
                sr += *v as f64 * a.cos();
                si += *v as f64 * a.sin();
            }
            let err = (re[k] as f64 - sr).hypot(im[k] as f64 - si);
            assert!(err < 2e-3, "{k}: ({}, {}) vs ({sr}, {si})", re[k], im[k]);
        }
    }

    #[test]
    fn fft_of_a_cosine_has_two_peaks() {
        let n = 64;
        let mut re: Vec<f32> = (0..n)
            .map(|i| (2.0 * core::f32::consts::PI * 5.0 * i as f32 / n as f32).cos())
            .collect();
        let mut im = vec![0.0; n];
        fft(&mut re, &mut im);
        for (k, (r, i)) in re.iter().zip(&im).enumerate() {
            let mag = r.hypot(*i);
            if k == 5 || k == n - 5 {
                assert!((mag - 32.0).abs() < 1e-3, "{k}: {mag}");
            } else {
                assert!(mag < 1e-3, "{k}: {mag}");
            }
        }
    }
}
