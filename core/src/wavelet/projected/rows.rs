//! Grids of a projected band along one axis-aligned normal, bit for bit as
//! [`Wavelet::projected_fast`] samples each point, with the work a grid row's samples share
//! done once ([`ProjectedNoise::fill_grid_projected`]).
//!
//! Along an axis-aligned normal a sample's basis is a product of per-axis weights and its sum
//! runs block by block ([`Wavelet::projected_axis`]). Along a grid row only x changes: the
//! row resolves y and z once (their supports, blocks, local indices and weights), and each
//! sample only x. Samples go [`LANES`] at a time; the lanes whose supports start in one block
//! along x within a few coefficients of each other (a group: along a row, usually the whole
//! chunk) find their blocks' placements and index parts once and read each coefficient once
//! for all of them, summed over the group's extent with each lane's weights at its own
//! offsets and zeros elsewhere, and the sums run entry by entry across the lanes, which the
//! compiler vectorises. Each lane's operations and their order are
//! [`block_sums`](super::block_sums)'s: z outermost, x innermost, blocks in slot order.
//!
//! Zero terms add `+0` to a line before its first term and `±0` after, and a group visits
//! the next block along x if any of its lanes reaches it, which the others weigh 0: a block
//! of zero terms adds `+0` to a sum that is never `−0` (sums start at `+0`; fixed point: 0).
//! Each lane's sum is the point's, bit for bit.
//! Lanes whose point sample would not take the axis path (a support near the end of `i32`'s
//! range, tiles narrower than the support) are sampled as points.

use super::{SPAN, axis_of, crossing, span, zone_offset};
use crate::batch::{Grid, LANES, for_each_row, store_lanes};
use crate::wavelet::band::{Placement, TileData, Wavelet, first_block};
use crate::{Error, Real};

/// One axis of a sample along an axis-aligned normal, resolved as
/// [`projected_along`](Wavelet::projected_along) and
/// [`projected_axis`](Wavelet::projected_axis) resolve it.
#[derive(Clone, Copy)]
struct Axis<R> {
    /// The block of the support's first coefficient.
    block: i32,
    /// The support's first coefficient's local index in that block, plus `n`.
    local: usize,
    /// Whether the next block reaches the support.
    two: bool,
    /// Per slot (the first block, the next), the B-splines times the slot's blend weights
    /// over the span from the support's start: 0 past the support and beyond the slot's
    /// reach.
    w: [[R; SPAN]; 2],
}

impl<R: Real> Axis<R> {
    const ZERO: Self = Axis {
        block: 0,
        local: 0,
        two: false,
        w: [[R::ZERO; SPAN]; 2],
    };
}

impl<T: TileData<3>> Wavelet<'_, T> {
    /// Axis `a` of a sample at coordinate `x` along unit normal `nrm`, whose axis is
    /// `normal`: the same numbers as `projected_along` and `projected_axis` compute. `None`
    /// where the point's axis path would not sum it (the sample then goes through
    /// [`projected_fast`](Self::projected_fast) on its own).
    #[inline(always)]
    fn projected_axis_of<R: Real>(
        &self,
        x: R,
        a: usize,
        nrm: [R; 3],
        normal: usize,
    ) -> Option<Axis<R>> {
        let (n, h) = (T::SIZE, self.half_width::<3>());
        let (g, len, t) = super::axis_support(x, a, nrm, normal)?;
        let span = span(a, normal);
        // An empty support (the point gives 0) or one the axis path does not take.
        if len == 0 || len > span || g.checked_add(span as i32).is_none() {
            return None;
        }
        let (block, local, _) = first_block(g, n, h);
        if local + len > 3 * n - h {
            return None;
        }
        let two = local + len > 2 * n - h;
        let [mut first, mut next] = [[R::ZERO; SPAN]; 2];
        let at = zone_offset(local, n, h);
        let slots = first.iter_mut().zip(&mut next);
        for (i, ((first, next), &t)) in slots.zip(&t).enumerate().take(len) {
            let b = super::bspline(t);
            if two {
                [*first, *next] = crossing::<R>(at + i, h).map(|omega| b.mul_rn(omega));
            } else {
                *first = b;
            }
        }
        let w = [first, next];
        Some(Axis {
            block,
            local,
            two,
            w,
        })
    }

    /// [`ProjectedNoise::fill_grid_projected`] along the unit normal `nrm`
    /// ([`unit_normal`](super::unit_normal)'s): rows along an axis-aligned normal by groups
    /// of lanes (module docs), other normals point by point.
    pub(crate) fn fill_grid_projected_unit<R: Real>(
        &self,
        grid: &Grid<R, 3>,
        nrm: [R; 3],
        out: &mut [R],
    ) -> Result<(), Error> {
        if axis_of(nrm).is_none() {
            return crate::batch::fill_grid_by(grid, out, |p| {
                self.projected_fast::<R, false>(p, nrm).0
            });
        }
        for_each_row(grid, out, |start, row_out| {
            for (c, chunk) in row_out.chunks_mut(LANES).enumerate() {
                let mut values = [R::ZERO; LANES];
                let xs = grid.lanes(0, c * LANES);
                self.projected_row(&xs, [start[1], start[2]], nrm, &mut values);
                store_lanes(chunk, &values);
            }
        })
    }

    /// The projected band along the unit normal `nrm` at the `LANES` points of a grid row,
    /// `xs` along x at `row` along y and z, into `values`: the point samples' bits.
    pub(crate) fn projected_row<R: Real>(
        &self,
        xs: &[R; LANES],
        row: [R; 2],
        nrm: [R; 3],
        values: &mut [R; LANES],
    ) {
        if let Some(normal) = axis_of(nrm) {
            let y = self.projected_axis_of(row[0], 1, nrm, normal);
            let z = self.projected_axis_of(row[1], 2, nrm, normal);
            if let (Some(y), Some(z)) = (y, z) {
                match normal {
                    0 => self.projected_lanes::<R, 0>(xs, row, [y, z], nrm, values),
                    1 => self.projected_lanes::<R, 1>(xs, row, [y, z], nrm, values),
                    _ => self.projected_lanes::<R, 2>(xs, row, [y, z], nrm, values),
                }
                return;
            }
        }
        for (v, &x) in values.iter_mut().zip(xs) {
            *v = self.projected_fast::<R, false>([x, row[0], row[1]], nrm).0;
        }
    }

    /// The projected band at `LANES` points of one row, `xs` along x at `row` along y and z,
    /// whose y and z axes `across` resolved, along unit normal `nrm` whose axis is `NORMAL`,
    /// into `values`: the lanes in groups ([`group_sums`](Self::group_sums)), each of the
    /// lanes whose supports start in one block within [`EXTENT`] coefficients.
    #[inline(never)]
    fn projected_lanes<R: Real, const NORMAL: usize>(
        &self,
        xs: &[R; LANES],
        row: [R; 2],
        across: [Axis<R>; 2],
        nrm: [R; 3],
        values: &mut [R; LANES],
    ) {
        let mut lanes = [Axis::ZERO; LANES];
        // Lanes still to sum.
        let mut todo = 0u32;
        for (l, &x) in xs.iter().enumerate() {
            match self.projected_axis_of(x, 0, nrm, NORMAL) {
                Some(a) => {
                    lanes[l] = a;
                    todo |= 1 << l;
                }
                None => values[l] = self.projected_fast::<R, false>([x, row[0], row[1]], nrm).0,
            }
        }
        // How far apart the lanes' first coefficients in a group may be.
        let reach = EXTENT - span(0, NORMAL);
        while todo != 0 {
            let anchor = lanes[todo.trailing_zeros() as usize % LANES];
            let near = |a: &Axis<R>| {
                a.block == anchor.block
                    && a.local + reach >= anchor.local
                    && a.local <= anchor.local + reach
            };
            let lo = (0..LANES)
                .filter(|&l| todo >> l & 1 == 1 && near(&lanes[l]))
                .map(|l| lanes[l].local)
                .min()
                .unwrap_or(anchor.local);
            let mut group = 0u32;
            for (l, a) in lanes.iter().enumerate() {
                if todo >> l & 1 == 1
                    && a.block == anchor.block
                    && a.local >= lo
                    && a.local <= lo + reach
                {
                    group |= 1 << l;
                }
            }
            let sums = self.group_sums::<R, NORMAL>(&lanes, group, lo, across);
            for (l, (v, s)) in values.iter_mut().zip(sums).enumerate() {
                if group >> l & 1 == 1 {
                    *v = s.canonical();
                }
            }
            todo &= !group;
        }
    }

    /// The sums of the lanes in `group` (bit `l`: lane `l`), whose supports start in one
    /// block along x at local indices from `lo` to `lo + EXTENT − span`, as
    /// [`axis_blocks`](Self::axis_blocks) sums each: over the `EXTENT` offsets from `lo`, each
    /// lane's weights placed at its own offsets and zeros at the others (which add `+0` to a
    /// line before its first term, and `±0` after, changing no bit). The other lanes'
    /// entries are not theirs.
    #[inline(always)]
    fn group_sums<R: Real, const NORMAL: usize>(
        &self,
        lanes: &[Axis<R>; LANES],
        group: u32,
        lo: usize,
        across: [Axis<R>; 2],
    ) -> [R; LANES] {
        let (n, tile) = (T::SIZE, self.tile());
        let unit = tile.unit::<R>();
        let member = |l: usize| group >> l & 1 == 1;
        let first = lanes[group.trailing_zeros() as usize % LANES];
        let (mut two_x, mut hi) = (false, lo);
        for (l, a) in lanes.iter().enumerate() {
            if member(l) {
                two_x |= a.two;
                hi = hi.max(a.local);
            }
        }
        let extent = (hi - lo + span(0, NORMAL)).min(EXTENT);
        let [y, z] = across;
        let slots = usize::from(two_x) | usize::from(y.two) << 1 | usize::from(z.two) << 2;
        let mut places = [(0, Placement::UNSHIFTED); 8];
        let count = self.slot_placements([first.block, y.block, z.block], slots, &mut places);
        // Each lane's x weights per slot at the offsets from `lo`, lanes innermost.
        let mut wx = [[[R::ZERO; LANES]; EXTENT]; 2];
        for (l, a) in lanes.iter().enumerate() {
            if member(l) {
                let shift = a.local - lo;
                for (s, w) in a.w.iter().enumerate() {
                    for (i, &w) in w.iter().enumerate().take(span(0, NORMAL)) {
                        wx[s][(shift + i) % EXTENT][l] = w;
                    }
                }
            }
        }
        let local = [lo, y.local, z.local];
        let mut sums = [R::ZERO; LANES];
        for &(block, ref place) in places.iter().take(count) {
            let mut parts = [[0usize; EXTENT]; 3];
            for (a, part) in parts.iter_mut().enumerate() {
                let map = place.axis(a, n);
                let len = if a == 0 { extent } else { span(a, NORMAL) };
                for (i, p) in part.iter_mut().enumerate().take(len) {
                    *p = map.offset(local[a] + i, n);
                }
            }
            let (wx, wy, wz) = (&wx[block & 1], &y.w[block >> 1 & 1], &z.w[block >> 2 & 1]);
            let mut block_sum = [R::ZERO; LANES];
            for (jz, &wz) in wz.iter().enumerate().take(span(2, NORMAL)) {
                let mut plane = [R::ZERO; LANES];
                for (jy, &wy) in wy.iter().enumerate().take(span(1, NORMAL)) {
                    let row = parts[1][jy] + parts[2][jz];
                    let mut line = [R::ZERO; LANES];
                    for (jx, wx) in wx.iter().enumerate().take(extent) {
                        let c = tile.flat_with(parts[0][jx] + row, unit);
                        for (line, &wx) in line.iter_mut().zip(wx) {
                            *line = line.saturating_add(wx.mul_rn(c));
                        }
                    }
                    for (plane, line) in plane.iter_mut().zip(line) {
                        *plane = plane.saturating_add(wy.mul_rn(line));
                    }
                }
                for (block_sum, plane) in block_sum.iter_mut().zip(plane) {
                    *block_sum = block_sum.saturating_add(wz.mul_rn(plane));
                }
            }
            for (sum, block_sum) in sums.iter_mut().zip(block_sum) {
                *sum = sum.saturating_add(block_sum);
            }
        }
        sums
    }
}

/// The most offsets along x a group of lanes sums: its lanes' supports (3 offsets across the
/// normal, 6 along it) start within `EXTENT − span` coefficients of each other.
const EXTENT: usize = 8;

#[cfg(test)]
mod tests {
    use crate::batch::Grid;
    use crate::wavelet::{
        Bands, Distribution, Multiband, TILE3, Tile3, TileData, Tiling, Wavelet, unit_normal,
    };
    use crate::{I16F16, ProjectedNoise, Real};

    static TILE4: Tile3<4> = Tile3::generate(3);
    static TILE12: Tile3<12> = Tile3::generate(5);
    static TILE16: Tile3<16> = Tile3::generate(6);

    /// Normals along each axis (either sign, unit and not), oblique, degenerate.
    const NORMALS: [[f32; 3]; 10] = [
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -5.0],
        [1.0, 0.0, 0.0],
        [-0.25, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, -3.0, 0.0],
        [0.48, 0.6, 0.64],
        [0.0, 0.6, 0.8],
        [0.0, 0.0, 0.0],
        [f32::NAN, 1.0, 0.0],
    ];

    /// Grids a user has (off the lattice, a step that is no power-of-two fraction), a
    /// sixteenth's, backwards, a single column, far from the origin and past `i32`'s cells.
    fn grids<R: Real>() -> [Grid<R, 3>; 6] {
        let r = |x: f64| R::from_f64_nearest(x);
        [
            Grid::new(
                [r(3.217), r(-5.683), r(0.37)],
                [r(0.0737), r(0.0737), r(0.0)],
                [70, 5, 1],
            ),
            Grid::new(
                [r(0.0), r(0.0), r(0.0)],
                [r(0.0625), r(0.5), r(0.25)],
                [40, 3, 3],
            ),
            Grid::new(
                [r(9.3), r(2.1), r(-7.9)],
                [r(-0.21), r(0.13), r(0.4)],
                [37, 3, 2],
            ),
            Grid::new(
                [r(1.5), r(2.5), r(3.5)],
                [r(0.0), r(0.3), r(0.0)],
                [20, 4, 1],
            ),
            Grid::new(
                [r(-1500.3), r(700.7), r(-300.1)],
                [r(0.31), r(0.19), r(0.0)],
                [33, 2, 1],
            ),
            Grid::new(
                [r(2.147_483e9), r(-2.147_48e9), r(1e30)],
                [r(64.0), r(0.0), r(0.0)],
                [20, 1, 1],
            ),
        ]
    }

    fn check<R: Real, N: ProjectedNoise<R>>(band: &N) -> usize {
        let mut compared = 0;
        for normal in NORMALS.map(|n| n.map(R::from_f32)) {
            for grid in grids::<R>() {
                let mut out = [R::ZERO; 400];
                let out = &mut out[..grid.len()];
                band.fill_grid_projected(&grid, normal, out).unwrap();
                for (i, &v) in out.iter().enumerate() {
                    let index = [
                        i % grid.size[0],
                        i / grid.size[0] % grid.size[1],
                        i / grid.size[0] / grid.size[1],
                    ];
                    let p = grid.point(index);
                    let expected = band.sample_projected(p, normal);
                    assert_eq!(
                        v.to_f64().to_bits(),
                        expected.to_f64().to_bits(),
                        "{normal:?} {p:?}"
                    );
                    compared += 1;
                }
            }
        }
        compared
    }

    /// Every grid is the point samples, bit for bit, in every number type, for every tile
    /// size and tiling (tiles of 4 reach three blocks along an axis, which the row path
    /// leaves to the point path; 12 blends without a power-of-two side).
    #[test]
    fn grids_are_the_point_samples() {
        fn all_types<T: TileData<3>>(band: &Wavelet<'_, T>) -> usize {
            check::<f32, _>(band) + check::<f64, _>(band) + check::<I16F16, _>(band)
        }
        let mut compared = 0;
        for tiling in [Tiling::Blended, Tiling::Varied, Tiling::Periodic] {
            compared += all_types(&Wavelet::new(0, &TILE3).with_tiling(tiling));
            compared += all_types(&Wavelet::new(3, &TILE4).with_tiling(tiling));
            compared += all_types(&Wavelet::new(4, &TILE12).with_tiling(tiling));
            compared += all_types(&Wavelet::new(5, &TILE16).with_tiling(tiling));
        }
        assert!(compared > 100_000, "{compared}");
    }

    /// Multiband noise's grids are its point samples too (each band's rows through the
    /// lanes, a band of weight 0 left out, both distributions).
    #[test]
    fn multiband_grids_are_the_point_samples() {
        let bands = Bands::new(-1, &[0.5, 0.0, 1.0, 0.25]).unwrap();
        for distribution in [Distribution::Gaussian, Distribution::Uniform] {
            let m = Multiband::new(2, &TILE3, bands, distribution);
            let compared = check::<f32, _>(&m) + check::<f64, _>(&m) + check::<I16F16, _>(&m);
            assert!(compared > 10_000, "{compared}");
        }
    }

    /// The rows of the default tile along an axis take the row path (so the test above
    /// compares it, not the point path with itself), and its runs hold several lanes.
    #[test]
    fn default_rows_take_the_row_path() {
        let band = Wavelet::new(0, &TILE3);
        let nrm = unit_normal([0.0f32, 0.0, 1.0]);
        for (x, y, z) in [(3.217f32, -5.683, 0.37), (-1500.3, 700.7, -300.1)] {
            assert!(band.projected_axis_of(x, 0, nrm, 2).is_some());
            assert!(band.projected_axis_of(y, 1, nrm, 2).is_some());
            assert!(band.projected_axis_of(z, 2, nrm, 2).is_some());
        }
        // Past i32's cells, and on a tile of 4 (three blocks along z), the point path.
        let nrm64 = unit_normal([0.0f64, 0.0, 1.0]);
        assert!(
            band.projected_axis_of(2_147_483_646.5f64, 0, nrm64, 2)
                .is_none()
        );
        let small = Wavelet::new(3, &TILE4).with_tiling(Tiling::Varied);
        assert!((0..40).any(|i| small.projected_axis_of(i as f32 * 0.1, 2, nrm, 2).is_none()));
    }
}
