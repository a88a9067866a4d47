// The preview's inputs: a control for each uniform member of the manifest
// (as the scene's `controls` say, else from the name and type), the values
// bound to conventions (time, resolution, mouse, frame, the orbit camera's
// matrices, ...), and a pattern for each sampler. docs/preview.md.

import { parseType, writeMember, readMember, uniformBuffers, bareName, structLeaves } from './draw.js';
import { PATTERNS, conventions, drawConventions, conventionValue, fitValue } from './scene.js';
import { texels } from './textures.js';

// The orbit camera: drag on a canvas to turn, wheel to zoom; it moves the
// scene's camera (umbrac::scene::OrbitCamera, degrees) by what was dragged.
export class Orbit {
  constructor() {
    this.yaw = 0;
    this.pitch = 0;
    this.zoom = 1;
  }

  camera(base) {
    const b = { yaw: 35, pitch: 25, distance: 3, ...base };
    return { ...b, yaw: b.yaw + this.yaw, pitch: Math.max(-89, Math.min(89, b.pitch + this.pitch)), distance: b.distance * this.zoom };
  }

  attach(el) {
    let last = null;
    el.addEventListener('pointerdown', (e) => { last = [e.clientX, e.clientY]; });
    window.addEventListener('pointerup', () => { last = null; });
    el.addEventListener('pointermove', (e) => {
      if (!last) return;
      this.yaw -= (e.clientX - last[0]) * 0.5;
      this.pitch += (e.clientY - last[1]) * 0.5;
      last = [e.clientX, e.clientY];
    });
    el.addEventListener('wheel', (e) => {
      e.preventDefault();
      this.zoom = Math.max(0.1, Math.min(20, this.zoom * Math.exp(e.deltaY * 0.001)));
    }, { passive: false });
  }
}

const isColour = (name, t) => t.scalar === 'float' && (t.n === 3 || t.n === 4) && /col|tint|albedo|diffuse|specular|ambient|emissive|fog|sky|light_?c/.test(bareName(name));

const toHex = (v) => '#' + v.slice(0, 3).map((x) => Math.round(Math.max(0, Math.min(1, x)) * 255).toString(16).padStart(2, '0')).join('');
const fromHex = (h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16) / 255);

// A slider's range when no scene gives one: [0, max(1, 2 |v|)] (from minus
// that for a negative v); integers up to max(10, 2 |v|).
function rangeOf(v, int) {
  const hi = Math.max(int ? 10 : 1, 2 * Math.abs(v));
  return [v < 0 ? -hi : 0, hi];
}

function slider(label, value, range, int, onInput) {
  const row = document.createElement('label');
  row.className = 'control';
  const [lo, hi, step] = range ?? [...rangeOf(value, int), null];
  const input = document.createElement('input');
  input.type = 'range';
  input.min = lo;
  input.max = hi;
  input.step = step ?? (int ? 1 : (hi - lo) / 1000);
  input.value = value;
  const out = document.createElement('output');
  const show = (v) => (int ? String(v) : Number(v).toFixed(3));
  out.textContent = show(value);
  input.addEventListener('input', () => {
    const v = int ? parseInt(input.value, 10) : parseFloat(input.value);
    out.textContent = show(v);
    onInput(v);
  });
  row.append(document.createTextNode(label), input, out);
  return row;
}

// A scene value (a number, numbers or a bool) as a member's numbers.
function numbersOf(spec, t) {
  if (typeof spec === 'boolean') return fitValue([spec ? 1 : 0], t);
  // A number fills every component, as the native runner's (src/render/plan/scene_file.rs).
  if (typeof spec === 'number') return Array(t.n).fill(spec);
  return fitValue(spec, t);
}

// The start of a member declared without a value: identity matrices and
// white colours (a zero would draw nothing), zero otherwise.
function undeclared(name, t) {
  if (t.cols) return Array.from({ length: t.n }, (_, k) => (Math.floor(k / t.rows) === k % t.rows ? 1 : 0));
  return Array(t.n).fill(isColour(name, t) ? 1 : 0);
}

function note(text) {
  const n = document.createElement('div');
  n.className = 'control bound';
  n.textContent = text;
  return n;
}

// The inputs of a plan (draw.js's planOf): { buffers, textures } each
// frame, with the controls in `panel`. `previous` (the Inputs of the last
// program) keeps the values and patterns of members and samplers still there.
export class Inputs {
  constructor(manifest, plan, panel, previous = null, orbit = new Orbit()) {
    this.manifest = manifest;
    this.plan = plan;
    this.defaults = uniformBuffers(manifest);
    this.values = new Map(); // member key -> numbers
    this.patterns = new Map(); // sampler -> pattern name
    this.bound = []; // { buffer, member, t, convention }
    this.leaves = []; // { buffer, member, values }: a struct's members the scene sets by path
    this.orbit = orbit;
    this.images = new Map();
    this.files = new Map(); // sampler -> an image file's texels
    panel.replaceChildren();
    for (const b of manifest.uniform_buffers ?? []) {
      for (const m of b.members) {
        const t = parseType(m.type);
        const key = `${b.name}.${m.name}`;
        const spec = plan.values[m.name];
        const control = plan.controls.find((c) => c.name === m.name);
        if (plan.perDraw?.has(m.name)) {
          panel.append(note(`${m.name}: set by the scene's passes and draws`));
          continue;
        }
        // A convention's name, or one element of an array convention ({ convention, index }).
        if (typeof spec === 'string' || (spec && typeof spec === 'object' && !Array.isArray(spec))) {
          this.bound.push({ buffer: b.name, member: m, t, convention: spec });
          const orbits = /^(view|view_rotation|projection|view_projection|model_view_projection|camera_position)$/.test(spec);
          panel.append(note(`${m.name}: ${typeof spec === 'string' ? spec : `${spec.convention}[${spec.index}]`}${orbits ? ' (orbit camera: drag, wheel)' : ''}`));
          continue;
        }
        if (!t || control?.kind === 'none') {
          // A struct or an array keeps its default (or the scene's numbers).
          if (t && spec !== undefined) this.values.set(key, numbersOf(spec, t));
          for (const leaf of structLeaves(manifest, m)) {
            const s = plan.values[leaf.name];
            const lt = parseType(leaf.type);
            if (s !== undefined && typeof s !== 'string' && lt) this.leaves.push({ buffer: b.name, member: leaf, values: numbersOf(s, lt) });
          }
          panel.append(note(`${m.name} : ${m.type}: its default`));
          continue;
        }
        const kept = previous?.values.get(key);
        const start = kept?.length === t.n ? kept : spec !== undefined ? numbersOf(spec, t) : m.default ? readMember(this.defaults[b.name], m) : undeclared(m.name, t);
        this.values.set(key, start.slice());
        panel.append(this.control(key, m.name, t, start, control));
      }
    }
    for (const [s, tex] of Object.entries(plan.textures)) {
      if (tex.depthCleared) {
        panel.append(note(`${s}: a depth target cleared to 1 (every comparison passes)`));
        continue;
      }
      const row = document.createElement('label');
      row.className = 'control';
      const select = document.createElement('select');
      // A cube map also offers the sky; image files make 2D textures only.
      const flat = (tex.kind ?? '2d') === '2d';
      for (const p of flat ? PATTERNS : ['sky', ...PATTERNS].slice(tex.kind === 'cube' ? 0 : 1)) select.append(new Option(p, p));
      // An image file of the user's (chosen or dropped on the button) joins the menu.
      const kept = previous?.files.get(s);
      if (kept) {
        this.files.set(s, kept);
        select.append(new Option(kept.name, 'file'));
      }
      select.value = previous?.patterns.get(s) ?? tex.pattern;
      this.patterns.set(s, select.value);
      select.addEventListener('change', () => this.patterns.set(s, select.value));
      const file = document.createElement('input');
      file.type = 'file';
      file.accept = 'image/*';
      file.addEventListener('change', async () => {
        const f = file.files[0];
        if (!f) return;
        const bitmap = await createImageBitmap(f);
        const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
        const ctx = canvas.getContext('2d');
        ctx.drawImage(bitmap, 0, 0);
        // Row 0 first, the image's top: as the patterns and the native runner's image files.
        const px = ctx.getImageData(0, 0, bitmap.width, bitmap.height);
        this.files.set(s, { name: f.name, width: bitmap.width, height: bitmap.height, data: new Uint8Array(px.data.buffer) });
        select.querySelector('option[value="file"]')?.remove();
        select.append(new Option(f.name, 'file'));
        select.value = 'file';
        this.patterns.set(s, 'file');
      });
      row.append(document.createTextNode(`${s} `), select, ...(flat ? [file] : []));
      panel.append(row);
    }
  }

  control(key, name, t, start, control) {
    const set = (k, v) => { this.values.get(key)[k] = v; };
    const kind = control?.kind ?? (t.scalar === 'bool' ? 'checkbox' : isColour(name, t) ? 'color' : 'slider');
    if (kind === 'checkbox') {
      const row = document.createElement('label');
      row.className = 'control';
      const box = document.createElement('input');
      box.type = 'checkbox';
      box.checked = !!start[0];
      box.addEventListener('change', () => set(0, box.checked ? 1 : 0));
      row.append(box, document.createTextNode(` ${name}`));
      return row;
    }
    if (kind === 'color') {
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
    const range = control?.min !== undefined && control?.max !== undefined ? [control.min, control.max, control.step ?? null] : null;
    // A matrix's sliders are named column.row: `c1.y`.
    const label = (k) => (t.cols ? `c${Math.floor(k / t.rows)}.${'xyzw'[k % t.rows]}` : t.n > 1 ? 'xyzw'[k] : '');
    start.forEach((v, k) => box.append(slider(label(k), v, range, int, (x) => set(k, x))));
    return box;
  }

  // The inputs of one frame: `clock` = { time, frame, width, height, mouse }.
  frame(clock) {
    const buffers = {};
    for (const [name, words] of Object.entries(this.defaults)) buffers[name] = words.slice();
    for (const b of this.manifest.uniform_buffers ?? []) {
      for (const m of b.members) {
        const v = this.values.get(`${b.name}.${m.name}`);
        if (v) writeMember(buffers[b.name], m, v);
      }
    }
    for (const l of this.leaves) writeMember(buffers[l.buffer], l.member, l.values);
    // With the scene's light, and its one draw's transform (draw.js's
    // single pass; passes.js sets each draw's own over these).
    const conv = drawConventions(conventions(this.orbit.camera(this.plan.camera), clock, this.plan.light ?? null), this.plan.transform ?? null, clock.time);
    for (const { buffer, member, t, convention } of this.bound) {
      const v = conventionValue(convention, conv);
      // An array member (t null: a light's matrices) takes the numbers whole.
      if (v) writeMember(buffers[buffer], member, t ? fitValue(v, t) : v);
    }
    const textures = {};
    for (const [s, p] of this.patterns) {
      const tex = this.plan.textures[s];
      const file = p === 'file' ? this.files.get(s) : null;
      if (file) {
        file.filter = tex.filter;
        textures[s] = file;
        continue;
      }
      const key = `${p}:${tex.size.join('x')}:${tex.kind ?? '2d'}:${tex.layers ?? 1}`;
      if (!this.images.has(key)) this.images.set(key, texels(p, tex));
      // One object per pattern, size and filter: a renderer uploads a texture when its object changes.
      const ikey = `${key}:${tex.filter}`;
      if (!this.images.has(ikey)) this.images.set(ikey, { ...this.images.get(key), filter: tex.filter });
      textures[s] = this.images.get(ikey);
    }
    // The conventions too: a scene's passes and draws set values of their own (passes.js).
    return { buffers, textures, conventions: conv };
  }
}
