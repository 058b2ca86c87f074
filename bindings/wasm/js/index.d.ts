// Types of the bandnoise package (index.js). The settings are the description's (README.md,
// "Settings"); a value the noise refuses is an Error with the crate's message.

/** A number of dimensions. */
export type Dims = 1 | 2 | 3 | 4;

/** Numbers along each axis of a grid: one per dimension. */
export type Axes = readonly number[] | Float32Array | Float64Array;

/** The value and gradient at a point. */
export interface ValueAndGradient {
  value: number;
  /** One partial derivative per dimension. */
  gradient: number[];
}

/**
 * A noise's settings, written as its description's text (`describe`). Each is optional; the
 * noise's default applies. A setting the noise does not take is an Error when it is built.
 */
export interface Settings {
  /** The number of dimensions to build it in (not a setting of the text); default 2. */
  dims?: Dims;
  seed?: number;
  /** One period per axis (lattice, white and cubic value noise). */
  period?: readonly number[];
  tiling?: 'blended' | 'varied' | 'periodic';
  first?: number;
  bands?: readonly number[];
  distribution?: 'gaussian' | 'uniform';
  density?: number;
  count?: number;
  kernel?: 'cosine' | 'catmull-rom';
  weights?: 'sign' | 'uniform';
  frequency?: number;
  bandwidth?: number;
  direction?: readonly number[];
  orientation?: 'anisotropic' | 'isotropic' | 'hybrid';
  envelope?: 'hann' | 'truncated';
  magnitude?: number;
  output?: 'f1' | 'f2' | 'f2-f1' | 'value';
  metric?: 'euclidean' | 'squared' | 'manhattan' | 'chebyshev';
  jitter?: number;
  covariance?: 'low-pass' | 'band-pass';
  improve?: 'standard' | 'xy' | 'xz';
  scale?: number;
  variation?: number;
  rings?: number;
  amount?: number;
  radius?: number;
  chance?: number;
  angle?: number;
  spin?: number;
  advection?: number;
  warp?: number;
  /** A fractal sum of this kind (one of the three). */
  fbm?: boolean;
  turbulence?: boolean;
  ridged?: boolean;
  octaves?: number;
  lacunarity?: number;
  gain?: number;
}

/** A noise built from its description in 1 to 4 dimensions. */
export class Noise {
  /** @param text a description such as "perlin seed=7 fbm octaves=4"; dims defaults to 2. */
  constructor(text: string, dims?: Dims);
  /** The number of dimensions it was built in. */
  readonly dims: Dims;
  /** The description in full, every setting written out. */
  readonly text: string;
  /** The value at a point: as many coordinates as dimensions. */
  sample(x: number, y?: number, z?: number, w?: number): number;
  /** The value and gradient at a point. */
  sampleWithGradient(x: number, y?: number, z?: number, w?: number): ValueAndGradient;
  /** Fills `out` with the grid's values, axis 0 fastest; returns `out`. */
  fillGrid(out: Float32Array, origin: Axes, step: Axes, size: Axes): Float32Array;
  /** A new array of the grid's values. */
  grid(origin: Axes, step: Axes, size: Axes): Float32Array;
  /** Frees the module's memory now rather than at garbage collection. */
  free(): void;
}

/** A noise class: `new Perlin({ seed: 7, fbm: true, octaves: 4, dims: 3 })`. */
export interface NoiseClass {
  new (settings?: Settings): Noise;
  /** The noise's name in descriptions. */
  readonly noiseName: string;
  /** The dimensions it has a form in. */
  readonly dimensions: readonly Dims[];
}

/** A noise from its description; dims defaults to 2. */
export function fromSpec(text: string, dims?: Dims): Noise;
/** The description text of a noise and its settings. */
export function describe(name: string, settings?: Settings): string;
/** The name of every noise, in the crate's order. */
export const bases: readonly string[];

export const Perlin: NoiseClass;
export const OriginalPerlin: NoiseClass;
export const Value: NoiseClass;
export const CNoise: NoiseClass;
export const MNoise: NoiseClass;
export const MNoise4093: NoiseClass;
export const Wavelet: NoiseClass;
export const Multiband: NoiseClass;
export const Sparse: NoiseClass;
export const Wiener: NoiseClass;
export const Gabor: NoiseClass;
export const Simplex: NoiseClass;
export const Cellular: NoiseClass;
export const White: NoiseClass;
export const ValueCubic: NoiseClass;
export const OpenSimplex2: NoiseClass;
export const OpenSimplex2S: NoiseClass;
export const Flow: NoiseClass;
export const Windy: NoiseClass;
export const Wrinkled: NoiseClass;
export const Marble: NoiseClass;
export const MarbleOlano: NoiseClass;
export const Wood: NoiseClass;
export const WoodOlano: NoiseClass;
export const PolkaDots: NoiseClass;
