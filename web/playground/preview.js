// The playground's live preview: each good bundle that main.js hands the
// #preview panel (an `umbrac-bundle` event) is drawn with WebGL2 and, where
// the browser has it, WebGPU, by the preview page's drawing module
// (web/preview/draw.js) with its controls (web/preview/controls.js); a
// failed compile leaves the last good program drawing. The share of
// pixels that differ between the two is shown as on `umbrac preview`.
import { createRenderer, planOf, compare, DrawError } from '../preview/draw.js';
import { Inputs, Orbit } from '../preview/controls.js';

export function mountPreview(panel) {
  const canvases = { webgl2: panel.querySelector('#preview-gl'), webgpu: panel.querySelector('#preview-gpu') };
  const statusOf = { webgl2: panel.querySelector('#preview-gl-status'), webgpu: panel.querySelector('#preview-gpu-status') };
  const controls = panel.querySelector('#preview-controls');
  const diffLine = panel.querySelector('#preview-diff');
  const renderers = {};
  const orbit = new Orbit();
  const clock = { start: performance.now(), time: 0, frame: 0, mouse: [0, 0, 0, 0] };
  const state = { drawn: 0, errors: {}, renderers: {}, diff: null, snapshot };
  let inputs = null;
  let loading = Promise.resolve();
  let generation = 0;

  // controls.js's Inputs takes the plan as its second argument on the
  // preview branch since the scene files (after the merge this page was
  // built on); until both meet on main, either form is served.
  const inputsFor = (manifest, plan, previous) =>
    Inputs.length >= 3 ? new Inputs(manifest, plan, controls, previous, orbit) : new Inputs(manifest, controls, previous, orbit);

  const setError = (api, message) => {
    state.errors[api] = message;
    statusOf[api].textContent = message ?? '';
  };

  const ready = (async () => {
    for (const api of ['webgl2', 'webgpu']) {
      try {
        renderers[api] = await createRenderer(canvases[api], api);
        state.renderers[api] = renderers[api].describe();
      } catch (e) {
        setError(api, e.message);
      }
      orbit.attach(canvases[api]);
    }
  })();

  async function show(bundle, n) {
    await ready;
    let plan;
    try {
      plan = planOf(bundle, 0);
    } catch (e) {
      for (const api of Object.keys(renderers)) setError(api, e.message);
      state.drawn = n;
      return;
    }
    for (const [api, r] of Object.entries(renderers)) {
      try {
        await r.load(bundle, plan);
        setError(api, null);
      } catch (e) {
        setError(api, e instanceof DrawError ? e.message : `${e}`);
      }
    }
    inputs = inputsFor(bundle.manifest, plan, inputs);
    drawFrame();
    const s = await snapshot().catch(() => null);
    state.diff = s && s.diff;
    diffLine.textContent = state.diff ? `${(100 * state.diff.share).toFixed(2)}% of pixels differ between WebGL2 and WebGPU (worst channel ${state.diff.worst}/255)` : '';
    state.drawn = n;
  }

  function frameInputs() {
    const { width, height } = canvases.webgl2;
    return inputs.frame({ ...clock, width, height });
  }

  function drawFrame() {
    if (!inputs) return;
    const given = frameInputs();
    for (const [api, r] of Object.entries(renderers)) {
      if (!r.loaded) continue;
      try {
        r.frame(given);
      } catch (e) {
        setError(api, e.message);
      }
    }
  }

  // Both pictures of the current inputs (rows bottom first) and their comparison.
  async function snapshot() {
    const out = { width: canvases.webgl2.width, height: canvases.webgl2.height };
    if (!inputs) return out;
    const given = frameInputs();
    for (const [api, r] of Object.entries(renderers)) if (r.loaded) out[api] = await r.read(given);
    out.diff = out.webgl2 && out.webgpu ? compare(out.webgl2, out.webgpu) : null;
    return out;
  }

  const paused = panel.querySelector('#preview-paused');
  function tick(now) {
    if (!paused.checked) {
      clock.time = (now - clock.start) / 1000;
      clock.frame++;
      drawFrame();
    }
    requestAnimationFrame(tick);
  }
  requestAnimationFrame(tick);

  panel.addEventListener('umbrac-bundle', (e) => {
    const n = ++generation;
    loading = loading.then(() => show(e.detail, n)).catch((err) => console.error(err));
  });
  return state;
}
