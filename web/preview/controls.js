// The preview's inputs: a control for each uniform member of the manifest,
// the values bound by name convention (time, resolution, mouse, frame),
// an orbit camera for matrices named view / projection / model, and a
// built-in pattern for each sampler. docs/preview.md lists the names.

import { parseType, writeMember, readMember, uniformBuffers, pattern } from './draw.js';

// A name without its usual prefixes, lower case: `u_Time`, `iTime` -> `time`.
export function bareName(name) {
  return name.replace(/^(u_|i(?=[A-Z])|g_|c_)/, '').toLowerCase();
}

// What a member is bound to by its name, or null (a control then).
export function conventionOf(name, t) {
  const n = bareName(name);
  if (!t) return null;
  if (t.cols === 4 && t.rows === 4) {
    if (/^(mvp|modelviewproj(ection)?|model_view_proj(ection)?|wvp)$/.test(n)) return 'mvp';
    if (/^(view_?proj(ection)?|vp|camera)$/.test(n)) return 'viewproj';
    if (/proj/.test(n)) return 'projection';
    if (/view/.test(n)) return 'view';
    if (/model|world/.test(n)) return 'model';
    return null;
  }
  if (/^(time|global_?time|seconds)$/.test(n) && t.n === 1 && t.scalar === 'float') return 'time';
  if (/^(resolution|screen_?size|viewport_?size|res)$/.test(n) && t.scalar === 'float' && t.n >= 2) return 'resolution';
  if (/^mouse$/.test(n) && t.scalar === 'float' && t.n >= 2) return 'mouse';
  if (/^(frame|frame_?index|frame_?count)$/.test(n) && t.n === 1) return 'frame';
  if (/^aspect(_?ratio)?$/.test(n) && t.n === 1 && t.scalar === 'float') return 'aspect';
  return null;
}

// ---- small matrix math (column-major, GL conventions) -------------------

function perspective(fovy, aspect, near, far) {
  const f = 1 / Math.tan(fovy / 2);
  return [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) / (near - far), -1, 0, 0, (2 * far * near) / (near - far), 0];
}

function lookAt(eye, at, up) {
  const sub = (a, b) => a.map((x, i) => x - b[i]);
  const norm = (a) => { const l = Math.hypot(...a); return a.map((x) => x / l); };
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const f = norm(sub(at, eye));
  const s = norm(cross(f, up));
  const u = cross(s, f);
  return [s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, -dot(s, eye), -dot(u, eye), dot(f, eye), 1];
}

function mul(a, b) {
  const o = new Array(16).fill(0);
  for (let c = 0; c < 4; c++) for (let r = 0; r < 4; r++) for (let k = 0; k < 4; k++) o[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return o;
}

const IDENTITY = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];

// The orbit camera: drag on a canvas to turn, wheel to zoom.
export class Orbit {
  constructor() {
    this.yaw = 0.6;
    this.pitch = 0.4;
    this.distance = 4;
  }

  matrices(aspect) {
    const eye = [
      this.distance * Math.cos(this.pitch) * Math.sin(this.yaw),
      this.distance * Math.sin(this.pitch),
      this.distance * Math.cos(this.pitch) * Math.cos(this.yaw),
    ];
    const view = lookAt(eye, [0, 0, 0], [0, 1, 0]);
    const projection = perspective(Math.PI / 3, aspect, 0.1, 100);
    const model = IDENTITY;
    const viewproj = mul(projection, view);
    return { view, projection, model, viewproj, mvp: mul(viewproj, model) };
  }

  attach(el) {
    let last = null;
    el.addEventListener('pointerdown', (e) => { last = [e.clientX, e.clientY]; });
    window.addEventListener('pointerup', () => { last = null; });
    el.addEventListener('pointermove', (e) => {
      if (!last) return;
      this.yaw -= (e.clientX - last[0]) * 0.01;
      this.pitch = Math.max(-1.5, Math.min(1.5, this.pitch + (e.clientY - last[1]) * 0.01));
      last = [e.clientX, e.clientY];
    });
    el.addEventListener('wheel', (e) => {
      e.preventDefault();
      this.distance = Math.max(0.5, Math.min(50, this.distance * Math.exp(e.deltaY * 0.001)));
    }, { passive: false });
  }
}

// ---- controls -------------------------------------------------------------

const isColour = (name, t) => t.scalar === 'float' && (t.n === 3 || t.n === 4) && /col|tint|albedo|diffuse|specular|ambient|emissive|fog|sky|light_?c/.test(bareName(name));

const toHex = (v) => '#' + v.slice(0, 3).map((x) => Math.round(Math.max(0, Math.min(1, x)) * 255).toString(16).padStart(2, '0')).join('');
const fromHex = (h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16) / 255);

// A slider's range around a default: [0, 1] for small ones, else up to twice it.
function rangeOf(v, int) {
  const a = Math.abs(v);
  if (int) return [Math.min(0, -a * 2), Math.max(16, a * 2)];
  if (a <= 1) return [v < 0 ? -1 : 0, 1];
  return [v < 0 ? -2 * a : 0, 2 * a];
}

function slider(label, value, int, onInput) {
  const row = document.createElement('label');
  row.className = 'control';
  const [lo, hi] = rangeOf(value, int);
  const input = document.createElement('input');
  input.type = 'range';
  input.min = lo;
  input.max = hi;
  input.step = int ? 1 : (hi - lo) / 1000;
  input.value = value;
  const out = document.createElement('output');
  out.textContent = int ? String(value) : value.toFixed(3);
  input.addEventListener('input', () => {
    const v = int ? parseInt(input.value, 10) : parseFloat(input.value);
    out.textContent = int ? String(v) : v.toFixed(3);
    onInput(v);
  });
  row.append(document.createTextNode(label), input, out);
  return row;
}

// The start of a member declared without a value: identity matrices and
// white colours (a zero would draw nothing), zero otherwise.
function undeclared(name, t) {
  if (t.cols) return Array.from({ length: t.n }, (_, k) => (Math.floor(k / t.rows) === k % t.rows ? 1 : 0));
  return Array(t.n).fill(isColour(name, t) ? 1 : 0);
}

// The inputs of a manifest: { buffers, textures } each frame, with the
// controls in `panel`. `previous` (the Inputs of the last program) keeps
// the values and patterns of members and samplers still there.
export class Inputs {
  constructor(manifest, panel, previous = null, orbit = new Orbit()) {
    this.manifest = manifest;
    this.defaults = uniformBuffers(manifest);
    this.values = new Map(); // member key -> numbers the user set
    this.patterns = new Map(); // sampler -> pattern name
    this.bound = []; // { buffer, member, convention }
    this.orbit = orbit;
    this.cache = new Map();
    panel.replaceChildren();
    for (const b of manifest.uniform_buffers ?? []) {
      for (const m of b.members) {
        const t = parseType(m.type);
        const key = `${b.name}.${m.name}`;
        const convention = conventionOf(m.name, t);
        if (convention) {
          this.bound.push({ buffer: b.name, member: m, convention });
          const note = document.createElement('div');
          note.className = 'control bound';
          note.textContent = `${m.name}: ${convention}${t.cols ? ' (orbit camera: drag, wheel)' : ''}`;
          panel.append(note);
          continue;
        }
        if (!t) {
          const note = document.createElement('div');
          note.className = 'control bound';
          note.textContent = `${m.name} : ${m.type}: its default`;
          panel.append(note);
          continue;
        }
        const kept = previous?.values.get(key);
        const start = kept?.length === t.n ? kept : m.default ? readMember(this.defaults[b.name], m) : undeclared(m.name, t);
        this.values.set(key, start.slice());
        panel.append(this.control(key, m.name, t, start));
      }
    }
    for (const s of manifest.samplers ?? []) {
      const row = document.createElement('label');
      row.className = 'control';
      const select = document.createElement('select');
      for (const p of ['checker', 'uv', 'noise']) select.append(new Option(p, p));
      select.value = previous?.patterns.get(s.name) ?? 'checker';
      this.patterns.set(s.name, select.value);
      select.addEventListener('change', () => this.patterns.set(s.name, select.value));
      row.append(document.createTextNode(`${s.name} `), select);
      panel.append(row);
    }
  }

  control(key, name, t, start) {
    const set = (k, v) => { this.values.get(key)[k] = v; };
    if (t.scalar === 'bool') {
      const row = document.createElement('label');
      row.className = 'control';
      const box = document.createElement('input');
      box.type = 'checkbox';
      box.checked = !!start[0];
      box.addEventListener('change', () => set(0, box.checked ? 1 : 0));
      row.append(box, document.createTextNode(` ${name}`));
      return row;
    }
    if (isColour(name, t)) {
      const row = document.createElement('label');
      row.className = 'control';
      const pick = document.createElement('input');
      pick.type = 'color';
      pick.value = toHex(start);
      pick.addEventListener('input', () => fromHex(pick.value).forEach((v, k) => set(k, v)));
      row.append(document.createTextNode(`${name} `), pick);
      return row;
    }
    const box = document.createElement('fieldset');
    box.className = 'control';
    const legend = document.createElement('legend');
    legend.textContent = `${name} : ${t.cols ? `float${t.cols}x${t.rows}` : t.n > 1 ? `${t.scalar}${t.n}` : t.scalar}`;
    box.append(legend);
    const int = t.scalar !== 'float';
    // A matrix's sliders are named column.row: `c1.y`.
    const label = (k) => (t.cols ? `c${Math.floor(k / t.rows)}.${'xyzw'[k % t.rows]}` : t.n > 1 ? 'xyzw'[k] : '');
    start.forEach((v, k) => box.append(slider(label(k), v, int, (x) => set(k, x))));
    return box;
  }

  // The inputs of one frame: `clock` = { time, frame, width, height, mouse: [x, y, cx, cy] }.
  frame(clock) {
    const buffers = {};
    for (const [name, words] of Object.entries(this.defaults)) buffers[name] = words.slice();
    for (const b of this.manifest.uniform_buffers ?? []) {
      for (const m of b.members) {
        const v = this.values.get(`${b.name}.${m.name}`);
        if (v) writeMember(buffers[b.name], m, v);
      }
    }
    const cam = this.orbit.matrices(clock.width / clock.height);
    for (const { buffer, member, convention } of this.bound) {
      const t = parseType(member.type);
      let v;
      if (convention === 'time') v = [clock.time];
      else if (convention === 'frame') v = [clock.frame];
      else if (convention === 'aspect') v = [clock.width / clock.height];
      else if (convention === 'resolution') v = [clock.width, clock.height, 1, 1].slice(0, t.n);
      else if (convention === 'mouse') v = clock.mouse.slice(0, t.n);
      else v = cam[convention];
      writeMember(buffers[buffer], member, v);
    }
    const textures = {};
    for (const [s, p] of this.patterns) {
      if (!this.cache.has(p)) this.cache.set(p, pattern(p));
      textures[s] = this.cache.get(p);
    }
    return { buffers, textures };
  }
}
