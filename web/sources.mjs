// The files docs/explorer.html is built from, and one digest of them all: web/assemble.mjs
// writes it into the page, and tests/web/fresh.mjs fails when the page's digest is not the
// sources' (the page is older than a change to them).
import { createHash } from 'node:crypto';
import { readFileSync, readdirSync } from 'node:fs';
import { join, relative } from 'node:path';

/** @param {string} dir @param {RegExp} name @returns {string[]} */
function filesIn(dir, name) {
  return readdirSync(dir, { withFileTypes: true })
    .filter((e) => e.isFile() && name.test(e.name))
    .map((e) => join(dir, e.name));
}

/** The page's sources under `root` (the repository), as paths relative to it, sorted. @param {string} root */
export function pageSources(root) {
  const files = [
    join(root, 'CMakeLists.txt'),
    join(root, 'src/CMakeLists.txt'),
    join(root, 'web/CMakeLists.txt'),
    join(root, 'web/bindings.cpp'),
    join(root, 'web/assemble.mjs'),
    join(root, 'web/sources.mjs'),
    ...filesIn(join(root, 'web/cmake'), /./),
    ...filesIn(join(root, 'web/src'), /\.(js|css|html|ts)$/),
    ...filesIn(join(root, 'src/core'), /\.(cpp|hpp)$/),
    ...filesIn(join(root, 'src/answers'), /\.(cpp|hpp)$/),
    ...filesIn(join(root, 'include/dragon'), /\.hpp$/),
    ...filesIn(join(root, 'assets/themes'), /\.toml$/),
  ];
  return files.map((f) => relative(root, f)).sort();
}

/** sha256 over every source's path and bytes. @param {string} root */
export function sourcesDigest(root) {
  const h = createHash('sha256');
  for (const f of pageSources(root)) {
    h.update(f + '\0');
    h.update(readFileSync(join(root, f)));
    h.update('\0');
  }
  return h.digest('hex');
}
