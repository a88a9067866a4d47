// Writes the playground's examples.json: the project's programs under
// shaders/ and, when ../shared/reference is there, daslang's 12 GL
// tutorials (read at build time, never committed).
//
//   node web/playground/examples.mjs REPO_ROOT OUT.json
import { readdirSync, readFileSync, existsSync, writeFileSync, statSync } from 'node:fs';
import { join, relative, sep } from 'node:path';

const [root, out] = process.argv.slice(2);
if (!root || !out) {
  console.error('usage: node examples.mjs REPO_ROOT OUT.json');
  process.exit(2);
}

function walk(dir) {
  const found = [];
  for (const name of readdirSync(dir).sort()) {
    const p = join(dir, name);
    if (statSync(p).isDirectory()) found.push(...walk(p));
    else if (name.endsWith('.das')) found.push(p);
  }
  return found;
}

// A program has an entry point (a stage annotation of either dialect).
const isProgram = (text) => /^\s*\[[a-z_]+_(program|shader)\b/m.test(text);
const slash = (p) => p.split(sep).join('/');

const examples = [];
const tutorials = join(root, '..', 'shared', 'reference', 'daslang-tutorials');
if (existsSync(tutorials)) {
  for (const name of readdirSync(tutorials).filter((n) => n.endsWith('.das')).sort()) {
    examples.push({ group: 'daslang GL tutorials', name: `tutorials/${name}`, path: name, source: readFileSync(join(tutorials, name), 'utf8') });
  }
}

// What the project's programs include: every file under an `include`
// folder, by its path under shaders/ (an example's path is too, so
// `#include "include/x.das"` resolves beside it).
const shaders = join(root, 'shaders');
const files = {};
for (const p of walk(shaders)) {
  const rel = slash(relative(shaders, p));
  const text = readFileSync(p, 'utf8');
  if (rel.split('/').includes('include')) files[rel] = text;
  else if (isProgram(text)) {
    const group = rel.includes('/') ? `shaders/${rel.split('/')[0]}` : 'shaders';
    examples.push({ group, name: `shaders/${rel}`, path: rel, source: text, shared: true });
  }
}

writeFileSync(out, JSON.stringify({ files, examples }));
console.log(`${examples.length} examples, ${Object.keys(files).length} shared files`);
