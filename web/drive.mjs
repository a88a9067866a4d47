// Opens a page of the WebGL2 consumer in Debian's headless chromium and
// writes what the page reports (window.umbracResult) to a JSON file.
//
//   node web/drive.mjs URL OUT.json [URL OUT.json ...]
//
// Several pages are loaded one after the other in one browser (a browser
// start is most of a small frame's time); each result goes to its file.
// The browser is /usr/bin/chromium (or $UMBRAC_CHROMIUM), never a
// downloaded one; its profile lives in a fresh temporary directory.
import { chromium } from 'playwright-core';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const pairs = process.argv.slice(2);
if (pairs.length === 0 || pairs.length % 2 !== 0) {
  console.error('usage: node drive.mjs URL OUT.json [URL OUT.json ...]');
  process.exit(2);
}
const executablePath = process.env.UMBRAC_CHROMIUM || '/usr/bin/chromium';
const profile = mkdtempSync(join(tmpdir(), 'umbrac-chromium-'));
const args = [
  '--headless', '--no-sandbox', '--disable-gpu',
  '--disable-background-networking', '--disable-component-update',
  '--disable-sync', '--no-first-run',
  // With the GPU off, WebGL2 runs on SwiftShader (ANGLE on its Vulkan). If a
  // later chromium refuses WebGL without a GPU, add
  // '--enable-unsafe-swiftshader'; chromium 156 headless does not need it.
];

let browser;
let allOk = true;
let launchError;
try {
  // A persistent context is how playwright takes --user-data-dir: the
  // fresh profile directory made above.
  browser = await chromium.launchPersistentContext(profile, { executablePath, args, headless: true, timeout: 60000 });
} catch (e) {
  launchError = `driving chromium: ${e.message}`;
}
for (let i = 0; i < pairs.length; i += 2) {
  const [url, out] = [pairs[i], pairs[i + 1]];
  let result;
  if (launchError) {
    result = { ok: false, error: launchError };
  } else {
    let page;
    try {
      page = await browser.newPage();
      page.on('console', (m) => console.error(`[page ${m.type()}] ${m.text()}`));
      page.on('pageerror', (e) => console.error(`[page error] ${e.message}`));
      await page.goto(url, { timeout: 60000 });
      await page.waitForFunction(() => window.umbracResult !== undefined, null, { timeout: 120000, polling: 50 });
      result = await page.evaluate(() => window.umbracResult);
      result.browser = browser.browser()?.version();
    } catch (e) {
      result = { ok: false, error: `driving chromium: ${e.message}` };
    } finally {
      if (page) await page.close().catch(() => {});
    }
  }
  allOk = allOk && result.ok;
  writeFileSync(out, JSON.stringify(result));
}
if (browser) await browser.close().catch(() => {});
rmSync(profile, { recursive: true, force: true });
process.exit(allOk ? 0 : 1);
