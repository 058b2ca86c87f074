//! Ken Perlin's 2002 permutation (pbrt §10.6.1 `NoisePerm`; Perlin, "Improving Noise", 2002),
//! and seeded reshuffles of it.

use super::seed::splitmix64;

/// Ken Perlin's permutation of `0..256` from his 2002 reference implementation of improved noise,
/// the table pbrt calls `NoisePerm`. Both store it twice in succession (`p[i + 256] = p[i]`), so
/// that `p[x] + y + 1` indexes it without a reduction. [`Permutation`] stores it once and
/// reduces each index `& 255`; [`Perlin`](crate::lattice::Perlin), whose point kernels are
/// the hot path, keeps the doubled copy (`hash::chain::Doubled`, 512 bytes).
pub const PERLIN_2002: [u8; 256] = [
    151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69,
    142, 8, 99, 37, 240, 21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219,
    203, 117, 35, 11, 32, 57, 177, 33, 88, 237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175,
    74, 165, 71, 134, 139, 48, 27, 166, 77, 146, 158, 231, 83, 111, 229, 122, 60, 211, 133, 230,
    220, 105, 92, 41, 55, 46, 245, 40, 244, 102, 143, 54, 65, 25, 63, 161, 1, 216, 80, 73, 209, 76,
    132, 187, 208, 89, 18, 169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100, 109, 198, 173,
    186, 3, 64, 52, 217, 226, 250, 124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206,
    59, 227, 47, 16, 58, 17, 182, 189, 28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163,
    70, 221, 153, 101, 155, 167, 43, 172, 9, 129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232,
    178, 185, 112, 104, 218, 246, 97, 228, 251, 34, 242, 193, 238, 210, 144, 12, 191, 179, 162,
    241, 81, 51, 145, 235, 249, 14, 239, 107, 49, 192, 214, 31, 181, 199, 106, 157, 184, 84, 204,
    176, 115, 121, 50, 45, 127, 4, 150, 254, 138, 236, 205, 93, 222, 114, 67, 29, 24, 72, 243, 141,
    128, 195, 78, 66, 215, 61, 156, 180,
];

/// A permutation of `0..256` used as a lattice hash.
///
/// Seed 0 is Perlin's own table ([`PERLIN_2002`]), so seed-0 noises reproduce his reference
/// values. Any other seed shuffles that table with a Fisher–Yates pass driven by SplitMix64 of the
/// seed, giving an unrelated permutation. `new` is `const`, so a seeded table can be built at
/// compile time: `static P: Permutation = Permutation::new(7);`.
///
/// The hash of a lattice point folds the permutation over its coordinates, each reduced mod 256
/// (period 256 on every axis): `perm[(perm[(perm[x] + y) & 255] + z) & 255]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Permutation {
    table: [u8; 256],
}

impl Permutation {
    /// The permutation for `seed` (0 is Perlin's 2002 table).
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        let mut table = PERLIN_2002;
        if seed != 0 {
            let mut state = seed as u64;
            let mut i = 255;
            while i > 0 {
                let (s, r) = splitmix64(state);
                state = s;
                // Multiply-shift maps r uniformly enough onto 0..=i.
                let j = (((r >> 32) * (i as u64 + 1)) >> 32) as usize;
                let t = table[i];
                table[i] = table[j];
                table[j] = t;
                i -= 1;
            }
        }
        Self { table }
    }

    /// The table entry for `i & 255`.
    #[inline]
    #[must_use]
    pub const fn get(&self, i: u32) -> u32 {
        self.table[(i & 255) as usize] as u32
    }

    /// The whole table.
    #[must_use]
    pub const fn table(&self) -> &[u8; 256] {
        &self.table
    }
}

impl Default for Permutation {
    fn default() -> Self {
        Self::new(0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seeded_tables_are_permutations() {
        for seed in [0, 1, 2, 0xFFFF_FFFF] {
            let p = Permutation::new(seed);
            let mut seen = [false; 256];
            for &v in p.table() {
                assert!(!seen[v as usize]);
                seen[v as usize] = true;
            }
        }
        assert_ne!(Permutation::new(1), Permutation::new(2));
        assert_eq!(Permutation::new(0).table(), &PERLIN_2002);
    }
}
