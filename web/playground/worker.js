// The compiler's thread: umbrac's WebAssembly build answers one compile
// request at a time with a bundle (src/bundle.rs), so the page never
// waits on the compiler, however large the program.
//
// A panic in the compiler aborts the module (a trap): the worker reports
// it as an internal error and closes; the page starts a fresh worker.
import init, { compile, last_panic, version } from './pkg/umbrac_web.js';

const wasmUrl = new URL('umbrac_web_bg.wasm', self.location.href);
const ready = init({ module_or_path: wasmUrl });

self.onmessage = async (e) => {
  const { id, name, source, options } = e.data;
  try {
    await ready;
  } catch (err) {
    self.postMessage({ id, error: `loading the compiler: ${err}` });
    return;
  }
  const t0 = performance.now();
  try {
    const bundle = compile(name, source, JSON.stringify(options || {}));
    self.postMessage({ id, bundle, ms: performance.now() - t0, version: version() });
  } catch (err) {
    let why = '';
    try { why = last_panic(); } catch (_) { /* the instance is gone */ }
    self.postMessage({ id, error: `internal compiler error: ${why || err}`, ms: performance.now() - t0, dead: true });
    self.close();
  }
};
