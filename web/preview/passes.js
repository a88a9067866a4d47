// Scenes of several passes, render targets and draws (docs/runner.md,
// "Scene files"), drawn as the native runner's scene plans are
// (src/render/plan/scene_file.rs): the passes in order, each into the
// screen or a target (cleared first; depth test LESS, writes, cleared to
// 1), each draw with its own mesh, instance grid, values and transform
// (its model conventions; the light's from the scene's `light`), samplers
// reading patterns, image files (served by `umbrac preview` under
// scene/NAME) or targets drawn earlier. The target `output` names is
// shown; `view = 'depth'` shows the depth target of the last pass into it.
//
// draw.js's renderers hand a plan with `passes` (passesPlan) to GLPasses
// (WebGL2) or GPUPasses (WebGPU); one pass of one draw to the screen stays
// draw.js's own path (it keeps the MRT output menu).

import {
  DrawError, parseType, writeMember, entryOf, fileOf, drawGeometry, colourOutputs, glUniformsOf, setGLUniforms, DEPTH_VIEW_WGSL,
} from './draw.js';
import { pattern, conventions, drawConventions, conventionValue, fitValue } from './scene.js';

// ---- the plan -----------------------------------------------------------

const isDepthFormat = (f) => f !== 'rgba8';

// Whether a scene needs this file: more than one drawn pass, a pass into
// a target, more than one draw, or a sampler that reads what is neither a
// pattern nor a depth target no pass draws into (draw.js's cleared one).
export function needsPasses(scene, drawn, clearOnly) {
  const cleared = new Set(clearOnly.map((p) => p.depth));
  const pattern = (name) => (scene.textures ?? []).some((t) => t.name === name && t.pattern);
  return drawn.length !== 1 || drawn[0].color !== 'screen' || (scene.output ?? 'screen') !== 'screen' || drawn[0].draws.length !== 1
    || Object.values(drawn[0].samplers ?? {}).some((i) => !cleared.has(i.texture) && !pattern(i.texture));
}

// The member of a uniform buffer (or a loose uniform) named `name`, its
// type an array's whole (`float4x4[3]`: n = 48) where it is one.
function memberOf(m, name) {
  for (const b of m.uniform_buffers ?? []) {
    const member = b.members.find((x) => x.name === name);
    if (!member) continue;
    const arr = /^(.+)\[(\d+)\]$/.exec(member.type);
    const elem = parseType(arr ? arr[1] : member.type);
    const t = arr && elem && member.array_stride ? { ...elem, n: elem.n * +arr[2], array: +arr[2] } : arr ? null : elem;
    return { buffer: b.name, member, t };
  }
  return null;
}

// Whether a scene value names a convention: its name, or one element of
// an array convention ({ convention, index }).
const isConvention = (spec) => typeof spec === 'string' || (!!spec && typeof spec === 'object' && !Array.isArray(spec));

// A scene value's numbers for a member of type `t` in `conv` (a draw's
// conventions): a number fills every component, as the native runner's
// scene values (src/render/plan/scene_file.rs).
function valueOf(spec, t, conv) {
  if (isConvention(spec)) return conventionValue(spec, conv);
  if (typeof spec === 'boolean') return [spec ? 1 : 0];
  if (typeof spec === 'number') return Array(t.n).fill(spec);
  return spec;
}

// The plan of a scene for draw.js's renderers: every pass with its
// program's entry points, samplers and draws checked against the manifest.
export function passesPlan(m, scene) {
  const targets = (scene.targets ?? []).map((t) => ({ name: t.name, format: t.format, size: t.size ?? null }));
  const targetOf = (name) => targets.find((t) => t.name === name);
  const output = scene.output ?? 'screen';
  if (output !== 'screen' && isDepthFormat(targetOf(output).format)) {
    throw new DrawError('plan', `the preview shows colour; \`output = "${output}"\` names a depth target`);
  }
  const perDraw = new Set();
  // Every convention with the scene's light, to check the names against.
  const known = conventions({}, { time: 0, frame: 0, width: 4, height: 4, mouse: null }, scene.light ?? null);
  const checkValues = (values, where) => {
    for (const [name, spec] of Object.entries(values ?? {})) {
      const at = memberOf(m, name);
      if (!at) throw new DrawError('plan', `${where} sets \`${name}\`, which is no uniform of the program`);
      if (!at.t) throw new DrawError('plan', `${where} sets \`${name} : ${at.member.type}\`, which the preview cannot write`);
      if (isConvention(spec) && !conventionValue(spec, known)) {
        const what = typeof spec === 'string' ? `the convention \`${spec}\`` : `element ${spec.index} of \`${spec.convention}\``;
        throw new DrawError('plan', `${where} sets \`${name}\` to ${what}, which the preview does not compute`);
      }
      perDraw.add(name);
    }
  };
  checkValues(scene.values, 'the scene');
  perDraw.clear(); // the scene's own values are the controls' (controls.js)
  const images = new Set();
  const patterns = {};
  const passes = scene.passes.map((p) => {
    const vertex = entryOf(m, p.vertex);
    const fragment = p.fragment ? entryOf(m, p.fragment) : null;
    if (!vertex || vertex.stage !== 'vertex') throw new DrawError('plan', `pass \`${p.name}\`: the program has no vertex entry point \`${p.vertex}\``);
    if (p.fragment && (!fragment || fragment.stage !== 'fragment')) throw new DrawError('plan', `pass \`${p.name}\`: the program has no fragment entry point \`${p.fragment}\``);
    if (!p.color && !p.depth) throw new DrawError('plan', `pass \`${p.name}\` draws into nothing (no \`color\`, no \`depth\`)`);
    // `color`: one name, or a list (output location i -> the i-th target).
    const colors = p.color == null ? [] : Array.isArray(p.color) ? p.color : [p.color];
    const entries = [vertex, fragment].filter(Boolean);
    const samplers = [];
    for (const [name, input] of Object.entries(p.samplers ?? {})) {
      const decl = (m.samplers ?? []).find((s) => s.name === name);
      if (!decl) throw new DrawError('plan', `pass \`${p.name}\` binds sampler \`${name}\`, which the program does not declare`);
      const target = targetOf(input.texture);
      const texture = (scene.textures ?? []).find((t) => t.name === input.texture);
      const depth = !!target && isDepthFormat(target.format);
      if (decl.dimension !== '2d' || decl.array_size) throw new DrawError('plan', `the preview binds 2D textures to scene samplers; \`${name} : ${decl.type}\` is not one`);
      if (decl.comparison && !depth) throw new DrawError('plan', `pass \`${p.name}\`: the comparison sampler \`${name}\` reads \`${input.texture}\`, which is not a depth target`);
      if (!depth && decl.sample_type !== 'float') throw new DrawError('plan', `pass \`${p.name}\`: \`${name} : ${decl.type}\` reads colour as ${decl.sample_type}; the preview's textures are float`);
      if (target && (colors.includes(target.name) || target.name === p.depth)) throw new DrawError('plan', `pass \`${p.name}\` samples \`${target.name}\`, which it draws into`);
      const source = target ? { target: target.name, depth } : texture.pattern ? { pattern: texture.pattern, size: texture.size ?? [64, 64] } : { image: texture.image };
      if (source.image) images.add(source.image);
      const filter = input.filter ?? 'linear';
      if (source.pattern) patterns[name] ??= { pattern: source.pattern, size: source.size, filter };
      samplers.push({ name, decl, source, filter, compare: !!decl.comparison });
    }
    const used = new Set(entries.flatMap((e) => e.samplers ?? []));
    for (const s of used) {
      if (!samplers.some((x) => x.name === s)) throw new DrawError('plan', `pass \`${p.name}\`'s program reads sampler \`${s}\`, which the pass binds to nothing (its \`samplers\`)`);
    }
    checkValues(p.values, `pass \`${p.name}\``);
    const draws = p.draws.map((d, i) => {
      checkValues(d.values, `draw ${i + 1} of pass \`${p.name}\``);
      if (d.primitive === 'points') throw new DrawError('plan', `draw ${i + 1} of pass \`${p.name}\` is of points, which the preview draws in scenes of one pass and one draw only`);
      return { ...drawGeometry(vertex, d), values: d.values ?? {}, transform: d.transform ?? null };
    });
    if (fragment) {
      colors.forEach((c, i) => {
        if (!colourOutputs(fragment).some((o) => o.location === i)) throw new DrawError('plan', `pass \`${p.name}\` draws colour into \`${c}\`, and \`${fragment.name}\` has no float colour output at location ${i}`);
      });
    }
    return {
      name: p.name, vertex, fragment, entries, color: colors[0] ?? null, colors, depth: p.depth ?? null, clear: p.clear ?? [0, 0, 0, 1],
      cull: p.cull ?? 'none', depthBias: !!p.depth_bias, samplers, values: p.values ?? {}, draws,
    };
  });
  // The depth view: the depth target of the last pass into the output.
  const last = [...passes].reverse().find((p) => (p.color ?? null) === output || p.colors.includes(output));
  const entries = [...new Set(passes.flatMap((p) => p.entries))];
  return {
    passes, targets, output, images: [...images], viewDepth: last?.depth ?? null,
    vertex: null, fragment: null, attributes: [], count: 0, instances: 1,
    depth: !!last?.depth, cull: 'none', clear: [0, 0, 0, 1],
    values: scene.values ?? {}, perDraw, textures: patterns, camera: scene.camera ?? {}, controls: scene.controls ?? [], entries,
    light: scene.light ?? null,
    // The scene's values that name conventions: each draw's own (its transform's model).
    sceneConventions: Object.entries(scene.values ?? {}).filter(([, spec]) => isConvention(spec)),
    outputs: [{ name: output, location: 0 }],
  };
}

// A draw's words of each uniform buffer: the frame's (controls and the
// scene's values), the scene's conventions again with the draw's
// transform, then the pass's values, then the draw's.
function drawWords(m, plan, base, conv, pass, draw) {
  const out = {};
  for (const [name, words] of Object.entries(base)) out[name] = words.slice();
  const own = drawConventions(conv, draw.transform, conv.time[0]);
  for (const [name, spec] of [...plan.sceneConventions, ...Object.entries(pass.values), ...Object.entries(draw.values)]) {
    const { buffer, member, t } = memberOf(m, name);
    writeMember(out[buffer], member, fitValue(valueOf(spec, t, own), t));
  }
  return out;
}

// The frame's conventions with the scene's light; the playground's
// one-shot draw gives none.
function conventionsOf(inputs, plan, width, height) {
  return inputs.conventions ?? conventions(plan.camera, { time: 0, frame: 0, width, height, mouse: null }, plan.light);
}

// The scene's image files, fetched from the preview server (scene/NAME):
// RGBA8, the image's top row first (as the native runner uploads them).
async function loadImages(names) {
  const out = {};
  for (const name of names) {
    let r;
    try {
      r = await fetch(`scene/${name.split('/').map(encodeURIComponent).join('/')}`, { cache: 'no-store' });
    } catch (e) {
      throw new DrawError('plan', `image \`${name}\`: ${e.message}`);
    }
    if (!r.ok) throw new DrawError('plan', `image \`${name}\`: HTTP ${r.status}: ${(await r.text()).trim()}`);
    const bitmap = await createImageBitmap(await r.blob(), { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
    const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
    const ctx = canvas.getContext('2d');
    ctx.drawImage(bitmap, 0, 0);
    const px = ctx.getImageData(0, 0, bitmap.width, bitmap.height);
    out[name] = { width: bitmap.width, height: bitmap.height, data: new Uint8Array(px.data.buffer) };
  }
  return out;
}

// A target's size: its own, else the output's (the canvas').
const sizeOf = (t, width, height) => t.size ?? [width, height];

// The texels a sampler with a pattern source reads: the frame's (the
// user may pick another pattern or a file), else the scene's.
function patternTexels(cache, inputs, s) {
  const given = inputs.textures?.[s.name];
  if (given) return given;
  const key = `${s.source.pattern}:${s.source.size.join('x')}`;
  if (!cache.has(key)) cache.set(key, pattern(s.source.pattern, s.source.size[0], s.source.size[1]));
  return cache.get(key);
}

// ---- WebGL2 -------------------------------------------------------------

const GL_EMPTY_FRAGMENT = '#version 300 es\nprecision highp float;\nvoid main() {}\n';

function glFormat(gl, format) {
  switch (format) {
    case 'rgba8': return gl.RGBA8;
    case 'depth32float': return gl.DEPTH_COMPONENT32F;
    case 'depth24plus': return gl.DEPTH_COMPONENT24;
    case 'depth16': return gl.DEPTH_COMPONENT16;
    default: throw new DrawError('plan', `the preview has no target format ${format}`);
  }
}

export class GLPasses {
  static async load(r, bundle, plan) {
    const images = await loadImages(plan.images);
    return new GLPasses(r, bundle, plan, images);
  }

  constructor(r, bundle, plan, images) {
    this.r = r;
    const gl = (this.gl = r.gl);
    this.plan = plan;
    this.m = bundle.manifest;
    this.programs = new Map();
    this.passes = [];
    this.made = []; // GL objects to delete: [kind, object]
    this.uploaded = new Map(); // texels object -> texture
    this.patterns = new Map();
    this.targets = null;
    try {
      for (const pass of plan.passes) {
        const key = `${pass.vertex.name}|${pass.fragment?.name ?? ''}`;
        if (!this.programs.has(key)) this.programs.set(key, this.link(bundle, pass));
        const program = this.programs.get(key);
        const vaos = pass.draws.map((d) => this.vao(program.program, d));
        this.passes.push({ pass, program, vaos });
      }
      this.images = {};
      for (const [name, img] of Object.entries(images)) this.images[name] = this.upload(img);
      this.samplerObjects = new Map();
    } catch (e) {
      this.destroy();
      throw e;
    }
    gl.bindVertexArray(null);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
  }

  link(bundle, pass) {
    const gl = this.gl;
    const r = this.r;
    const vs = r.compile(gl.VERTEX_SHADER, pass.vertex.files.gles300, fileOf(bundle, pass.vertex, 'gles300'));
    const fs = pass.fragment
      ? r.compile(gl.FRAGMENT_SHADER, pass.fragment.files.gles300, fileOf(bundle, pass.fragment, 'gles300'))
      // A depth-only pass: ES links no program without a fragment shader.
      : r.compile(gl.FRAGMENT_SHADER, 'the empty fragment shader', GL_EMPTY_FRAGMENT);
    const program = gl.createProgram();
    this.made.push(['program', program]);
    gl.attachShader(program, vs);
    gl.attachShader(program, fs);
    for (const a of pass.vertex.inputs) {
      const loc = a.glsl_location ?? a.location;
      if (loc !== null && loc !== undefined) gl.bindAttribLocation(program, loc, a.glsl_name ?? a.name);
    }
    gl.linkProgram(program);
    gl.deleteShader(vs);
    gl.deleteShader(fs);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
      throw new DrawError('link', `pass \`${pass.name}\`'s program does not link on WebGL2: ${gl.getProgramInfoLog(program).trim()}`);
    }
    const used = new Set(pass.entries.flatMap((e) => [...e.uniform_buffers, ...e.uniforms, ...e.samplers]));
    gl.useProgram(program);
    const uniforms = glUniformsOf(gl, program, this.m, used);
    uniforms.blocks.forEach((b) => this.made.push(['buffer', b.ubo]));
    for (const s of pass.samplers) {
      const loc = gl.getUniformLocation(program, s.decl.glsl_name);
      if (loc !== null) gl.uniform1i(loc, s.decl.texture_unit);
    }
    gl.useProgram(null);
    return { program, uniforms };
  }

  vao(program, draw) {
    const gl = this.gl;
    const vao = gl.createVertexArray();
    this.made.push(['vao', vao]);
    gl.bindVertexArray(vao);
    for (const a of draw.attributes) {
      const loc = gl.getAttribLocation(program, a.glsl_name);
      if (loc < 0 || a.type.scalar !== 'float') continue;
      const vbo = gl.createBuffer();
      this.made.push(['buffer', vbo]);
      gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(a.data), gl.STATIC_DRAW);
      gl.enableVertexAttribArray(loc);
      gl.vertexAttribPointer(loc, a.type.n, gl.FLOAT, false, 0, 0);
      gl.vertexAttribDivisor(loc, a.perInstance ? 1 : 0);
    }
    gl.bindVertexArray(null);
    return vao;
  }

  upload(img) {
    const gl = this.gl;
    const t = gl.createTexture();
    this.made.push(['texture', t]);
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, img.width, img.height, 0, gl.RGBA, gl.UNSIGNED_BYTE, img.data);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.bindTexture(gl.TEXTURE_2D, null);
    return t;
  }

  // Linear or nearest, clamped to the edge (as the native runner's), a
  // comparison LEQUAL for a shadow sampler.
  sampler(s) {
    const key = `${s.filter}:${s.compare}:${!!s.source.depth}`;
    if (this.samplerObjects.has(key)) return this.samplerObjects.get(key);
    const gl = this.gl;
    const o = gl.createSampler();
    this.made.push(['sampler', o]);
    // A depth texture is filterable only through a comparison.
    const filter = s.filter === 'nearest' || (s.source.depth && !s.compare) ? gl.NEAREST : gl.LINEAR;
    gl.samplerParameteri(o, gl.TEXTURE_MIN_FILTER, filter);
    gl.samplerParameteri(o, gl.TEXTURE_MAG_FILTER, filter);
    gl.samplerParameteri(o, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.samplerParameteri(o, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    if (s.compare) {
      gl.samplerParameteri(o, gl.TEXTURE_COMPARE_MODE, gl.COMPARE_REF_TO_TEXTURE);
      gl.samplerParameteri(o, gl.TEXTURE_COMPARE_FUNC, gl.LEQUAL);
    }
    this.samplerObjects.set(key, o);
    return o;
  }

  // The targets at the canvas' size (made again when it changes); `screen`
  // is a texture too, shown (blitted) when `output` names it.
  ensureTargets() {
    const gl = this.gl;
    const { width, height } = this.r.canvas;
    if (this.targets && this.targets.width === width && this.targets.height === height) return this.targets;
    this.dropTargets();
    const made = {};
    for (const t of [{ name: 'screen', format: 'rgba8', size: null }, ...this.plan.targets]) {
      const [w, h] = sizeOf(t, width, height);
      const tex = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, tex);
      gl.texStorage2D(gl.TEXTURE_2D, 1, glFormat(gl, t.format), w, h);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      made[t.name] = { texture: tex, width: w, height: h, depth: isDepthFormat(t.format) };
    }
    gl.bindTexture(gl.TEXTURE_2D, null);
    this.targets = { width, height, made, fbo: gl.createFramebuffer() };
    return this.targets;
  }

  dropTargets() {
    if (!this.targets) return;
    const gl = this.gl;
    Object.values(this.targets.made).forEach((t) => gl.deleteTexture(t.texture));
    gl.deleteFramebuffer(this.targets.fbo);
    this.targets = null;
  }

  frame(inputs, view) {
    const gl = this.gl;
    const { made, fbo } = this.ensureTargets();
    const conv = conventionsOf(inputs, this.plan, this.r.canvas.width, this.r.canvas.height);
    gl.disable(gl.BLEND);
    gl.frontFace(gl.CCW);
    gl.depthFunc(gl.LESS);
    gl.depthMask(true);
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    for (const { pass, program, vaos } of this.passes) {
      const colours = pass.colors.map((c) => made[c]);
      const colour = colours[0] ?? null;
      const depth = pass.depth ? made[pass.depth] : null;
      // One framebuffer for every pass: attachment i is location i's target,
      // those an earlier pass left beyond this pass's list are detached.
      for (let i = 0; i < Math.max(colours.length, this.attached ?? 1); i++) {
        gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, gl.TEXTURE_2D, colours[i]?.texture ?? null, 0);
      }
      this.attached = colours.length;
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.TEXTURE_2D, depth?.texture ?? null, 0);
      gl.drawBuffers(colours.length ? colours.map((_, i) => gl.COLOR_ATTACHMENT0 + i) : [gl.NONE]);
      const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
      if (status !== gl.FRAMEBUFFER_COMPLETE) throw new DrawError('api', `pass \`${pass.name}\`: incomplete framebuffer (${status})`);
      const drawn = colour ?? depth;
      gl.viewport(0, 0, drawn.width, drawn.height);
      colours.forEach((_, i) => gl.clearBufferfv(gl.COLOR, i, new Float32Array(pass.clear)));
      if (depth) {
        gl.enable(gl.DEPTH_TEST);
        gl.clearDepth(1);
        gl.clear(gl.DEPTH_BUFFER_BIT);
      } else gl.disable(gl.DEPTH_TEST);
      if (pass.cull === 'none') gl.disable(gl.CULL_FACE);
      else {
        gl.enable(gl.CULL_FACE);
        gl.cullFace(pass.cull === 'front' ? gl.FRONT : gl.BACK);
      }
      // The native runner's shadow bias: factor 2, units 4.
      if (pass.depthBias) {
        gl.enable(gl.POLYGON_OFFSET_FILL);
        gl.polygonOffset(2.0, 4.0);
      } else gl.disable(gl.POLYGON_OFFSET_FILL);
      gl.useProgram(program.program);
      for (const s of pass.samplers) {
        const unit = s.decl.texture_unit;
        let texture;
        if (s.source.target) texture = made[s.source.target].texture;
        else if (s.source.image) texture = this.images[s.source.image];
        else {
          const texels = patternTexels(this.patterns, inputs, s);
          if (!this.uploaded.has(texels)) this.uploaded.set(texels, this.upload(texels));
          texture = this.uploaded.get(texels);
        }
        gl.activeTexture(gl.TEXTURE0 + unit);
        gl.bindTexture(gl.TEXTURE_2D, texture);
        gl.bindSampler(unit, this.sampler(s));
      }
      pass.draws.forEach((d, i) => {
        setGLUniforms(gl, program.uniforms, drawWords(this.m, this.plan, inputs.buffers, conv, pass, d));
        gl.bindVertexArray(vaos[i]);
        gl.drawArraysInstanced(gl.TRIANGLES, 0, d.count, d.instances);
      });
      gl.bindVertexArray(null);
      // Unbound, so that a later pass may draw into what this one read.
      for (const s of pass.samplers) {
        gl.activeTexture(gl.TEXTURE0 + s.decl.texture_unit);
        gl.bindTexture(gl.TEXTURE_2D, null);
        gl.bindSampler(s.decl.texture_unit, null);
      }
      gl.activeTexture(gl.TEXTURE0);
      gl.useProgram(null);
    }
    gl.disable(gl.POLYGON_OFFSET_FILL);
    gl.disable(gl.CULL_FACE);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.TEXTURE_2D, null, 0);
    const { width, height } = this.r.canvas;
    if (view === 'depth' && this.plan.viewDepth) {
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      this.r.showDepth(made[this.plan.viewDepth].texture);
    } else {
      const out = made[this.plan.output];
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, out.texture, 0);
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, fbo);
      gl.readBuffer(gl.COLOR_ATTACHMENT0);
      gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
      gl.blitFramebuffer(0, 0, out.width, out.height, 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    const err = gl.getError();
    if (err !== gl.NO_ERROR) throw new DrawError('api', `WebGL error ${err}`);
  }

  destroy() {
    const gl = this.gl;
    this.dropTargets();
    const del = { program: 'deleteProgram', buffer: 'deleteBuffer', vao: 'deleteVertexArray', texture: 'deleteTexture', sampler: 'deleteSampler' };
    for (const [kind, o] of this.made) gl[del[kind]](o);
    this.made = [];
  }
}

// ---- WebGPU -------------------------------------------------------------

const GPU_FORMATS = { rgba8: 'rgba8unorm', depth32float: 'depth32float', depth24plus: 'depth24plus', depth16: 'depth16unorm' };

// Copies the output (any size) onto the picture read back; both are
// GL's way up in memory (umbrac's portable WGSL flips y).
const BLIT_WGSL = `
@group(0) @binding(0) var src: texture_2d<f32>;
@group(0) @binding(1) var smp: sampler;
struct V { @builtin(position) p: vec4<f32>, @location(0) uv: vec2<f32> }
@vertex fn vs(@builtin(vertex_index) i: u32) -> V {
  let p = vec2<f32>(select(-1.0, 3.0, i == 1u), select(-1.0, 3.0, i == 2u));
  return V(vec4<f32>(p, 0.0, 1.0), vec2<f32>(p.x * 0.5 + 0.5, 0.5 - p.y * 0.5));
}
@fragment fn fs(v: V) -> @location(0) vec4<f32> { return textureSampleLevel(src, smp, v.uv, 0.0); }
`;

export class GPUPasses {
  static async load(r, bundle, plan) {
    const device = r.device;
    const m = bundle.manifest;
    const wgsl = bundle.files.find((f) => f.target === 'wgsl');
    if (!wgsl) throw new DrawError('plan', 'the bundle has no WGSL output');
    device.pushErrorScope('validation');
    const module = device.createShaderModule({ code: wgsl.text });
    const info = await module.getCompilationInfo();
    const errors = info.messages.filter((x) => x.type === 'error');
    await device.popErrorScope();
    if (errors.length) throw new DrawError('compile', `${wgsl.name} does not compile on WebGPU: ${errors.map((e) => `${e.lineNum}:${e.linePos}: ${e.message}`).join('\n')}`);
    const images = await loadImages(plan.images);
    const p = new GPUPasses(r, m, plan, module, images);
    device.pushErrorScope('validation');
    try {
      p.build();
    } finally {
      const err = await device.popErrorScope();
      if (err) {
        p.destroy();
        throw new DrawError('link', `the WebGPU pipelines are refused: ${err.message}`);
      }
    }
    return p;
  }

  constructor(r, m, plan, module, images) {
    this.r = r;
    this.device = r.device;
    this.m = m;
    this.plan = plan;
    this.module = module;
    this.images = images;
    this.owned = []; // buffers and textures to destroy
    this.uploaded = new Map();
    this.patterns = new Map();
    this.targets = null;
  }

  build() {
    const device = this.device;
    const vis = GPUShaderStage.VERTEX | GPUShaderStage.FRAGMENT;
    for (const [name, img] of Object.entries(this.images)) this.images[name] = this.upload(img);
    this.passes = this.plan.passes.map((pass) => {
      const used = new Set(pass.entries.flatMap((e) => [...e.uniform_buffers, ...e.uniforms, ...e.samplers]));
      const groups = [];
      const group = (g) => (groups[g] ??= []);
      const buffers = (this.m.uniform_buffers ?? []).filter((b) => used.has(b.name) || (b.loose && b.members.some((x) => used.has(x.name))));
      for (const b of buffers) group(b.group).push({ binding: b.binding, visibility: vis, buffer: { type: 'uniform' } });
      for (const s of pass.samplers) {
        if (!used.has(s.name)) continue;
        // A depth target: compared, or read as unfilterable floats.
        const [sampleType, type] = s.source.depth ? (s.compare ? ['depth', 'comparison'] : ['unfilterable-float', 'non-filtering']) : ['float', 'filtering'];
        group(s.decl.group).push({ binding: s.decl.texture_binding, visibility: vis, texture: { sampleType, viewDimension: '2d' }, of: s });
        group(s.decl.group).push({ binding: s.decl.sampler_binding, visibility: vis, sampler: { type }, of: s });
      }
      const layouts = Array.from({ length: groups.length }, (_, g) => device.createBindGroupLayout({
        entries: (groups[g] ?? []).map(({ binding, visibility, buffer, texture, sampler }) => ({ binding, visibility, ...(buffer ? { buffer } : texture ? { texture } : { sampler }) })),
      }));
      const layout = device.createPipelineLayout({ bindGroupLayouts: layouts });
      const pipelines = new Map();
      const draws = pass.draws.map((d) => {
        const vertexBuffers = [];
        const vbos = [];
        for (const a of d.attributes) {
          const format = (a.format ?? `Float32x${a.type.n}`).toLowerCase().replace(/x1$/, '');
          const data = a.type.scalar === 'float' ? new Float32Array(a.data) : new Int32Array(a.data.length);
          const buf = this.buffer(Math.max(16, data.byteLength), GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST);
          device.queue.writeBuffer(buf, 0, data);
          vbos.push(buf);
          vertexBuffers.push({ arrayStride: 4 * a.type.n, stepMode: a.perInstance ? 'instance' : 'vertex', attributes: [{ shaderLocation: a.wgsl_location, offset: 0, format }] });
        }
        const key = vertexBuffers.map((v) => `${v.stepMode}${v.attributes[0].format}`).join();
        if (!pipelines.has(key)) pipelines.set(key, this.pipeline(pass, layout, vertexBuffers));
        const uniforms = buffers.map((b) => ({ b, size: Math.max(16, Math.ceil(b.size / 16) * 16) }));
        uniforms.forEach((u) => { u.buffer = this.buffer(u.size, GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST); });
        return { d, vbos, pipeline: pipelines.get(key), uniforms };
      });
      return { pass, groups, layouts, draws };
    });
  }

  pipeline(pass, layout, buffers) {
    const depth = pass.depth ? this.plan.targets.find((t) => t.name === pass.depth) : null;
    return this.device.createRenderPipeline({
      layout,
      vertex: { module: this.module, entryPoint: pass.vertex.name, buffers },
      fragment: pass.fragment ? { module: this.module, entryPoint: pass.fragment.name, targets: pass.colors.map(() => ({ format: 'rgba8unorm' })) } : undefined,
      // umbrac's portable WGSL flips y, so GL's counter-clockwise fronts arrive clockwise.
      primitive: { topology: 'triangle-list', frontFace: 'cw', cullMode: pass.cull },
      depthStencil: depth ? {
        format: GPU_FORMATS[depth.format], depthWriteEnabled: true, depthCompare: 'less',
        // The native runner's shadow bias: constant 4, slope 2.
        ...(pass.depthBias ? { depthBias: 4, depthBiasSlopeScale: 2 } : {}),
      } : undefined,
    });
  }

  buffer(size, usage) {
    const b = this.device.createBuffer({ size, usage });
    this.owned.push(b);
    return b;
  }

  upload(img) {
    const t = this.device.createTexture({ size: [img.width, img.height], format: 'rgba8unorm', usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    this.device.queue.writeTexture({ texture: t }, img.data, { bytesPerRow: img.width * 4 }, [img.width, img.height]);
    this.owned.push(t);
    return t;
  }

  samplerOf(s) {
    const f = s.filter === 'nearest' || (s.source.depth && !s.compare) ? 'nearest' : 'linear';
    return this.device.createSampler({ magFilter: f, minFilter: f, addressModeU: 'clamp-to-edge', addressModeV: 'clamp-to-edge', ...(s.compare ? { compare: 'less-equal' } : {}) });
  }

  ensureTargets(width, height) {
    if (this.targets && this.targets.width === width && this.targets.height === height) return this.targets.made;
    this.dropTargets();
    const made = {};
    for (const t of [{ name: 'screen', format: 'rgba8', size: null }, ...this.plan.targets]) {
      const [w, h] = sizeOf(t, width, height);
      const texture = this.device.createTexture({ size: [w, h], format: GPU_FORMATS[t.format], usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.TEXTURE_BINDING });
      made[t.name] = { texture, width: w, height: h };
    }
    this.targets = { width, height, made };
    return made;
  }

  dropTargets() {
    if (!this.targets) return;
    Object.values(this.targets.made).forEach((t) => t.texture.destroy());
    this.targets = null;
  }

  frame(inputs, view, readback) {
    const device = this.device;
    const target = readback.texture;
    const made = this.ensureTargets(target.width, target.height);
    const conv = conventionsOf(inputs, this.plan, target.width, target.height);
    const enc = device.createCommandEncoder();
    for (const { pass, groups, layouts, draws } of this.passes) {
      const depth = pass.depth ? made[pass.depth] : null;
      const rp = enc.beginRenderPass({
        colorAttachments: pass.colors.map((c) => ({ view: made[c].texture.createView(), loadOp: 'clear', storeOp: 'store', clearValue: pass.clear })),
        depthStencilAttachment: depth ? { view: depth.texture.createView(), depthClearValue: 1, depthLoadOp: 'clear', depthStoreOp: 'store' } : undefined,
      });
      const textureOf = (s) => {
        if (s.source.target) return made[s.source.target].texture;
        if (s.source.image) return this.images[s.source.image];
        const texels = patternTexels(this.patterns, inputs, s);
        if (!this.uploaded.has(texels)) this.uploaded.set(texels, this.upload(texels));
        return this.uploaded.get(texels);
      };
      for (const { d, vbos, pipeline, uniforms } of draws) {
        const words = drawWords(this.m, this.plan, inputs.buffers, conv, pass, d);
        for (const u of uniforms) {
          const bytes = new Uint8Array(u.size);
          const w = words[u.b.name];
          bytes.set(new Uint8Array(w.buffer, w.byteOffset, Math.min(u.size, w.byteLength)));
          device.queue.writeBuffer(u.buffer, 0, bytes);
        }
        rp.setPipeline(pipeline);
        layouts.forEach((layout, g) => {
          const entries = (groups[g] ?? []).map((e) => ({
            binding: e.binding,
            resource: e.buffer ? { buffer: uniforms.find((u) => u.b.group === g && u.b.binding === e.binding).buffer } : e.texture ? textureOf(e.of).createView() : this.samplerOf(e.of),
          }));
          rp.setBindGroup(g, device.createBindGroup({ layout, entries }));
        });
        vbos.forEach((b, i) => rp.setVertexBuffer(i, b));
        rp.draw(d.count, d.instances);
      }
      rp.end();
    }
    // The picture: the output, or the depth view.
    const depthView = view === 'depth' && this.plan.viewDepth;
    const code = depthView ? DEPTH_VIEW_WGSL : BLIT_WGSL;
    this.shows ??= {};
    this.shows[code] ??= device.createRenderPipeline({
      layout: 'auto',
      vertex: { module: device.createShaderModule({ code }), entryPoint: 'vs' },
      fragment: { module: device.createShaderModule({ code }), entryPoint: 'fs', targets: [{ format: 'rgba8unorm' }] },
    });
    const show = this.shows[code];
    const src = made[depthView ? this.plan.viewDepth : this.plan.output].texture.createView();
    const entries = depthView ? [{ binding: 0, resource: src }] : [{ binding: 0, resource: src }, { binding: 1, resource: device.createSampler() }];
    const rp = enc.beginRenderPass({ colorAttachments: [{ view: target.createView(), loadOp: 'clear', storeOp: 'store', clearValue: [0, 0, 0, 1] }] });
    rp.setPipeline(show);
    rp.setBindGroup(0, device.createBindGroup({ layout: show.getBindGroupLayout(0), entries }));
    rp.draw(3);
    rp.end();
    enc.copyTextureToBuffer({ texture: target }, { buffer: readback.buffer, bytesPerRow: readback.bytesPerRow }, [target.width, target.height]);
    device.queue.submit([enc.finish()]);
  }

  destroy() {
    this.dropTargets();
    this.owned.forEach((x) => x.destroy());
    this.owned = [];
  }
}
