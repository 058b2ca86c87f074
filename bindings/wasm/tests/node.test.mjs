// The npm package from Node, as a user gets it: scripts/npm.sh installs the packed tarball
// into an empty folder, copies this file there and runs `node --test` on it.
// BANDNOISE_ROOT names the repository, for the crate's checksums (capi/examples/checks.h).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as bandnoise from 'bandnoise';
import { Noise, fromSpec, describe, bases, Perlin, Wavelet, Cellular, Flow } from 'bandnoise';
import { parseChecks, checksum } from './checks.mjs';

const root = process.env.BANDNOISE_ROOT;
assert.ok(root, 'BANDNOISE_ROOT names the repository');

const checks = parseChecks(readFileSync(`${root}/capi/examples/checks.h`, 'utf8'));

test('every description the crate checks gives the crate\'s f32 checksum', () => {
  assert.equal(checks.length, 110);
  const differ = checks.filter((c) => checksum(fromSpec(c.text, c.dims), c.range) !== c.f32);
  assert.deepEqual(differ.map((c) => `${c.text} (${c.dims}D)`), []);
});

test('fillGrid writes the values sample gives, off the lattice, in every dimension', () => {
  for (const [text, dims] of [['perlin seed=3 fbm octaves=5', 2], ['wavelet seed=2', 3],
    ['cellular seed=1 output=f2-f1', 4], ['sparse seed=4', 1], ['flow seed=1 angle=0.3', 2]]) {
    const noise = fromSpec(text, dims);
    const size = [7, 5, 3, 2].slice(0, dims);
    const origin = [0.37, -0.61, 2.3, 0.9].slice(0, dims);
    const step = [0.0731, 0.113, -0.29, 0.5].slice(0, dims);
    const out = new Float32Array(size.reduce((a, b) => a * b));
    assert.equal(noise.fillGrid(out, origin, step, size), out);
    let k = 0;
    for (let l = 0; l < (size[3] ?? 1); l++) for (let j = 0; j < (size[2] ?? 1); j++)
      for (let i = 0; i < (size[1] ?? 1); i++) for (let h = 0; h < size[0]; h++) {
        const idx = [h, i, j, l];
        const p = origin.map((o, a) => Math.fround(Math.fround(o) + Math.fround(idx[a] * Math.fround(step[a]))));
        assert.equal(out[k++], noise.sample(...p), `${text} ${dims}D at ${idx.slice(0, dims)}`);
      }
    assert.deepEqual(noise.grid(origin, step, size), out);
  }
});

test('a grid longer than the module\'s buffer, in rows of several copies, equals its samples', () => {
  const noise = new Perlin({ seed: 9 });
  const [w, h] = [20000, 3];
  const out = noise.grid([0.25, 0.5], [0.01, 0.7], [w, h]);
  for (const i of [0, 1, 16383, 16384, 19999, 20000, 45000, 59999]) {
    const x = Math.fround(0.25 + Math.fround((i % w) * Math.fround(0.01)));
    const y = Math.fround(0.5 + Math.fround(Math.floor(i / w) * Math.fround(0.7)));
    assert.equal(out[i], noise.sample(x, y), `index ${i}`);
  }
  const rows = noise.grid([0.1, 0.2], [0.3, 0.05], [3, 10000]);
  assert.equal(rows[3 * 9999 + 2], noise.sample(Math.fround(0.1 + Math.fround(2 * Math.fround(0.3))),
    Math.fround(Math.fround(0.2) + Math.fround(9999 * Math.fround(0.05)))));
});

test('errors are Errors with the crate\'s message', () => {
  assert.throws(() => fromSpec('perlin seed=-1'), { name: 'Error', message: /at byte 12: expected a seed in 0\.\.=4294967295/ });
  assert.throws(() => fromSpec('perlin fbm octaves=0'), (e) => e instanceof Error && /octave/.test(e.message));
  assert.throws(() => fromSpec('flow seed=1', 3), (e) => e instanceof Error && /3D/.test(e.message));
  assert.throws(() => fromSpec('perlin', 5), RangeError);
  assert.throws(() => fromSpec(7), TypeError);
  const noise = fromSpec('perlin', 2);
  assert.throws(() => noise.fillGrid(new Float32Array(5), [0, 0], [1, 1], [2, 2]), /has 4 values, not 5/);
  assert.throws(() => noise.fillGrid([0, 0, 0, 0], [0, 0], [1, 1], [2, 2]), TypeError);
  assert.throws(() => noise.fillGrid(new Float32Array(4), [0], [1, 1], [2, 2]), /origin has 2 numbers, not 1/);
  assert.throws(() => noise.fillGrid(new Float32Array(4), [0, 0], [1, 1], [2, -2]), /whole number/);
  assert.throws(() => noise.fillGrid(new Float32Array(4), [0, 0], [1, 1], [2, 1.5]), /whole number/);
  // 2³² points along an axis do not fit a 32-bit index: refused, not cast.
  assert.throws(() => noise.fillGrid(new Float32Array(4), [0, 0], [1, 1], [2 ** 32, 1]), /below 2\^32/);
  assert.throws(() => noise.fillGrid(new Float32Array(4), [0, 0], [1, 1], [2 ** 31, 2]), /2\^32 or more/);
  assert.throws(() => noise.fillGrid(new Float32Array(4), [0, 0], ['a', 1], [2, 2]), TypeError);
  assert.throws(() => new Cellular({ octaves: 3 }), Error);
  // The noise still works after its errors.
  assert.ok(Number.isFinite(noise.sample(0.3, 0.7)));
});

test('a class per noise, with its dimensions; descriptions from settings', () => {
  const classes = Object.values(bandnoise).filter((v) => typeof v === 'function' && v.noiseName);
  // (A module namespace lists its exports in alphabetical order.)
  assert.deepEqual(classes.map((c) => c.noiseName).sort(), [...bases].sort());
  assert.equal(bases.length, 25);
  assert.deepEqual(Flow.dimensions, [2]);
  assert.deepEqual(Wavelet.dimensions, [2, 3]);
  assert.deepEqual(Perlin.dimensions, [1, 2, 3, 4]);
  for (const cls of classes) {
    for (const dims of cls.dimensions) {
      const noise = new cls({ seed: 5, dims });
      assert.ok(noise instanceof Noise && noise.dims === dims);
      assert.ok(Number.isFinite(noise.sample(0.3, 1.7, -2.1, 0.4)), `${cls.name} ${dims}D`);
      noise.free();
    }
  }
  assert.equal(describe('perlin', { seed: 7, period: [16, 16], fbm: true, octaves: 4, ridged: false, dims: 3 }),
    'perlin seed=7 period=16,16 fbm octaves=4');
  // Numbers JavaScript prints with an exponent are written out as decimals that read back.
  assert.equal(describe('multiband', { bands: [1e-7, 0.5] }), 'multiband bands=0.0000001,0.5');
  const p = new Perlin({ seed: 7, period: [16, 16], fbm: true, octaves: 4 });
  assert.equal(p.text, 'perlin seed=7 period=16,16 fbm octaves=4 lacunarity=1.99 gain=0.5');
  assert.equal(fromSpec(p.text).sample(0.3, 5.7), p.sample(0.3, 5.7));
  assert.equal(new Perlin().text, 'perlin seed=0');
});

test('gradients: the value, and one derivative per dimension matching central differences', () => {
  const noise = fromSpec('perlin seed=4', 3);
  const { value, gradient } = noise.sampleWithGradient(0.3, 1.1, 2.7);
  assert.equal(value, noise.sample(0.3, 1.1, 2.7));
  assert.equal(gradient.length, 3);
  const h = 1e-3;
  const numeric = [0, 1, 2].map((a) => {
    const p = [0.3, 1.1, 2.7], q = [0.3, 1.1, 2.7];
    p[a] += h; q[a] -= h;
    return (noise.sample(...p) - noise.sample(...q)) / (2 * h);
  });
  gradient.forEach((g, a) => assert.ok(Math.abs(g - numeric[a]) < 0.02, `∂${a}: ${g} vs ${numeric[a]}`));
});

test('any coordinate gives a value', () => {
  const noise = fromSpec('simplex seed=1 fbm octaves=3', 2);
  for (const v of [NaN, Infinity, -Infinity, 1e30, -1e38, 3.4e38, 0, -0]) {
    assert.equal(typeof noise.sample(v, 0.5), 'number');
    assert.ok(!Number.isNaN(noise.sample(v, v)), `at ${v}`);
  }
});

test('a freed noise throws rather than reading freed memory; dims is read-only', () => {
  for (const dims of [1, 2, 3, 4]) {
    const noise = new Perlin({ seed: 3, dims });
    assert.equal(typeof noise.sample(0.3, 0.7, 1.1, 1.9), 'number');
    assert.throws(() => { noise.dims = 5; }, TypeError);
    assert.equal(noise.dims, dims);
    noise.free();
    // A noise built after the free may take the freed memory: the freed one still throws.
    const other = new Perlin({ seed: 4, dims });
    assert.throws(() => noise.sample(0.3, 0.7, 1.1, 1.9));
    assert.throws(() => noise.fillGrid(new Float32Array(1), [0, 0, 0, 0].slice(0, dims),
      [1, 1, 1, 1].slice(0, dims), [1, 1, 1, 1].slice(0, dims)));
    other.free();
  }
});
