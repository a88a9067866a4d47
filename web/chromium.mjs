// What every driver of headless Chromium here shares (web/drive.mjs,
// web/preview-drive.mjs, web/playground/live-drive.mjs, test.mjs,
// web/bench-load.mjs): the browser's launch, a page with its console
// forwarded, pixels out of a page (window.umbracBase64) into RGBA files,
// a save as editors make it, and a static server for the built playground.
// (PNGs of pictures are written by the Rust tests that read the RGBA, with
// the image crate.)
//
// The browser is Debian's /usr/bin/chromium (or $UMBRAC_CHROMIUM), never a
// downloaded one, with a fresh temporary profile removed at the end.
import { createServer } from 'node:http';
import { createRequire } from 'node:module';
import { existsSync, mkdtempSync, readFileSync, renameSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';

const executablePath = process.env.UMBRAC_CHROMIUM || '/usr/bin/chromium';

// How long a launch or a navigation may take, and a wait for the page.
export const LAUNCH_MS = 60000;
export const WAIT = { timeout: 120000, polling: 50 };

const FLAGS = [
  '--headless', '--no-sandbox', '--disable-gpu',
  '--disable-background-networking', '--disable-component-update',
  '--disable-sync', '--no-first-run',
  // With the GPU off, WebGL2 runs on SwiftShader (ANGLE on its Vulkan). If
  // a later chromium refuses WebGL without a GPU, add
  // '--enable-unsafe-swiftshader'; chromium 156 headless does not need it.
];
// WebGPU on SwiftShader (docs/preview.md, "WebGPU in headless chromium").
const WEBGPU = ['--enable-unsafe-webgpu'];

// playwright-core from web/node_modules, whichever folder the driver is in.
function playwright() {
  return createRequire(join(dirname(fileURLToPath(import.meta.url)), 'package.json'))('playwright-core');
}

// Why the browser cannot be driven here (no chromium, no playwright-core),
// or null.
export function missing() {
  if (!existsSync(executablePath)) return `no chromium at ${executablePath}`;
  try {
    playwright();
  } catch (e) {
    return `playwright-core is not installed in web/ (npm ci --prefix web): ${e.message}`;
  }
  return null;
}

// Starts chromium with a fresh profile: { context, version, newPage, close }.
// `webgpu` adds the flag the preview needs; `quiet` lists console texts not
// forwarded (ANGLE's "GPU stall due to ReadPixels" is expected where a
// driver reads pixels). close() closes the browser and removes the profile.
export async function launch({ webgpu = false, quiet = [], profilePrefix = 'umbrac-chromium-' } = {}) {
  const profile = mkdtempSync(join(tmpdir(), profilePrefix));
  let context;
  try {
    // A persistent context is how playwright takes --user-data-dir.
    context = await playwright().chromium.launchPersistentContext(profile, {
      executablePath, headless: true, timeout: LAUNCH_MS, args: webgpu ? [...FLAGS, ...WEBGPU] : FLAGS,
    });
  } catch (e) {
    rmSync(profile, { recursive: true, force: true });
    throw e;
  }
  // window.umbracBase64(px) in every page: a snapshot's Uint8Array as
  // base64 (in slices: String.fromCharCode takes a bounded argument list),
  // to carry pixels out of page.evaluate.
  await context.addInitScript(() => {
    window.umbracBase64 = (px) => {
      if (!px) return null;
      let bin = '';
      for (let i = 0; i < px.length; i += 0x8000) bin += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
      return btoa(bin);
    };
  });
  return {
    context,
    version: context.browser()?.version(),
    // A new page whose console and errors go to this process's stderr.
    async newPage() {
      const page = await context.newPage();
      page.on('console', (m) => { if (!quiet.some((q) => m.text().includes(q))) console.error(`[page ${m.type()}] ${m.text()}`); });
      page.on('pageerror', (e) => console.error(`[page error] ${e.message}`));
      return page;
    },
    async close() {
      await context.close().catch(() => {});
      rmSync(profile, { recursive: true, force: true });
    },
  };
}

// Writes RGBA bytes (a Buffer, a Uint8Array or base64 text) to `path`;
// nothing (and false) for a missing picture.
export function writeRgba(path, rgba) {
  if (!rgba) return false;
  writeFileSync(path, typeof rgba === 'string' ? Buffer.from(rgba, 'base64') : rgba);
  return true;
}

// Saves `data` over `path` as editors do: a whole new file renamed over the
// old one (one watch event, never a half-written file).
export function saveAsEditor(path, data) {
  writeFileSync(`${path}.saving`, data);
  renameSync(`${path}.saving`, path);
}


const MIME = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.json': 'application/json', '.wasm': 'application/wasm' };

// Serves `dir` as static files on 127.0.0.1 (a free port), as any web
// server would the built playground: { url, close }. Nothing outside dir.
export async function serveStatic(dir) {
  const server = createServer((req, res) => {
    const path = normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname)).replace(/^(\.\.[/\\])+/, '');
    const file = join(dir, path === '/' ? 'index.html' : path);
    if (!file.startsWith(normalize(dir)) || !existsSync(file)) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'content-type': MIME[extname(file)] || 'application/octet-stream' }).end(readFileSync(file));
  });
  await new Promise((r) => server.listen(0, '127.0.0.1', r));
  return { url: `http://127.0.0.1:${server.address().port}/`, close: () => server.close() };
}
