// Opens a page of the WebGL2 consumer in Debian's headless chromium and
// writes what the page reports (window.umbracResult) to a JSON file.
//
//   node web/drive.mjs URL OUT.json [URL OUT.json ...]
//
// Several pages are loaded one after the other in one browser (a browser
// start is most of a small frame's time); each result goes to its file.
// The browser and its profile: web/chromium.mjs.
import { writeFileSync } from 'node:fs';
import { launch, LAUNCH_MS, WAIT } from './chromium.mjs';

const pairs = process.argv.slice(2);
if (pairs.length === 0 || pairs.length % 2 !== 0) {
  console.error('usage: node drive.mjs URL OUT.json [URL OUT.json ...]');
  process.exit(2);
}

let browser;
let allOk = true;
let launchError;
try {
  browser = await launch();
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
      await page.goto(url, { timeout: LAUNCH_MS });
      await page.waitForFunction(() => window.umbracResult !== undefined, null, WAIT);
      result = await page.evaluate(() => window.umbracResult);
      result.browser = browser.version;
    } catch (e) {
      result = { ok: false, error: `driving chromium: ${e.message}` };
    } finally {
      if (page) await page.close().catch(() => {});
    }
  }
  allOk = allOk && result.ok;
  writeFileSync(out, JSON.stringify(result));
}
if (browser) await browser.close();
process.exit(allOk ? 0 : 1);
