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
// the page was reloaded). The browser (with WebGPU asked for): chromium.mjs.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { launch, saveAsEditor, writeRgba, LAUNCH_MS, WAIT } from './chromium.mjs';

const [url, program, outDir, ...saves] = process.argv.slice(2);
if (!url || !program || !outDir) {
  console.error('usage: node preview-drive.mjs URL PROGRAM OUTDIR SAVE...');
  process.exit(2);
}

const result = { ok: false, steps: [] };
let browser;
try {
  // ANGLE's "GPU stall due to ReadPixels" is expected: the test reads pixels.
  browser = await launch({ webgpu: true, quiet: ['GPU stall'], profilePrefix: 'umbrac-preview-' });
  result.browser = browser.version;
  const page = await browser.newPage();
  // Committed is enough: the page's own state says when it has drawn (below,
  // with the longer wait). Waiting for `load` here timed out at 60 s on a
  // loaded 2-core machine with several browsers drawing at once.
  await page.goto(url, { timeout: LAUNCH_MS, waitUntil: 'commit' });
  await page.waitForFunction(() => document.readyState !== 'loading', null, WAIT);
  // A mark that a reload would lose.
  await page.evaluate(() => { window.umbracNotReloaded = true; });
  let seen = 0;
  for (let step = 0; step <= saves.length; step++) {
    if (step > 0) saveAsEditor(program, readFileSync(saves[step - 1]));
    // The next bundle, drawn (ok) or shown (an error): received past `seen`
    // and, when ok, drawn.
    await page.waitForFunction(
      (seen) => {
        const s = window.umbracPreview;
        return s && s.received > seen && (s.ok === false || s.drawn === s.received);
      },
      seen,
      WAIT,
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
    for (const api of ['webgl2', 'webgpu']) state[api] = writeRgba(join(outDir, `${step}.${api}.rgba`), state[api]);
    result.steps.push(state);
    // UMBRAC_PREVIEW_CONTROL=NAME=VALUE: after the first picture, the first
    // slider of NAME's control is moved to VALUE as a user would, and the
    // pictures are written as control.API.rgba.
    const control = process.env.UMBRAC_PREVIEW_CONTROL;
    if (step === 0 && control) {
      const [name, value] = control.split('=');
      const slider = page.locator('fieldset.control', { has: page.locator(`legend:text-matches("^${name} :")`) }).locator('input[type=range]').first();
      await slider.evaluate((el, v) => { el.value = v; el.dispatchEvent(new Event('input', { bubbles: true })); }, value);
      const snap = await page.evaluate(() => window.umbracSnapshot());
      for (const api of ['webgl2', 'webgpu']) writeRgba(join(outDir, `control.${api}.rgba`), snap[api]);
      result.control = { name, value, diff: snap.diff };
    }
  }
  result.ok = true;
} catch (e) {
  result.error = `driving chromium: ${e.message}`;
} finally {
  if (browser) await browser.close();
}
writeFileSync(join(outDir, 'result.json'), JSON.stringify(result, null, 1));
process.exit(result.ok ? 0 : 1);
