//! The hashing seam every lattice noise uses: a hash folded over the axes of a cell, one
//! coordinate per step (Perlin 1985 §3, Perlin 2002, Olano 2005 §3.3).
//!
//! A noise hashes either one cell (simplex corners, feature-point cells) or the `2^D` corners
//! of a cube, where the corners share the prefixes of their chains (3D: 2 + 4 + 8 steps instead
//! of 8 × 3). Both fold the axes in an order that is part of the noise's definition: Perlin's
//! `p[p[p[x] + y] + z]` takes axis 0 innermost ([`Order::XFirst`]), Olano's
//! `hash(x + hash(y + hash(z)))` the last axis ([`Order::LastFirst`], which makes his noises
//! dimension reducible).
//!
//! A [`ChainHash`] says how one step folds a coordinate, reduced to its own period (256 for a
//! permutation, `M` for [`Bbs`]). The corners take the lower and upper coordinate of each axis
//! separately, so a periodic noise passes wrapped coordinates ([`Wrap`]) through the same
//! chain; the plain noises pass `(c mod period, c mod period + 1)`, which every step accepts.

use super::{Bbs, Permutation};

/// The most corners a cube has here (4D).
pub(crate) const MAX_CORNERS: usize = 16;

/// A hash folded one coordinate at a time.
pub(crate) trait ChainHash {
    /// The hash's own period along every axis: coordinates are reduced modulo it.
    const PERIOD: u32;
    /// `c mod PERIOD`, in `0..PERIOD`, for any `i32`.
    fn reduce(c: i32) -> u32;
    /// Folds a coordinate `c` in `0..=PERIOD` (the upper corner of the last cell is `PERIOD`)
    /// into `h`, the start value or an earlier step's result.
    fn step(&self, h: u32, c: u32) -> u32;
}

impl ChainHash for Permutation {
    const PERIOD: u32 = 256;
    #[inline]
    fn reduce(c: i32) -> u32 {
        (c & 255) as u32
    }
    #[inline]
    fn step(&self, h: u32, c: u32) -> u32 {
        self.get(h + c)
    }
}

/// A permutation stored twice in succession (`p[i + 256] = p[i]`), as in Perlin's reference
/// code: a step needs no `& 255`, since `h < 256` and `c ≤ 256`.
#[derive(Clone, PartialEq, Eq)]
pub(crate) struct Doubled(pub(crate) [u8; 512]);

impl Doubled {
    /// The permutation for `seed`, doubled.
    pub(crate) const fn new(seed: u32) -> Self {
        let perm = Permutation::new(seed);
        let table = perm.table();
        let mut p = [0u8; 512];
        let mut i = 0;
        while i < 512 {
            p[i] = table[i & 255];
            i += 1;
        }
        Self(p)
    }
}

impl ChainHash for Doubled {
    const PERIOD: u32 = Permutation::PERIOD;
    #[inline]
    fn reduce(c: i32) -> u32 {
        Permutation::reduce(c)
    }
    #[inline]
    fn step(&self, h: u32, c: u32) -> u32 {
        // h is a table entry (< 256) or the start 0, and c ≤ 256: the index is below 512, and
        // `get` keeps the lookup provably panic-free.
        u32::from(self.0.get((h + c) as usize).copied().unwrap_or(0))
    }
}

impl<const M: u32> ChainHash for Bbs<M> {
    const PERIOD: u32 = M;
    #[inline]
    fn reduce(c: i32) -> u32 {
        Bbs::<M>::reduce(c)
    }
    #[inline]
    fn step(&self, h: u32, c: u32) -> u32 {
        // h < M and c ≤ M: the argument is at most 2M, as `Bbs::step` requires.
        Bbs::<M>::step(h + c)
    }
}

/// The order in which a chain folds the axes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Order {
    /// Axis 0 innermost: `step(…step(step(start, x), y)…)`, Perlin's `p[p[p[x] + y] + z]`.
    XFirst,
    /// The last axis innermost: `step(…step(step(start, w), z)…, x)`, Olano's
    /// `hash(x + hash(y + hash(z)))`.
    LastFirst,
}

/// The hash of one cell whose coordinates are already reduced (or wrapped), folded from
/// `start` in `order`.
#[inline]
pub(crate) fn cell<const D: usize>(
    order: Order,
    start: u32,
    coords: [u32; D],
    step: impl Fn(u32, u32) -> u32,
) -> u32 {
    let mut h = start;
    for i in 0..D {
        let a = match order {
            Order::XFirst => i,
            Order::LastFirst => D - 1 - i,
        };
        h = step(h, coords[a]);
    }
    h
}

/// The hashes of the `2^D` corners of a cell, indexed by corner bit mask (bit `a` set: the
/// upper coordinate along axis `a`), each the [`cell`] hash of its corner, with shared prefixes.
///
/// `lower[a]` and `upper[a]` are the reduced (or wrapped) coordinates of the cell's lower and
/// upper corner along axis `a`. `T` is one value (`u32`) or one per lane (`[u32; LANES]`), so the
/// point and batch kernels share the chain; `step(h, c)` folds `c` into `h`.
#[inline]
pub(crate) fn corners<T: Copy, const D: usize>(
    order: Order,
    start: T,
    lower: [T; D],
    upper: [T; D],
    step: impl Fn(T, T) -> T,
) -> [T; MAX_CORNERS] {
    let mut h = [start; MAX_CORNERS];
    // Every index is below 2^D ≤ MAX_CORNERS; the mask lets the compiler see it where it does
    // not unroll the loops (a periodic mNoise chain), so no bounds check, hence no panic path.
    const MASK: usize = MAX_CORNERS - 1;
    match order {
        Order::XFirst => {
            // After axis a, h[m] for m < 2^(a+1) holds the prefix of axes 0..=a.
            for a in 0..D {
                let bit = 1 << a;
                for m in 0..bit {
                    h[(m | bit) & MASK] = step(h[m & MASK], upper[a]);
                    h[m & MASK] = step(h[m & MASK], lower[a]);
                }
            }
        }
        Order::LastFirst => {
            // After axis a (from D − 1 down), the prefixes sit at the multiples of 2^a.
            for a in (0..D).rev() {
                let bit = 1 << a;
                for j in 0..(1 << (D - 1 - a)) {
                    let m = (j << (a + 1)) & MASK;
                    h[(m | bit) & MASK] = step(h[m], upper[a]);
                    h[m] = step(h[m], lower[a]);
                }
            }
        }
    }
    h
}

/// The lower and upper corner coordinates of `cell` for a hash `H` without a period of its own
/// choosing: `(c mod H::PERIOD, c mod H::PERIOD + 1)`.
#[inline]
pub(crate) fn natural<H: ChainHash, const D: usize>(cell: [i32; D]) -> ([u32; D], [u32; D]) {
    let lower = cell.map(H::reduce);
    (lower, lower.map(|c| c.wrapping_add(1)))
}

/// Per-axis periods of a periodic noise: every coordinate is wrapped into `0..period` before
/// hashing, so the noise repeats with that period, bit for bit.
///
/// A period up to the hash's own folds the wrapped coordinate in one step, as the plain noise
/// does; a longer one folds its digits in base `H::PERIOD`, low digit first, one step each
/// (a second step for coordinates of 256 and more with a permutation), so cells within one
/// period do not repeat with the hash's own period.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Wrap<const D: usize> {
    period: [u32; D],
}

impl<const D: usize> Wrap<D> {
    /// Periods of at least 1 (the caller validates them).
    pub(crate) const fn new(period: [u32; D]) -> Self {
        Self { period }
    }

    /// The periods.
    pub(crate) const fn period(&self) -> [u32; D] {
        self.period
    }

    /// The coordinate `c + k` of axis `axis` wrapped into `0..period` (an axis beyond the
    /// periods is not wrapped).
    #[inline]
    pub(crate) fn cell(&self, axis: usize, c: i32, k: i32) -> u32 {
        match self.period.get(axis) {
            // Periods are in 1..=2^16: the sum and the remainder fit i64, the result a u32.
            Some(&p) => (i64::from(c) + i64::from(k)).rem_euclid(i64::from(p.max(1))) as u32,
            None => c.wrapping_add(k) as u32,
        }
    }

    /// The lower and upper corner coordinates of `cell` translated by `shift` (a noise's seed
    /// translation), wrapped into `0..period`.
    #[inline]
    pub(crate) fn corners(&self, cell: [i32; D], shift: [u32; D]) -> ([u32; D], [u32; D]) {
        let mut lower = [0u32; D];
        let mut upper = [0u32; D];
        for a in 0..D {
            // Periods are in 1..=2^16, so everything fits i64 and the sum a u32.
            let p = self.period[a].max(1) as i64;
            let c = ((cell[a] as i64).rem_euclid(p) + (shift[a] as i64 % p)) % p;
            let c = c as u32;
            lower[a] = c;
            upper[a] = if c as i64 + 1 == p { 0 } else { c + 1 };
        }
        (lower, upper)
    }

    /// The `2^D` corner hashes of `cell` translated by `shift` and wrapped ([`corners`](Self::corners)),
    /// folded by `hash` ([`fold`](Self::fold)) in `order` from `start`: the wrapped form of the
    /// module's [`corners`](self::corners) chain, which every periodic lattice noise uses.
    #[inline]
    pub(crate) fn corner_hashes<H: ChainHash>(
        &self,
        hash: &H,
        order: Order,
        start: u32,
        cell: [i32; D],
        shift: [u32; D],
    ) -> [u32; MAX_CORNERS] {
        let (lower, upper) = self.corners(cell, shift);
        corners(order, start, lower, upper, |h, c| Self::fold(hash, h, c))
    }

    /// `step` extended to wrapped coordinates of any size: `c` in base `H::PERIOD`, low digit
    /// first, one step per digit (a coordinate below `H::PERIOD` is one step, as without a
    /// period).
    #[inline]
    pub(crate) fn fold<H: ChainHash>(hash: &H, h: u32, c: u32) -> u32 {
        let base = H::PERIOD;
        let mut h = hash.step(h, c % base);
        let mut rest = c / base;
        while rest > 0 {
            h = hash.step(h, rest % base);
            rest /= base;
        }
        h
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The corner chains equal the one-cell chain at every corner, in both orders.
    #[test]
    fn corners_are_the_cells_of_the_corners() {
        let perm = Doubled::new(3);
        let step = |h, c| perm.step(h, c);
        for order in [Order::XFirst, Order::LastFirst] {
            for cell_coords in [[0i32, 0, 0], [255, 17, -1], [-300, 1000, 42]] {
                let (lower, upper) = natural::<Doubled, 3>(cell_coords);
                let h = corners(order, 7, lower, upper, step);
                for (m, &hm) in h.iter().enumerate().take(8) {
                    let corner: [u32; 3] =
                        core::array::from_fn(|a| if m >> a & 1 == 1 { upper[a] } else { lower[a] });
                    assert_eq!(hm, cell(order, 7, corner, step), "{order:?} {m}");
                }
            }
        }
    }

    /// A wrap to the hash's own period hashes as the plain noise does: the upper corner of the
    /// last cell (`PERIOD`, unreduced) folds like 0.
    #[test]
    fn a_wrap_to_the_natural_period_is_the_plain_chain() {
        let perm = Doubled::new(9);
        let bbs = Bbs::<61>;
        let wrap_perm = Wrap::new([256u32; 2]);
        let wrap_bbs = Wrap::new([61u32; 2]);
        for c in [[-1i32, 0], [255, 255], [60, 61], [-512, 7]] {
            let (l, u) = natural::<Doubled, 2>(c);
            let (wl, wu) = wrap_perm.corners(c, [0; 2]);
            let plain = corners(Order::XFirst, 0, l, u, |h, c| perm.step(h, c));
            let fold = |h, c| Wrap::<2>::fold(&perm, h, c);
            assert_eq!(plain, corners(Order::XFirst, 0, wl, wu, fold), "{c:?}");
            let (l, u) = natural::<Bbs<61>, 2>(c);
            let (wl, wu) = wrap_bbs.corners(c, [0; 2]);
            let plain = corners(Order::LastFirst, 0, l, u, |h, c| bbs.step(h, c));
            let fold = |h, c| Wrap::<2>::fold(&bbs, h, c);
            assert_eq!(plain, corners(Order::LastFirst, 0, wl, wu, fold), "{c:?}");
        }
    }

    #[test]
    fn wrapped_corners() {
        let w = Wrap::new([5u32, 1, 70000]);
        assert_eq!(w.corners([4, 9, -1], [0; 3]), ([4, 0, 69999], [0, 0, 0]));
        assert_eq!(
            w.corners([i32::MIN, i32::MAX, 70000], [0; 3]),
            ([2, 0, 0], [3, 0, 1])
        );
        // A translation moves the lattice within the period.
        assert_eq!(w.corners([4, 9, -1], [3, 5, 2]), ([2, 0, 1], [3, 0, 2]));
    }
}
