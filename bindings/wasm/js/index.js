// bandnoise for JavaScript: every noise of the Rust crate, compiled to WebAssembly
// (bindings/wasm/src/lib.rs), behind a class per noise and `fromSpec` for any description.
// The module loads when this file is imported (top-level await): from the file next to this
// one in Node, by fetch in a browser. Types: index.d.ts; guide: README.md.
import init, { initSync, RawNoise, bases as rawBases, dimensionMask } from './bandnoise_js.js';

const wasmUrl = new URL('./bandnoise_js_bg.wasm', import.meta.url);
/** The module's exports: `Noise.sample` calls them directly (see `Noise`). */
let wasm;
if (wasmUrl.protocol === 'file:') {
  // Node, Deno and Bun read the file (their fetch does not take file: URLs).
  const { readFile } = await import('node:fs/promises');
  wasm = initSync({ module: await readFile(wasmUrl) });
} else {
  wasm = await init({ module_or_path: wasmUrl });
}

/** The name of every noise, in the crate's order (`Base::ALL`). */
export const bases = Object.freeze(rawBases().split(' '));

function checkDims(dims) {
  if (!(dims === 1 || dims === 2 || dims === 3 || dims === 4)) {
    throw new RangeError(`dims must be 1, 2, 3 or 4, not ${String(dims)}`);
  }
}

function checkAxes(name, value, dims) {
  if (!Array.isArray(value) && !ArrayBuffer.isView(value)) {
    throw new TypeError(`a grid's ${name} is an array of ${dims} numbers, not ${String(value)}`);
  }
  for (const v of value) {
    if (typeof v !== 'number') {
      throw new TypeError(`a grid's ${name} holds numbers, not ${String(v)}`);
    }
  }
}

/**
 * A noise built from its description in 1 to 4 dimensions. Its values are the Rust crate's,
 * bit for bit, at the same `f32` coordinates (JavaScript numbers are rounded to `f32`).
 */
export class Noise {
  #raw;
  /**
   * The noise's address in the module, which `sample` passes to the module's exports itself:
   * wasm-bindgen's method (`RawNoise.sample2`, the same export with the same address) is one
   * more JavaScript call per sample, 4 ns of 17 where the engine does not inline it
   * (bench/README.md). 0 once freed: the module then throws.
   */
  #ptr;
  #dims;

  /**
   * @param {string} text a description such as "perlin seed=7 fbm octaves=4"
   * @param {1|2|3|4} [dims=2]
   */
  constructor(text, dims = 2) {
    if (typeof text !== 'string') {
      throw new TypeError(`a noise description is a string such as "perlin seed=7", not ${String(text)}`);
    }
    checkDims(dims);
    this.#raw = new RawNoise(text, dims);
    this.#ptr = this.#raw.__wbg_ptr;
    this.#dims = dims;
  }

  /** The number of dimensions. */
  get dims() {
    return this.#dims;
  }

  /** The description in full (every setting written out): `fromSpec(noise.text)` is the same noise. */
  get text() {
    return this.#raw.text;
  }

  /** The value at a point: as many coordinates as dimensions (a missing one is `NaN`). */
  sample(x, y, z, w) {
    const p = this.#ptr;
    switch (this.#dims) {
      case 2: return wasm.rawnoise_sample2(p, x, y);
      case 3: return wasm.rawnoise_sample3(p, x, y, z);
      case 1: return wasm.rawnoise_sample1(p, x);
      default: return wasm.rawnoise_sample4(p, x, y, z, w);
    }
  }

  /** The value and its gradient (one partial derivative per dimension) at a point. */
  sampleWithGradient(x, y, z, w) {
    const r = this.#raw.gradient(Float32Array.of(x, y, z, w));
    return { value: r[0], gradient: Array.from(r.subarray(1)) };
  }

  /**
   * Fills `out` with the values of a grid, axis 0 fastest: point `(i, j, …)` is at
   * `origin + (i·step[0], j·step[1], …)` and its value at `out[i + size[0]·(j + size[1]·…)]`,
   * equal to `sample` there. Writes into `out` (no array is created); returns it.
   */
  fillGrid(out, origin, step, size) {
    if (!(out instanceof Float32Array)) {
      throw new TypeError(`fillGrid writes into a Float32Array, not ${Object.prototype.toString.call(out)}`);
    }
    checkAxes('origin', origin, this.#dims);
    checkAxes('step', step, this.#dims);
    checkAxes('size', size, this.#dims);
    this.#raw.fill_grid(out, origin, step, size);
    return out;
  }

  /** A new Float32Array holding the grid's values (see `fillGrid`). */
  grid(origin, step, size) {
    checkAxes('size', size, this.#dims);
    let length = 1;
    for (const s of size) length *= s;
    if (!Number.isSafeInteger(length) || length < 0 || length >= 2 ** 32) {
      throw new RangeError(`a grid has a whole number of points below 2^32, not ${size.join('×')}`);
    }
    return this.fillGrid(new Float32Array(length), origin, step, size);
  }

  /** Frees the module's memory now (otherwise when the noise is garbage-collected). */
  free() {
    this.#ptr = 0;
    this.#raw.free();
  }
}

/** A noise from its description: `fromSpec("perlin seed=7 fbm octaves=4", 3)`. */
export function fromSpec(text, dims = 2) {
  return new Noise(text, dims);
}

/**
 * A number as the description's text takes it: a plain decimal (no exponent) that reads
 * back to the same `f32` as the number.
 */
function decimal(v) {
  if (typeof v !== 'number' || !Number.isFinite(v)) return String(v);
  const s = String(v);
  if (!/e/i.test(s)) return s;
  if (Math.abs(v) >= 1e21) return BigInt(v).toString();
  const f = Math.fround(v);
  for (let digits = 0; digits < 100; digits++) {
    const t = v.toFixed(digits);
    if (Math.fround(Number(t)) === f) return t;
  }
  return v.toFixed(100);
}

/**
 * The description text of a noise and its settings: `describe('perlin', { seed: 7, fbm: true,
 * octaves: 4 })` is `"perlin seed=7 fbm octaves=4"`. `true` writes the bare word (a fractal
 * kind), `false` and `undefined` nothing, arrays comma-separated; `dims` is not a setting.
 */
export function describe(name, settings = {}) {
  const words = [name];
  for (const [key, value] of Object.entries(settings)) {
    if (key === 'dims' || value === undefined || value === false) continue;
    if (value === true) {
      words.push(key);
    } else if (Array.isArray(value) || ArrayBuffer.isView(value)) {
      words.push(`${key}=${Array.from(value, decimal).join(',')}`);
    } else {
      words.push(`${key}=${decimal(value)}`);
    }
  }
  return words.join(' ');
}

function noiseClass(className, name) {
  const cls = class extends Noise {
    constructor(settings = {}) {
      super(describe(name, settings), settings.dims ?? 2);
    }
  };
  Object.defineProperty(cls, 'name', { value: className });
  /** The noise's name in descriptions. */
  cls.noiseName = name;
  /** The dimensions it has a form in. */
  cls.dimensions = Object.freeze([1, 2, 3, 4].filter((d) => dimensionMask(name) & (1 << (d - 1))));
  return cls;
}

export const Perlin = noiseClass('Perlin', 'perlin');
export const OriginalPerlin = noiseClass('OriginalPerlin', 'original');
export const Value = noiseClass('Value', 'value');
export const CNoise = noiseClass('CNoise', 'cnoise');
export const MNoise = noiseClass('MNoise', 'mnoise');
export const MNoise4093 = noiseClass('MNoise4093', 'mnoise4093');
export const Wavelet = noiseClass('Wavelet', 'wavelet');
export const Multiband = noiseClass('Multiband', 'multiband');
export const Sparse = noiseClass('Sparse', 'sparse');
export const Wiener = noiseClass('Wiener', 'wiener');
export const Gabor = noiseClass('Gabor', 'gabor');
export const Simplex = noiseClass('Simplex', 'simplex');
export const Cellular = noiseClass('Cellular', 'cellular');
export const White = noiseClass('White', 'white');
export const ValueCubic = noiseClass('ValueCubic', 'value-cubic');
export const OpenSimplex2 = noiseClass('OpenSimplex2', 'opensimplex2');
export const OpenSimplex2S = noiseClass('OpenSimplex2S', 'opensimplex2s');
export const Flow = noiseClass('Flow', 'flow');
export const Windy = noiseClass('Windy', 'windy');
export const Wrinkled = noiseClass('Wrinkled', 'wrinkled');
export const Marble = noiseClass('Marble', 'marble');
export const MarbleOlano = noiseClass('MarbleOlano', 'marble-olano');
export const Wood = noiseClass('Wood', 'wood');
export const WoodOlano = noiseClass('WoodOlano', 'wood-olano');
export const PolkaDots = noiseClass('PolkaDots', 'polka-dots');
