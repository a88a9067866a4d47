// Textures of every kind a sampler reads (2D, cube, 3D, 2D array) for the
// preview's two renderers: the texels of a scene texture (the bytes
// src/scene/mod.rs's Texture::pattern_texels makes, docs/runner.md
// "Textures"), and their upload on WebGL2 and WebGPU. No other state.

import { pattern } from './scene.js';

// The layers' (cube faces') tints, by index mod 6.
const TINTS = [[255, 120, 120], [120, 255, 255], [120, 255, 120], [255, 120, 255], [120, 120, 255], [255, 255, 120]];

// Integer division as Rust's (towards zero).
const div = (a, b) => Math.trunc(a / b);

// Face f (+x, -x, +y, -y, +z, -z) of the sky cube map, n x n.
function skyFace(n, f) {
  const data = new Uint8Array(n * n * 4);
  const mix = (from, to, t) => from + div((to - from) * t, 256);
  for (let y = 0; y < n; y++) {
    for (let x = 0; x < n; x++) {
      const a = 2 * x + 1 - n, b = 2 * y + 1 - n;
      const [rx, ry, rz] = [[n, -b, -a], [-n, -b, a], [a, n, b], [a, -n, -b], [a, -b, n], [-a, -b, -n]][f];
      const e = div(256 * ry, Math.abs(ry) + Math.max(Math.abs(rx), Math.abs(rz)));
      let px;
      if (e >= 0) px = [mix(215, 40, e), mix(228, 100, e), mix(250, 210, e)];
      else {
        const g = Math.abs(rx) >= Math.abs(rz) ? (rx > 0 ? [170, 70, 50] : [60, 150, 60]) : rz > 0 ? [60, 90, 170] : [170, 150, 50];
        px = g.map((c) => mix(c, 20, -e));
      }
      data.set([px[0], px[1], px[2], 255], 4 * (y * n + x));
    }
  }
  return data;
}

// Layer (face) l of a layered pattern.
function layer(name, width, height, l) {
  if (name === 'sky') return skyFace(width, l);
  const data = pattern(name, width, height).data;
  const swap = name === 'checker' && l % 2 === 1;
  const tint = TINTS[l % 6];
  for (let i = 0; i < data.length; i += 4) {
    for (let k = 0; k < 3; k++) data[i + k] = div((swap ? 260 - data[i + k] : data[i + k]) * tint[k], 255);
  }
  return data;
}

// The image a renderer uploads for texture `tex` of a scene ({ kind,
// size, layers }) holding pattern `name`: { width, height, layers, kind,
// data } with the layers one after another. A 2D one is scene.js's.
export function texels(name, tex = {}) {
  const kind = tex.kind ?? '2d';
  const [width, height] = tex.size ?? [64, 64];
  if (kind === '2d') return { ...pattern(name, width, height), layers: 1, kind };
  const layers = kind === 'cube' ? 6 : tex.layers ?? 1;
  const data = new Uint8Array(width * height * 4 * layers);
  for (let l = 0; l < layers; l++) data.set(layer(name, width, height, l), l * width * height * 4);
  return { width, height, layers, kind, data };
}

// The scene kind of a manifest sampler's `dimension`.
export function kindOf(dimension) {
  return { '2d': '2d', cube: 'cube', '3d': '3d', '2d-array': '2d_array' }[dimension] ?? null;
}

// ---- WebGL2 -------------------------------------------------------------------

export function glTarget(gl, kind) {
  return { cube: gl.TEXTURE_CUBE_MAP, '3d': gl.TEXTURE_3D, '2d_array': gl.TEXTURE_2D_ARRAY }[kind] ?? gl.TEXTURE_2D;
}

// Uploads `img` into `texture` (bound here to its target on the active
// unit), filtered as `img.filter` says; 2D textures repeat, the others
// clamp to the edge (as the native runner's samplers).
export function glUpload(gl, texture, img) {
  const target = glTarget(gl, img.kind);
  gl.bindTexture(target, texture);
  const { width: w, height: h, data } = img;
  if (target === gl.TEXTURE_2D) gl.texImage2D(target, 0, gl.RGBA8, w, h, 0, gl.RGBA, gl.UNSIGNED_BYTE, data);
  else if (target === gl.TEXTURE_CUBE_MAP) {
    for (let f = 0; f < 6; f++) gl.texImage2D(gl.TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, gl.RGBA8, w, h, 0, gl.RGBA, gl.UNSIGNED_BYTE, data.subarray(f * w * h * 4, (f + 1) * w * h * 4));
  } else gl.texImage3D(target, 0, gl.RGBA8, w, h, img.layers, 0, gl.RGBA, gl.UNSIGNED_BYTE, data);
  const filter = img.filter === 'nearest' ? gl.NEAREST : gl.LINEAR;
  const wrap = target === gl.TEXTURE_2D ? gl.REPEAT : gl.CLAMP_TO_EDGE;
  gl.texParameteri(target, gl.TEXTURE_MIN_FILTER, filter);
  gl.texParameteri(target, gl.TEXTURE_MAG_FILTER, filter);
  gl.texParameteri(target, gl.TEXTURE_WRAP_S, wrap);
  gl.texParameteri(target, gl.TEXTURE_WRAP_T, wrap);
  gl.texParameteri(target, gl.TEXTURE_WRAP_R, wrap);
}

// ---- WebGPU -------------------------------------------------------------------

// The view dimension of a scene kind.
export function viewDimension(kind) {
  return { cube: 'cube', '3d': '3d', '2d_array': '2d-array' }[kind] ?? '2d';
}

// A texture holding `img` (a 1 x 1 placeholder of `kind` when `img` is
// null), and the view a bind group takes.
export function gpuTexture(device, img, kind = img?.kind ?? '2d') {
  const layers = kind === 'cube' ? 6 : img?.layers ?? 1;
  const [w, h] = img ? [img.width, img.height] : [1, 1];
  const texture = device.createTexture({
    size: [w, h, layers],
    dimension: kind === '3d' ? '3d' : '2d',
    format: 'rgba8unorm',
    usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST,
  });
  if (img) device.queue.writeTexture({ texture }, img.data, { bytesPerRow: w * 4, rowsPerImage: h }, [w, h, layers]);
  return { texture, view: () => texture.createView({ dimension: viewDimension(kind) }) };
}
