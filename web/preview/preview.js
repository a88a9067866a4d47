// The page of `umbrac preview` (docs/preview.md): receives the program's
// bundles over Server-Sent Events, draws the last good one with WebGL2 and
// WebGPU side by side (draw.js) with the inputs of controls.js, shows the
// share of pixels that differ, and shows a failed compile's diagnostics
// over the last good picture.
//
// Query parameters: `time=T` fixes the clock at T seconds (and frame 0);
// `api=webgl2` or `api=webgpu` draws with one only; `output=LOCATION` shows
// that colour output of a program with several.
//
// window.umbracPreview is the state a test reads: { received, drawn (the
// bundle numbers last received and last drawn), ok, diagnostics, errors
// { webgl2, webgpu }, renderers, snapshot() }.

import { createRenderer, planOf, compare, DrawError } from './draw.js';
import { Inputs, Orbit } from './controls.js';

const $ = (id) => document.getElementById(id);
const query = new URLSearchParams(location.search);
const fixedTime = query.has('time') ? parseFloat(query.get('time')) : null;
const apis = query.has('api') ? [query.get('api')] : ['webgl2', 'webgpu'];
// The colour output shown (its location), for programs with several.
const viewOf = (v) => (v === 'depth' ? 'depth' : +v);
let view = query.has('output') ? viewOf(query.get('output')) : null;
if (fixedTime !== null) $('paused').checked = true;

const state = (window.umbracPreview = {
  received: 0, drawn: 0, ok: null, diagnostics: [], errors: {}, renderers: {}, diff: null, snapshot,
});

const panes = { webgl2: { canvas: $('gl'), status: $('gl-status'), info: $('gl-info') }, webgpu: { canvas: $('gpu'), status: $('gpu-status'), info: $('gpu-info') } };
const renderers = {};
let inputs = null;
let lastGood = null;
let programIndex = 0;
const orbit = new Orbit();
// No click yet: `mouse` is null, and the convention gives the centre.
const clock = { start: performance.now(), time: fixedTime ?? 0, frame: 0, mouse: null };

function setError(api, message) {
  state.errors[api] = message;
  panes[api].status.textContent = message ?? '';
}

async function start() {
  for (const api of ['webgl2', 'webgpu']) {
    if (!apis.includes(api)) {
      setError(api, `not drawn (api=${apis.join(',')})`);
      continue;
    }
    try {
      renderers[api] = await createRenderer(panes[api].canvas, api);
      state.renderers[api] = renderers[api].describe();
      panes[api].info.textContent = `on ${state.renderers[api]}`;
    } catch (e) {
      setError(api, e.message);
    }
  }
  performance.mark('umbrac:renderers'); // web/bench-load.mjs reads the marks
  // Mouse by convention: pixels from the bottom left, the last click in .zw.
  for (const { canvas } of Object.values(panes)) {
    orbit.attach(canvas);
    const at = (e) => {
      const r = canvas.getBoundingClientRect();
      return [(e.clientX - r.left) * canvas.width / r.width, (1 - (e.clientY - r.top) / r.height) * canvas.height];
    };
    canvas.addEventListener('pointermove', (e) => { if (e.buttons && clock.mouse) clock.mouse.splice(0, 2, ...at(e)); });
    canvas.addEventListener('pointerdown', (e) => { const p = at(e); clock.mouse = [p[0], p[1], p[0], p[1]]; });
  }
  $('output').addEventListener('change', () => {
    view = viewOf($('output').value);
    for (const r of Object.values(renderers)) r.view = view;
  });
  $('program').addEventListener('change', () => {
    programIndex = +$('program').value;
    if (lastGood) show(lastGood.bundle, lastGood.generation);
  });
  const events = new EventSource('events');
  events.addEventListener('bundle', (e) => {
    const generation = +e.lastEventId;
    state.received = generation;
    performance.mark('umbrac:bundle');
    receive(JSON.parse(e.data), generation);
  });
  requestAnimationFrame(tick);
}

// Serialises loads: a bundle that arrives while one loads waits for it.
let loading = Promise.resolve();

function receive(bundle, generation) {
  loading = loading.then(() => (bundle.ok ? show(bundle, generation) : fail(bundle))).catch((e) => console.error(e));
}

function fail(bundle) {
  state.ok = false;
  state.diagnostics = bundle.diagnostics;
  $('diagnostics').textContent = bundle.diagnostics.map((d) => d.rendered).join('\n');
  $('overlay').hidden = false;
}

// True while a program loads: a frame then would draw the new program
// with the old one's inputs.
let switching = false;

async function show(bundle, generation) {
  switching = true;
  try {
    await switchTo(bundle, generation);
  } finally {
    switching = false;
  }
  drawFrame();
  performance.mark('umbrac:frame');
  await measure().catch((e) => { $('diff').textContent = `cannot compare: ${e.message}`; });
  state.drawn = generation;
}

async function switchTo(bundle, generation) {
  state.ok = true;
  state.diagnostics = bundle.diagnostics;
  $('overlay').hidden = true;
  $('source').textContent = bundle.manifest?.source ?? '';
  const programs = bundle.manifest?.programs ?? [];
  $('program').replaceChildren(...programs.map((p, i) => new Option(`${p.vertex} + ${p.fragment}`, i)));
  $('program').hidden = programs.length < 2;
  if (programIndex >= programs.length) programIndex = 0;
  $('program').value = programIndex;
  let plan;
  try {
    plan = planOf(bundle, programIndex);
  } catch (e) {
    for (const api of Object.keys(renderers)) setError(api, e.message);
    return;
  }
  const outputs = plan.outputs;
  $('output').replaceChildren(...outputs.map((o) => new Option(plan.passes ? `${o.name} (the scene's output)` : `${o.name} (location ${o.location})`, o.location)));
  if (plan.depth) $('output').append(new Option('depth (z^32: near dark, far white)', 'depth'));
  $('output').hidden = $('output').options.length < 2;
  if (!(view === 'depth' && plan.depth) && !outputs.some((o) => o.location === view)) view = outputs[0]?.location ?? 0;
  $('output').value = view;
  for (const r of Object.values(renderers)) r.view = view;
  const next = new Inputs(bundle.manifest, plan, $('controls'), inputs, orbit);
  for (const [api, r] of Object.entries(renderers)) {
    try {
      await r.load(bundle, plan);
      inputsOf[api] = next;
      setError(api, null);
    } catch (e) {
      // The last program that loaded keeps drawing in this pane, with its inputs.
      setError(api, e instanceof DrawError ? e.message : `${e}`);
    }
  }
  inputs = next;
  lastGood = { bundle, generation };
}

// Each pane's program's inputs (the last that loaded there), and one
// frame's values of each.
const inputsOf = {};

function frameInputs() {
  const { width, height } = panes.webgl2.canvas;
  const given = new Map();
  for (const i of Object.values(inputsOf)) if (!given.has(i)) given.set(i, i.frame({ ...clock, width, height }));
  return (api) => given.get(inputsOf[api]);
}

function drawFrame() {
  if (switching) return;
  const given = frameInputs();
  for (const [api, r] of Object.entries(renderers)) {
    if (!inputsOf[api]) continue;
    try {
      r.frame(given(api));
    } catch (e) {
      setError(api, e.message);
    }
  }
}

// Both pictures of the current inputs, and how far they agree.
async function snapshot() {
  const given = frameInputs();
  const out = { width: panes.webgl2.canvas.width, height: panes.webgl2.canvas.height };
  for (const [api, r] of Object.entries(renderers)) {
    if (!r.loaded || !inputsOf[api]) continue;
    out[api] = await r.read(given(api));
  }
  out.diff = out.webgl2 && out.webgpu ? compare(out.webgl2, out.webgpu) : null;
  return out;
}

async function measure() {
  const s = await snapshot();
  state.diff = s.diff;
  const drawn = Object.values(renderers).filter((r) => r.loaded).length;
  $('diff').textContent = s.diff
    ? `${(100 * s.diff.share).toFixed(2)}% of pixels differ (worst channel: ${s.diff.worst}/255)`
    : drawn ? 'one picture: nothing to compare' : 'nothing drawn';
}

let lastMeasure = 0;
function tick(now) {
  if (!$('paused').checked) {
    clock.time = (now - clock.start) / 1000;
    clock.frame++;
  } else if (fixedTime !== null) clock.time = fixedTime;
  // Paused or not, every frame is drawn: a control changes the picture.
  drawFrame();
  if (now - lastMeasure > 1000 && lastGood && !$('paused').checked) {
    lastMeasure = now;
    measure().catch(() => {});
  }
  requestAnimationFrame(tick);
}

// For tests: the pictures as base64.
window.umbracSnapshot = async () => {
  const s = await snapshot();
  const b64 = (px) => {
    if (!px) return null;
    let bin = '';
    for (let i = 0; i < px.length; i += 0x8000) bin += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
    return btoa(bin);
  };
  return { width: s.width, height: s.height, webgl2: b64(s.webgl2), webgpu: b64(s.webgpu), diff: s.diff };
};

start();
