// How fast the playground's WebAssembly compiler is (a benchmark, not a
// test): node runs the same module Chromium does (V8), loaded from a built
// playground (scripts/build-playground.sh).
//
//   node web/playground/bench.mjs PLAYGROUND_DIR FILE.das...
//
// For each file: the median process CPU time of one compile to every
// default output (`compile_only`, the work `compile_source` does natively;
// compare docs/performance.md's `all_targets/umbrac_shadow_all_outputs`
// for shaders/shadow.das) and of the whole `compile` call the page makes
// (the bundle as JSON with the SPIR-V disassembled), after a warm-up.
import { readFileSync } from 'node:fs';
import { join, resolve, basename } from 'node:path';
import { pathToFileURL } from 'node:url';

const [dir, ...files] = process.argv.slice(2);
if (!dir || files.length === 0) {
  console.error('usage: node bench.mjs PLAYGROUND_DIR FILE.das...');
  process.exit(2);
}
const glue = await import(pathToFileURL(resolve(dir, 'umbrac_web.js')).href);
const t0 = performance.now();
await glue.default({ module_or_path: readFileSync(join(dir, 'umbrac_web_bg.wasm')) });
console.log(`instantiate: ${(performance.now() - t0).toFixed(1)} ms`);

const WARM = 30;
const RUNS = 200;
function cpuMedian(f) {
  for (let i = 0; i < WARM; i++) f();
  const t = [];
  for (let i = 0; i < RUNS; i++) {
    const s = process.cpuUsage();
    f();
    const d = process.cpuUsage(s);
    t.push(d.user + d.system);
  }
  t.sort((a, b) => a - b);
  return t[t.length >> 1];
}

console.log('| file | compile_only (us, CPU) | compile + bundle JSON (us, CPU) |');
console.log('|---|---|---|');
for (const file of files) {
  const src = readFileSync(file, 'utf8');
  const name = basename(file);
  if (!glue.compile_only(name, src)) {
    console.error(`${file} does not compile`);
    process.exit(1);
  }
  const only = cpuMedian(() => glue.compile_only(name, src));
  const whole = cpuMedian(() => glue.compile(name, src, '{}'));
  console.log(`| ${file} | ${only} | ${whole} |`);
}
