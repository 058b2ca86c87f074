// Times bandnoise's 2D Perlin, mNoise and wavelet noise (wasm), point by point and through the
// batch API (fill_grid, simd128), against the npm simplex-noise package (JavaScript) over the
// same grid, and reports the ratios in window.benchResults.
import init, { bench_sum } from './pkg-bench/bandnoise_wasm_bench.js';
import { createNoise2D } from './vendor/simplex-noise.js';

const COUNT = 1 << 20;
const RUNS = 7;

// A seeded generator so simplex-noise builds the same table every run (mulberry32).
function mulberry32(a) {
  return () => {
    a |= 0; a = (a + 0x6d2b79f5) | 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function best(f) {
  let ms = Infinity, result = 0;
  for (let r = 0; r < RUNS; r++) {
    const t0 = performance.now();
    result = f();
    ms = Math.min(ms, performance.now() - t0);
  }
  return { msps: COUNT / ms / 1000, checksum: result };
}

await init();
const simplex2D = createNoise2D(mulberry32(1));
const results = {
  simplex: best(() => {
    let acc = 0;
    for (let k = 0; k < COUNT; k++) acc += simplex2D((k % 256) * 0.0625, ((k >>> 8) % 256) * 0.0625);
    return acc;
  }),
};
for (const kind of ['perlin', 'mnoise', 'wavelet', 'perlin-batch', 'mnoise-batch']) {
  results[kind] = best(() => bench_sum(kind, COUNT));
}
const body = document.querySelector('#results tbody');
for (const [name, r] of Object.entries(results)) {
  r.ratio = r.msps / results.simplex.msps;
  const row = document.createElement('tr');
  row.innerHTML = `<td>${name === 'simplex' ? 'simplex-noise 4.0.3 (JS)' : 'bandnoise ' + name}</td>` +
    `<td>${r.msps.toFixed(1)}</td><td>${r.ratio.toFixed(2)}</td>`;
  body.appendChild(row);
}
window.benchResults = results;
