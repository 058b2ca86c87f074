// The package from TypeScript: type-checked by `tsc --noEmit --strict` (scripts/npm.sh), then
// compiled and run. A mistake in index.d.ts, or in how a user is told to call the package,
// fails here.
import { Perlin, Wavelet, fromSpec, describe, bases, type Noise, type Settings } from 'bandnoise';

const settings: Settings = { seed: 7, fbm: true, octaves: 4, dims: 2 };
const terrain: Noise = new Perlin(settings);
const height: number = terrain.sample(0.3, 0.7);

// A 64² image of one wavelet band, into an array the caller owns.
const band = new Wavelet({ seed: 3, tiling: 'periodic' });
const image = new Float32Array(64 * 64);
band.fillGrid(image, [0.37, 0.61], [0.0731, 0.0731], [64, 64]);

const moving = fromSpec(describe('simplex', { seed: 2, turbulence: true, octaves: 3 }), 3);
const { value, gradient } = moving.sampleWithGradient(0.5, 0.5, 1.25);

console.log(`${bases.length} noises; height ${height.toFixed(4)}; image[0] ${image[0].toFixed(4)};`
  + ` value ${value.toFixed(4)}, gradient of ${gradient.length}; ${moving.text}`);
band.free();
