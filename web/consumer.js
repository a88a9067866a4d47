// The WebGL2 consumer of umbrac's GLSL ES 3.00 output.
//
// Everything bound comes from the reflection manifest: uniform blocks by
// their `glsl_block` names (getUniformBlockIndex + uniformBlockBinding),
// filled at the manifest's member offsets; the shadow sampler by its
// `glsl_name` (getUniformLocation + uniform1i with its `texture_unit`);
// attributes at the manifest's locations. The host values (matrices,
// meshes, sizes) come ready-made in data/scene.json, written by umbrac
// from the same code the other consumers use.
//
// The result goes to window.umbracResult: { ok, width, height, pixels
// (base64 RGBA read back from the canvas, rows bottom first), renderer }
// or { ok: false, error }.

const DATA = 'data/';

async function fetchOk(path) {
  const r = await fetch(DATA + path, { cache: 'no-store' });
  if (!r.ok) throw new Error(`fetching ${path}: HTTP ${r.status}`);
  return r;
}

function compile(gl, type, file, source) {
  const s = gl.createShader(type);
  gl.shaderSource(s, source);
  gl.compileShader(s);
  if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
    const log = gl.getShaderInfoLog(s);
    gl.deleteShader(s);
    throw new Error(`${file} does not compile: ${log.trim()}`);
  }
  return s;
}

// A uniform block's bytes for one draw: a loose value (one member named
// like the block, or of the block's type) is the scene value of the
// block's name; a struct block's members are scene values by member name;
// a member the scene does not set keeps the manifest's default.
function blockBytes(block, size, values) {
  const bytes = new ArrayBuffer(Math.max(size, block.size));
  const view = new DataView(bytes);
  const loose = block.members.length === 1 &&
    (block.members[0].name === block.name || block.members[0].type === block.type);
  for (const m of block.members) {
    const name = loose ? block.name : m.name;
    const v = values[name];
    if (v === undefined && m.default) {
      // A value the scene does not set keeps its default (its words).
      m.default.forEach((w, i) => view.setUint32(m.offset + 4 * i, w, true));
      continue;
    }
    if (v === undefined) throw new Error(`uniform \`${name}\` is not a value the scene sets and has no default`);
    const put = (at, x) => view.setFloat32(at, x, true);
    if (m.type === 'float4x4') {
      const stride = m.matrix_stride ?? 16;
      for (let c = 0; c < 4; c++) for (let r = 0; r < 4; r++) put(m.offset + c * stride + r * 4, v[c * 4 + r]);
    } else if (m.type === 'float3') {
      for (let i = 0; i < 3; i++) put(m.offset + i * 4, v[i]);
    } else if (m.type === 'float') {
      put(m.offset, v);
    } else {
      throw new Error(`uniform \`${name}\` has type ${m.type}, which the scene does not set`);
    }
  }
  return new Uint8Array(bytes);
}

async function main() {
  const scene = await (await fetchOk('scene.json')).json();
  const manifest = await (await fetchOk(scene.manifest)).json();
  const { width, height } = scene;
  const n = scene.shadow_size;
  const canvas = document.getElementById('view');
  canvas.width = width;
  canvas.height = height;
  const gl = canvas.getContext('webgl2', { antialias: false, alpha: false, depth: false, preserveDrawingBuffer: true });
  if (!gl) throw new Error('this browser gives no WebGL2 context');
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const renderer = gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER);

  const entry = (name) => {
    const e = manifest.entry_points.find((e) => e.name === name);
    if (!e) throw new Error(`the manifest has no entry point \`${name}\``);
    if (!e.files.gles300) throw new Error(`entry point \`${name}\` has no gles300 file`);
    return e;
  };

  // Meshes.
  const meshes = {};
  for (const [name, m] of Object.entries(scene.meshes)) {
    const vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(m.vertices), gl.STATIC_DRAW);
    meshes[name] = { vbo, indices: new Uint32Array(m.indices) };
  }

  // One uniform buffer per manifest block, at binding point = its index.
  const ubos = manifest.uniform_blocks.map(() => gl.createBuffer());
  const uboSize = manifest.uniform_blocks.map((b) => b.size);

  async function link(label, pass) {
    const ve = entry(pass.vertex);
    const fe = entry(pass.fragment);
    const vsText = await (await fetchOk(ve.files.gles300)).text();
    const fsText = await (await fetchOk(fe.files.gles300)).text();
    const vs = compile(gl, gl.VERTEX_SHADER, ve.files.gles300, vsText);
    const fs = compile(gl, gl.FRAGMENT_SHADER, fe.files.gles300, fsText);
    const program = gl.createProgram();
    gl.attachShader(program, vs);
    gl.attachShader(program, fs);
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
      throw new Error(`the ${label} pass's program does not link: ${gl.getProgramInfoLog(program).trim()}`);
    }
    const problems = [];
    const usedBlocks = new Set([...ve.uniform_blocks, ...fe.uniform_blocks]);
    const usedSamplers = new Set([...ve.samplers, ...fe.samplers]);
    const blocks = [];
    gl.useProgram(program);
    manifest.uniform_blocks.forEach((b, i) => {
      if (!usedBlocks.has(b.name)) return;
      const index = gl.getUniformBlockIndex(program, b.glsl_block);
      if (index === gl.INVALID_INDEX) {
        problems.push(`uniform block \`${b.glsl_block}\` is not in the linked program`);
        return;
      }
      gl.uniformBlockBinding(program, index, i);
      const size = gl.getActiveUniformBlockParameter(program, index, gl.UNIFORM_BLOCK_DATA_SIZE);
      uboSize[i] = Math.max(uboSize[i], size);
      blocks.push(i);
    });
    let shadowUnit = null;
    for (const s of manifest.samplers) {
      if (!usedSamplers.has(s.name)) continue;
      if (!(s.comparison && s.sample_type === 'depth' && s.dimension === '2d')) {
        problems.push(`sampler \`${s.name}\` is a ${s.type}; the scene's only texture is the shadow map`);
        continue;
      }
      const loc = gl.getUniformLocation(program, s.glsl_name);
      if (loc === null) {
        problems.push(`sampler \`${s.glsl_name}\` is not in the linked program`);
        continue;
      }
      gl.uniform1i(loc, s.texture_unit);
      shadowUnit = s.texture_unit;
    }
    gl.useProgram(null);
    const attributes = [];
    for (const input of ve.inputs) {
      const field = scene.vertex.fields[input.name];
      if (!field) {
        problems.push(`vertex input \`${input.name}\` is not in the scene's meshes`);
        continue;
      }
      const loc = gl.getAttribLocation(program, input.glsl_name);
      if (loc !== input.location) {
        problems.push(`attribute \`${input.glsl_name}\` is at location ${loc} in the linked program, ${input.location} in the manifest`);
      }
      attributes.push({ location: input.location, offset: field.offset, components: field.components });
    }
    if (problems.length) throw new Error(`the ${label} pass does not match the manifest: ${problems.join('; ')}`);
    const vaos = {};
    for (const [name, m] of Object.entries(meshes)) {
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      gl.bindBuffer(gl.ARRAY_BUFFER, m.vbo);
      for (const a of attributes) {
        gl.enableVertexAttribArray(a.location);
        gl.vertexAttribPointer(a.location, a.components, gl.FLOAT, false, scene.vertex.stride, a.offset);
      }
      const ibo = gl.createBuffer();
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ibo);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, m.indices, gl.STATIC_DRAW);
      gl.bindVertexArray(null);
      vaos[name] = { vao, count: m.indices.length };
    }
    return { program, blocks, shadowUnit, vaos };
  }

  const shadowPass = await link('shadow', scene.passes.shadow);
  const mainPass = await link('main', scene.passes.main);
  ubos.forEach((ubo, i) => {
    gl.bindBuffer(gl.UNIFORM_BUFFER, ubo);
    gl.bufferData(gl.UNIFORM_BUFFER, uboSize[i], gl.DYNAMIC_DRAW);
  });
  gl.bindBuffer(gl.UNIFORM_BUFFER, null);

  // The shadow map: a depth texture with hardware compare, linear, clamped.
  const shadowTex = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, shadowTex);
  gl.texStorage2D(gl.TEXTURE_2D, 1, gl.DEPTH_COMPONENT32F, n, n);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_COMPARE_MODE, gl.COMPARE_REF_TO_TEXTURE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_COMPARE_FUNC, gl.LEQUAL);
  gl.bindTexture(gl.TEXTURE_2D, null);
  const shadowFbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, shadowFbo);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.TEXTURE_2D, shadowTex, 0);
  gl.drawBuffers([gl.NONE]);
  gl.readBuffer(gl.NONE);
  const shadowStatus = gl.checkFramebufferStatus(gl.FRAMEBUFFER);

  // The main pass's target: RGBA8 colour, 32-bit float depth.
  const colorRb = gl.createRenderbuffer();
  gl.bindRenderbuffer(gl.RENDERBUFFER, colorRb);
  gl.renderbufferStorage(gl.RENDERBUFFER, gl.RGBA8, width, height);
  const depthRb = gl.createRenderbuffer();
  gl.bindRenderbuffer(gl.RENDERBUFFER, depthRb);
  gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT32F, width, height);
  const colorFbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, colorFbo);
  gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, colorRb);
  gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depthRb);
  const colorStatus = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
  if (shadowStatus !== gl.FRAMEBUFFER_COMPLETE || colorStatus !== gl.FRAMEBUFFER_COMPLETE) {
    throw new Error(`incomplete framebuffer (shadow ${shadowStatus}, colour ${colorStatus})`);
  }

  const drawAll = (pass) => {
    for (const d of scene.draws) {
      for (const i of pass.blocks) {
        gl.bindBuffer(gl.UNIFORM_BUFFER, ubos[i]);
        gl.bufferSubData(gl.UNIFORM_BUFFER, 0, blockBytes(manifest.uniform_blocks[i], uboSize[i], d.values));
        gl.bindBufferBase(gl.UNIFORM_BUFFER, i, ubos[i]);
      }
      const v = pass.vaos[d.mesh];
      gl.bindVertexArray(v.vao);
      gl.drawElements(gl.TRIANGLES, v.count, gl.UNSIGNED_INT, 0);
      gl.bindVertexArray(null);
    }
  };

  gl.disable(gl.CULL_FACE);
  gl.disable(gl.BLEND);
  gl.enable(gl.DEPTH_TEST);
  gl.depthFunc(gl.LESS);
  gl.depthMask(true);

  // Pass 1: depth from the sun.
  gl.bindFramebuffer(gl.FRAMEBUFFER, shadowFbo);
  gl.viewport(0, 0, n, n);
  gl.clearDepth(1.0);
  gl.clear(gl.DEPTH_BUFFER_BIT);
  if (scene.view !== 'lit') {
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(scene.polygon_offset.factor, scene.polygon_offset.units);
    gl.useProgram(shadowPass.program);
    drawAll(shadowPass);
    gl.disable(gl.POLYGON_OFFSET_FILL);
  }

  // Pass 2: the lit scene.
  gl.bindFramebuffer(gl.FRAMEBUFFER, colorFbo);
  gl.viewport(0, 0, width, height);
  gl.clearColor(scene.clear[0], scene.clear[1], scene.clear[2], 1.0);
  gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  gl.useProgram(mainPass.program);
  if (mainPass.shadowUnit !== null) {
    gl.activeTexture(gl.TEXTURE0 + mainPass.shadowUnit);
    gl.bindTexture(gl.TEXTURE_2D, shadowTex);
  }
  drawAll(mainPass);
  gl.useProgram(null);

  // Read the frame from the framebuffer it was drawn to, copy it to the
  // canvas and read the canvas back: the two must agree.
  const fromFbo = new Uint8Array(width * height * 4);
  gl.pixelStorei(gl.PACK_ALIGNMENT, 1);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, fromFbo);
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, colorFbo);
  gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
  gl.blitFramebuffer(0, 0, width, height, 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  const pixels = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  const err = gl.getError();
  if (err !== gl.NO_ERROR) throw new Error(`WebGL error ${err}`);
  let mismatched = 0;
  for (let i = 0; i < pixels.length; i++) if (pixels[i] !== fromFbo[i]) mismatched++;
  if (mismatched) throw new Error(`the canvas differs from the framebuffer drawn in ${mismatched} bytes`);

  let binary = '';
  for (let i = 0; i < pixels.length; i += 0x8000) binary += String.fromCharCode.apply(null, pixels.subarray(i, i + 0x8000));
  return { ok: true, width, height, pixels: btoa(binary), renderer, version: gl.getParameter(gl.VERSION) };
}

const status = document.getElementById('status');
main().then(
  (r) => { status.textContent = `drawn on ${r.renderer}`; window.umbracResult = r; },
  (e) => { status.textContent = `error: ${e.message}`; window.umbracResult = { ok: false, error: e.message }; },
);
