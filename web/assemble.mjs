// Assembles docs/explorer.html: the page's template with its style, the gallery's themes, the
// engine (emscripten's one file of JavaScript with the wasm inside), the worker and the page's
// scripts, all inline, so that the one file opens from file:// with no request anywhere.
//   node web/assemble.mjs ENGINE_JS OUT_HTML
import { readFileSync, writeFileSync, renameSync, statSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { sourcesDigest } from './sources.mjs';

const web = dirname(fileURLToPath(import.meta.url));
const root = join(web, '..');
const [enginePath, outPath] = process.argv.slice(2);
if (!enginePath || !outPath) {
  console.error('usage: node web/assemble.mjs ENGINE_JS OUT_HTML');
  process.exit(2);
}
const MAX_BYTES = 2.5e6;

const read = (/** @type {string} */ p) => readFileSync(p, 'utf8');

/** A theme file's colours: `key = "#rrggbb"` lines and the speed_ramp array. @param {string} text */
function themeColours(text) {
  /** @type {Record<string, string | string[]>} */
  const out = {};
  for (const line of text.split('\n')) {
    const m = line.match(/^\s*([a-z_]+)\s*=\s*(.+?)\s*(#[^"\]]*)?$/);
    if (!m) continue;
    const [, key, value] = m;
    if (value.startsWith('[')) out[key] = [...value.matchAll(/"(#[0-9a-fA-F]{6,8})"/g)].map((x) => x[1]);
    else if (/^"#[0-9a-fA-F]{6,8}"$/.test(value)) out[key] = value.slice(1, -1);
  }
  return out;
}

/** Script text that cannot end its <script> element early. @param {string} js */
const inline = (js) => js.replace(/<\/(script)/gi, '<\\/$1').replace(/<!--/g, '<\\!--');

const themes = {
  light: themeColours(read(join(root, 'assets/themes/light.toml'))),
  dark: themeColours(read(join(root, 'assets/themes/dark.toml'))),
};
const app = ['i18n.js', 'scene.js', 'app.js'].map((f) => `// ---- web/src/${f}\n${read(join(web, 'src', f))}`).join('\n');
const parts = {
  STYLE: read(join(web, 'src/style.css')),
  THEMES: `const DRAGON_THEMES = ${JSON.stringify(themes)};`,
  ENGINE: inline(read(enginePath)),
  WORKER: inline(read(join(web, 'src/worker.js'))),
  APP: inline(app),
};
let html = read(join(web, 'src/explorer.html'));
for (const [name, text] of Object.entries(parts)) {
  const marker = `/*@${name}@*/`;
  if (!html.includes(marker)) throw new Error(`template has no ${marker}`);
  html = html.replace(marker, () => text);
}
html = html.replace('<meta name="generator"', `<meta name="sources" content="${sourcesDigest(root)}">\n<meta name="generator"`);
if (/(src|href)\s*=\s*["']?(https?:)?\/\//i.test(html)) throw new Error('the page refers to a network address');
const bytes = Buffer.byteLength(html);
if (bytes > MAX_BYTES) throw new Error(`the page is ${bytes} bytes, over ${MAX_BYTES}`);
writeFileSync(outPath + '.tmp', html);
renameSync(outPath + '.tmp', outPath);
console.log(`wrote ${outPath}: ${(statSync(outPath).size / 1e6).toFixed(2)} MB`);
