//! The reference the fast paths are tested against (tests only): each coefficient of a band
//! found on its own, for the projected basis (`Wavelet::projected_fast`) and the widened one
//! (`Wavelet::widened_by`), which read theirs through a [`Window`](super::window::Window).
//!
//! Finding a coefficient on its own costs per axis a Euclidean division, its blocks' placements
//! (cached by slot) and an oriented index; the window resolves each axis and block once per
//! sample. Both must give the same values, bit for bit (`projected.rs`'s tests): the same
//! blocks, read in the same order, with the same blend weights.

use crate::Real;

use super::band::{Placement, TileData, Wavelet, blend_weight, first_block, tile_index};
use super::projected::{Sums, bspline, offsets_within};

/// Block placements for the blocks per axis that a projected or filtered sample touches, by
/// their place from the base, the first block that reaches its first coefficient: its at most
/// 8 coefficients per axis and a blend zone's reach (`8 − 1 + 2h < 2n`) span at most 3 tile
/// blocks for every tile size.
struct Placements<const D: usize> {
    base: [i32; D],
    cache: [[[Option<Placement<D>>; 3]; 3]; 3],
}

impl<const D: usize> Placements<D> {
    /// An empty cache whose block slots start at `base` along each axis.
    #[inline]
    fn new(base: [i32; D]) -> Self {
        Placements {
            base,
            cache: [[[None; 3]; 3]; 3],
        }
    }
}

impl<T: TileData<3>> Wavelet<'_, T> {
    /// The projected band in the simplest way: every coefficient of the basis's bounding
    /// box, each found on its own ([`fetch`](Self::fetch)).
    pub(crate) fn projected_compact<R: Real, const GRADIENT: bool>(
        &self,
        p: [R; 3],
        nrm: [R; 3],
    ) -> (R, [R; 3]) {
        let n = T::SIZE as i32;
        let half = R::from_ratio(1, 1);
        let three_halves = R::from_ratio(3, 1);
        let mut cell = [0i32; 3];
        let mut frac = [R::ZERO; 3];
        let mut kmin = [0i32; 3];
        let mut kmax = [0i32; 3];
        for a in 0..3 {
            (cell[a], frac[a]) = p[a].split();
            (kmin[a], kmax[a]) = wide_box(frac[a], nrm[a]);
        }
        // Block q reaches coefficients [qn − h, qn + n + h): the first block that reaches
        // coefficient c is ⌊(c − h)/n⌋.
        let h = self.half_width::<3>() as i32;
        let mut placements = Placements::new(core::array::from_fn(|a| {
            cell[a].wrapping_add(kmin[a]).wrapping_sub(h).div_euclid(n)
        }));
        let mut sums = Sums::<R, GRADIENT>::default();
        for kz in kmin[2]..=kmax[2] {
            for ky in kmin[1]..=kmax[1] {
                for kx in kmin[0]..=kmax[0] {
                    let k = [kx, ky, kz];
                    // p − c, small whatever p is: the fraction minus an integer offset.
                    let d: [R; 3] = core::array::from_fn(|a| frac[a] - R::from_i32(k[a]));
                    let dot = nrm[0].mul_rn(d[0]) + nrm[1].mul_rn(d[1]) + nrm[2].mul_rn(d[2]);
                    let t: [R; 3] = core::array::from_fn(|a| {
                        three_halves - d[a] + nrm[a].mul_rn(dot).mul_rn(half)
                    });
                    let b = t.map(bspline);
                    let Some(weight) = Sums::<R, GRADIENT>::weight(&t, &b) else {
                        continue;
                    };
                    let g: [i32; 3] = core::array::from_fn(|a| cell[a].wrapping_add(k[a]));
                    sums.add(weight, t, b, self.fetch(g, &mut placements));
                }
            }
        }
        sums.finish(nrm)
    }
}

impl<T> Wavelet<'_, T> {
    /// The coefficient at global index `g`: `Σ ω_b t_b(g)` over the (up to 2ᴰ) blocks `b` that
    /// reach it, each read in its placement and weighted by its blend weights.
    #[inline]
    fn fetch<R: Real, const D: usize>(&self, g: [i32; D], placements: &mut Placements<D>) -> R
    where
        T: TileData<D>,
    {
        let n = T::SIZE;
        let h = self.half_width::<D>();
        // Along each axis: the first block reaching g, g's local index in it plus n, and the
        // number of blocks (2 in a blend zone).
        let mut first = [0i32; D];
        let mut local = [0usize; D];
        let mut count = [1usize; 3];
        for a in 0..D {
            let zone;
            (first[a], local[a], zone) = first_block(g[a], n, h);
            count[a] = 1 + zone as usize;
        }
        let mut value = R::ZERO;
        for mz in 0..count[2] {
            for my in 0..count[1] {
                for mx in 0..count[0] {
                    let m = [mx, my, mz];
                    let block: [i32; D] =
                        core::array::from_fn(|a| first[a].wrapping_add(m[a] as i32));
                    let slot: [usize; 3] = core::array::from_fn(|a| {
                        if a < D {
                            block[a].wrapping_sub(placements.base[a]).clamp(0, 2) as usize
                        } else {
                            0
                        }
                    });
                    let place = *placements.cache[slot[2]][slot[1]][slot[0]]
                        .get_or_insert_with(|| self.placement(block));
                    let l: [usize; D] = core::array::from_fn(|a| local[a] - m[a] * n);
                    let mut c: R = self.tile().flat(tile_index(l, &place, n));
                    for a in 0..D {
                        if count[a] == 2 {
                            c = blended(c, l[a], n, h);
                        }
                    }
                    value = value.saturating_add(c);
                }
            }
        }
        value
    }
}

/// `c` times its blend weight at local index `l_plus_n − n` ([`blend_weight`]). Out of line:
/// only blend zones call it.
#[inline(never)]
fn blended<R: Real>(c: R, l_plus_n: usize, n: usize, h: usize) -> R {
    c.mul_fraction(blend_weight(l_plus_n, n, h))
}

/// The coefficients from global index `first` found one by one ([`Wavelet::fetch`]), as the
/// source of [`Wavelet::widened_by`]: offsets `k` in, coefficients out.
pub(crate) fn fetcher<'a, R: Real, T: TileData<D>, const D: usize>(
    band: &'a Wavelet<'_, T>,
    first: [i32; D],
) -> impl FnMut([usize; D]) -> R + 'a {
    let (n, h) = (T::SIZE as i32, band.half_width::<D>() as i32);
    let mut placements = Placements::new(core::array::from_fn(|a| {
        first[a].wrapping_sub(h).div_euclid(n)
    }));
    move |k| {
        let g = core::array::from_fn(|a| first[a].wrapping_add(k[a] as i32));
        band.fetch(g, &mut placements)
    }
}

/// The offsets `kmin..=kmax` from the cell, along one axis, that the reference visits from
/// fraction `frac` along a unit normal with component `na`: those within
/// `3|n_a| + 3√((1 − n_a²)/2) + 2⁻⁸` of the point. For every unit normal that is at least the
/// support's extent along the axis, `3/2 (1 + |n_a| ‖n‖₁)` (equal to it, but for the `2⁻⁸`,
/// only when `n_a = ±1`), up to 0.6 more elsewhere, and it does not depend on the fast paths'
/// bound (`projected::support_box`): so the tests see any coefficient of the support those
/// windows would leave out.
fn wide_box<R: Real>(frac: R, na: R) -> (i32, i32) {
    let na = na.abs();
    let s = R::from_i32(3).mul_rn(na)
        + R::from_i32(3).mul_rn((R::ONE - na.mul_rn(na)).mul_rn(R::from_ratio(1, 1)).sqrt())
        + R::from_ratio(1, 8);
    offsets_within(frac, s)
}
