//! Colour maps: grey, and pbrt's marble colours (pbrt §10.6.6), as a Bézier spline.

/// pbrt's marble control colours.
const MARBLE: [[f32; 3]; 9] = [
    [0.58, 0.58, 0.6],
    [0.58, 0.58, 0.6],
    [0.58, 0.58, 0.6],
    [0.5, 0.5, 0.5],
    [0.6, 0.59, 0.58],
    [0.58, 0.58, 0.6],
    [0.58, 0.58, 0.6],
    [0.2, 0.2, 0.33],
    [0.58, 0.58, 0.6],
];

/// RGB for `t` in `[0, 1]`.
pub(crate) fn color(t: f32, marble: bool) -> [u8; 3] {
    let t = t.clamp(0.0, 1.0);
    if !marble {
        let g = (t * 255.0 + 0.5) as u8;
        return [g, g, g];
    }
    // pbrt: cubic Bézier through consecutive quadruples of the 9 colours (6 segments), × 1.5.
    let segments = (MARBLE.len() - 3) as f32;
    let first = ((t * segments) as usize).min(MARBLE.len() - 4);
    let u = t * segments - first as f32;
    let mut rgb = [0u8; 3];
    for (ch, out) in rgb.iter_mut().enumerate() {
        let c = |i: usize| MARBLE[first + i][ch];
        let lerp = |a: f32, b: f32| (1.0 - u) * a + u * b;
        let (s0, s1, s2) = (lerp(c(0), c(1)), lerp(c(1), c(2)), lerp(c(2), c(3)));
        let (s0, s1) = (lerp(s0, s1), lerp(s1, s2));
        *out = ((1.5 * lerp(s0, s1)).clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
    }
    rgb
}
