// Draws one umbrac program in a canvas, with WebGL2 from its GLSL ES 3.00
// outputs or WebGPU from its WGSL, bound by its reflection manifest.
// The preview page (umbrac preview) and the playground both use it.
//
//   import { createRenderer, planOf, uniformBuffers, DrawError } from './draw.js';
//   const r = await createRenderer(canvas, 'webgl2');   // or 'webgpu'
//   await r.load(bundle, planOf(bundle)); // compiles; throws DrawError, the last load stays
//   r.frame({ buffers, textures });   // draws: buffers from uniformBuffers() (or
//                                     // controls.js's Inputs), textures
//                                     // { samplerName: {width, height, data, filter} }
//   r.view = 1;                       // the colour output shown (MRT), or 'depth'
//   const rgba = await r.read(inputs); // Uint8Array, rows bottom first (GL's order)
//
// A bundle is src/bundle.rs's JSON (docs/preview.md). What is drawn
// comes from planOf: the bundle's scene (umbrac::scene) where it has one;
// else the manifest's first vertex/fragment program over a full-screen
// quad whose attributes are made up from their names, or a lone fragment
// entry point over a full-screen triangle whose varyings are made up the
// same way. Uniform values live in one word array per
// uniform buffer of the manifest, laid out as the manifest says (WGSL's
// buffers; GLSL's std140 blocks; GLSL's loose uniforms are read back
// from the same words), so both APIs draw the same values.

import { pattern, mesh, instance, fit, PATTERNS } from './scene.js';
import { needsPasses, passesPlan, GLPasses, GPUPasses } from './passes.js';
import { texels, kindOf, glTarget, glUpload, viewDimension, gpuTexture } from './textures.js';

export { pattern, PATTERNS };

export class DrawError extends Error {
  constructor(kind, message) {
    super(message);
    this.kind = kind;
  }
}

// ---- what to draw -------------------------------------------------------

// 'float3' -> { scalar: 'float', n: 3 }; 'float4x4' -> { cols: 4, rows: 4 };
// 'bool' -> { scalar: 'bool', n: 1 }; anything else (structs, arrays): null.
export function parseType(t) {
  let m = /^(float|int|uint|bool|half)([234])?$/.exec(t);
  if (m) return { scalar: m[1] === 'half' ? 'float' : m[1], n: m[2] ? +m[2] : 1 };
  m = /^float([234])x([234])$/.exec(t);
  if (m) return { scalar: 'float', cols: +m[1], rows: +m[2], n: +m[1] * +m[2] };
  return null;
}

// What an attribute or varying of this name and type is made up as, on
// a full-screen shape whose corner is `p` (GL clip space, -1..1).
function madeUp(name, t) {
  const n = name.toLowerCase();
  if (t.scalar !== 'float') return 'zero';
  if (/pos|vertex|coord(?!s?_?uv)/.test(n) && !/uv|tex/.test(n)) return 'position';
  if (/uv|tex|st$/.test(n)) return 'uv';
  if (/norm/.test(n)) return 'normal';
  if (/col/.test(n)) return 'colour';
  return t.n === 2 ? 'uv' : 'zero';
}

function madeUpValues(kind, n, p) {
  const v = { position: [p[0], p[1], 0, 1], uv: [p[0] * 0.5 + 0.5, p[1] * 0.5 + 0.5, 0, 1], normal: [0, 0, 1, 0], colour: [1, 1, 1, 1], zero: [0, 0, 0, 0] }[kind];
  // A vec4 position's w is 1; a 3-component one ends at z.
  return v.slice(0, n);
}

// The same, as shader expressions of the corner `p` (GLSL and WGSL alike).
function madeUpExprs(kind, t) {
  if (t.scalar !== 'float') return Array(t.n).fill('0');
  const v = { position: ['p.x', 'p.y', '0.0', '1.0'], uv: ['p.x * 0.5 + 0.5', 'p.y * 0.5 + 0.5', '0.0', '1.0'], normal: ['0.0', '0.0', '1.0', '0.0'], colour: ['1.0', '1.0', '1.0', '1.0'], zero: ['0.0', '0.0', '0.0', '0.0'] }[kind];
  return v.slice(0, t.n);
}

const QUAD = [[-1, -1], [1, -1], [1, 1], [-1, -1], [1, 1], [-1, 1]];

// What a bundle is drawn with:
// { vertex, fragment (entry points; vertex null: the page's full-screen
//   triangle), attributes: [{ name, glsl_name, location, wgsl_location,
//   type, format, data (numbers, one record per vertex or instance),
//   perInstance }], count (vertices), instances, depth, cull ('none' |
//   'back' | 'front', counter-clockwise is front), clear, values (name ->
//   a scene value: numbers, a bool, a convention's name or { convention,
//   index }), textures (sampler -> { pattern, size, filter }), camera,
//   light (the scene's, or null), transform (the draw's, or null: the
//   default slow turn), controls, entries }.
// From the bundle's scene (umbrac::scene, inferred by the compiler) where
// it has one; else made up here from the names (a lone fragment entry point,
// or a program the scene inference refused).
export function planOf(bundle, programIndex = 0) {
  const m = bundle.manifest;
  if (!m) throw new DrawError('plan', 'the bundle has no manifest (the program did not compile)');
  if (bundle.scene && programIndex === 0) return planOfScene(m, bundle.scene);
  return madeUpPlan(m, programIndex);
}

export const entryOf = (m, name) => m.entry_points.find((e) => e.name === name);

function checkColourOutput(fragment) {
  const out0 = fragment.outputs.find((o) => o.location === 0) ?? fragment.outputs[0];
  if (!out0 || parseType(out0.type)?.scalar !== 'float') {
    throw new DrawError('plan', `the preview draws a float colour output at location 0; \`${fragment.name}\` has ${out0 ? `\`${out0.name} : ${out0.type}\`` : 'none'}`);
  }
}

// The fragment's float colour outputs by location (MRT): which one is
// shown is the renderer's `view`.
export function colourOutputs(fragment) {
  return fragment.outputs.filter((o) => parseType(o.type)?.scalar === 'float').map((o) => ({ name: o.name, location: o.location })).sort((a, b) => a.location - b.location);
}

// A scene draw's vertex attributes for `vertex`'s inputs (one record per
// vertex or instance), its vertex count and its instances.
export function drawGeometry(vertex, draw) {
  const vertices = mesh(draw.mesh);
  const instances = draw.instances ? draw.instances.count.reduce((a, b) => a * b, 1) : 1;
  const attributes = [];
  for (const a of draw.mesh === 'none' ? [] : vertex.inputs) {
    const t = parseType(a.type);
    const source = draw.attributes?.[a.name];
    if (!t || t.cols || !source) throw new DrawError('plan', `the scene feeds no attribute to the vertex input \`${a.name} : ${a.type}\``);
    const perInstance = source.startsWith('instance_');
    if (perInstance && !draw.instances) throw new DrawError('plan', `\`${a.name}\` is per instance and the draw has no instance grid`);
    const records = perInstance ? Array.from({ length: instances }, (_, i) => instance(draw.instances, i)[source]) : vertices.map((v) => v[source]);
    attributes.push({ name: a.name, glsl_name: a.glsl_name ?? a.name, location: a.glsl_location ?? a.location, wgsl_location: a.location, type: t, format: a.vertex_format, perInstance, data: records.flatMap((r) => fit(r, t.n)) });
  }
  return { attributes, count: draw.mesh === 'none' ? draw.vertices ?? 3 : vertices.length, instances };
}

function planOfScene(m, scene) {
  const passes = scene.passes ?? [];
  // Passes that only clear a depth target (what a shadow sampler reads when
  // nothing draws its map) are the depth texture itself, cleared to 1.
  const clearOnly = passes.filter((p) => p.draws.length === 0 && p.depth && !p.color);
  const drawn = passes.filter((p) => !clearOnly.includes(p));
  // Anything more than one draw of one pass to the screen (sampling at
  // most cleared depth targets and patterns) is passes.js's.
  if (needsPasses(scene, drawn, clearOnly)) return passesPlan(m, scene);
  const pass = drawn[0];
  const cleared = new Set(clearOnly.map((p) => p.depth));
  const draw = pass.draws[0];
  const vertex = entryOf(m, pass.vertex);
  const fragment = pass.fragment ? entryOf(m, pass.fragment) : null;
  if (!vertex || !fragment) throw new DrawError('plan', `pass \`${pass.name}\` names an entry point the manifest lacks`);
  checkColourOutput(fragment);
  const { attributes, count, instances } = drawGeometry(vertex, draw);
  const textures = {};
  for (const [sampler, input] of Object.entries(pass.samplers ?? {})) {
    if (cleared.has(input.texture)) {
      const target = (scene.targets ?? []).find((x) => x.name === input.texture);
      textures[sampler] = { depthCleared: true, size: target?.size ?? [64, 64], filter: input.filter ?? 'linear' };
      continue;
    }
    const tex = (scene.textures ?? []).find((x) => x.name === input.texture);
    textures[sampler] = { pattern: tex.pattern, size: tex.size ?? [64, 64], filter: input.filter ?? 'linear', kind: tex.kind ?? '2d', layers: tex.layers ?? 1 };
  }
  return {
    vertex, fragment, attributes,
    count,
    // A point list: each vertex a point (the page's mesh repeats a vertex
    // per triangle; the repeats land on the same pixels).
    points: draw.primitive === 'points',
    instances,
    depth: !!pass.depth,
    cull: pass.cull ?? 'none',
    clear: pass.clear ?? [0, 0, 0, 1],
    values: { ...(scene.values ?? {}), ...(pass.values ?? {}), ...(draw.values ?? {}) },
    textures,
    camera: scene.camera ?? {},
    // The conventions' light and the draw's model (controls.js).
    light: scene.light ?? null,
    transform: draw.transform ?? null,
    controls: scene.controls ?? [],
    entries: [vertex, fragment],
    outputs: colourOutputs(fragment),
  };
}

// A name without its usual prefixes, lower case: `u_Time`, `iTime` -> `time`.
export function bareName(name) {
  return name.replace(/^(u_|i(?=[A-Z])|g_|c_)/, '').toLowerCase();
}

// The convention (umbrac::scene's names) a member of this name and type
// is bound to when no scene says (docs/preview.md), or null.
export function conventionOf(name, t) {
  const n = bareName(name);
  if (!t) return null;
  if (t.cols === 4 && t.rows === 4) {
    if (/^(mvp|modelviewproj(ection)?|model_view_proj(ection)?|wvp)$/.test(n)) return 'model_view_projection';
    if (/^(view_?proj(ection)?|vp|camera)$/.test(n)) return 'view_projection';
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

function conventionsByName(m) {
  const out = {};
  for (const b of m.uniform_buffers ?? []) {
    for (const x of b.members) {
      const c = conventionOf(x.name, parseType(x.type));
      if (c) out[x.name] = c;
    }
  }
  return out;
}

// The made-up plan: the program on a full-screen quad (a lone fragment
// entry point: the page's full-screen triangle), values by name.
function madeUpPlan(m, programIndex) {
  const prog = m.programs[programIndex];
  let vertex = null;
  let fragment;
  if (prog) {
    vertex = entryOf(m, prog.vertex);
    fragment = entryOf(m, prog.fragment);
  } else {
    fragment = m.entry_points.find((e) => e.stage === 'fragment');
  }
  if (!fragment) throw new DrawError('plan', 'the program has no fragment entry point to draw');
  checkColourOutput(fragment);
  const attributes = [];
  if (vertex) {
    for (const a of vertex.inputs) {
      const t = parseType(a.type);
      if (!t || t.cols) throw new DrawError('plan', `the preview cannot make up vertex attribute \`${a.name} : ${a.type}\``);
      const kind = madeUp(a.name, t);
      const data = QUAD.flatMap((p) => madeUpValues(kind, t.n, p));
      attributes.push({ name: a.name, glsl_name: a.glsl_name ?? a.name, location: a.glsl_location ?? a.location, wgsl_location: a.location, type: t, format: a.vertex_format, perInstance: false, data });
    }
  }
  const entries = [vertex, fragment].filter(Boolean);
  const textures = {};
  for (const s of m.samplers ?? []) textures[s.name] = { pattern: 'checker', size: [64, 64], filter: 'linear' };
  return {
    vertex, fragment, attributes, count: vertex ? QUAD.length : 3, instances: 1, depth: false, cull: 'none', clear: [0, 0, 0, 1],
    values: conventionsByName(m), textures, camera: {}, controls: [], entries, outputs: colourOutputs(fragment),
  };
}

// ---- uniform values -----------------------------------------------------

// One Uint32Array per uniform buffer of the manifest, holding its
// defaults ({ name -> words }).
export function uniformBuffers(manifest) {
  const out = {};
  for (const b of manifest.uniform_buffers ?? []) {
    const words = new Uint32Array(Math.ceil(b.size / 4));
    for (const m of b.members) if (m.default) words.set(m.default, m.offset / 4);
    out[b.name] = words;
  }
  return out;
}

// The words of `values` (numbers, a matrix column by column) at a member.
export function writeMember(words, member, values) {
  // An array (a light's matrices): its elements one after another, at the array stride.
  const arr = /^(.+)\[(\d+)\]$/.exec(member.type);
  if (arr && member.array_stride) {
    const n = parseType(arr[1])?.n ?? 0;
    for (let k = 0; k < +arr[2]; k++) writeMember(words, { ...member, type: arr[1], offset: member.offset + k * member.array_stride }, values.slice(k * n, (k + 1) * n));
    return;
  }
  const t = parseType(member.type);
  if (!t) return;
  const f = new Float32Array(words.buffer, words.byteOffset, words.length);
  const i = new Int32Array(words.buffer, words.byteOffset, words.length);
  const base = member.offset / 4;
  const put = (at, v) => {
    if (t.scalar === 'float') f[at] = v;
    else if (t.scalar === 'bool') words[at] = v ? 1 : 0;
    else if (t.scalar === 'int') i[at] = v;
    else words[at] = v >>> 0;
  };
  if (t.cols) {
    const stride = (member.matrix_stride ?? 16) / 4;
    for (let c = 0; c < t.cols; c++) for (let r = 0; r < t.rows; r++) put(base + c * stride + r, values[c * t.rows + r]);
  } else for (let k = 0; k < t.n; k++) put(base + k, values[k]);
}

// The leaves of a struct member (or an array of structs) as members of
// their own: `u_instances[3].color` at its byte offset in the buffer, as
// the native runner's scene values name them (docs/runner.md, "Inference").
export function structLeaves(manifest, m) {
  const out = [];
  const struct = (n) => (manifest.structs ?? []).find((s) => s.name === n);
  const walk = (name, type, offset, arrayStride, matrixStride) => {
    const arr = /^(.*)\[(\d+)\]$/.exec(type);
    if (arr && struct(arr[1])) {
      const stride = arrayStride ?? Math.ceil(struct(arr[1]).size / 16) * 16;
      for (let i = 0; i < +arr[2]; i++) walk(`${name}[${i}]`, arr[1], offset + i * stride);
    } else if (!arr && struct(type)) {
      for (const x of struct(type).members) walk(`${name}.${x.name}`, x.type, offset + x.offset, x.array_stride, x.matrix_stride);
    } else if (name !== m.name) out.push({ name, type, offset, array_stride: arrayStride, matrix_stride: matrixStride });
  };
  walk(m.name, m.type, m.offset, m.array_stride, m.matrix_stride);
  return out;
}

// A member's values read back from the words (matrices column by column).
export function readMember(words, member) {
  const t = parseType(member.type);
  const f = new Float32Array(words.buffer, words.byteOffset, words.length);
  const i = new Int32Array(words.buffer, words.byteOffset, words.length);
  const base = member.offset / 4;
  const get = (at) => (t.scalar === 'float' ? f[at] : t.scalar === 'int' ? i[at] : words[at]);
  const out = [];
  if (t.cols) {
    const stride = (member.matrix_stride ?? 16) / 4;
    for (let c = 0; c < t.cols; c++) for (let r = 0; r < t.rows; r++) out.push(get(base + c * stride + r));
  } else for (let k = 0; k < t.n; k++) out.push(get(base + k));
  return out;
}

// What this preview cannot bind yet, named, rather than drawn wrong.
export function refuseUnsupported(m, plan) {
  const entries = plan.entries;
  const used = new Set(entries.flatMap((e) => [...(e.uniform_buffers ?? []), ...(e.samplers ?? []), ...(e.storage_buffers ?? []), ...(e.images ?? [])]));
  for (const s of m.samplers ?? []) {
    if (!used.has(s.name) || plan.passes) continue;
    const depth = plan.textures[s.name]?.depthCleared;
    const kind = depth ? '2d' : plan.textures[s.name]?.kind ?? '2d';
    if (kindOf(s.dimension) !== kind || s.array_size || (depth ? !s.comparison : s.comparison || s.sample_type !== 'float')) {
      throw new DrawError('plan', `the preview binds built-in colour textures (2D, cube, 3D, 2D array) and cleared 2D depth targets only; \`${s.name} : ${s.type}\` is not one here`);
    }
  }
  for (const b of m.uniform_buffers ?? []) {
    if (used.has(b.name) && b.push_constant) throw new DrawError('plan', `the preview does not bind push constants (\`${b.name}\`)`);
  }
  for (const key of ['storage_buffers', 'images']) {
    for (const b of m[key] ?? []) if (used.has(b.name)) throw new DrawError('plan', `the preview does not bind ${key.replace('_', ' ')} (\`${b.name}\`)`);
  }
}

// ---- WebGL2 -------------------------------------------------------------

function glslVaryingType(t) {
  const s = { float: 'float', int: 'int', uint: 'uint', bool: 'bool' }[t.scalar];
  if (t.n === 1) return s;
  return { float: 'vec', int: 'ivec', uint: 'uvec', bool: 'bvec' }[t.scalar] + t.n;
}

// The vertex shader a lone fragment entry point is drawn with.
function glslFullScreen(fragment) {
  const lines = ['#version 300 es', 'precision highp float;', 'precision highp int;'];
  const body = [];
  for (const v of fragment.inputs) {
    const t = parseType(v.type);
    if (!t || t.cols) throw new DrawError('plan', `the preview cannot make up varying \`${v.name} : ${v.type}\``);
    const flat = t.scalar !== 'float' || v.interpolation === 'flat';
    lines.push(`${flat ? 'flat ' : ''}out ${glslVaryingType(t)} ${v.glsl_name ?? v.name};`);
    body.push(`  ${v.glsl_name ?? v.name} = ${glslVaryingType(t)}(${madeUpExprs(madeUp(v.name, t), t).join(', ')});`);
  }
  lines.push('void main() {', '  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);', ...body, '  gl_Position = vec4(p, 0.0, 1.0);', '}');
  return lines.join('\n') + '\n';
}

export function fileOf(bundle, entry, target) {
  const name = entry.files[target];
  const f = bundle.files.find((x) => x.name === name);
  if (!f) throw new DrawError('plan', `the bundle lacks ${name}, the ${target} output of \`${entry.name}\``);
  return f.text;
}

// The depth view's shaders (a full-screen triangle, each pixel its depth
// texel as grey, raised to the 32nd power: a perspective depth buffer is
// nearly all above 0.9).
export const DEPTH_VIEW_GLSL = [
  '#version 300 es\nvoid main() { gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0); }\n',
  '#version 300 es\nprecision highp float;\nuniform highp sampler2D depth_view;\nout vec4 colour;\nvoid main() { float z = pow(texelFetch(depth_view, ivec2(gl_FragCoord.xy), 0).r, 32.0); colour = vec4(vec3(z), 1.0); }\n',
];

export const DEPTH_VIEW_WGSL = `
@group(0) @binding(0) var depth_view: texture_depth_2d;
@vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
  return vec4<f32>(select(-1.0, 3.0, i == 1u), select(-1.0, 3.0, i == 2u), 0.0, 1.0);
}
@fragment fn fs(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
  let z = pow(textureLoad(depth_view, vec2<i32>(p.xy), 0), 32.0);
  return vec4<f32>(vec3<f32>(z), 1.0);
}
`;

// The uniform blocks (bound to their points) and loose uniforms of a
// linked `program` that `used` names; `program` is in use.
export function glUniformsOf(gl, program, m, used) {
  const blocks = [];
  const loose = [];
  for (const b of m.uniform_buffers ?? []) {
    if (!used.has(b.name) && !(b.loose && b.members.some((x) => used.has(x.name)))) continue;
    if (b.glsl_block) {
      const index = gl.getUniformBlockIndex(program, b.glsl_block);
      if (index === gl.INVALID_INDEX) continue; // dropped by the driver
      gl.uniformBlockBinding(program, index, b.glsl_binding);
      const size = Math.max(b.size, gl.getActiveUniformBlockParameter(program, index, gl.UNIFORM_BLOCK_DATA_SIZE));
      blocks.push({ name: b.name, point: b.glsl_binding, size, ubo: gl.createBuffer() });
    } else {
      for (const x of b.members) {
        // An array of numbers, vectors or matrices is set whole: its elements
        // read at the array stride.
        const arr = /^(.+)\[(\d+)\]$/.exec(x.type);
        const t = parseType(arr ? arr[1] : x.type);
        const loc = gl.getUniformLocation(program, x.glsl_name ?? x.name);
        if (loc === null) {
          // A struct (an array of them): each leaf by its GLSL path.
          for (const leaf of structLeaves(m, x)) {
            const at = gl.getUniformLocation(program, (x.glsl_name ?? x.name) + leaf.name.slice(x.name.length));
            const lt = parseType(leaf.type);
            if (at !== null && lt) loose.push({ buffer: b.name, elements: [leaf], t: lt, loc: at });
          }
          continue;
        }
        if (!t) throw new DrawError('plan', `the preview does not set the loose uniform \`${x.name} : ${x.type}\` on WebGL2 yet`);
        const elements = arr ? Array.from({ length: +arr[2] }, (_, k) => ({ ...x, type: arr[1], offset: x.offset + k * x.array_stride })) : [x];
        loose.push({ buffer: b.name, elements, t, loc });
      }
    }
  }
  return { blocks, loose };
}

// Sets them from the words of each uniform buffer.
export function setGLUniforms(gl, { blocks, loose }, buffers) {
  for (const b of blocks) {
    const bytes = new Uint8Array(b.size);
    bytes.set(new Uint8Array(buffers[b.name].buffer, buffers[b.name].byteOffset, Math.min(b.size, buffers[b.name].byteLength)));
    gl.bindBuffer(gl.UNIFORM_BUFFER, b.ubo);
    gl.bufferData(gl.UNIFORM_BUFFER, bytes, gl.DYNAMIC_DRAW);
    gl.bindBufferBase(gl.UNIFORM_BUFFER, b.point, b.ubo);
  }
  for (const u of loose) {
    const v = u.elements.flatMap((e) => readMember(buffers[u.buffer], e));
    const { t, loc } = u;
    if (t.cols) {
      const fn = t.cols === t.rows ? `uniformMatrix${t.cols}fv` : `uniformMatrix${t.cols}x${t.rows}fv`;
      gl[fn](loc, false, new Float32Array(v));
    } else if (t.scalar === 'float') gl[`uniform${t.n}fv`](loc, new Float32Array(v));
    else if (t.scalar === 'uint') gl[`uniform${t.n}uiv`](loc, new Uint32Array(v));
    else gl[`uniform${t.n}iv`](loc, new Int32Array(v));
  }
}

class WebGL2Renderer {
  constructor(canvas) {
    this.api = 'webgl2';
    this.canvas = canvas;
    const gl = canvas.getContext('webgl2', { antialias: false, alpha: false, depth: true, preserveDrawingBuffer: true });
    if (!gl) throw new DrawError('api', 'this browser gives no WebGL2 context');
    this.gl = gl;
    this.loaded = null;
  }

  describe() {
    const gl = this.gl;
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    return gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER);
  }

  compile(type, file, source) {
    const gl = this.gl;
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
      const log = gl.getShaderInfoLog(s).trim();
      gl.deleteShader(s);
      throw new DrawError('compile', `${file} does not compile on WebGL2: ${log}`);
    }
    return s;
  }

  load(bundle, plan) {
    if (plan.passes) return this.loadPasses(bundle, plan);
    const gl = this.gl;
    const m = bundle.manifest;
    refuseUnsupported(m, plan);
    const vsText = plan.vertex ? fileOf(bundle, plan.vertex, 'gles300') : glslFullScreen(plan.fragment);
    const vs = this.compile(gl.VERTEX_SHADER, plan.vertex ? plan.vertex.files.gles300 : 'the full-screen vertex shader', vsText);
    const fs = this.compile(gl.FRAGMENT_SHADER, plan.fragment.files.gles300, fileOf(bundle, plan.fragment, 'gles300'));
    const program = gl.createProgram();
    gl.attachShader(program, vs);
    gl.attachShader(program, fs);
    for (const a of plan.attributes) if (a.location !== null && a.location !== undefined) gl.bindAttribLocation(program, a.location, a.glsl_name);
    gl.linkProgram(program);
    gl.deleteShader(vs);
    gl.deleteShader(fs);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
      const log = gl.getProgramInfoLog(program).trim();
      gl.deleteProgram(program);
      throw new DrawError('link', `the program does not link on WebGL2: ${log}`);
    }
    const used = new Set(plan.entries.flatMap((e) => [...e.uniform_buffers, ...e.uniforms, ...e.samplers]));
    gl.useProgram(program);
    const { blocks, loose } = glUniformsOf(gl, program, m, used);
    const samplers = [];
    for (const s of m.samplers ?? []) {
      const loc = gl.getUniformLocation(program, s.glsl_name);
      if (loc === null) continue;
      gl.uniform1i(loc, s.texture_unit);
      const texture = gl.createTexture();
      const depth = plan.textures[s.name]?.depthCleared ? plan.textures[s.name] : null;
      if (depth) {
        // The cleared depth target: every texel 1, compared LEQUAL.
        const [w, h] = depth.size;
        gl.bindTexture(gl.TEXTURE_2D, texture);
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.DEPTH_COMPONENT32F, w, h, 0, gl.DEPTH_COMPONENT, gl.FLOAT, new Float32Array(w * h).fill(1));
        const filter = depth.filter === 'nearest' ? gl.NEAREST : gl.LINEAR;
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_COMPARE_MODE, gl.COMPARE_REF_TO_TEXTURE);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_COMPARE_FUNC, gl.LEQUAL);
        gl.bindTexture(gl.TEXTURE_2D, null);
      }
      samplers.push({ name: s.name, unit: s.texture_unit, texture, kind: depth ? '2d' : plan.textures[s.name]?.kind ?? '2d' });
    }
    gl.useProgram(null);
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const vbos = [];
    for (const a of plan.attributes) {
      const loc = gl.getAttribLocation(program, a.glsl_name);
      if (loc < 0) continue;
      if (a.type.scalar !== 'float') {
        gl.disableVertexAttribArray(loc);
        continue; // a constant 0, the default attribute value
      }
      const vbo = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(a.data), gl.STATIC_DRAW);
      gl.enableVertexAttribArray(loc);
      gl.vertexAttribPointer(loc, a.type.n, gl.FLOAT, false, 0, 0);
      gl.vertexAttribDivisor(loc, a.perInstance ? 1 : 0);
      vbos.push(vbo);
    }
    gl.bindVertexArray(null);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
    this.unload();
    this.loaded = { program, blocks, loose, samplers, vao, vbos, plan, textureOf: new Map(), targets: null };
  }

  // A scene of several passes, targets or draws (passes.js).
  async loadPasses(bundle, plan) {
    refuseUnsupported(bundle.manifest, plan);
    const passes = await GLPasses.load(this, bundle, plan);
    this.unload();
    this.loaded = { passes, plan };
  }

  unload() {
    const l = this.loaded;
    if (!l) return;
    const gl = this.gl;
    if (l.passes) {
      l.passes.destroy();
      this.loaded = null;
      return;
    }
    gl.deleteProgram(l.program);
    gl.deleteVertexArray(l.vao);
    l.vbos.forEach((b) => gl.deleteBuffer(b));
    l.blocks.forEach((b) => gl.deleteBuffer(b.ubo));
    l.samplers.forEach((s) => gl.deleteTexture(s.texture));
    this.dropTargets(l);
    this.loaded = null;
  }

  dropTargets(l) {
    const gl = this.gl;
    if (!l.targets) return;
    gl.deleteFramebuffer(l.targets.fbo);
    l.targets.textures.forEach((t) => gl.deleteTexture(t));
    gl.deleteTexture(l.targets.depth);
    l.targets = null;
  }

  // A program with several colour outputs draws into a texture for each
  // (and a depth buffer of its own); the one viewed is copied to the canvas.
  mrtTargets(l) {
    const gl = this.gl;
    const { width, height } = this.canvas;
    if (l.targets && l.targets.width === width && l.targets.height === height) return l.targets;
    this.dropTargets(l);
    const fbo = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    const textures = [];
    const buffers = [];
    const top = Math.max(...l.plan.outputs.map((o) => o.location));
    for (let loc = 0; loc <= top; loc++) {
      if (!l.plan.outputs.some((o) => o.location === loc)) {
        buffers.push(gl.NONE);
        continue;
      }
      const t = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, t);
      gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, width, height);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + loc, gl.TEXTURE_2D, t, 0);
      textures.push(t);
      buffers.push(gl.COLOR_ATTACHMENT0 + loc);
    }
    // A depth texture: viewable as grey (`view` 'depth').
    const depth = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, depth);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.DEPTH_COMPONENT24, width, height);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.TEXTURE_2D, depth, 0);
    gl.drawBuffers(buffers);
    gl.bindTexture(gl.TEXTURE_2D, null);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    l.targets = { fbo, textures, depth, width, height };
    return l.targets;
  }

  // The depth texture as grey on the canvas (z^32: near dark, far white).
  showDepth(texture) {
    const gl = this.gl;
    if (!this.depthProgram) {
      const vs = this.compile(gl.VERTEX_SHADER, 'the depth view', DEPTH_VIEW_GLSL[0]);
      const fs = this.compile(gl.FRAGMENT_SHADER, 'the depth view', DEPTH_VIEW_GLSL[1]);
      const p = gl.createProgram();
      gl.attachShader(p, vs);
      gl.attachShader(p, fs);
      gl.linkProgram(p);
      gl.deleteShader(vs);
      gl.deleteShader(fs);
      this.depthProgram = p;
      this.depthVao = gl.createVertexArray();
    }
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.CULL_FACE);
    gl.useProgram(this.depthProgram);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.uniform1i(gl.getUniformLocation(this.depthProgram, 'depth_view'), 0);
    gl.bindVertexArray(this.depthVao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
    gl.bindTexture(gl.TEXTURE_2D, null);
    gl.useProgram(null);
  }

  frame(inputs) {
    const l = this.loaded;
    if (!l) return;
    if (l.passes) {
      l.passes.frame(inputs, this.view);
      return;
    }
    const { buffers, textures } = inputs;
    const gl = this.gl;
    const { plan } = l;
    const depthView = this.view === 'depth' && plan.depth;
    const mrt = plan.outputs.length > 1 || depthView ? this.mrtTargets(l) : null;
    gl.bindFramebuffer(gl.FRAMEBUFFER, mrt ? mrt.fbo : null);
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    gl.clearColor(...plan.clear);
    gl.clearDepth(1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    if (plan.depth) {
      gl.enable(gl.DEPTH_TEST);
      gl.depthFunc(gl.LESS);
    } else gl.disable(gl.DEPTH_TEST);
    if (plan.cull === 'none') gl.disable(gl.CULL_FACE);
    else {
      gl.enable(gl.CULL_FACE);
      gl.frontFace(gl.CCW);
      gl.cullFace(plan.cull === 'front' ? gl.FRONT : gl.BACK);
    }
    gl.useProgram(l.program);
    setGLUniforms(gl, l, buffers);
    for (const s of l.samplers) {
      const img = textures[s.name];
      gl.activeTexture(gl.TEXTURE0 + s.unit);
      gl.bindTexture(glTarget(gl, s.kind), s.texture);
      if (img && l.textureOf.get(s.name) !== img) {
        glUpload(gl, s.texture, { ...img, kind: s.kind });
        l.textureOf.set(s.name, img);
      }
    }
    gl.activeTexture(gl.TEXTURE0);
    gl.bindVertexArray(l.vao);
    gl.drawArraysInstanced(plan.points ? gl.POINTS : gl.TRIANGLES, 0, plan.count, plan.instances);
    gl.bindVertexArray(null);
    gl.useProgram(null);
    if (depthView) {
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      this.showDepth(mrt.depth);
    } else if (mrt) {
      const { width, height } = this.canvas;
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, mrt.fbo);
      gl.readBuffer(gl.COLOR_ATTACHMENT0 + (this.view ?? plan.outputs[0].location));
      gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
      gl.blitFramebuffer(0, 0, width, height, 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    }
    const err = gl.getError();
    if (err !== gl.NO_ERROR) throw new DrawError('api', `WebGL error ${err}`);
  }

  async read() {
    const gl = this.gl;
    const { width, height } = this.canvas;
    const px = new Uint8Array(width * height * 4);
    gl.pixelStorei(gl.PACK_ALIGNMENT, 1);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, px);
    return px;
  }
}

// ---- WebGPU -------------------------------------------------------------

function wgslType(t) {
  const s = { float: 'f32', int: 'i32', uint: 'u32' }[t.scalar];
  if (!s) throw new DrawError('plan', 'a bool varying cannot cross stages in WGSL');
  return t.n === 1 ? s : `vec${t.n}<${s}>`;
}

// A vertex entry point appended to the module for a lone fragment entry
// point: its varyings at their locations, the clip-space adaptation of
// umbrac's portable conventions (y flipped, so rows come out as GL's).
function wgslFullScreen(fragment) {
  const fields = ['  @builtin(position) umbrac_preview_position: vec4<f32>,'];
  const body = [];
  for (const v of fragment.inputs) {
    const t = parseType(v.type);
    if (!t || t.cols) throw new DrawError('plan', `the preview cannot make up varying \`${v.name} : ${v.type}\``);
    const flat = t.scalar !== 'float' || v.interpolation === 'flat';
    const interp = flat ? ' @interpolate(flat)' : v.interpolation === 'linear' ? ' @interpolate(linear)' : '';
    fields.push(`  @location(${v.location})${interp} umbrac_preview_${v.location}: ${wgslType(t)},`);
    body.push(`  o.umbrac_preview_${v.location} = ${wgslType(t)}(${madeUpExprs(madeUp(v.name, t), t).join(', ')});`);
  }
  return `
struct UmbracPreviewVaryings {
${fields.join('\n')}
}

@vertex
fn umbrac_preview_vs(@builtin(vertex_index) i: u32) -> UmbracPreviewVaryings {
  let p = vec2<f32>(select(-1.0, 3.0, i == 1u), select(-1.0, 3.0, i == 2u));
  var o: UmbracPreviewVaryings;
${body.join('\n')}
  o.umbrac_preview_position = vec4<f32>(p.x, -p.y, 0.5, 1.0);
  return o;
}
`;
}

// One rgba8unorm target per colour output location; none at a gap.
function colourTargets(plan) {
  const top = Math.max(0, ...plan.outputs.map((o) => o.location));
  return Array.from({ length: top + 1 }, (_, loc) => (plan.outputs.some((o) => o.location === loc) ? { format: 'rgba8unorm' } : null));
}

class WebGPURenderer {
  static async create(canvas) {
    if (!navigator.gpu) throw new DrawError('api', 'this browser has no WebGPU (navigator.gpu)');
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter) throw new DrawError('api', 'this browser offers no WebGPU adapter');
    const device = await adapter.requestDevice();
    const r = new WebGPURenderer(canvas, adapter, device);
    return r;
  }

  constructor(canvas, adapter, device) {
    this.api = 'webgpu';
    this.canvas = canvas;
    this.adapter = adapter;
    this.device = device;
    // The picture is drawn offscreen, read back and put in a 2D canvas: in
    // headless chromium 156 (SwiftShader) a configured WebGPU canvas
    // context makes every later mapAsync fail ("A valid external Instance
    // reference no longer exists"), so no frame could be compared.
    this.context = canvas.getContext('2d');
    if (!this.context) throw new DrawError('api', 'the canvas gives no 2D context to show the WebGPU picture in');
    this.busy = false;
    this.loaded = null;
    this.lost = null;
    device.lost.then((i) => { this.lost = i.message; });
  }

  describe() {
    const i = this.adapter.info ?? {};
    return [i.vendor, i.architecture, i.description].filter(Boolean).join(' / ') || 'WebGPU';
  }

  async load(bundle, plan) {
    const device = this.device;
    const m = bundle.manifest;
    refuseUnsupported(m, plan);
    if (plan.passes) {
      // A scene of several passes, targets or draws (passes.js).
      const passes = await GPUPasses.load(this, bundle, plan);
      this.unload();
      this.loaded = { passes, plan };
      return;
    }
    const wgsl = bundle.files.find((f) => f.target === 'wgsl');
    if (!wgsl) throw new DrawError('plan', 'the bundle has no WGSL output');
    const code = plan.vertex ? wgsl.text : wgsl.text + wgslFullScreen(plan.fragment);
    device.pushErrorScope('validation');
    const module = device.createShaderModule({ code });
    const info = await module.getCompilationInfo();
    const errors = info.messages.filter((x) => x.type === 'error');
    await device.popErrorScope();
    if (errors.length) throw new DrawError('compile', `${wgsl.name} does not compile on WebGPU: ${errors.map((e) => `${e.lineNum}:${e.linePos}: ${e.message}`).join('\n')}`);

    const used = new Set(plan.entries.flatMap((e) => [...e.uniform_buffers, ...e.uniforms, ...e.samplers]));
    const vis = GPUShaderStage.VERTEX | GPUShaderStage.FRAGMENT;
    const groups = [];
    const group = (g) => (groups[g] ??= []);
    const buffers = [];
    for (const b of m.uniform_buffers ?? []) {
      if (!used.has(b.name) && !(b.loose && b.members.some((x) => used.has(x.name)))) continue;
      const size = Math.max(16, Math.ceil(b.size / 16) * 16);
      const buffer = device.createBuffer({ size, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
      group(b.group).push({ layout: { binding: b.binding, visibility: vis, buffer: { type: 'uniform' } }, resource: { buffer } });
      buffers.push({ name: b.name, buffer, size });
    }
    const samplers = [];
    for (const s of m.samplers ?? []) {
      if (!used.has(s.name)) continue;
      const depth = plan.textures[s.name]?.depthCleared ? plan.textures[s.name] : null;
      let entry;
      if (depth) {
        // The cleared depth target: a depth32float texture a pass clears to 1, compared less-equal.
        const texture = device.createTexture({ size: depth.size, format: 'depth32float', usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.RENDER_ATTACHMENT });
        const enc = device.createCommandEncoder();
        enc.beginRenderPass({ colorAttachments: [], depthStencilAttachment: { view: texture.createView(), depthClearValue: 1, depthLoadOp: 'clear', depthStoreOp: 'store' } }).end();
        device.queue.submit([enc.finish()]);
        const f = depth.filter === 'nearest' ? 'nearest' : 'linear';
        entry = { name: s.name, texture, sampler: device.createSampler({ compare: 'less-equal', magFilter: f, minFilter: f }), image: null, fixed: true };
        group(s.group).push({ layout: { binding: s.texture_binding, visibility: vis, texture: { sampleType: 'depth', viewDimension: '2d' } }, texture: entry });
        group(s.group).push({ layout: { binding: s.sampler_binding, visibility: vis, sampler: { type: 'comparison' } }, sampler: entry });
      } else {
        const kind = plan.textures[s.name]?.kind ?? '2d';
        const made = gpuTexture(device, null, kind);
        entry = { name: s.name, texture: made.texture, view: made.view, kind, sampler: this.sampler('linear', kind), image: null };
        group(s.group).push({ layout: { binding: s.texture_binding, visibility: vis, texture: { sampleType: 'float', viewDimension: viewDimension(kind) } }, texture: entry });
        group(s.group).push({ layout: { binding: s.sampler_binding, visibility: vis, sampler: { type: 'filtering' } }, sampler: entry });
      }
      samplers.push(entry);
    }
    const layouts = [];
    for (let g = 0; g < groups.length; g++) layouts.push(device.createBindGroupLayout({ entries: (groups[g] ?? []).map((e) => e.layout) }));

    const vertexBuffers = [];
    const vbos = [];
    for (const a of plan.attributes) {
      const t = a.type;
      const format = (a.format ?? `Float32x${t.n}`).toLowerCase().replace(/x1$/, '');
      const data = t.scalar === 'float' ? new Float32Array(a.data) : new Int32Array(a.data.length);
      const buf = device.createBuffer({ size: Math.max(16, data.byteLength), usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
      device.queue.writeBuffer(buf, 0, data);
      vbos.push(buf);
      vertexBuffers.push({ arrayStride: 4 * t.n, stepMode: a.perInstance ? 'instance' : 'vertex', attributes: [{ shaderLocation: a.wgsl_location, offset: 0, format }] });
    }
    device.pushErrorScope('validation');
    const pipeline = device.createRenderPipeline({
      layout: device.createPipelineLayout({ bindGroupLayouts: layouts }),
      vertex: { module, entryPoint: plan.vertex ? plan.vertex.name : 'umbrac_preview_vs', buffers: vertexBuffers },
      fragment: { module, entryPoint: plan.fragment.name, targets: colourTargets(plan) },
      // umbrac's portable WGSL flips y, so GL's counter-clockwise fronts arrive clockwise.
      primitive: { topology: plan.points ? 'point-list' : 'triangle-list', frontFace: 'cw', cullMode: plan.cull ?? 'none' },
      depthStencil: plan.depth ? { format: 'depth24plus', depthWriteEnabled: true, depthCompare: 'less' } : undefined,
    });
    const err = await device.popErrorScope();
    if (err) throw new DrawError('link', `the WebGPU pipeline is refused: ${err.message}`);
    this.unload();
    this.loaded = { pipeline, groups, layouts, buffers, samplers, vbos, plan, bindGroups: null };
  }

  unload() {
    const l = this.loaded;
    if (!l) return;
    if (l.passes) {
      l.passes.destroy();
      this.loaded = null;
      return;
    }
    l.buffers.forEach((b) => b.buffer.destroy());
    l.samplers.forEach((s) => s.texture.destroy());
    l.vbos.forEach((b) => b.destroy());
    this.loaded = null;
  }

  sampler(filter, kind = '2d') {
    const f = filter === 'nearest' ? 'nearest' : 'linear';
    // 2D textures repeat; the other kinds clamp, as the native runner's.
    const a = kind === '2d' ? 'repeat' : 'clamp-to-edge';
    return this.device.createSampler({ magFilter: f, minFilter: f, addressModeU: a, addressModeV: a, addressModeW: a });
  }

  bindGroups() {
    const l = this.loaded;
    return l.layouts.map((layout, g) => this.device.createBindGroup({
      layout,
      entries: (l.groups[g] ?? []).map((e) => ({ binding: e.layout.binding, resource: e.texture ? (e.texture.view ? e.texture.view() : e.texture.texture.createView()) : e.sampler ? e.sampler.sampler : e.resource })),
    }));
  }

  frame({ buffers, textures, conventions }, readback = null) {
    const l = this.loaded;
    if (!l) return;
    if (this.lost) throw new DrawError('api', `the WebGPU device was lost: ${this.lost}`);
    if (!readback) {
      // Shown when read back; a frame that comes while one is read is dropped.
      if (this.busy) return;
      this.busy = true;
      this.read({ buffers, textures, conventions }).then((px) => this.present(px), (e) => { this.lost ??= e.message; }).finally(() => { this.busy = false; });
      return;
    }
    if (l.passes) {
      l.passes.frame({ buffers, textures, conventions }, this.view, readback);
      return;
    }
    const device = this.device;
    for (const b of l.buffers) {
      const bytes = new Uint8Array(b.size);
      const w = buffers[b.name];
      bytes.set(new Uint8Array(w.buffer, w.byteOffset, Math.min(b.size, w.byteLength)));
      device.queue.writeBuffer(b.buffer, 0, bytes);
    }
    let rebind = !l.bindGroups;
    for (const s of l.samplers) {
      const img = textures[s.name];
      if (!img || s.fixed || s.image === img) continue;
      s.texture.destroy();
      const made = gpuTexture(device, { ...img, kind: s.kind ?? '2d' });
      [s.texture, s.view] = [made.texture, made.view];
      s.sampler = this.sampler(img.filter, s.kind);
      s.image = img;
      rebind = true;
    }
    if (rebind) l.bindGroups = this.bindGroups();
    // Every colour output is drawn; the one viewed is read back.
    const depthView = this.view === 'depth' && l.plan.depth;
    const view = depthView || this.view === null || this.view === undefined || this.view === 'depth' ? l.plan.outputs[0].location : this.view;
    const others = colourTargets(l.plan).map((t, loc) => (t && (loc !== view || depthView) ? device.createTexture({ size: [readback.texture.width, readback.texture.height], format: 'rgba8unorm', usage: GPUTextureUsage.RENDER_ATTACHMENT }) : null));
    const target = readback.texture;
    const enc = device.createCommandEncoder();
    const depth = l.plan.depth ? device.createTexture({ size: [target.width, target.height], format: 'depth24plus', usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.TEXTURE_BINDING }) : null;
    const pass = enc.beginRenderPass({
      colorAttachments: colourTargets(l.plan).map((t, loc) => (t ? { view: (others[loc] ?? target).createView(), loadOp: 'clear', storeOp: 'store', clearValue: l.plan.clear } : null)),
      depthStencilAttachment: depth ? { view: depth.createView(), depthClearValue: 1, depthLoadOp: 'clear', depthStoreOp: depthView ? 'store' : 'discard' } : undefined,
    });
    pass.setPipeline(l.pipeline);
    l.bindGroups.forEach((g, i) => pass.setBindGroup(i, g));
    l.vbos.forEach((b, i) => pass.setVertexBuffer(i, b));
    pass.draw(l.plan.count, l.plan.instances);
    pass.end();
    if (depthView) {
      this.depthPipeline ??= device.createRenderPipeline({
        layout: 'auto',
        vertex: { module: device.createShaderModule({ code: DEPTH_VIEW_WGSL }), entryPoint: 'vs' },
        fragment: { module: device.createShaderModule({ code: DEPTH_VIEW_WGSL }), entryPoint: 'fs', targets: [{ format: 'rgba8unorm' }] },
      });
      const group = device.createBindGroup({ layout: this.depthPipeline.getBindGroupLayout(0), entries: [{ binding: 0, resource: depth.createView() }] });
      const show = enc.beginRenderPass({ colorAttachments: [{ view: target.createView(), loadOp: 'clear', storeOp: 'store', clearValue: [0, 0, 0, 1] }] });
      show.setPipeline(this.depthPipeline);
      show.setBindGroup(0, group);
      show.draw(3);
      show.end();
    }
    if (readback) {
      enc.copyTextureToBuffer({ texture: target }, { buffer: readback.buffer, bytesPerRow: readback.bytesPerRow }, [target.width, target.height]);
    }
    device.queue.submit([enc.finish()]);
    depth?.destroy();
    others.forEach((t) => t?.destroy());
  }

  // Rows bottom first (GL's order) into the 2D canvas, top first.
  present(px) {
    const { width, height } = this.canvas;
    const img = this.context.createImageData(width, height);
    for (let y = 0; y < height; y++) img.data.set(px.subarray((height - 1 - y) * width * 4, (height - y) * width * 4), y * width * 4);
    this.context.putImageData(img, 0, 0);
  }

  // Draws a frame into a texture of its own and reads it back.
  async read(inputs) {
    const { width, height } = this.canvas;
    const bytesPerRow = Math.ceil((width * 4) / 256) * 256;
    const buffer = this.device.createBuffer({ size: bytesPerRow * height, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
    const texture = this.device.createTexture({ size: [width, height], format: 'rgba8unorm', usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC });
    this.frame(inputs, { buffer, bytesPerRow, texture });
    await buffer.mapAsync(GPUMapMode.READ);
    const src = new Uint8Array(buffer.getMappedRange());
    const px = new Uint8Array(width * height * 4);
    // Memory row 0 holds the bottom of the GL picture (the y flip): already GL's order.
    for (let y = 0; y < height; y++) px.set(src.subarray(y * bytesPerRow, y * bytesPerRow + width * 4), y * width * 4);
    buffer.unmap();
    buffer.destroy();
    texture.destroy();
    return px;
  }
}

// A renderer of `api` ('webgl2' or 'webgpu') on `canvas`; throws
// DrawError('api') where the browser has none.
export async function createRenderer(canvas, api) {
  if (api === 'webgl2') {
    const r = new WebGL2Renderer(canvas);
    const read = r.read.bind(r);
    r.read = async (inputs) => {
      if (inputs) r.frame(inputs);
      return read();
    };
    return r;
  }
  if (api === 'webgpu') return WebGPURenderer.create(canvas);
  throw new DrawError('api', `unknown API ${api}`);
}

// The share of pixels whose channels differ by more than `tolerance`
// (0..255) between two RGBA images of one size, and the worst channel difference.
export function compare(a, b, tolerance = 2) {
  let differ = 0;
  let worst = 0;
  for (let i = 0; i < a.length; i += 4) {
    let d = 0;
    for (let c = 0; c < 3; c++) d = Math.max(d, Math.abs(a[i + c] - b[i + c]));
    if (d > tolerance) differ++;
    worst = Math.max(worst, d);
  }
  return { share: differ / (a.length / 4), differ, worst, tolerance };
}

// One picture of a bundle in a fresh renderer: the convenience the
// playground's one-shot view wants. `inputs` defaults to the manifest's
// default uniform values and checker textures.
export async function draw(bundle, canvas, { api = 'webgl2', inputs = null } = {}) {
  const r = await createRenderer(canvas, api);
  const plan = planOf(bundle);
  await r.load(bundle, plan);
  const textures = {};
  for (const [s, t] of Object.entries(plan.textures)) textures[s] = { ...texels(t.pattern, t), filter: t.filter };
  const given = inputs ?? { buffers: uniformBuffers(bundle.manifest), textures };
  r.frame(given);
  return r;
}
