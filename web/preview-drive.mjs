// Drives the page of `umbrac preview` in Debian's headless chromium through
// a scenario of saves, for tests/gpu/preview.rs:
//
//   node web/preview-drive.mjs URL PROGRAM OUTDIR SAVE...
//
// Opens URL, waits for the first picture, then for each SAVE (a file whose
// text is written over PROGRAM) waits for the page to take the new bundle
// (drawn, or shown as an error) without reloading. After each step it
// writes OUTDIR/STEP.webgl2.rgba and STEP.webgpu.rgba (rows bottom first,
// when drawn) and, at the end, OUTDIR/result.json: per step the page's
// state (ok, diagnostics, errors, renderers, diff, overlay shown, whether
// the page was reloaded). WebGPU is asked for with --enable-unsafe-webgpu.
import { chromium } from 'playwright-core';
import { mkdtempSync, readFileSync, renameSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const [url, program, outDir, ...saves] = process.argv.slice(2);
if (!url || !program || !outDir) {
  console.error('usage: node preview-drive.mjs URL PROGRAM OUTDIR SAVE...');
  process.exit(2);
}
const executablePath = process.env.UMBRAC_CHROMIUM || '/usr/bin/chromium';
const profile = mkdtempSync(join(tmpdir(), 'umbrac-preview-'));
const args = [
  '--headless', '--no-sandbox', '--disable-gpu',
  '--disable-background-networking', '--disable-component-update',
  '--disable-sync', '--no-first-run',
  // WebGPU on SwiftShader (docs/preview.md, "WebGPU in headless chromium").
  '--enable-unsafe-webgpu',
];

const result = { ok: false, steps: [] };
let browser;
try {
  browser = await chromium.launchPersistentContext(profile, { executablePath, args, headless: true, timeout: 60000 });
  result.browser = browser.browser()?.version();
  const page = await browser.newPage();
  // ANGLE's "GPU stall due to ReadPixels" is expected: the test reads pixels.
  page.on('console', (m) => { if (!m.text().includes('GPU stall')) console.error(`[page ${m.type()}] ${m.text()}`); });
  page.on('pageerror', (e) => console.error(`[page error] ${e.message}`));
  await page.goto(url, { timeout: 60000 });
  // A mark that a reload would lose.
  await page.evaluate(() => { window.umbracNotReloaded = true; });
  let seen = 0;
  for (let step = 0; step <= saves.length; step++) {
    if (step > 0) {
      // Saved as editors save: a whole new file renamed over the old one.
      writeFileSync(`${program}.saving`, readFileSync(saves[step - 1]));
      renameSync(`${program}.saving`, program);
    }
    // The next bundle, drawn (ok) or shown (an error): received past `seen`
    // and, when ok, drawn.
    await page.waitForFunction(
      (seen) => {
        const s = window.umbracPreview;
        return s && s.received > seen && (s.ok === false || s.drawn === s.received);
      },
      seen,
      { timeout: 120000, polling: 50 },
    );
    const state = await page.evaluate(async () => {
      const s = window.umbracPreview;
      const snap = await window.umbracSnapshot();
      return {
        received: s.received, drawn: s.drawn, ok: s.ok, diagnostics: s.diagnostics, errors: s.errors,
        renderers: s.renderers, diff: snap.diff, width: snap.width, height: snap.height,
        webgl2: snap.webgl2, webgpu: snap.webgpu,
        overlay: !document.getElementById('overlay').hidden,
        overlayText: document.getElementById('diagnostics').textContent,
        notReloaded: window.umbracNotReloaded === true,
      };
    });
    seen = state.received;
    for (const api of ['webgl2', 'webgpu']) {
      if (state[api]) writeFileSync(join(outDir, `${step}.${api}.rgba`), Buffer.from(state[api], 'base64'));
      state[api] = !!state[api];
    }
    result.steps.push(state);
  }
  result.ok = true;
} catch (e) {
  result.error = `driving chromium: ${e.message}`;
} finally {
  if (browser) await browser.close().catch(() => {});
  rmSync(profile, { recursive: true, force: true });
}
writeFileSync(join(outDir, 'result.json'), JSON.stringify(result, null, 1));
process.exit(result.ok ? 0 : 1);
