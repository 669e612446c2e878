// What the page's tests and its timing script share: finding a browser, the page and the
// dragon tool, and reading a value out of JSON text as written.
import { existsSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { createRequire } from 'node:module';

export const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
export const pageUrl = pathToFileURL(join(root, 'docs/explorer.html')).href;
export const SKIP = 77;  // ctest's SKIP_RETURN_CODE for these tests

/** Ends the process as skipped, saying why. @param {string} why @returns {never} */
export function skip(why) {
  console.log(`SKIP: ${why}`);
  process.exit(SKIP);
}

/** Debian's headless Chromium, or its full one; null when neither is installed. */
export function findChromium() {
  for (const p of [process.env.DRAGON_CHROMIUM, '/usr/bin/chromium-headless-shell', '/usr/lib/chromium/chromium-headless-shell',
    '/usr/bin/chromium', '/usr/lib/chromium/chromium']) {
    if (p && existsSync(p)) return p;
  }
  return null;
}

/** playwright-core from web/node_modules (scripts/web.sh --test-deps installs it), or null. */
export async function loadPlaywright() {
  try {
    const require = createRequire(join(root, 'web/package.json'));
    return require('playwright-core');
  } catch {
    return null;
  }
}

/** Launches the browser, or skips the test with the reason it cannot. */
export async function launch() {
  const exe = findChromium();
  if (!exe) skip('no Chromium (apt-get install chromium-headless-shell, or bash scripts/web.sh --test-deps)');
  const pw = await loadPlaywright();
  if (!pw) skip('no playwright-core in web/node_modules (bash scripts/web.sh --test-deps)');
  if (!existsSync(join(root, 'docs/explorer.html'))) skip('no docs/explorer.html (bash scripts/web.sh)');
  // Root may not use Chromium's sandbox.
  const args = process.getuid && process.getuid() === 0 ? ['--no-sandbox'] : [];
  return pw.chromium.launch({ executablePath: exe, args });
}

/**
 * The text of the value at a dotted key path ("first_contact.time") inside JSON text, exactly as
 * written there; undefined when there is no such key.
 * @param {string} text @param {string} path
 */
export function jsonLeafText(text, path) {
  let i = 0;
  const ws = () => { while (/\s/.test(text[i] ?? '')) ++i; };
  /** Skips one value and returns its text. */
  const value = () => {
    ws();
    const start = i;
    if (text[i] === '"') {
      ++i;
      while (text[i] !== '"') i += text[i] === '\\' ? 2 : 1;
      ++i;
    } else if (text[i] === '{' || text[i] === '[') {
      let depth = 0;
      do {
        const c = text[i];
        if (c === '"') { ++i; while (text[i] !== '"') i += text[i] === '\\' ? 2 : 1; }
        else if (c === '{' || c === '[') ++depth;
        else if (c === '}' || c === ']') --depth;
        ++i;
      } while (depth > 0);
    } else {
      while (i < text.length && !/[,}\]\s]/.test(text[i])) ++i;
    }
    return text.slice(start, i);
  };
  /** In the object at i, the value of `key`; i then at that value's start. */
  const find = (/** @type {string} */ key) => {
    ws();
    if (text[i] !== '{') return false;
    ++i;
    for (;;) {
      ws();
      if (text[i] === '}') return false;
      const k = JSON.parse(value());
      ws();
      ++i;  // the colon
      if (k === key) { ws(); return true; }
      value();
      ws();
      if (text[i] === ',') ++i;
    }
  };
  for (const key of path.split('.')) if (!find(key)) return undefined;
  return value();
}
