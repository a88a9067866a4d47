// Drives the playground as `umbrac preview FILE` serves it (with the file
// loaded) in Debian's headless chromium, for tests/gpu/preview.rs:
//
//   node web/playground/live-drive.mjs URL OUTDIR STEPS.json
//
// STEPS.json is a list: `{ "save": PATH, "text": T }` writes T over PATH
// as editors save (a new file renamed over it) and waits for the server's
// bundle to reach the page; `{ "type": T }` puts T in the editor as an
// edit and waits for the page's own (WebAssembly) compile. Before the
// first step and after each, it records the page's state (the editor's
// text, the bundle's ok, the lint marks, the preview's errors and
// comparison, whether the page was reloaded) in OUTDIR/result.json and
// the pictures as OUTDIR/STEP.webgl2.rgba, STEP.webgpu.rgba (rows bottom
// first).
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { launch, saveAsEditor, writeRgba, LAUNCH_MS, WAIT } from '../chromium.mjs';

const [url, outDir, stepsFile] = process.argv.slice(2);
if (!url || !outDir || !stepsFile) {
  console.error('usage: node live-drive.mjs URL OUTDIR STEPS.json');
  process.exit(2);
}
const steps = JSON.parse(readFileSync(stepsFile, 'utf8'));

// What the page shows now, once the preview has drawn the last bundle.
async function record(page, step) {
  const s = await page.evaluate(async () => {
    const pg = window.umbracPlayground;
    const snap = await pg.preview.snapshot();
    const b64 = window.umbracBase64;
    return {
      editor: pg.source(), live: pg.live, ok: pg.state.lastBundle ? pg.state.lastBundle.ok : null,
      marks: pg.marks(), drawn: pg.preview.drawn, errors: pg.preview.errors, diff: snap.diff,
      width: snap.width, height: snap.height, webgl2: b64(snap.webgl2), webgpu: b64(snap.webgpu),
      status: document.getElementById('status').textContent,
      menu: document.getElementById('examples').selectedOptions[0]?.textContent ?? null,
      fileMenu: [...document.getElementById('file').options].map((o) => o.value),
      notReloaded: window.umbracNotReloaded === true,
    };
  });
  for (const api of ['webgl2', 'webgpu']) s[api] = writeRgba(join(outDir, `${step}.${api}.rgba`), s[api]);
  return s;
}

const result = { ok: false, steps: [] };
let browser;
try {
  browser = await launch({ webgpu: true, quiet: ['GPU stall'], profilePrefix: 'umbrac-live-' });
  const page = await browser.newPage();
  await page.goto(url, { timeout: LAUNCH_MS });
  await page.evaluate(() => { window.umbracNotReloaded = true; });
  // The server's first bundle, drawn.
  await page.waitForFunction(() => {
    const pg = window.umbracPlayground;
    return pg && pg.live && pg.live.received > 0 && pg.preview.drawn > 0;
  }, null, WAIT);
  result.steps.push(await record(page, 0));
  for (const [i, step] of steps.entries()) {
    const before = await page.evaluate(() => ({ received: window.umbracPlayground.live.received, drawn: window.umbracPlayground.preview.drawn }));
    if (step.save) {
      saveAsEditor(step.save, step.text);
      await page.waitForFunction(({ before, text }) => {
        const pg = window.umbracPlayground;
        if (pg.live.received <= before.received || pg.source() !== text) return false;
        return pg.state.lastBundle.ok === false || pg.preview.drawn > before.drawn;
      }, { before, text: step.text }, WAIT);
    } else {
      await page.evaluate((text) => window.umbracPlayground.setSource(text), step.type);
      await page.waitForFunction((before) => {
        const pg = window.umbracPlayground;
        if (!pg.settled()) return false;
        return pg.state.lastBundle.ok === false || pg.preview.drawn > before.drawn;
      }, before, WAIT);
    }
    result.steps.push(await record(page, i + 1));
  }
  result.ok = true;
} catch (e) {
  result.error = `driving chromium: ${e.message}`;
} finally {
  if (browser) await browser.close();
}
writeFileSync(join(outDir, 'result.json'), JSON.stringify(result, null, 1));
process.exit(result.ok ? 0 : 1);
