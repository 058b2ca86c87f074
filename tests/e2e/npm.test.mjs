// The npm package in Debian's Chromium, driven by playwright-core: scripts/npm.sh installs the
// packed tarball into an empty folder (argument 1) with bindings/wasm/tests/page.html and the
// simplex-noise peer, and this serves that folder on 127.0.0.1. Checks that the page loads the
// package from node_modules, computes the crate's checksums bit for bit, fills a grid equal to
// its samples and throws Errors with the crate's message; prints the samples per second of 2D
// Perlin noise (per call and by fillGrid) against simplex-noise in the same run, and the time to
// fill a 512² frame of the demo's two goal noises (measurements, not tests: the machines are
// shared). Exits non-zero on any failure.
import { readFileSync } from 'node:fs';
import assert from 'node:assert/strict';
import { parseChecks } from '../../bindings/wasm/tests/checks.mjs';
import { serve, launchChromium } from './harness.mjs';

const [app, checksPath] = process.argv.slice(2);
const PORT = 8124;
const { base, stop } = await serve(app, PORT, 'page.html');
const browser = await launchChromium();
let failed = 0;
try {
  const page = await browser.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${base}/page.html`);
  await page.waitForFunction(() => window.ready, null, { timeout: 30000 });

  const test = async (name, body) => {
    try { await body(); console.log(`ok   ${name}`); } catch (e) { failed++; console.log(`FAIL ${name}\n     ${e.message}`); }
  };
  await test('the crate\'s f32 checksums of every description, in Chromium', async () => {
    const checks = parseChecks(readFileSync(checksPath, 'utf8'));
    assert.equal(checks.length, 110);
    const differ = [];
    for (const c of checks) {
      const got = await page.evaluate(([t, d, r]) => window.runChecksum(t, d, r), [c.text, c.dims, c.range]);
      if (got !== c.f32) differ.push(`${c.text} (${c.dims}D)`);
    }
    assert.deepEqual(differ, []);
  });
  await test('fillGrid equals sample; errors are Errors with the message', async () => {
    const r = await page.evaluate(() => {
      const noise = new window.bandnoise.Gabor({ seed: 2, dims: 2 });
      const out = new Float32Array(9 * 4);
      noise.fillGrid(out, [0.37, 0.61], [0.0731, 0.11], [9, 4]);
      let same = true;
      for (let j = 0; j < 4; j++) for (let i = 0; i < 9; i++) {
        const x = Math.fround(Math.fround(0.37) + Math.fround(i * Math.fround(0.0731)));
        const y = Math.fround(Math.fround(0.61) + Math.fround(j * Math.fround(0.11)));
        same &&= out[i + 9 * j] === noise.sample(x, y);
      }
      let error;
      try { window.bandnoise.fromSpec('perlin octaves=2'); } catch (e) { error = e; }
      return { same, isError: error instanceof Error, message: String(error?.message) };
    });
    assert.ok(r.same);
    assert.ok(r.isError);
    assert.match(r.message, /at byte \d+: expected/);
  });
  await test('2D Perlin noise against simplex-noise, 1024² points off the lattice (measured)', async () => {
    const { perSecond } = await page.evaluate(() => window.runSpeed(5));
    const m = (v) => `${(v / 1e6).toFixed(1)} M/s`;
    console.log(`     per call: Perlin ${m(perSecond.perlin)}, simplex-noise ${m(perSecond.simplex)}: `
      + `${(perSecond.perlin / perSecond.simplex).toFixed(2)}× (goal 1.5×)`);
    console.log(`     fillGrid: ${m(perSecond.fillGrid)}: ${(perSecond.fillGrid / perSecond.simplex).toFixed(2)}× simplex-noise per call`);
    assert.ok(perSecond.perlin > 0 && perSecond.fillGrid > 0);
  });
  await test('512² frames of the demo\'s goal noises by fillGrid (measured)', async () => {
    // Issue 20's demo goal is 30 frames per second for these two; this is the sampling alone.
    const texts = [
      'perlin fbm octaves=6 lacunarity=1.99 gain=0.5',
      'multiband bands=1,0.5,0.25,0.125,0.0625,0.03125',
    ];
    const ms = await page.evaluate((t) => window.runFrames(t, 5), texts);
    texts.forEach((t, i) => console.log(`     ${t}: ${ms[i].toFixed(1)} ms, ${(1000 / ms[i]).toFixed(0)} frames/s`));
    assert.ok(ms.every((v) => v > 0));
  });
  await test('no page errors', async () => assert.deepEqual(errors, []));
} finally {
  await browser.close();
  stop();
}
console.log(failed ? `${failed} failed` : 'all passed');
process.exit(failed ? 1 : 0);
