// The WebGL2 executor of umbrac's frame plans (src/render/exec/webgl.rs).
//
// data/plan.json is a frame plan with everything bound already resolved
// by umbrac from the program's manifest (src/render/bind/gl.rs, the code
// the native GL executor runs too): for each pass's program, the GLSL
// names of its uniform blocks and their binding points, its samplers and
// their texture units, its attributes and their locations, its uniforms
// set by name; for each draw, every block's words and every uniform's
// value with the call that sets it. This page makes the targets, compiles
// and links the .300es.* files, checks that each linked program has what
// it is told to bind, draws, and reads the target back. It reads no
// manifest and does no math.
//
// The result goes to window.umbracResult: { ok, width, height, pixels
// (base64 of the target read back, rows bottom first), renderer } or
// { ok: false, kind, error, file, pass, log }.

const DATA = 'data/';

class PageError extends Error {
  constructor(kind, message, extra = {}) {
    super(message);
    this.kind = kind;
    Object.assign(this, extra);
  }
}

async function fetchOk(path) {
  const r = await fetch(DATA + path, { cache: 'no-store' });
  if (!r.ok) throw new PageError('api', `fetching ${path}: HTTP ${r.status}`);
  return r;
}

function compile(gl, type, file, source) {
  const s = gl.createShader(type);
  gl.shaderSource(s, source);
  gl.compileShader(s);
  if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
    const log = gl.getShaderInfoLog(s).trim();
    gl.deleteShader(s);
    throw new PageError('compile', `${file} does not compile: ${log}`, { file, log });
  }
  return s;
}

// Texel formats: [internal format, format, type, bytes per texel].
function formatOf(gl, name) {
  switch (name) {
    case 'rgba8': return [gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE, 4];
    case 'rgba32uint': return [gl.RGBA32UI, gl.RGBA_INTEGER, gl.UNSIGNED_INT, 16];
    case 'depth16': return [gl.DEPTH_COMPONENT16, gl.DEPTH_COMPONENT, gl.UNSIGNED_SHORT, 2];
    case 'depth24plus': return [gl.DEPTH_COMPONENT24, gl.DEPTH_COMPONENT, gl.UNSIGNED_INT, 4];
    case 'depth32float': return [gl.DEPTH_COMPONENT32F, gl.DEPTH_COMPONENT, gl.FLOAT, 4];
    default: throw new PageError('api', `unknown target format ${name}`);
  }
}

const isDepth = (name) => name.startsWith('depth');

// A uniform's words as the typed array its call takes.
function uniformData(u) {
  const words = new Uint32Array(u.words);
  if (u.call.endsWith('uiv')) return words;
  if (u.call.endsWith('iv')) return new Int32Array(words.buffer);
  return new Float32Array(words.buffer);
}

async function link(gl, p, sources, meshes) {
  const vs = compile(gl, gl.VERTEX_SHADER, p.vertex, sources[p.vertex]);
  const fs = compile(gl, gl.FRAGMENT_SHADER, p.fragment, sources[p.fragment]);
  const program = gl.createProgram();
  gl.attachShader(program, vs);
  gl.attachShader(program, fs);
  // Attributes the GLSL declares without a location take the manifest's.
  for (const a of p.attributes) {
    if (a.location !== null) gl.bindAttribLocation(program, a.location, a.name);
  }
  gl.linkProgram(program);
  gl.deleteShader(vs);
  gl.deleteShader(fs);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    const log = gl.getProgramInfoLog(program).trim();
    throw new PageError('link', `the ${p.pass} pass's program does not link: ${log}`, { pass: p.pass, log });
  }
  const problems = [];
  const blockSize = {};
  gl.useProgram(program);
  for (const b of p.blocks) {
    const index = gl.getUniformBlockIndex(program, b.name);
    if (index === gl.INVALID_INDEX) {
      problems.push(`uniform block \`${b.name}\` is not in the linked program`);
      continue;
    }
    gl.uniformBlockBinding(program, index, b.point);
    blockSize[b.point] = Math.max(b.size, gl.getActiveUniformBlockParameter(program, index, gl.UNIFORM_BLOCK_DATA_SIZE));
  }
  for (const s of p.samplers) {
    const loc = gl.getUniformLocation(program, s.name);
    if (loc === null) problems.push(`sampler \`${s.name}\` is not in the linked program`);
    else gl.uniform1i(loc, s.unit);
  }
  const locations = {};
  // A driver may drop a uniform the program does not need: not an error.
  for (const name of p.uniforms) {
    const loc = gl.getUniformLocation(program, name);
    if (loc !== null) locations[name] = loc;
  }
  gl.useProgram(null);
  const attributes = [];
  for (const a of p.attributes) {
    const loc = gl.getAttribLocation(program, a.name);
    if (loc < 0) problems.push(`attribute \`${a.name}\` is not in the linked program`);
    else if (a.location !== null && loc !== a.location) {
      problems.push(`attribute \`${a.name}\` is at location ${loc} in the linked program, ${a.location} in the reflection`);
    } else attributes.push({ ...a, location: loc });
  }
  if (problems.length) {
    throw new PageError('program', `the ${p.pass} pass does not match its reflection:\n  - ${problems.join('\n  - ')}`);
  }
  // One vertex array per mesh, and one with no buffers.
  const vaos = { '': gl.createVertexArray() };
  for (const [name, m] of Object.entries(meshes)) {
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, m.vbo);
    for (const a of attributes) {
      gl.enableVertexAttribArray(a.location);
      // Instance records follow the vertices in the same buffer.
      const inst = a.per_instance ? m.instances : null;
      if (inst) gl.vertexAttribPointer(a.location, a.components, gl.FLOAT, false, inst.stride, inst.base + a.offset);
      else gl.vertexAttribPointer(a.location, a.components, gl.FLOAT, false, m.stride, a.offset);
      gl.vertexAttribDivisor(a.location, inst ? 1 : 0);
    }
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, m.ibo);
    gl.bindVertexArray(null);
    vaos[name] = vao;
  }
  return { program, blockSize, locations, vaos };
}

async function main() {
  const plan = await (await fetchOk('plan.json')).json();
  const readTarget = plan.targets[plan.readback];
  const canvas = document.getElementById('view');
  canvas.width = readTarget.width;
  canvas.height = readTarget.height;
  const gl = canvas.getContext('webgl2', { antialias: false, alpha: false, depth: false, preserveDrawingBuffer: true });
  if (!gl) throw new PageError('api', 'this browser gives no WebGL2 context');
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const renderer = gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER);

  const sources = {};
  for (const p of plan.programs) {
    for (const f of [p.vertex, p.fragment]) {
      if (!(f in sources)) sources[f] = await (await fetchOk(f)).text();
    }
  }
  const meshes = {};
  for (const [name, m] of Object.entries(plan.meshes)) {
    const vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(m.vertices), gl.STATIC_DRAW);
    const ibo = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ibo);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint32Array(m.indices), gl.STATIC_DRAW);
    meshes[name] = { vbo, ibo, count: m.indices.length, stride: m.stride, instances: m.instances, mode: m.points ? gl.POINTS : gl.TRIANGLES };
  }
  gl.bindBuffer(gl.ARRAY_BUFFER, null);
  const programs = [];
  for (const p of plan.programs) programs.push(await link(gl, p, sources, meshes));

  // A target's GL texture target: only uploaded textures are other than 2D.
  const kindOf = (t) => ({ cube: gl.TEXTURE_CUBE_MAP, '3d': gl.TEXTURE_3D, '2d-array': gl.TEXTURE_2D_ARRAY })[t.dim] ?? gl.TEXTURE_2D;
  const textures = plan.targets.map((t) => {
    const tex = gl.createTexture();
    const kind = kindOf(t);
    gl.bindTexture(kind, tex);
    const [internal] = formatOf(gl, t.format);
    // A texture the host uploads: rgba8, memory row 0 first, layers (cube
    // faces +x, -x, +y, -y, +z, -z) one after another.
    const bytes = t.contents ? new Uint8Array(t.contents) : null;
    if (kind === gl.TEXTURE_2D || kind === gl.TEXTURE_CUBE_MAP) {
      gl.texStorage2D(kind, 1, internal, t.width, t.height);
      const face = t.width * t.height * 4;
      if (bytes && kind === gl.TEXTURE_2D) gl.texSubImage2D(kind, 0, 0, 0, t.width, t.height, gl.RGBA, gl.UNSIGNED_BYTE, bytes);
      if (bytes && kind === gl.TEXTURE_CUBE_MAP) {
        for (let f = 0; f < 6; f++) gl.texSubImage2D(gl.TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, 0, 0, t.width, t.height, gl.RGBA, gl.UNSIGNED_BYTE, bytes.subarray(f * face, (f + 1) * face));
      }
    } else {
      gl.texStorage3D(kind, 1, internal, t.width, t.height, t.layers);
      if (bytes) gl.texSubImage3D(kind, 0, 0, 0, 0, t.width, t.height, t.layers, gl.RGBA, gl.UNSIGNED_BYTE, bytes);
    }
    gl.texParameteri(kind, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(kind, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.bindTexture(kind, null);
    return tex;
  });
  // `colors`: target indices, output location i -> the i-th.
  const framebuffer = (colors, depth) => {
    const fbo = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    const buffers = colors.map((c, i) => {
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, gl.TEXTURE_2D, textures[c], 0);
      return gl.COLOR_ATTACHMENT0 + i;
    });
    gl.drawBuffers(buffers.length ? buffers : [gl.NONE]);
    gl.readBuffer(buffers.length ? gl.COLOR_ATTACHMENT0 : gl.NONE);
    if (depth !== null) gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.TEXTURE_2D, textures[depth], 0);
    const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
    if (status !== gl.FRAMEBUFFER_COMPLETE) throw new PageError('api', `incomplete framebuffer ${status}`);
    return fbo;
  };
  const sampler = (t) => {
    const s = gl.createSampler();
    const filter = t.linear ? gl.LINEAR : gl.NEAREST;
    gl.samplerParameteri(s, gl.TEXTURE_MIN_FILTER, filter);
    gl.samplerParameteri(s, gl.TEXTURE_MAG_FILTER, filter);
    // WebGL2 has no clamp to border: lookups outside clamp to the edge,
    // or repeat (a scene's pattern texture).
    const wrap = t.repeat ? gl.REPEAT : gl.CLAMP_TO_EDGE;
    gl.samplerParameteri(s, gl.TEXTURE_WRAP_S, wrap);
    gl.samplerParameteri(s, gl.TEXTURE_WRAP_T, wrap);
    gl.samplerParameteri(s, gl.TEXTURE_WRAP_R, wrap);
    if (t.compare) {
      gl.samplerParameteri(s, gl.TEXTURE_COMPARE_MODE, gl.COMPARE_REF_TO_TEXTURE);
      gl.samplerParameteri(s, gl.TEXTURE_COMPARE_FUNC, gl.LEQUAL);
    }
    return s;
  };
  const ubos = {};
  const ubo = (point) => (ubos[point] ??= gl.createBuffer());

  gl.disable(gl.BLEND);
  // Vulkan-dialect code is upside down to GL: its counter-clockwise fronts arrive clockwise.
  gl.frontFace(plan.top_first ? gl.CW : gl.CCW);
  gl.depthFunc(gl.LESS);
  gl.depthMask(true);
  for (const pass of plan.passes) {
    const p = programs[pass.program];
    const colors = pass.color ? [pass.color, ...(pass.more_colors ?? [])] : [];
    const fbo = framebuffer(colors.map((c) => c.target), pass.depth ? pass.depth.target : null);
    const drawn = plan.targets[(pass.color ?? pass.depth).target];
    gl.viewport(0, 0, drawn.width, drawn.height);
    colors.forEach((a, i) => {
      const c = a.clear;
      if (plan.targets[a.target].format === 'rgba32uint') gl.clearBufferuiv(gl.COLOR, i, new Uint32Array(c));
      else gl.clearBufferfv(gl.COLOR, i, new Float32Array(c));
    });
    if (pass.depth) {
      gl.enable(gl.DEPTH_TEST);
      gl.clearDepth(pass.depth.clear);
      gl.clear(gl.DEPTH_BUFFER_BIT);
    } else gl.disable(gl.DEPTH_TEST);
    if (pass.cull === 'none') gl.disable(gl.CULL_FACE);
    else {
      gl.enable(gl.CULL_FACE);
      gl.cullFace(pass.cull === 'front' ? gl.FRONT : gl.BACK);
    }
    if (pass.depth_bias) {
      gl.enable(gl.POLYGON_OFFSET_FILL);
      gl.polygonOffset(2.0, 4.0);
    } else gl.disable(gl.POLYGON_OFFSET_FILL);
    gl.useProgram(p.program);
    const samplers = [];
    for (const t of pass.textures) {
      const s = sampler(t);
      samplers.push(s);
      gl.activeTexture(gl.TEXTURE0 + t.unit);
      gl.bindTexture(kindOf(plan.targets[t.target]), textures[t.target]);
      gl.bindSampler(t.unit, s);
    }
    gl.activeTexture(gl.TEXTURE0);
    for (const d of pass.draws) {
      for (const b of d.blocks) {
        const bytes = new Uint8Array(Math.max(p.blockSize[b.point] ?? 0, 4 * b.words.length));
        const view = new DataView(bytes.buffer);
        b.words.forEach((w, i) => view.setUint32(4 * i, w, true));
        gl.bindBuffer(gl.UNIFORM_BUFFER, ubo(b.point));
        gl.bufferData(gl.UNIFORM_BUFFER, bytes, gl.DYNAMIC_DRAW);
        gl.bindBufferBase(gl.UNIFORM_BUFFER, b.point, ubo(b.point));
      }
      for (const u of d.uniforms) {
        const loc = p.locations[u.name];
        if (loc === undefined) continue;
        if (u.matrix) gl[u.call](loc, false, uniformData(u));
        else gl[u.call](loc, uniformData(u));
      }
      if (d.mesh !== null) {
        gl.bindVertexArray(p.vaos[d.mesh]);
        const m = meshes[d.mesh];
        if (m.instances) gl.drawElementsInstanced(m.mode, m.count, gl.UNSIGNED_INT, 0, m.instances.count);
        else gl.drawElements(m.mode, m.count, gl.UNSIGNED_INT, 0);
      } else {
        gl.bindVertexArray(p.vaos['']);
        gl.drawArrays(gl.TRIANGLES, 0, d.vertices);
      }
      gl.bindVertexArray(null);
    }
    for (const t of pass.textures) {
      gl.activeTexture(gl.TEXTURE0 + t.unit);
      gl.bindTexture(kindOf(plan.targets[t.target]), null);
      gl.bindSampler(t.unit, null);
    }
    gl.activeTexture(gl.TEXTURE0);
    samplers.forEach((s) => gl.deleteSampler(s));
    gl.useProgram(null);
    gl.deleteFramebuffer(fbo);
  }
  gl.disable(gl.POLYGON_OFFSET_FILL);
  gl.disable(gl.CULL_FACE);

  // Read the target from a framebuffer of its own. A colour frame is also
  // copied to the canvas and read back from there: the two must agree.
  if (isDepth(readTarget.format)) throw new PageError('api', 'WebGL2 cannot read depth back');
  const [, format, type, texel] = formatOf(gl, readTarget.format);
  const { width, height } = readTarget;
  const readFbo = framebuffer([plan.readback], null);
  gl.pixelStorei(gl.PACK_ALIGNMENT, 1);
  const integer = readTarget.format === 'rgba32uint';
  const fromFbo = integer ? new Uint32Array(width * height * 4) : new Uint8Array(width * height * texel);
  gl.readPixels(0, 0, width, height, format, type, fromFbo);
  let pixels = new Uint8Array(fromFbo.buffer);
  if (!integer) {
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, readFbo);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
    gl.blitFramebuffer(0, 0, width, height, 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    const fromCanvas = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, fromCanvas);
    // The canvas has no alpha (`alpha: false`): colour is compared, and
    // alpha comes from the framebuffer.
    let mismatched = 0;
    for (let i = 0; i < fromCanvas.length; i++) {
      if (i % 4 === 3) fromCanvas[i] = fromFbo[i];
      else if (fromCanvas[i] !== fromFbo[i]) mismatched++;
    }
    if (mismatched) throw new PageError('api', `the canvas differs from the framebuffer drawn in ${mismatched} bytes`);
    pixels = fromCanvas;
  }
  const err = gl.getError();
  if (err !== gl.NO_ERROR) throw new PageError('api', `WebGL error ${err}`);

  let binary = '';
  for (let i = 0; i < pixels.length; i += 0x8000) binary += String.fromCharCode.apply(null, pixels.subarray(i, i + 0x8000));
  return { ok: true, width, height, pixels: btoa(binary), renderer, version: gl.getParameter(gl.VERSION) };
}

const status = document.getElementById('status');
main().then(
  (r) => { status.textContent = `drawn on ${r.renderer}`; window.umbracResult = r; },
  (e) => {
    status.textContent = `error: ${e.message}`;
    window.umbracResult = { ok: false, kind: e.kind ?? 'api', error: e.message, file: e.file, pass: e.pass, log: e.log };
  },
);
