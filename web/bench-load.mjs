// Page load to first frame (a benchmark, not a test; docs/performance.md,
// "Page load to first frame"):
//
//   node web/bench-load.mjs [--runs N] UMBRAC PLAYGROUND_DIR FILE.das [EXAMPLE]
//
// (a) `UMBRAC preview FILE`: the page receives the bundle the server
//     compiled when it started and draws it on both panes (WebGL2 and
//     WebGPU). No compiler in the page: the peer of (b).
// (b) the built playground (PLAYGROUND_DIR, served here as static files)
//     at `#example=EXAMPLE` (default `tutorials/` + FILE's name): the page
//     fetches and instantiates the WebAssembly compiler in its worker,
//     compiles the example, and draws the bundle with the same draw.js.
// (c) the same playground as `umbrac preview --playground DIR FILE` serves
//     it: the same page and canvases (320x240, smaller than (a)'s
//     480x360), the bundle compiled by the server, so nothing is compiled
//     in the page before the first frame (the module is still fetched and
//     instantiated beside it): the peer of (b). (b) / (c) is what the
//     compiler in the page costs before the first picture.
//
// Each run is a fresh browser (a new profile: nothing cached) and one
// navigation; the times are the page's own (ms from the navigation's
// start, `performance`), and the tables print the medians of N runs
// (default 7) with their parts.
import { spawn } from 'node:child_process';
import { createInterface } from 'node:readline';
import { basename } from 'node:path';
import { launch, serveStatic, LAUNCH_MS, WAIT } from './chromium.mjs';

const args = process.argv.slice(2);
let runs = 7;
if (args[0] === '--runs') {
  runs = +args[1];
  args.splice(0, 2);
}
const [umbrac, playground, file, example = `tutorials/${basename(file ?? '')}`] = args;
if (!umbrac || !playground || !file || !(runs > 0)) {
  console.error('usage: node bench-load.mjs [--runs N] UMBRAC PLAYGROUND_DIR FILE.das [EXAMPLE]');
  process.exit(2);
}

// Polls in the page every 5 ms; the predicate notes when it first held.
const POLL = { ...WAIT, polling: 5 };

// `umbrac preview FILE` (with the playground) on a free port: its URL, once
// its first compile is done.
async function startPreview() {
  const child = spawn(umbrac, ['preview', '--port', '0', '--playground', playground, file], { stdio: ['ignore', 'pipe', 'inherit'] });
  const lines = createInterface({ input: child.stdout });
  const url = await new Promise((resolve, reject) => {
    lines.once('line', (l) => {
      const m = l.match(/http:\/\/127\.0\.0\.1:\d+\//);
      if (m) resolve(m[0]);
      else reject(new Error(`no URL in ${JSON.stringify(l)}`));
    });
    child.once('exit', (code) => reject(new Error(`umbrac preview exited (${code})`)));
  });
  lines.on('line', () => {});
  // The bundle is there (503 before the first compile ends).
  for (let i = 0; i < 600 && (await fetch(`${url}bundle.json`)).status !== 200; i++) await new Promise((r) => setTimeout(r, 100));
  return { url, close: () => child.kill() };
}

// One navigation in a fresh browser: the page's times (ms).
async function once(url, measure) {
  const browser = await launch({ webgpu: true, quiet: ['GPU stall', '404'], profilePrefix: 'umbrac-bench-' });
  try {
    const page = await browser.newPage();
    const requests = [];
    browser.context.on('requestfinished', (r) => requests.push(r));
    await page.goto(url, { timeout: LAUNCH_MS, waitUntil: 'commit' });
    return await measure(page, requests);
  } finally {
    await browser.close();
  }
}

async function previewRun(page) {
  await page.waitForFunction(() => {
    const s = window.umbracPreview;
    if (!(s && s.drawn > 0)) return false;
    window.benchDrawn ??= performance.now();
    return true;
  }, null, POLL);
  return page.evaluate(() => {
    const mark = (n) => performance.getEntriesByName(n)[0]?.startTime ?? NaN;
    const nav = performance.getEntriesByType('navigation')[0];
    const s = window.umbracPreview;
    if (s.errors.webgl2 || s.errors.webgpu) throw new Error(`not drawn: ${JSON.stringify(s.errors)}`);
    return {
      dom: nav.domContentLoadedEventEnd, renderers: mark('umbrac:renderers'), bundle: mark('umbrac:bundle'),
      frame: mark('umbrac:frame'), drawn: window.benchDrawn,
    };
  });
}

// The module's fetch (by the worker), on the page's clock.
function wasmFetched(requests, origin) {
  const timing = requests.find((r) => r.url().endsWith('.wasm'))?.timing();
  return timing ? timing.startTime + timing.responseEnd - origin : NaN;
}

async function playgroundRun(page, requests) {
  await page.waitForFunction(() => {
    const pg = window.umbracPlayground;
    if (pg && pg.state.compiles > 0) window.benchCompiled ??= performance.now();
    if (pg && pg.live && pg.live.received > 0) window.benchBundle ??= performance.now();
    if (!(pg && pg.preview.drawn > 0)) return false;
    window.benchDrawn ??= performance.now();
    return true;
  }, null, POLL);
  const t = await page.evaluate(() => {
    const nav = performance.getEntriesByType('navigation')[0];
    const pg = window.umbracPlayground;
    if (!pg.state.lastBundle.ok || pg.preview.errors.webgl2) throw new Error(`not drawn: ${JSON.stringify(pg.preview.errors)}`);
    return {
      origin: performance.timeOrigin, dom: nav.domContentLoadedEventEnd, compiled: window.benchCompiled ?? NaN,
      compileMs: pg.state.compiles > 0 ? pg.state.lastMs : NaN, bundle: window.benchBundle ?? NaN, drawn: window.benchDrawn,
    };
  });
  t.wasm = wasmFetched(requests, t.origin);
  delete t.origin;
  return t;
}

const median = (xs) => {
  const s = xs.filter((x) => Number.isFinite(x)).sort((a, b) => a - b);
  return s.length ? s[(s.length - 1) >> 1] : NaN;
};
const ms = (x) => (Number.isFinite(x) ? x.toFixed(0) : '-');

async function bench(what, url, measure) {
  const all = [];
  for (let i = 0; i < runs; i++) all.push(await once(url, measure));
  const out = {};
  for (const k of Object.keys(all[0])) out[k] = median(all.map((r) => r[k]));
  console.error(`${what}: ${JSON.stringify(all.map((r) => Math.round(r.drawn)))}`);
  return out;
}

const preview = await startPreview();
let a;
let c;
try {
  a = await bench('(a) preview', preview.url, previewRun);
  c = await bench('(c) playground under preview', `${preview.url}playground/`, playgroundRun);
} finally {
  preview.close();
}
const server = await serveStatic(playground);
let b;
try {
  b = await bench('(b) playground', `${server.url}#example=${encodeURIComponent(example)}`, playgroundRun);
} finally {
  server.close();
}

console.log(`page load to first frame, ${file} (medians of ${runs} runs, ms from navigation start)\n`);
console.log('| page | DOMContentLoaded | renderers made | bundle received | first frame drawn | read back and compared |');
console.log('|---|---|---|---|---|---|');
console.log(`| (a) umbrac preview, 480x360 | ${ms(a.dom)} | ${ms(a.renderers)} | ${ms(a.bundle)} | ${ms(a.frame)} | ${ms(a.drawn)} |`);
console.log('\n| page, 320x240 | DOMContentLoaded | .wasm fetched | bundle: compiled in the page (its own ms) or received | first frame read back and compared |');
console.log('|---|---|---|---|---|');
console.log(`| (b) playground, ${example} | ${ms(b.dom)} | ${ms(b.wasm)} | ${ms(b.compiled)} (${ms(b.compileMs)}) | ${ms(b.drawn)} |`);
console.log(`| (c) playground under umbrac preview | ${ms(c.dom)} | ${ms(c.wasm)} | ${ms(c.bundle)} | ${ms(c.drawn)} |`);
console.log(`\n(b) / (c), navigation to the first picture: ${(b.drawn / c.drawn).toFixed(2)}`);
