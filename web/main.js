// The bandnoise demo page: controls → wasm Params → a frame of values → Demo → canvases.
// The values come from the npm package's batch path (web/npm: `fillGrid`, the crate's row
// kernels) once it has loaded, after the first frame, wherever the settings have a description
// (`Params.batch_text`: f32, not filtered, projected or infinitely zoomed); else from the demo's
// own module, point by point (`Demo.render`). Both give the same frame, bit for bit (the
// end-to-end test compares them for every noise).
import init, { Demo, Params, kinds } from './pkg/bandnoise_wasm.js';

// Pixels across a view: its canvas's backing store, shown at as many CSS pixels.
const SIZE = 512;
const $ = (id) => document.getElementById(id);
const state = {
  pan: [0, 0],
  bandWeights: [0, 0, 0.2, 0.5, 1, 0.5, 0.25, 0.12], // bands -3..4
  renders: 0,
  lastError: '',
  // How the last main view was sampled ('batch' or 'point'), what its sampling and colouring
  // took and what its whole frame took (ms).
  path: '',
  viewMs: 0,
  frameMs: 0,
  // Set by the end-to-end test to compare the two paths.
  pointOnly: false,
};
window.bandnoise = state; // for the end-to-end test

function number(id) {
  const text = $(id).value.trim();
  // Empty stays NaN so the wasm side reports the field by name.
  return text === '' ? NaN : Number(text);
}

// Labels for the noises the wasm module offers (its list comes from bandnoise's description;
// a noise without a label here shows its name).
const LABELS = {
  perlin: 'Perlin (improved, 2002)',
  original: 'Perlin (original, 1985)',
  value: 'value noise',
  cnoise: 'Olano cNoise',
  mnoise: 'Olano mNoise',
  mnoise4093: 'Olano mNoise, M = 4093',
  wavelet: 'wavelet, one band (Cook & DeRose)',
  multiband: 'wavelet, multiband (Cook & DeRose)',
  sparse: 'sparse convolution (Lewis)',
  wiener: 'Wiener-interpolated (Lewis)',
  gabor: 'Gabor (Lagae et al.)',
  simplex: 'simplex (Perlin 2001, Gustavson)',
  cellular: 'cellular, F1 (Worley)',
  white: 'lattice white noise (Lewis)',
  'value-cubic': 'value noise, Catmull-Rom',
  flow: 'flow (Perlin & Neyret; time turns it)',
};

function fillKinds() {
  const options = () => kinds().split(' ').map((name) => new Option(LABELS[name] || name, name));
  $('kind').replaceChildren(...options());
  $('compare').replaceChildren(new Option('none', 'none'), ...options());
  $('compare').value = 'wavelet';
}

// A refused comparison leaves no picture of the settings before it: its canvases go blank.
function blankCompare() {
  for (const id of ['noise-b', 'spectrum-b', 'sphere']) {
    const ctx = $(id).getContext('2d');
    ctx.fillStyle = '#fafafa';
    ctx.fillRect(0, 0, ctx.canvas.width, ctx.canvas.height);
  }
}

// The comparison view: the same view of a second noise (by default one wavelet band beside
// Perlin noise), with its spectrum. Its refusals show in its caption; the main view is not
// held up by them.
let demoB, demoS;

// The batch path: the npm package once loaded, and the noise each view last built from its
// description (rebuilt when the description changes).
let batch = null;
const batchNoises = new Map();

/** Renders `p`'s plane view into `demo`: by the batch path where it applies, else by the
 *  demo's module. Returns the path taken. */
function renderView(demo, p, view) {
  const text = batch && !state.pointOnly ? p.batch_text() : undefined;
  if (text === undefined) {
    demo.render(p);
    return 'point';
  }
  const dims = p.dims;
  let held = batchNoises.get(view);
  if (!held || held.text !== text || held.dims !== dims) {
    held?.noise.free();
    held = { text, dims, noise: batch.fromSpec(text, dims) };
    batchNoises.set(view, held);
  }
  // The grid the demo's module would sample (its first pixel, the time and the step), filled
  // straight into the frame's values in the demo's module.
  const [x, y, t, step] = demo.grid(p);
  const values = new Float32Array(demoMemory.buffer, demo.values_address(), SIZE * SIZE);
  if (dims === 3) held.noise.fillGrid(values, [x, y, t], [step, step, 1], [SIZE, SIZE, 1]);
  else held.noise.fillGrid(values, [x, y], [step, step], [SIZE, SIZE]);
  demo.render_values(p);
  return 'batch';
}
function renderCompare() {
  const kind = $('compare').value;
  for (const figure of document.querySelectorAll('.compare')) figure.hidden = kind === 'none';
  if (kind === 'none') {
    document.querySelector('.sphere').hidden = true;
    return;
  }
  $('compare-name').textContent = LABELS[kind] || kind;
  let p;
  try {
    p = params(kind, $('compare-projected').checked);
  } catch (e) {
    $('compare-message').textContent = refusal(e)[1];
    blankCompare();
    return;
  }
  renderView(demoB, p, 'compare');
  demoB.draw($('noise-b').getContext('2d'));
  demoB.draw_spectrum($('spectrum-b').getContext('2d'));
  const sphere = $('compare-sphere').checked;
  document.querySelector('.sphere').hidden = !sphere;
  if (sphere) {
    demoS.render_sphere(p);
    demoS.draw($('sphere').getContext('2d'));
  }
  p.free();
  $('compare-message').textContent = '';
}

// The settings of the main view; the comparison view takes the same with its own kind and
// projection.
function params(kind = $('kind').value, projected = $('projected').checked) {
  // An empty period is no period.
  const period = $('period').value.trim() === '' ? 0 : number('period');
  return new Params(
    kind, $('number').value, number('seed'), number('zoom'),
    state.pan[0], state.pan[1], number('time'), period, $('fractal').value,
    number('octaves'), number('lacunarity'), number('gain'),
    new Float32Array(state.bandWeights), $('distribution').value, $('tiling').value,
    number('density'), $('kernel').value, $('covariance').value,
    number('frequency'), number('bandwidth'),
    Math.cos(number('angle') * Math.PI / 180), Math.sin(number('angle') * Math.PI / 180),
    $('orientation').value, $('envelope').value,
    // Empty texture settings are the texture's defaults (NaN); an empty warp is none.
    new Float64Array([number('texture1'), number('texture2')]),
    $('warp').value.trim() === '' ? 0 : number('warp'),
    projected, $('filtered').checked, $('infinite').checked, $('palette').value,
  );
}

function drawHistogram(demo) {
  const ctx = $('histogram').getContext('2d');
  const bins = demo.histogram();
  const w = ctx.canvas.width, h = ctx.canvas.height;
  ctx.clearRect(0, 0, w, h);
  const total = bins.reduce((a, b) => a + b, 0) || 1;
  const binWidth = 8 / bins.length; // bins span [-4σ, 4σ]
  const density = Array.from(bins, (b) => b / total / binWidth);
  const peak = Math.max(0.45, ...density);
  ctx.fillStyle = '#9bb4e8';
  density.forEach((d, i) => {
    const bh = (d / peak) * (h - 4);
    ctx.fillRect((i * w) / bins.length, h - bh, w / bins.length - 1, bh);
  });
  ctx.strokeStyle = '#c0392b';
  ctx.lineWidth = 2;
  ctx.beginPath();
  for (let x = 0; x <= w; x++) {
    const z = (x / w) * 8 - 4;
    const y = h - (Math.exp(-z * z / 2) / Math.sqrt(2 * Math.PI) / peak) * (h - 4);
    x === 0 ? ctx.moveTo(x, y) : ctx.lineTo(x, y);
  }
  ctx.stroke();
}

function drawBands() {
  const box = $('bands');
  box.replaceChildren();
  state.bandWeights.forEach((wgt, i) => {
    const bar = document.createElement('div');
    bar.className = 'band';
    bar.dataset.band = String(i);
    bar.style.height = `${Math.max(1, wgt * 100)}px`;
    bar.title = `band ${i - 3}: weight ${wgt.toFixed(2)}`;
    box.appendChild(bar);
  });
}

// The whole view in the URL's fragment, so a view can be shared: every control by its id,
// the pan and the band weights. Written after each frame that rendered (so a shared URL is a
// view that works), read once at load; unknown keys are ignored, and a bad value lands in its
// field, whose message the page then shows.
function saveState() {
  const q = new URLSearchParams();
  for (const el of $('controls').elements) {
    if (!el.id) continue;
    q.set(el.id, el.type === 'checkbox' ? (el.checked ? '1' : '0') : el.value);
  }
  q.set('pan', state.pan.join(','));
  q.set('bands', state.bandWeights.join(','));
  history.replaceState(null, '', `#${q}`);
}

function loadState() {
  const q = new URLSearchParams(location.hash.slice(1));
  for (const [key, value] of q) {
    if (key === 'pan' || key === 'bands') {
      const numbers = value.split(',').map(Number);
      const target = key === 'pan' ? state.pan : state.bandWeights;
      if (numbers.length === target.length && numbers.every(Number.isFinite)) target.splice(0, target.length, ...numbers);
      continue;
    }
    const el = $('controls').elements.namedItem(key);
    if (!el || !el.id) continue;
    if (el.type === 'checkbox') el.checked = value === '1'; else el.value = value;
  }
}

/** A thrown refusal as [field, message]: a BadField from the wasm side (freed here), or
 *  anything else by its text, with no field. */
function refusal(e) {
  if (typeof e === 'object' && e !== null && typeof e.field === 'string') {
    const r = [e.field, e.message];
    e.free();
    return r;
  }
  return ['', String(e)];
}

// Each refused value's message sits next to its field (the wasm side names the field: the
// element's id; the pan has none), and in the message line under the page.
function showError(field, text) {
  for (const old of document.querySelectorAll('.field-error')) old.remove();
  $('message').textContent = text;
  const el = field ? $(field) : null;
  if (!el || !text) return;
  const note = document.createElement('span');
  note.className = 'field-error';
  note.id = `error-${field}`;
  note.setAttribute('role', 'alert');
  note.textContent = text;
  (el.closest('label') || el).after(note);
}

let demo;
function render() {
  let p;
  try {
    p = params();
  } catch (e) {
    const [field, text] = refusal(e);
    state.lastError = text;
    showError(field, text);
    return false;
  }
  // The whole frame: sampling, colours, spectrum, histogram, and the comparison view.
  const t0 = performance.now();
  state.path = renderView(demo, p, 'main');
  state.viewMs = performance.now() - t0;
  demo.draw($('noise').getContext('2d'));
  demo.draw_spectrum($('spectrum').getContext('2d'));
  drawHistogram(demo);
  p.free();
  renderCompare();
  const ms = performance.now() - t0;
  state.frameMs = ms;
  $('readout').textContent =
    `${ms.toFixed(1)} ms per frame, ${state.viewMs.toFixed(1)} of them sampling and colouring ` +
    `(${state.path === 'batch' ? 'batch' : 'point by point'}), ` +
    `${(demo.samples() / ms / 1000).toFixed(1)} Msamples/s ` +
    `(mean ${demo.mean().toFixed(3)}, σ ${demo.std_dev().toFixed(3)})`;
  showError('', '');
  state.lastError = '';
  state.renders++;
  saveState();
  return true;
}

function bandFromEvent(e) {
  const box = $('bands').getBoundingClientRect();
  const i = Math.floor(((e.clientX - box.left) / box.width) * state.bandWeights.length);
  const weight = Math.min(1, Math.max(0, (box.bottom - e.clientY) / 100));
  return [i, weight];
}

function wire() {
  $('controls').addEventListener('input', render);
  $('controls').addEventListener('change', render);
  let dragging = null;
  const canvas = $('noise');
  canvas.addEventListener('pointerdown', (e) => { dragging = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
  canvas.addEventListener('pointermove', (e) => {
    if (!dragging) return;
    const zoom = number('zoom'); // the canvas is shown at its size
    if (!(zoom > 0)) return;
    state.pan[0] -= (e.clientX - dragging[0]) / zoom;
    state.pan[1] -= (e.clientY - dragging[1]) / zoom;
    dragging = [e.clientX, e.clientY];
    render();
  });
  canvas.addEventListener('pointerup', () => { dragging = null; });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    const zoom = number('zoom');
    if (zoom > 0) { $('zoom').value = String(+(zoom * Math.exp(-e.deltaY / 500)).toPrecision(4)); render(); }
  }, { passive: false });
  let bandDrag = false;
  const setBand = (e) => {
    const [i, w] = bandFromEvent(e);
    if (i >= 0 && i < state.bandWeights.length) { state.bandWeights[i] = w; drawBands(); render(); }
  };
  $('bands').addEventListener('pointerdown', (e) => { bandDrag = true; $('bands').setPointerCapture(e.pointerId); setBand(e); });
  $('bands').addEventListener('pointermove', (e) => { if (bandDrag) setBand(e); });
  $('bands').addEventListener('pointerup', () => { bandDrag = false; });
  const tick = () => {
    if ($('animate').checked) {
      $('time').value = (number('time') + 0.05).toFixed(2);
      render();
    }
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
}

const demoMemory = (await init()).memory;
demo = new Demo(SIZE);
demoB = new Demo(SIZE);
demoS = new Demo(SIZE);
fillKinds();
loadState();
drawBands();
wire();
render();
state.ready = true;
// The batch path after the first frame: a larger module, compiled while the page is in use.
import('./npm/index.js').then((m) => {
  batch = m;
  state.batch = true;
  render();
}, (e) => {
  state.batchError = String(e);
});
