// docs/explorer.html is built from the sources it names (web/sources.mjs): fails when any of
// them changed since it was built (rebuild it with bash scripts/web.sh and commit it).
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { root } from './browser.mjs';
import { sourcesDigest } from '../../web/sources.mjs';

const html = readFileSync(join(root, 'docs/explorer.html'), 'utf8');
const built = html.match(/<meta name="sources" content="([0-9a-f]{64})">/)?.[1];
const now = sourcesDigest(root);
if (built !== now) {
  console.log(`FAIL: docs/explorer.html was built from other sources (digest ${built}, the sources' now ${now}): ` +
    'rebuild it with bash scripts/web.sh');
  process.exit(1);
}
console.log('docs/explorer.html is built from the sources as they are');
