//! Noise tiles generated at compile time (Cook & DeRose 2005, §3.4, §4.3 and Appendix 1).
//!
//! A tile holds the coefficients `n_i` of one noise band: Gaussian random coefficients `r`, minus
//! their projection onto the half-resolution space (`r↑ = up(down(r))`, applied along every axis),
//! plus a copy of itself shifted by an odd offset in every axis to even out the variance of even
//! and odd coefficients. Everything is `const fn`, so
//! `static TILE: Tile3<32> = Tile3::generate(SEED);` puts a finished tile in flash.

use super::constmath::Gaussian;

/// The largest tile side supported.
pub const MAX_TILE: usize = 256;

/// Cook & DeRose's analysis (downsampling) filter for quadratic B-splines, `a_k` for
/// `k = −16..−1`; the filter is symmetric (`a_{−1−k} = a_k`), so these 16 values give all 32 taps.
/// The printed table differs in its last digit at ±13 (0.003545 / 0.003546, erratum 3): the
/// symmetric value used here is their midpoint.
const ANALYSIS: [f64; 16] = [
    0.000334, -0.001528, 0.000410, 0.0035455, -0.000938, -0.008233, 0.002172, 0.019120, -0.005040,
    -0.044412, 0.011655, 0.103311, -0.025936, -0.243780, 0.033979, 0.655340,
];

/// Replaces one periodic row of length `n` by its coarse part `up(down(row))`.
///
/// `down`: `c_i = Σ_{k=2i−16}^{2i+15} a_{k−2i} r_{k mod n}` (erratum 2: 32 taps, not 33);
/// `up`: `r↑_{2m} = ¾c_m + ¼c_{m+1}`, `r↑_{2m+1} = ¼c_m + ¾c_{m+1}` (refinement `¼ ¾ ¾ ¼`).
/// The 32-tap sum is written out (16 products, using the symmetry) so that the constant
/// evaluation of a tile stays short.
const fn coarse_row(row: &mut [f64; MAX_TILE], n: usize) {
    // ext[m] = row[(m − 16) mod n]: the periodic row with 16 values of margin on each side.
    let mut ext = [0.0f64; MAX_TILE + 32];
    let mut m = 0;
    while m < n + 32 {
        ext[m] = row[(m + 16 * n - 16) % n];
        m += 1;
    }
    let a = ANALYSIS;
    let mut coarse = [0.0f64; MAX_TILE / 2];
    let mut i = 0;
    while i < n / 2 {
        let b = 2 * i;
        coarse[i] = a[0] * (ext[b] + ext[b + 31])
            + a[1] * (ext[b + 1] + ext[b + 30])
            + a[2] * (ext[b + 2] + ext[b + 29])
            + a[3] * (ext[b + 3] + ext[b + 28])
            + a[4] * (ext[b + 4] + ext[b + 27])
            + a[5] * (ext[b + 5] + ext[b + 26])
            + a[6] * (ext[b + 6] + ext[b + 25])
            + a[7] * (ext[b + 7] + ext[b + 24])
            + a[8] * (ext[b + 8] + ext[b + 23])
            + a[9] * (ext[b + 9] + ext[b + 22])
            + a[10] * (ext[b + 10] + ext[b + 21])
            + a[11] * (ext[b + 11] + ext[b + 20])
            + a[12] * (ext[b + 12] + ext[b + 19])
            + a[13] * (ext[b + 13] + ext[b + 18])
            + a[14] * (ext[b + 14] + ext[b + 17])
            + a[15] * (ext[b + 15] + ext[b + 16]);
        i += 1;
    }
    let h = n / 2;
    let mut m = 0;
    while m < h {
        let (c0, c1) = (coarse[m], coarse[(m + 1) % h]);
        row[2 * m] = 0.75 * c0 + 0.25 * c1;
        row[2 * m + 1] = 0.25 * c0 + 0.75 * c1;
        m += 1;
    }
}

/// `G(δ) = ∫ B(x) B(x − δ) dx` for the quadratic B-spline, `δ = 0, ±1, ±2`: how much two
/// coefficients `δ` apart contribute together to `∫ N²`.
const OVERLAP: [f64; 3] = [11.0 / 20.0, 13.0 / 60.0, 1.0 / 120.0];

/// `Σ_δ G(δ) n_{i+δ}`: the 5-tap convolution with [`OVERLAP`] of the coefficient `c` and its
/// neighbours `m2, m1` before and `p1, p2` after (the callers read them periodically).
const fn overlap5(m2: f64, m1: f64, c: f64, p1: f64, p2: f64) -> f64 {
    OVERLAP[0] * c + OVERLAP[1] * (m1 + p1) + OVERLAP[2] * (m2 + p2)
}

/// The odd offset of the even/odd variance correction: `n/2`, made odd.
const fn odd_offset(n: usize) -> usize {
    let o = n / 2;
    if o.is_multiple_of(2) { o + 1 } else { o }
}

/// Salt mixed into the user's seed so tile seeds differ from the lattice noises' seeds.
const TILE_SALT: u64 = 0x5741_5645_4C45_5421; // "WAVELET!"

/// A 2D noise tile of `N × N` coefficients, indexed `[y][x]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Tile2<const N: usize> {
    pub(crate) data: [[f32; N]; N],
    pub(crate) max_abs: f32,
    pub(crate) variance: f32,
}

/// A 3D noise tile of `N × N × N` coefficients, indexed `[z][y][x]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Tile3<const N: usize> {
    pub(crate) data: [[[f32; N]; N]; N],
    pub(crate) max_abs: f32,
    pub(crate) variance: f32,
}

/// The checks every tile size passes, at compile time.
const fn check_size<const N: usize>() {
    const {
        assert!(
            N.is_multiple_of(2),
            "a wavelet tile size must be even (Cook & DeRose footnote 4)"
        )
    };
    const {
        assert!(
            N >= 4 && N <= MAX_TILE,
            "a wavelet tile size must be in 4..=256"
        )
    };
}

impl<const N: usize> Tile2<N> {
    /// Generates the tile for `seed` (`const`: use it in a `static`).
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::wavelet::Tile2;
    ///
    /// static TILE: Tile2<16> = Tile2::generate(7);
    /// assert!(TILE.coefficient(3, 5).is_finite());
    /// ```
    #[must_use]
    pub const fn generate(seed: u32) -> Self {
        check_size::<N>();
        let mut gauss = Gaussian::new(seed as u64 ^ TILE_SALT);
        let mut r = [[0.0f64; N]; N];
        let mut y = 0;
        while y < N {
            let mut x = 0;
            while x < N {
                r[y][x] = gauss.next();
                x += 1;
            }
            y += 1;
        }
        // Coarse part: rows, then columns.
        let mut c = r;
        let mut row = [0.0f64; MAX_TILE];
        let mut y = 0;
        while y < N {
            let mut x = 0;
            while x < N {
                row[x] = c[y][x];
                x += 1;
            }
            coarse_row(&mut row, N);
            let mut x = 0;
            while x < N {
                c[y][x] = row[x];
                x += 1;
            }
            y += 1;
        }
        let mut x = 0;
        while x < N {
            let mut y = 0;
            while y < N {
                row[y] = c[y][x];
                y += 1;
            }
            coarse_row(&mut row, N);
            let mut y = 0;
            while y < N {
                c[y][x] = row[y];
                y += 1;
            }
            x += 1;
        }
        // n = r − r↑, then n + n shifted by an odd offset in every axis.
        let o = odd_offset(N);
        let mut data = [[0.0f32; N]; N];
        let mut max_abs = 0.0f32;
        let mut y = 0;
        while y < N {
            let mut x = 0;
            while x < N {
                let (ys, xs) = ((y + o) % N, (x + o) % N);
                let v = ((r[y][x] - c[y][x]) + (r[ys][xs] - c[ys][xs])) as f32;
                data[y][x] = v;
                max_abs = max_abs.max(v.abs());
                x += 1;
            }
            y += 1;
        }
        let variance = variance2(&data);
        Self {
            data,
            max_abs,
            variance,
        }
    }

    /// The coefficient at `(x, y)`, both reduced mod `N`.
    #[must_use]
    pub const fn coefficient(&self, x: usize, y: usize) -> f32 {
        self.data[y % N][x % N]
    }

    /// The largest `|coefficient|`, which bounds the noise (its B-spline weights are
    /// non-negative and sum to 1).
    #[must_use]
    pub const fn max_abs(&self) -> f32 {
        self.max_abs
    }

    /// The exact variance of this tile's band averaged over space (one period), computed at
    /// generation: `E[N²] − E[N]²` with `E[N²] = (1/Nᵈ) Σ_i n_i Σ_δ G(δ) n_{i+δ}`. Multiband
    /// noise divides by it, so its variance is 1 for every tile, not only on average.
    #[must_use]
    pub const fn variance(&self) -> f32 {
        self.variance
    }

    /// The side of the tile.
    pub const SIZE: usize = N;
}

impl<const N: usize> Tile3<N> {
    /// Generates the tile for `seed` (`const`: use it in a `static`).
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::wavelet::Tile3;
    ///
    /// static TILE: Tile3<8> = Tile3::generate(7);
    /// assert!(TILE.coefficient(1, 2, 3).is_finite());
    /// ```
    #[must_use]
    pub const fn generate(seed: u32) -> Self {
        check_size::<N>();
        let mut gauss = Gaussian::new(seed as u64 ^ TILE_SALT);
        let mut r = [[[0.0f64; N]; N]; N];
        let mut i = 0;
        while i < N * N * N {
            r[i / (N * N)][(i / N) % N][i % N] = gauss.next();
            i += 1;
        }
        let mut c = r;
        let mut row = [0.0f64; MAX_TILE];
        // Each x row, then each y row, then each z row (Appendix 1).
        let mut axis = 0;
        while axis < 3 {
            let mut j = 0;
            while j < N * N {
                let (u, v) = (j / N, j % N);
                let mut k = 0;
                while k < N {
                    row[k] = match axis {
                        0 => c[u][v][k],
                        1 => c[u][k][v],
                        _ => c[k][u][v],
                    };
                    k += 1;
                }
                coarse_row(&mut row, N);
                let mut k = 0;
                while k < N {
                    match axis {
                        0 => c[u][v][k] = row[k],
                        1 => c[u][k][v] = row[k],
                        _ => c[k][u][v] = row[k],
                    }
                    k += 1;
                }
                j += 1;
            }
            axis += 1;
        }
        let o = odd_offset(N);
        let mut data = [[[0.0f32; N]; N]; N];
        let mut max_abs = 0.0f32;
        let mut i = 0;
        while i < N * N * N {
            let (z, y, x) = (i / (N * N), (i / N) % N, i % N);
            let (zs, ys, xs) = ((z + o) % N, (y + o) % N, (x + o) % N);
            let v = ((r[z][y][x] - c[z][y][x]) + (r[zs][ys][xs] - c[zs][ys][xs])) as f32;
            data[z][y][x] = v;
            max_abs = max_abs.max(v.abs());
            i += 1;
        }
        let variance = variance3(&data);
        Self {
            data,
            max_abs,
            variance,
        }
    }

    /// The coefficient at `(x, y, z)`, each reduced mod `N`.
    #[must_use]
    pub const fn coefficient(&self, x: usize, y: usize, z: usize) -> f32 {
        self.data[z % N][y % N][x % N]
    }

    /// The largest `|coefficient|`, which bounds the noise (its B-spline weights are
    /// non-negative and sum to 1).
    #[must_use]
    pub const fn max_abs(&self) -> f32 {
        self.max_abs
    }

    /// The exact variance of this tile's band averaged over space (one period), computed at
    /// generation: `E[N²] − E[N]²` with `E[N²] = (1/Nᵈ) Σ_i n_i Σ_δ G(δ) n_{i+δ}`. Multiband
    /// noise divides by it, so its variance is 1 for every tile, not only on average.
    #[must_use]
    pub const fn variance(&self) -> f32 {
        self.variance
    }

    /// The side of the tile.
    pub const SIZE: usize = N;
}

/// The exact space-averaged variance of a 2D tile's band.
const fn variance2<const N: usize>(c: &[[f32; N]; N]) -> f32 {
    // t = G * c along x, then along y; E[N²] = mean(c · t).
    let mut t = [[0.0f64; N]; N];
    let mut i = 0;
    while i < N * N {
        let (y, x) = (i / N, i % N);
        let r = &c[y];
        t[y][x] = overlap5(
            r[(x + N - 2) % N] as f64,
            r[(x + N - 1) % N] as f64,
            r[x] as f64,
            r[(x + 1) % N] as f64,
            r[(x + 2) % N] as f64,
        );
        i += 1;
    }
    let (mut sum, mut mean) = (0.0f64, 0.0f64);
    let mut i = 0;
    while i < N * N {
        let (y, x) = (i / N, i % N);
        let v = overlap5(
            t[(y + N - 2) % N][x],
            t[(y + N - 1) % N][x],
            t[y][x],
            t[(y + 1) % N][x],
            t[(y + 2) % N][x],
        );
        sum += c[y][x] as f64 * v;
        mean += c[y][x] as f64;
        i += 1;
    }
    let count = (N * N) as f64;
    (sum / count - (mean / count) * (mean / count)) as f32
}

/// The exact space-averaged variance of a 3D tile's band.
const fn variance3<const N: usize>(c: &[[[f32; N]; N]; N]) -> f32 {
    let mut t = [[[0.0f64; N]; N]; N];
    let mut u = [[[0.0f64; N]; N]; N];
    let mut i = 0;
    while i < N * N * N {
        let (z, y, x) = (i / (N * N), (i / N) % N, i % N);
        let r = &c[z][y];
        t[z][y][x] = overlap5(
            r[(x + N - 2) % N] as f64,
            r[(x + N - 1) % N] as f64,
            r[x] as f64,
            r[(x + 1) % N] as f64,
            r[(x + 2) % N] as f64,
        );
        i += 1;
    }
    let mut i = 0;
    while i < N * N * N {
        let (z, y, x) = (i / (N * N), (i / N) % N, i % N);
        let p = &t[z];
        u[z][y][x] = overlap5(
            p[(y + N - 2) % N][x],
            p[(y + N - 1) % N][x],
            p[y][x],
            p[(y + 1) % N][x],
            p[(y + 2) % N][x],
        );
        i += 1;
    }
    let (mut sum, mut mean) = (0.0f64, 0.0f64);
    let mut i = 0;
    while i < N * N * N {
        let (z, y, x) = (i / (N * N), (i / N) % N, i % N);
        let v = overlap5(
            u[(z + N - 2) % N][y][x],
            u[(z + N - 1) % N][y][x],
            u[z][y][x],
            u[(z + 1) % N][y][x],
            u[(z + 2) % N][y][x],
        );
        sum += c[z][y][x] as f64 * v;
        mean += c[z][y][x] as f64;
        i += 1;
    }
    let count = (N * N * N) as f64;
    (sum / count - (mean / count) * (mean / count)) as f32
}
