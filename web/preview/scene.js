// The data of a scene (umbrac::scene, docs/runner.md "Scene files") as a
// page needs it: the built-in meshes and patterns, the instance grid, and
// the conventions' values each frame. Pure functions, no GPU.

// ---- patterns ---------------------------------------------------------------

function noise(x, y) {
  const h = (cx, cy) => {
    let v = (Math.imul(cx, 374761393) ^ Math.imul(cy, 668265263)) >>> 0;
    v = Math.imul((v ^ (v >>> 13)) >>> 0, 1274126177) >>> 0;
    return (v ^ (v >>> 16)) & 255;
  };
  const [cx, cy, fx, fy] = [x >> 2, y >> 2, x & 3, y & 3];
  const top = h(cx, cy) * (4 - fx) + h(cx + 1, cy) * fx;
  const bottom = h(cx, cy + 1) * (4 - fx) + h(cx + 1, cy + 1) * fx;
  return Math.floor((top * (4 - fy) + bottom * fy) / 16);
}

// RGBA8 texels of a built-in pattern, row 0 first (texture v = 0): the
// bytes src/scene/mod.rs's Pattern::texels makes.
export function pattern(kind, width = 64, height = width) {
  const data = new Uint8Array(width * height * 4);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      let px;
      if (kind === 'checker') { const c = ((x >> 3) + (y >> 3)) % 2 === 0 ? 200 : 60; px = [c, c, c, 255]; }
      else if (kind === 'noise') { const c = noise(x, y); px = [c, c, c, 255]; }
      else if (kind === 'uv') px = [Math.floor(x * 255 / Math.max(1, width - 1)), Math.floor(y * 255 / Math.max(1, height - 1)), 128, 255];
      else if (kind === 'flat_normal') px = [128, 128, 255, 255];
      else if (kind === 'white') px = [255, 255, 255, 255];
      else throw new Error(`unknown pattern ${kind}`);
      data.set(px, 4 * (y * width + x));
    }
  }
  return { width, height, data };
}

export const PATTERNS = ['checker', 'noise', 'uv', 'flat_normal', 'white'];

// ---- meshes -------------------------------------------------------------------

const sub = (a, b) => a.map((x, i) => x - b[i]);
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a.reduce((s, x, i) => s + x * b[i], 0);
const normalize = (a) => { const l = Math.hypot(...a); return a.map((x) => x / l); };

// The meshes are laid out as the native runner's (src/render/plan/meshes.rs):
// the same vertices, in the same order, and the same triangles, so that
// the two draw the same picture.

// A mesh's colour attribute: the position mapped to [0, 1].
const colourOf = (p) => [...p.map((x) => Math.min(1, Math.max(0, x + 0.5))), 1];

function indexed(vertices, indices) {
  return indices.map((i) => vertices[i]);
}

function cube() {
  const v = [];
  const idx = [];
  const faces = [
    [[0, 0, 1], [1, 0, 0], [0, 1, 0]], [[1, 0, 0], [0, 1, 0], [0, 0, 1]], [[0, 1, 0], [0, 0, 1], [1, 0, 0]],
    [[-1, 0, 0], [0, 0, 1], [0, 1, 0]], [[0, -1, 0], [1, 0, 0], [0, 0, 1]], [[0, 0, -1], [0, 1, 0], [1, 0, 0]],
  ];
  faces.forEach(([n, u, w], i) => {
    for (const [su, sv] of [[1, 1], [-1, 1], [-1, -1], [1, -1]]) {
      const position = [0, 1, 2].map((k) => (n[k] + u[k] * su + w[k] * sv) * 0.5);
      v.push({ position, normal: n, tangent: [...u, 1], uv: [(su + 1) / 2, (sv + 1) / 2], color: colourOf(position) });
    }
    const b = 4 * i;
    idx.push(b, b + 1, b + 2, b + 2, b + 3, b);
  });
  return indexed(v, idx);
}

function sphere() {
  const v = [];
  const idx = [];
  const [segments, rings] = [24, 16];
  for (let r = 0; r <= rings; r++) {
    const theta = (r / rings) * Math.PI;
    for (let s = 0; s <= segments; s++) {
      const phi = (s / segments) * 2 * Math.PI;
      const normal = [Math.sin(theta) * Math.sin(phi), Math.cos(theta), Math.sin(theta) * Math.cos(phi)];
      const position = normal.map((x) => 0.5 * x);
      v.push({ position, normal, tangent: [Math.cos(phi), 0, -Math.sin(phi), 1], uv: [s / segments, r / rings], color: colourOf(position) });
    }
  }
  const row = segments + 1;
  for (let r = 0; r < rings; r++) {
    for (let s = 0; s < segments; s++) {
      const [a, b, c, d] = [r * row + s, (r + 1) * row + s, (r + 1) * row + s + 1, r * row + s + 1];
      idx.push(a, b, c, a, c, d);
    }
  }
  return indexed(v, idx);
}

function plane() {
  const v = [[-1, 1], [1, 1], [1, -1], [-1, -1]].map(([x, z]) => ({
    position: [x, 0, z], normal: [0, 1, 0], tangent: [1, 0, 0, 1], uv: [(x + 1) / 2, (z + 1) / 2], color: colourOf([x, 0, z]),
  }));
  return indexed(v, [0, 1, 2, 0, 2, 3]);
}

function fullscreenTriangle() {
  return [[-1, -1], [3, -1], [-1, 3]].map(([x, y]) => ({
    position: [x, y, 0], normal: [0, 0, 1], tangent: [1, 0, 0, 1], uv: [(x + 1) / 2, (y + 1) / 2], color: [x * 0.5 + 0.5, y * 0.5 + 0.5, 0.5, 1],
  }));
}

// A mesh's vertices ({ position, normal, tangent, uv, color } each), as
// a triangle list; `none`: no vertices (the program places them).
export function mesh(kind) {
  switch (kind) {
    case 'fullscreen_triangle': return fullscreenTriangle();
    case 'cube': return cube();
    case 'sphere': return sphere();
    case 'plane': return plane();
    case 'none': return [];
    default: throw new Error(`unknown mesh ${kind}`);
  }
}

// The grid's instance `i`: { instance_offset, instance_color, instance_phase }.
export function instance(grid, i) {
  const [nx, nz, ny] = grid.count.map((n) => Math.max(1, n));
  const spacing = grid.spacing ?? 1.5;
  const total = grid.count.reduce((a, b) => a * b, 1);
  const [ix, iz, iy] = [i % nx, Math.floor(i / nx) % nz, Math.floor(i / (nx * nz))];
  const centre = (k, n) => (k - (n - 1) / 2) * spacing;
  const frac = (k, n) => (n > 1 ? k / (n - 1) : 0.5);
  return {
    instance_offset: [centre(ix, nx), centre(iy, ny), centre(iz, nz)],
    instance_color: [0.25 + 0.7 * frac(ix, nx), 0.8 - 0.5 * frac(iz, nz), 0.3 + 0.6 * frac(iy, ny)],
    instance_phase: [i / total],
  };
}

// An attribute's value fitted to `n` components: zeros, then a w of 1.
export function fit(value, n) {
  const out = value.slice(0, n);
  while (out.length < n) out.push(out.length === 3 ? 1 : 0);
  return out;
}

// ---- conventions --------------------------------------------------------------

export const CAMERA = { target: [0, 0, 0], distance: 3, yaw: 35, pitch: 25, spin: 0, fov_y: 45, near: 0.1, far: 100 };

function mul(a, b) {
  const o = new Array(16).fill(0);
  for (let c = 0; c < 4; c++) for (let r = 0; r < 4; r++) for (let k = 0; k < 4; k++) o[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return o;
}

function lookAt(eye, at, up) {
  const f = normalize(sub(at, eye));
  const s = normalize(cross(f, up));
  const u = cross(s, f);
  return [s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, -dot(s, eye), -dot(u, eye), dot(f, eye), 1];
}

function perspective(fovy, aspect, near, far) {
  const f = 1 / Math.tan(fovy / 2);
  return [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) / (near - far), -1, 0, 0, (2 * far * near) / (near - far), 0];
}

function orthographic(l, r, b, t, n, f) {
  return [2 / (r - l), 0, 0, 0, 0, 2 / (t - b), 0, 0, 0, 0, -2 / (f - n), 0, -(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n), 1];
}

const rad = (d) => (d * Math.PI) / 180;

// Every convention's value at `clock` = { time, frame, width, height,
// mouse: [x, y, z, w] or null } with `camera` (the scene's, as dragged)
// and `light` (the scene's `light`, or none: the default still sun):
// numbers in order, matrices 4 x 4 column by column. The `model` ones are
// the default slow turn's; drawConventions gives a draw's own.
export function conventions(camera, clock, light = null) {
  const c = { ...CAMERA, ...camera };
  const yaw = rad(c.yaw + c.spin * clock.time);
  const pitch = rad(c.pitch);
  const eye = [0, 1, 2].map((k) => c.target[k] + c.distance * [Math.cos(pitch) * Math.sin(yaw), Math.sin(pitch), Math.cos(pitch) * Math.cos(yaw)][k]);
  const view = lookAt(eye, c.target, [0, 1, 0]);
  const aspect = clock.width / clock.height;
  const projection = perspective(rad(c.fov_y), aspect, c.near, c.far);
  const a = 0.5 * clock.time;
  const model = [Math.cos(a), 0, -Math.sin(a), 0, 0, 1, 0, 0, Math.sin(a), 0, Math.cos(a), 0, 0, 0, 0, 1];
  const viewRotation = view.slice();
  viewRotation.splice(12, 3, 0, 0, 0);
  const lit = lightConventions(light, clock.time);
  const viewProjection = mul(projection, view);
  return {
    time: [clock.time],
    frame: [clock.frame],
    resolution: [clock.width, clock.height, 1, clock.time],
    aspect: [aspect],
    mouse: clock.mouse ?? [clock.width / 2, clock.height / 2, 0, 0],
    texel_size: [1 / clock.width, 1 / clock.height],
    view,
    view_rotation: viewRotation,
    projection,
    view_projection: viewProjection,
    model,
    model_view_projection: mul(viewProjection, model),
    // A turn's inverse transpose is itself.
    normal_matrix: model,
    camera_position: [...eye, 1],
    ...lit,
  };
}

// ---- lights and transforms (docs/runner.md, "Lights and transforms") ---------

export const LIGHT = {
  kind: 'sun', direction: [0.4, 0.8, 0.45], position: [0, 5, 0], target: [0, 0, 0], spin: 0,
  distance: 10, half_size: 4, cascades: [], fov_y: 60, near: 0.1, far: 20,
};

// A turn of `a` radians about +y, applied to a point (glam's from_rotation_y).
const turnY = (a, p) => [p[0] * Math.cos(a) + p[2] * Math.sin(a), p[1], -p[0] * Math.sin(a) + p[2] * Math.cos(a)];

// The light conventions of `light` (a scene's `light`, or none) at `time`:
// light_direction, light_position, spot_direction, light_view_projection,
// light_view_projections (the boxes' matrices one after another) and
// shadow_matrix, as src/render/plan/scene_file.rs computes them.
export function lightConventions(light, time) {
  const l = { ...LIGHT, ...(light ?? {}) };
  const a = rad(l.spin * time);
  let dir;
  let eye;
  if (l.kind === 'spot') {
    eye = turnY(a, l.position);
    dir = normalize(sub(eye, l.target));
  } else {
    dir = normalize(turnY(a, l.direction));
    eye = l.target.map((x, k) => x + dir[k] * l.distance);
  }
  const view = lookAt(eye, l.target, Math.abs(dir[1]) > 0.999 ? [0, 0, 1] : [0, 1, 0]);
  const boxes = l.kind === 'sun' && l.cascades.length ? l.cascades : [l.half_size];
  const matrices = l.kind === 'spot'
    ? [mul(perspective(rad(l.fov_y), 1, l.near, l.far), view)]
    : boxes.map((h) => mul(orthographic(-h, h, -h, h, l.near, l.far), view));
  const bias = [0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0.5, 0.5, 0.5, 1];
  return {
    light_direction: dir,
    light_position: [...eye, 1],
    spot_direction: dir.map((x) => -x),
    light_view_projection: matrices[0],
    light_view_projections: matrices.flat(),
    shadow_matrix: mul(bias, matrices[0]),
  };
}

// A draw's model matrix at `time`: translate * rotate(axis, angle + spin
// * time degrees) * scale; none: the default slow turn about +y.
export function modelMatrix(transform, time) {
  if (!transform) {
    const a = 0.5 * time;
    return [Math.cos(a), 0, -Math.sin(a), 0, 0, 1, 0, 0, Math.sin(a), 0, Math.cos(a), 0, 0, 0, 0, 1];
  }
  const t = { translate: [0, 0, 0], axis: [0, 1, 0], angle: 0, spin: 0, scale: 1, ...transform };
  const [x, y, z] = normalize(t.axis);
  const a = rad(t.angle + t.spin * time);
  const [c, s, k] = [Math.cos(a), Math.sin(a), 1 - Math.cos(a)];
  const sc = typeof t.scale === 'number' ? [t.scale, t.scale, t.scale] : t.scale;
  const r = [
    [c + x * x * k, y * x * k + z * s, z * x * k - y * s],
    [x * y * k - z * s, c + y * y * k, z * y * k + x * s],
    [x * z * k + y * s, y * z * k - x * s, c + z * z * k],
  ];
  return [...r[0].map((v) => v * sc[0]), 0, ...r[1].map((v) => v * sc[1]), 0, ...r[2].map((v) => v * sc[2]), 0, ...t.translate, 1];
}

// `conv` (conventions()) with a draw's own `model`,
// `model_view_projection` and `normal_matrix`, from its `transform`.
export function drawConventions(conv, transform, time) {
  const model = modelMatrix(transform, time);
  // The inverse transpose of R * S is R * S^-1: each column over its scale squared.
  const normal = model.slice();
  for (let col = 0; col < 3; col++) {
    const len2 = normal[col * 4] ** 2 + normal[col * 4 + 1] ** 2 + normal[col * 4 + 2] ** 2;
    for (let r = 0; r < 3; r++) normal[col * 4 + r] /= len2;
  }
  normal.splice(12, 3, 0, 0, 0);
  return { ...conv, model, model_view_projection: mul(conv.view_projection, model), normal_matrix: normal };
}

// The conventions that are arrays of matrices (an `index` picks one).
const ARRAY_CONVENTIONS = new Set(['light_view_projections']);

// The numbers a scene value names in `conv`: a convention's (a string),
// one element of an array convention ({ convention, index }), or null.
export function conventionValue(spec, conv) {
  if (typeof spec === 'string') return conv[spec] ?? null;
  if (spec && typeof spec === 'object' && !Array.isArray(spec) && ARRAY_CONVENTIONS.has(spec.convention) && Number.isInteger(spec.index) && spec.index >= 0) {
    const all = conv[spec.convention];
    return all && all.length >= 16 * (spec.index + 1) ? all.slice(16 * spec.index, 16 * (spec.index + 1)) : null;
  }
  return null;
}

// A value (a convention's or a scene's numbers) fitted to a member of
// type `t` (draw.js's parseType): a 4 x 4 matrix's upper 3 x 3 for a
// float3x3, vectors cut or padded with zeros.
export function fitValue(v, t) {
  if (t.cols && v.length === 16 && t.n !== 16) {
    const out = [];
    for (let c = 0; c < t.cols; c++) for (let r = 0; r < t.rows; r++) out.push(v[c * 4 + r]);
    return out;
  }
  const out = v.slice(0, t.n);
  while (out.length < t.n) out.push(0);
  return out;
}
