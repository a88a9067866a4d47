// The playground page: a CodeMirror 6 editor over umbrac's compiler in
// WebAssembly (worker.js), every output side by side, examples, share
// links, and the live preview (preview.js), which each good bundle is
// handed to. docs/preview.md, "Playground".
//
// Served by `umbrac preview FILE` (under /playground/, with a
// `live.json` beside it), the page holds FILE: each bundle the server
// compiles from disk (its Server-Sent Events) puts the file's text in the
// editor and is shown and drawn as it is; edits typed here compile in the
// page's WebAssembly as anywhere else.
import { EditorView, basicSetup } from 'codemirror';
import { EditorState } from '@codemirror/state';
import { StreamLanguage } from '@codemirror/language';
import { python } from '@codemirror/legacy-modes/mode/python';
import { setDiagnostics, forEachDiagnostic, lintGutter } from '@codemirror/lint';
import LZString from 'lz-string';
import { mountPreview } from './preview.js';

// Quiet time after the last keystroke before a compile starts.
const DEBOUNCE_MS = 250;
// A compile still running this long while newer text waits is cut off
// (the worker is replaced), so a pathological program cannot stall edits.
const STALE_COMPILE_MS = 5000;

const $ = (id) => document.getElementById(id);

// ---- the compiler worker ------------------------------------------------

let worker = null;
let running = null; // { id, version, started }
let waiting = null; // the newest request not yet sent
let nextId = 1;
let docVersion = 0;
let lastGood = null;
// Results of compiles asked for before this id are dropped: the file was
// reloaded from disk since.
let dropBefore = 0;
// Set while the editor's text is replaced by the file's from disk, so
// that the change does not start a compile of its own.
let fromDisk = false;

function startWorker() {
  worker = new Worker('worker.js', { type: 'module' });
  worker.onmessage = (e) => onResult(e.data);
  worker.onerror = (e) => onResult({ id: running && running.id, error: `the compiler worker failed: ${e.message}`, dead: true });
}

function request() {
  const source = mainSource();
  waiting = { name: fileName, source, options: options(), version: docVersion };
  pump();
}

function pump() {
  if (running) {
    if (waiting && performance.now() - running.started > STALE_COMPILE_MS) {
      worker.terminate();
      startWorker();
      showStatus(`a compile ran over ${STALE_COMPILE_MS / 1000} s and was stopped`, 'warn');
      running = null;
    } else {
      return;
    }
  }
  if (!waiting) return;
  const req = waiting;
  waiting = null;
  running = { id: nextId++, version: req.version, started: performance.now() };
  worker.postMessage({ id: running.id, name: req.name, source: req.source, options: req.options });
}

setInterval(() => { if (running && waiting) pump(); }, 500);

function onResult(msg) {
  if (!running || msg.id !== running.id) return;
  const version = running.version;
  running = null;
  if (msg.dead) startWorker();
  if (msg.id < dropBefore) {
    pump();
    return;
  }
  if (msg.error) {
    state.lastVersion = version;
    showStatus(msg.error, 'error');
  } else {
    const bundle = JSON.parse(msg.bundle);
    state.compiles += 1;
    state.lastMs = msg.ms;
    state.lastBundle = bundle;
    state.lastVersion = version;
    if (msg.version) $('version').textContent = `umbrac ${msg.version}`;
    // Positions are only good for the text they were computed from.
    // (and are the program's: none are marked in another file).
    if (version === docVersion && !active) showDiagnostics(bundle);
    showOutputs(bundle);
    const errors = bundle.diagnostics.filter((d) => d.severity === 'error' || d.severity === 'bug').length;
    showStatus(bundle.ok ? `compiled in ${msg.ms.toFixed(1)} ms` : `${errors} error${errors === 1 ? '' : 's'} (${msg.ms.toFixed(1)} ms)`, bundle.ok ? 'ok' : 'error');
    if (bundle.ok) draw(bundle);
  }
  pump();
}

function draw(bundle) {
  lastGood = bundle;
  previewPanel.dispatchEvent(new CustomEvent('umbrac-bundle', { detail: bundle }));
}

// ---- under `umbrac preview`: the file on disk ---------------------------------

// live.json's contents when served by `umbrac preview`, else null.
let live = null;

async function findLive() {
  try {
    const r = await fetch('live.json', { cache: 'no-store' });
    return r.ok ? await r.json() : null;
  } catch (_) {
    return null;
  }
}

// A bundle the server compiled from disk: its text replaces the editor's
// (unsaved edits typed here give way to the saved file, as in an editor
// that reloads a file changed on disk), and it is shown and drawn as is.
function fromServer(bundle, id) {
  const src = bundle.source || {};
  fileName = src.name || live.file;
  exampleFiles = src.files || {};
  listFiles();
  clearTimeout(timer);
  waiting = null;
  dropBefore = nextId;
  if (typeof src.text === 'string' && src.text !== mainSource()) {
    fromDisk = true;
    try { setSource(src.text); } finally { fromDisk = false; }
  }
  state.lastVersion = docVersion;
  state.lastBundle = bundle;
  live.received = id;
  if (!active) showDiagnostics(bundle);
  showOutputs(bundle);
  const errors = bundle.diagnostics.filter((d) => d.severity === 'error' || d.severity === 'bug').length;
  showStatus(bundle.ok ? `${fileName}: compiled by umbrac preview (compile ${id})` : `${fileName}: ${errors} error${errors === 1 ? '' : 's'} (compile ${id})`, bundle.ok ? 'ok' : 'error');
  if (bundle.ok) draw(bundle);
}

function startLive(cfg) {
  live = { file: cfg.file, received: 0 };
  fileName = cfg.file;
  defines = cfg.defines || {};
  if (cfg.conventions) $('conventions').value = cfg.conventions;
  // The menu names the served file, not "(a shared program)".
  const served = new Option(cfg.file, 'live');
  $('examples').prepend(served);
  $('examples').value = 'live';
  showStatus(`waiting for umbrac preview's compile of ${cfg.file}`, 'warn');
  const events = new EventSource(cfg.events);
  events.addEventListener('bundle', (e) => fromServer(JSON.parse(e.data), +e.lastEventId));
}

// ---- options ------------------------------------------------------------

let fileName = 'playground.das';
let exampleFiles = {};
// `-D`s of the preview server's compiles, for the page's own.
let defines = {};

// ---- several files ------------------------------------------------------------
//
// The editor holds the program (`fileName`) or one of the files it may
// `#include` or `require` (`exampleFiles`, by their paths beside it, as the
// compiler's file seam takes them); the file menu switches. Every compile
// is of the program, with the files as they are now.

// The path of the file in the editor: '' for the program.
let active = '';
// The program's text while another file is in the editor.
let mainText = '';

function mainSource() {
  return active ? mainText : view.state.doc.toString();
}

function listFiles() {
  const sel = $('file');
  const paths = Object.keys(exampleFiles).sort();
  if (active && !paths.includes(active)) openFile('');
  sel.replaceChildren(new Option(fileName, ''), ...paths.map((p) => new Option(p, p)));
  sel.value = active;
  sel.parentElement.hidden = paths.length === 0;
}

function openFile(path) {
  if (path === active) return;
  const text = path ? exampleFiles[path] : mainText;
  if (text === undefined) return;
  if (!active) mainText = view.state.doc.toString();
  active = path;
  switching = true;
  try { view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: text } }); } finally { switching = false; }
  view.dispatch(setDiagnostics(view.state, []));
  $('file').value = path;
}

// Set while openFile swaps the editor's text: no edit, no compile.
let switching = false;

// An edit to the file in the editor.
function edited() {
  if (active) exampleFiles = { ...exampleFiles, [active]: view.state.doc.toString() };
}

function options() {
  return { conventions: $('conventions').value, files: exampleFiles, defines };
}

// ---- diagnostics in the editor --------------------------------------------

// umbrac's columns count characters; CodeMirror's offsets count UTF-16 units.
function offsetOf(doc, line, column) {
  if (line < 1) return 0;
  if (line > doc.lines) return doc.length;
  const l = doc.line(line);
  let off = 0;
  let chars = 1;
  while (chars < column && off < l.length) {
    const code = l.text.charCodeAt(off);
    off += code >= 0xd800 && code < 0xdc00 ? 2 : 1;
    chars += 1;
  }
  return l.from + off;
}

// Where a diagnostic shows in the edited file: its own place, or (in an
// included file) the `#include` that brought it in; a file-less one at the top.
function placeOf(d) {
  const here = (loc) => loc && loc.file === fileName;
  if (here(d.location)) return d.location;
  return (d.include_chain || []).find(here) || null;
}

function showDiagnostics(bundle) {
  const doc = view.state.doc;
  const list = [];
  for (const d of bundle.diagnostics) {
    const loc = placeOf(d);
    let from = 0;
    let to = 0;
    if (loc) {
      from = offsetOf(doc, loc.line, loc.column);
      to = Math.max(from, offsetOf(doc, loc.end_line, loc.end_column));
    }
    const severity = d.severity === 'warning' ? 'warning' : d.severity === 'note' ? 'info' : 'error';
    const notes = d.notes && d.notes.length ? `\n${d.notes.join('\n')}` : '';
    list.push({ from, to, severity, message: `${d.message}${d.label ? ` (${d.label})` : ''}${notes}`, source: 'umbrac' });
  }
  view.dispatch(setDiagnostics(view.state, list));
  $('diagnostics').textContent = bundle.diagnostics.map((d) => d.rendered).join('');
}

// ---- outputs ---------------------------------------------------------------

const PANELS = [
  { key: 'glsl330', title: 'GLSL 330', pick: (f) => f.target === 'glsl330' || f.target === 'glsl430' },
  { key: 'gles300', title: 'GLSL ES 3.00', pick: (f) => f.target === 'gles300' || f.target === 'gles310' },
  { key: 'wgsl', title: 'WGSL', pick: (f) => f.target === 'wgsl' },
  { key: 'spirv', title: 'SPIR-V', pick: (f) => f.target === 'spirv' },
  { key: 'manifest', title: 'Manifest', pick: (f) => !f.target },
];

function buildPanels() {
  const host = $('outputs');
  for (const p of PANELS) {
    const sec = document.createElement('section');
    sec.className = 'panel';
    sec.id = `out-${p.key}`;
    sec.innerHTML = `<header><span class="title">${p.title}</span><select></select></header><pre class="code"></pre>`;
    host.appendChild(sec);
    p.select = sec.querySelector('select');
    p.pre = sec.querySelector('pre');
    p.files = [];
    p.select.onchange = () => showFile(p);
  }
}

function textOf(f) {
  if (f.text !== undefined) return f.text;
  if (f.disassembly !== undefined) return f.disassembly;
  if (f.words) return `; ${f.words.length} words (no disassembly in this build)`;
  return '';
}

function showFile(p) {
  const f = p.files[p.select.selectedIndex];
  p.pre.textContent = f ? textOf(f) : '';
}

function showOutputs(bundle) {
  for (const p of PANELS) {
    const files = bundle.files.filter(p.pick);
    // A failed compile leaves the last good outputs, dimmed.
    p.pre.parentElement.classList.toggle('stale', !bundle.ok);
    if (!bundle.ok) continue;
    const chosen = p.select.value;
    p.files = files;
    p.select.innerHTML = '';
    for (const f of files) p.select.add(new Option(f.name, f.name));
    p.select.hidden = files.length < 2;
    if (files.some((f) => f.name === chosen)) p.select.value = chosen;
    if (files.length === 0) p.pre.textContent = '(no output for this target)';
    else showFile(p);
  }
}

// ---- status, examples, share links --------------------------------------

function showStatus(text, kind) {
  const s = $('status');
  s.textContent = text;
  s.className = kind;
}

let examples = [];
let sharedFiles = {};

async function loadExamples() {
  try {
    const r = await fetch('examples.json');
    const data = await r.json();
    examples = data.examples || [];
    sharedFiles = data.files || {};
  } catch (_) {
    examples = [];
  }
  const sel = $('examples');
  sel.add(new Option('(a shared program)', ''));
  const groups = new Map();
  for (const [i, ex] of examples.entries()) {
    if (!groups.has(ex.group)) {
      const g = document.createElement('optgroup');
      g.label = ex.group;
      groups.set(ex.group, g);
      sel.appendChild(g);
    }
    groups.get(ex.group).appendChild(new Option(ex.name, String(i)));
  }
  sel.onchange = () => {
    const ex = sel.value === '' ? null : examples[Number(sel.value)];
    if (ex) openExample(ex);
  };
}

function openExample(ex) {
  // The example's path and the files it includes, by their paths beside it.
  fileName = ex.path;
  exampleFiles = ex.shared ? sharedFiles : {};
  openFile('');
  listFiles();
  $('examples').value = String(examples.indexOf(ex));
  setSource(ex.source);
  history.replaceState(null, '', `#example=${encodeURIComponent(ex.name)}`);
}

function shareLink() {
  const packed = LZString.compressToEncodedURIComponent(mainSource());
  const url = new URL(location.href);
  url.hash = `code=${packed}&name=${encodeURIComponent(fileName)}`;
  // The files the program may read, one compressed JSON object.
  if (Object.keys(exampleFiles).length) url.hash += `&files=${LZString.compressToEncodedURIComponent(JSON.stringify(exampleFiles))}`;
  return url.toString();
}

function fromHash() {
  const params = new URLSearchParams(location.hash.slice(1));
  if (params.has('code')) {
    const text = LZString.decompressFromEncodedURIComponent(params.get('code'));
    let files = {};
    try {
      files = params.has('files') ? JSON.parse(LZString.decompressFromEncodedURIComponent(params.get('files'))) : {};
    } catch (_) {
      files = null;
    }
    const good = files && typeof files === 'object' && Object.values(files).every((t) => typeof t === 'string');
    if (text !== null && good) {
      fileName = params.get('name') || 'playground.das';
      exampleFiles = files;
      openFile('');
      listFiles();
      $('examples').value = '';
      return { source: text };
    }
    showStatus('the share link is damaged', 'error');
  }
  if (params.has('example')) {
    const ex = examples.find((e) => e.name === params.get('example'));
    if (ex) return { example: ex };
  }
  return null;
}

// ---- the editor ------------------------------------------------------------

let timer = null;
const state = { compiles: 0, lastMs: 0, lastBundle: null, lastVersion: -1 };

const view = new EditorView({
  parent: $('editor'),
  state: EditorState.create({
    doc: '',
    extensions: [
      basicSetup,
      StreamLanguage.define(python),
      lintGutter(),
      EditorView.updateListener.of((u) => {
        if (!u.docChanged) return;
        if (switching) return;
        docVersion += 1;
        edited();
        if (fromDisk) return;
        clearTimeout(timer);
        timer = setTimeout(request, DEBOUNCE_MS);
      }),
    ],
  }),
});

function setSource(text) {
  openFile('');
  view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: text } });
}

const previewPanel = $('preview');
const preview = mountPreview(previewPanel);

// What tests and the preview module read; nothing here changes the page.
window.umbracPlayground = {
  view,
  state,
  preview,
  get lastGood() { return lastGood; },
  setSource,
  source: mainSource,
  // The files beside the program ({ path: text }), the one in the editor
  // ('' for the program), and switching it.
  files: () => exampleFiles,
  get active() { return active; },
  openFile,
  setFiles(files) { exampleFiles = { ...files }; listFiles(); request(); },
  shareLink,
  settled: () => running === null && waiting === null && state.lastVersion === docVersion,
  // Under `umbrac preview`: { file, received (the last bundle's number) }; else null.
  get live() { return live; },
  // The editor's own lint marks: [{ line, severity, message }].
  marks: () => {
    const out = [];
    forEachDiagnostic(view.state, (d, from) => out.push({ line: view.state.doc.lineAt(from).number, severity: d.severity, message: d.message }));
    return out;
  },
};

async function main() {
  buildPanels();
  startWorker();
  $('conventions').onchange = request;
  $('file').onchange = () => openFile($('file').value);
  $('share').onclick = async () => {
    const link = shareLink();
    history.replaceState(null, '', link);
    $('share-link').value = link;
    try { await navigator.clipboard.writeText(link); showStatus('share link copied', 'ok'); } catch (_) { /* no clipboard: the field shows it */ }
  };
  const [cfg] = await Promise.all([findLive(), loadExamples()]);
  if (cfg) {
    startLive(cfg);
    return;
  }
  const start = fromHash();
  if (start && start.source !== undefined) setSource(start.source);
  else if (start && start.example) openExample(start.example);
  else if (examples.length) openExample(examples[0]);
  else setSource('var @out f_color : float4\n\n[fragment_program]\ndef main_fs {\n    f_color = float4(1.0, 0.5, 0.25, 1.0)\n}\n');
  window.addEventListener('hashchange', () => {
    const again = fromHash();
    if (again && again.source !== undefined && again.source !== mainSource()) setSource(again.source);
  });
}

main();
