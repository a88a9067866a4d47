// The playground in real headless Chromium (docs/preview.md, "Playground"):
//
//   node web/playground/test.mjs PLAYGROUND_DIR
//
// serves the built page (scripts/build-playground.sh) on the loopback
// interface and checks: a tutorial loads and every output shows (equal to
// the native compiler's when $UMBRAC names an umbrac binary); a typed error
// is marked at its line and clears when fixed; a 1 MB paste leaves the page
// answering; a share link round-trips; a program `require`ing a module
// of its own compiles, an edit to the module through the File menu
// recompiles it, and a share link carries both files. Chromium is /usr/bin/chromium (or
// $UMBRAC_CHROMIUM); without it the test skips, or fails with CI=true.
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { execFileSync } from 'node:child_process';
import { launch, missing, serveStatic } from '../chromium.mjs';

const dir = process.argv[2];
const ci = process.env.CI === 'true';
function skip(why) {
  if (ci) {
    console.error(`FAIL: ${why} (CI=true)`);
    process.exit(1);
  }
  console.error(`skipped: ${why}`);
  process.exit(0);
}
if (!dir || !existsSync(join(dir, 'index.html'))) skip(`no built playground at ${dir} (bash scripts/build-playground.sh)`);
const cannot = missing();
if (cannot) skip(cannot);

// Seconds the page may take to answer while a 1 MB paste compiles.
const ANSWER_MS = 1000;
const SETTLE_MS = 60000;

const server = await serveStatic(dir);
const base = server.url;

const failures = [];
const results = {};
function check(name, ok, detail) {
  results[name] = { ok, ...(detail || {}) };
  if (!ok) failures.push(`${name}: ${JSON.stringify(detail)}`);
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${name} ${detail ? JSON.stringify(detail) : ''}`);
}

const settled = (page) => page.waitForFunction(() => window.umbracPlayground && window.umbracPlayground.settled() && window.umbracPlayground.state.compiles > 0, null, { timeout: SETTLE_MS, polling: 50 });
const panelText = (page, key) => page.$eval(`#out-${key} pre`, (e) => e.textContent);

// Two SPIR-V modules hold the same header and the same instructions.
function sameInstructions(a, b) {
  const split = (w) => {
    const out = [];
    for (let i = 5; i < w.length;) {
      const n = w[i] >>> 16;
      if (n === 0) return null;
      out.push(w.slice(i, i + n).join(','));
      i += n;
    }
    return out.sort();
  };
  const [x, y] = [split(a), split(b)];
  return a.length === b.length && a.slice(0, 5).join() === b.slice(0, 5).join() && x !== null && y !== null && x.join(';') === y.join(';');
}

const PROGRAM = 'var @out f_color : float4\n\n[fragment_program]\ndef main_fs {\n    f_color = float4(1.0, 0.5, 0.25, 1.0)\n}\n';

// Several files: a program that `require`s a module of its own (a daslang
// module, host code and all, in a folder beside it), the module edited
// through the editor's file menu, and a share link carrying both.
const REQUIRING = 'options gen2\nrequire lib/tint\n\nvar @out f_color : float4\n\n[fragment_program]\ndef main_fs {\n    f_color = float4(tint(), 1.0)\n}\n';
const TINT = 'options gen2\nmodule tint public\n\ndef tint() : float3 {\n    return float3(0.25, 0.5, 0.75)\n}\n';

async function severalFiles(browser, page) {
  const wgsl = () => page.evaluate(() => window.umbracPlayground.state.lastBundle.files.filter((f) => f.name.endsWith('.wgsl')).map((f) => f.text).join('\n'));
  await page.evaluate(([main, files]) => { window.umbracPlayground.setFiles(files); window.umbracPlayground.setSource(main); }, [REQUIRING, { 'lib/tint.das': TINT }]);
  await settled(page);
  const first = await page.evaluate(() => ({ ok: window.umbracPlayground.state.lastBundle.ok, diagnostics: window.umbracPlayground.state.lastBundle.diagnostics.map((d) => d.message) }));
  const menu = await page.$$eval('#file option', (o) => o.map((x) => x.value));
  check('a program requiring its own module compiles in the page', first.ok && (await wgsl()).includes('0.25') && menu.includes('lib/tint.das'), { ...first, menu });
  // The module in the editor, edited: the program compiles with the edit.
  const compiles = await page.evaluate(() => window.umbracPlayground.state.compiles);
  await page.selectOption('#file', 'lib/tint.das');
  await page.evaluate(() => {
    const v = window.umbracPlayground.view;
    const at = v.state.doc.toString().indexOf('0.25');
    v.dispatch({ changes: { from: at, to: at + 4, insert: '0.125' } });
  });
  await page.waitForFunction((n) => window.umbracPlayground.state.compiles > n && window.umbracPlayground.settled(), compiles, { timeout: SETTLE_MS, polling: 50 });
  const edited = await page.evaluate(() => ({ active: window.umbracPlayground.active, source: window.umbracPlayground.source(), ok: window.umbracPlayground.state.lastBundle.ok }));
  const text = await wgsl();
  check('an edit to the module recompiles the program', edited.active === 'lib/tint.das' && edited.source === REQUIRING && edited.ok && text.includes('0.125') && !text.includes('0.25'), edited);
  // The share link: both files, as they are now.
  await page.click('#share');
  const link = await page.$eval('#share-link', (e) => e.value);
  const other = await browser.newPage();
  await other.goto(link);
  await settled(other);
  const back = await other.evaluate(() => ({ source: window.umbracPlayground.source(), files: window.umbracPlayground.files(), ok: window.umbracPlayground.state.lastBundle.ok }));
  check('a share link carries every file', back.ok && back.source === REQUIRING && Object.keys(back.files).length === 1 && back.files['lib/tint.das'] === TINT.replace('0.25', '0.125'), { link_chars: link.length, ok: back.ok });
  await other.close();
}

// Every example that `require`s a module of the project's (found among
// the shared files, as the page passes them) compiles with the page's
// compiler, here loaded in node.
async function examplesWithModules() {
  const { pathToFileURL } = await import('node:url');
  const glue = await import(pathToFileURL(resolve(dir, 'umbrac_web.js')).href);
  await glue.default({ module_or_path: readFileSync(join(dir, 'umbrac_web_bg.wasm')) });
  const data = JSON.parse(readFileSync(join(dir, 'examples.json'), 'utf8'));
  const requiring = data.examples.filter((e) => e.shared && /^\s*require\s+\S*\//m.test(e.source));
  const failed = requiring.map((e) => [e.name, JSON.parse(glue.compile(e.path, e.source, JSON.stringify({ files: data.files })))]).filter(([, b]) => !b.ok);
  check('the examples requiring modules compile in the page', requiring.length > 0 && failed.length === 0, { examples: requiring.map((e) => e.name), failed: failed.map(([n, b]) => [n, b.diagnostics[0]?.message]) });
}

let browser;
try {
  // WebGPU, where this chromium offers it (docs/preview.md), for the preview.
  browser = await launch({ webgpu: true, quiet: ['GPU stall'], profilePrefix: 'umbrac-playground-' });
  const page = await browser.newPage();
  page.on('pageerror', (e) => failures.push(`page error: ${e.message}`));

  // 1. A tutorial (or, without the reference, the project's shadow program)
  // loads and every output shows.
  const examples = JSON.parse(readFileSync(join(dir, 'examples.json'), 'utf8')).examples;
  const tutorial = examples.find((e) => e.name === 'tutorials/03_sdf.das');
  if (!tutorial) {
    if (ci) failures.push('the GL tutorials are not among the examples (../shared/reference missing?)');
    else console.error('note: no GL tutorials among the examples; loading shaders/shadow.das');
  }
  const example = tutorial || examples.find((e) => e.name === 'shaders/shadow.das');
  const t0 = Date.now();
  await page.goto(`${base}#example=${encodeURIComponent(example.name)}`);
  await settled(page);
  const loadMs = Date.now() - t0;
  const bundle = await page.evaluate(() => window.umbracPlayground.state.lastBundle);
  const texts = {};
  for (const key of ['glsl330', 'gles300', 'wgsl', 'spirv', 'manifest']) texts[key] = await panelText(page, key);
  check('tutorial compiles in the page', bundle.ok && (await page.evaluate(() => window.umbracPlayground.source())) === example.source, { example: example.name, load_to_outputs_ms: loadMs, compile_ms: await page.evaluate(() => window.umbracPlayground.state.lastMs) });
  check('every output is shown', texts.glsl330.startsWith('#version 330') && texts.gles300.startsWith('#version 300 es') && texts.wgsl.includes('@fragment') && texts.spirv.includes('OpEntryPoint') && texts.manifest.includes('"entry_points"'),
    { heads: Object.fromEntries(Object.entries(texts).map(([k, v]) => [k, v.slice(0, 40)])) });

  // The preview draws it: a picture that is not one flat colour, and the
  // two APIs agree where WebGPU is there (the tolerance is draw.js's).
  await page.waitForFunction(() => window.umbracPlayground.preview.drawn > 0, null, { timeout: SETTLE_MS, polling: 100 });
  const firstFrameMs = Date.now() - t0;
  const pic = await page.evaluate(async () => {
    const s = await window.umbracPlayground.preview.snapshot();
    const px = s.webgl2;
    const colours = new Set();
    for (let i = 0; px && i < px.length; i += 4 * 97) colours.add(`${px[i]},${px[i + 1]},${px[i + 2]}`);
    return { colours: colours.size, webgpu: !!s.webgpu, diff: s.diff, errors: window.umbracPlayground.preview.errors };
  });
  check('the preview draws the tutorial', pic.colours > 8 && (!pic.diff || pic.diff.share < 0.01), { ...pic, max_share: 0.01, load_to_first_frame_ms: firstFrameMs });

  // The same text as the native compiler writes, file for file.
  if (process.env.UMBRAC) {
    const native = mkdtempSync(join(tmpdir(), 'umbrac-native-'));
    const src = join(native, example.path);
    writeFileSync(src, example.source);
    // Named as the page names it, so the manifests' `source` agree.
    execFileSync(resolve(process.env.UMBRAC), ['compile', example.path, '-o', 'out', '--no-cache'], { cwd: native });
    const differ = bundle.files.filter((f) => f.text !== undefined && readFileSync(join(native, 'out', f.name), 'utf8') !== f.text).map((f) => f.name);
    // SPIR-V: the same instructions. Their order may differ: naga's writer
    // emits a function's OpVariables in hash-map order, and its hash of a
    // handle differs between 32-bit WebAssembly and a 64-bit host.
    const spv = bundle.files.find((f) => f.words);
    const file = readFileSync(join(native, 'out', spv.name));
    const nativeWords = Array.from({ length: file.length / 4 }, (_, i) => file.readUInt32LE(i * 4));
    const sameSpv = sameInstructions(nativeWords, spv.words);
    check('the page\'s outputs are the native compiler\'s', differ.length === 0 && sameSpv, { files: bundle.files.length, differ, same_spirv: sameSpv });
    rmSync(native, { recursive: true, force: true });
  }

  // 2. A typed error is marked at its line; fixing it clears the mark.
  await page.evaluate((p) => window.umbracPlayground.setSource(p), PROGRAM);
  await settled(page);
  await page.click('.cm-content');
  await page.keyboard.press('Control+Home');
  for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowDown');
  await page.keyboard.press('End');
  await page.keyboard.type(' * nope', { delay: 20 });
  const typedAt = Date.now();
  await page.waitForFunction(() => window.umbracPlayground.marks().length > 0, null, { timeout: SETTLE_MS, polling: 50 });
  const marks = await page.evaluate(() => window.umbracPlayground.marks());
  check('a typed error is marked at its line', marks.some((m) => m.line === 5 && m.severity === 'error' && m.message.includes('nope')), { marks, ms: Date.now() - typedAt });
  for (let i = 0; i < ' * nope'.length; i++) await page.keyboard.press('Backspace');
  await page.waitForFunction(() => window.umbracPlayground.marks().length === 0 && window.umbracPlayground.settled(), null, { timeout: SETTLE_MS, polling: 50 });
  check('fixing it clears the mark', await page.evaluate(() => window.umbracPlayground.state.lastBundle.ok && window.umbracPlayground.source()) === PROGRAM);

  // 3. A 1 MB paste: the editor takes it and the page keeps answering
  // while the worker compiles it.
  const helper = (i) => `def helper_${i}(x : float) : float {\n    return x * ${i}.5 + sin(x)\n}\n`;
  let big = '';
  for (let i = 0; big.length < (1 << 20); i++) big += helper(i);
  big += PROGRAM.replace('float4(1.0, 0.5, 0.25, 1.0)', 'float4(helper_7(1.0), 0.5, 0.25, 1.0)');
  await page.evaluate(() => window.umbracPlayground.setSource(''));
  await settled(page);
  const compilesBefore = await page.evaluate(() => window.umbracPlayground.state.compiles);
  await page.click('.cm-content');
  const pasteStart = Date.now();
  await page.evaluate((text) => {
    const dt = new DataTransfer();
    dt.setData('text/plain', text);
    window.umbracPlayground.view.contentDOM.dispatchEvent(new ClipboardEvent('paste', { clipboardData: dt, bubbles: true, cancelable: true }));
  }, big);
  const pastedMs = Date.now() - pasteStart;
  // While the compile runs, the page answers promptly (a frame and a key).
  let worst = 0;
  for (let i = 0; i < 5; i++) {
    const s = Date.now();
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
    worst = Math.max(worst, Date.now() - s);
    await new Promise((r) => setTimeout(r, 100));
  }
  const lengthNow = await page.evaluate(() => window.umbracPlayground.view.state.doc.length);
  await page.waitForFunction((n) => window.umbracPlayground.state.compiles > n && window.umbracPlayground.settled(), compilesBefore, { timeout: SETTLE_MS, polling: 100 });
  const bigDone = await page.evaluate(() => ({ ok: window.umbracPlayground.state.lastBundle.ok, ms: window.umbracPlayground.state.lastMs }));
  check('a 1 MB paste does not hang the page', lengthNow === big.length && pastedMs < 5000 && worst < ANSWER_MS && bigDone.ok,
    { bytes: big.length, paste_ms: pastedMs, slowest_answer_ms: worst, limit_ms: ANSWER_MS, compile_ms: Math.round(bigDone.ms), ok: bigDone.ok });

  // 4. A share link round-trips (text outside ASCII included).
  const shared = PROGRAM.replace('def main_fs', '// é ✓ 🎨 a comment\ndef main_fs');
  await page.evaluate((p) => window.umbracPlayground.setSource(p), shared);
  await settled(page);
  await page.click('#share');
  const link = await page.$eval('#share-link', (e) => e.value);
  const other = await browser.newPage();
  await other.goto(link);
  await settled(other);
  const back = await other.evaluate(() => ({ source: window.umbracPlayground.source(), ok: window.umbracPlayground.state.lastBundle.ok }));
  check('a share link round-trips', back.source === shared && back.ok, { link_chars: link.length });

  // 5. Several files.
  await severalFiles(browser, page);
  await examplesWithModules();
} catch (e) {
  failures.push(`driving chromium: ${e.stack || e.message}`);
} finally {
  if (browser) await browser.close();
  server.close();
}
if (failures.length) {
  console.error(`playground test failed:\n${failures.join('\n')}`);
  process.exit(1);
}
console.log('playground: all checks passed');
