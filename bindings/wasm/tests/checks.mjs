// The crate's checksums recomputed through the package (bandnoise-checks: 64 samples of each
// description at points from a counter, FNV-1a over their f32 bits), shared by the Node test,
// the page and the Chromium test. scripts/npm.sh copies it beside them.

/** The table of `capi/examples/checks.h`: each description, its dimensions, range and f32 checksum. */
export function parseChecks(header) {
  return [...header.matchAll(/\{"([^"]+)", (\d), (\d+), 0x([0-9a-f]+)u, 0x([0-9a-f]+)u\}/g)]
    .map((m) => ({ text: m[1], dims: Number(m[2]), range: Number(m[3]), f32: parseInt(m[5], 16) }));
}

/** bandnoise-checks' `point`: multiples of 2⁻¹⁶ in (-range, range), exact in f32. */
export function point(i, dims, range) {
  const p = [];
  for (let a = 0; a < dims; a++) {
    let h = (Math.imul(i, 0x9e3779b9) ^ Math.imul(a, 0x85ebca6b)) >>> 0;
    h = (h ^ (h >>> 15)) >>> 0;
    h = Math.imul(h, 0x2c1b3c6d) >>> 0;
    h = (h ^ (h >>> 12)) >>> 0;
    p.push(((h % ((2 * range) * 65536)) - range * 65536) / 65536);
  }
  return p;
}

const word = new Float32Array(1);
const bits = new Uint32Array(word.buffer);

/** The checksum of a noise over `(-range, range)^dims`. */
export function checksum(noise, range) {
  let f = 0x811c9dc5;
  for (let i = 0; i < 64; i++) {
    word[0] = noise.sample(...point(i, noise.dims, range));
    for (let b = 0; b < 4; b++) f = Math.imul(f ^ ((bits[0] >>> (8 * b)) & 0xff), 0x01000193) >>> 0;
  }
  return f;
}
