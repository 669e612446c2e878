// The page's speed in Debian's headless Chromium (scripts/bench-web.sh; not a test): how soon it
// is ready, what a frame costs while playing, how soon Q2 and all the answers follow a change.
// Prints a Markdown table for docs/performance.md.
import { statSync } from 'node:fs';
import { join } from 'node:path';
import { launch, pageUrl, root } from './browser.mjs';

const median = (/** @type {number[]} */ xs) => { const s = [...xs].sort((a, b) => a - b); return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2; };
const pct = (/** @type {number[]} */ xs, /** @type {number} */ p) => { const s = [...xs].sort((a, b) => a - b); return s[Math.min(s.length - 1, Math.floor(p * s.length))]; };
const runs = Number(process.env.RUNS ?? 5);

const browser = await launch();
const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
await context.setOffline(true);

// Ready: from opening the file to the engine compiled and the first frame drawn; all answers of
// the first load (a cold engine in a fresh worker).
const ready = [], firstAll = [], firstQ2 = [];
for (let i = 0; i < runs; ++i) {
  const page = await context.newPage();
  await page.goto(pageUrl);
  await page.waitForSelector('body[data-ready="true"]');
  await page.waitForFunction(() => document.body.dataset.answers === 'done', null, { timeout: 60000 });
  const m = await page.evaluate(() => ({
    ready: performance.getEntriesByName('ready')[0].duration,
    q2: performance.getEntriesByName('answer:collide')[0].startTime - performance.getEntriesByName('ready')[0].duration,
    all: performance.getEntriesByName('answers:done')[0].startTime - performance.getEntriesByName('ready')[0].duration,
  }));
  ready.push(m.ready); firstQ2.push(m.q2); firstAll.push(m.all);
  await page.close();
}

const page = await context.newPage();
await page.goto(pageUrl + '#t=0');
await page.waitForSelector('body[data-ready="true"]');
await page.waitForFunction(() => document.body.dataset.answers === 'done', null, { timeout: 60000 });

// Playing: 4 s at 20x over the contest's coiling in; each frame's measure, and the gaps between frames.
const play = await page.evaluate(async () => {
  performance.clearMeasures('frame');
  const gaps = [];
  let last = 0;
  await new Promise((done) => {
    const tick = (/** @type {number} */ now) => {
      if (last) gaps.push(now - last);
      last = now;
      if (gaps.length < 240) requestAnimationFrame(tick); else done(undefined);
    };
    /** @type {HTMLSelectElement} */ (document.getElementById('rate')).value = '20';
    document.getElementById('rate')?.dispatchEvent(new Event('change'));
    document.getElementById('play')?.click();
    requestAnimationFrame(tick);
  });
  document.getElementById('play')?.click();
  return { frames: performance.getEntriesByName('frame').map((m) => m.duration), gaps };
});

// A change: the time from the value set to Q2 on the page, and to every answer (a warm worker).
const q2 = [], all = [], searches = /** @type {Record<string, number[]>} */ ({});
for (let i = 0; i < runs; ++i) {
  const m = await page.evaluate(async (width) => {
    performance.clearMarks();
    performance.clearMeasures();
    const f = /** @type {HTMLInputElement} */ (document.getElementById('f-width'));
    const t0 = performance.now();
    f.value = String(width);
    f.dispatchEvent(new Event('input'));
    await new Promise((done) => {
      const check = () => (performance.getEntriesByName('answers:done').length ? done(undefined) : setTimeout(check, 5));
      check();
    });
    const at = (/** @type {string} */ n) => performance.getEntriesByName(n)[0].startTime - t0;
    const own = Object.fromEntries(['collide', 'gaps', 'max-speed', 'turnaround', 'min-pitch'].map((c) => [c, performance.getEntriesByName(c)[0].duration]));
    return { q2: at('answer:collide'), all: at('answers:done'), own };
  }, i % 2 ? 0.3 : 0.29);
  q2.push(m.q2); all.push(m.all);
  for (const [c, v] of Object.entries(m.own)) (searches[c] ??= []).push(v);
}
// The minimum-pitch map (525 cells), with MAP=1 (a minute or more).
let mapSeconds = NaN;
if (process.env.MAP === '1') {
  const t0 = Date.now();
  await page.click('#map-start');
  await page.waitForFunction(() => map.cells.length > 0 && map.done === map.cells.length && map.running === 0, null, { timeout: 300000, polling: 500 });
  mapSeconds = (Date.now() - t0) / 1000;
}
await browser.close();

const f1 = (/** @type {number} */ x) => x.toFixed(1);
const bytes = statSync(join(root, 'docs/explorer.html')).size;
const dropped = play.gaps.filter((g) => g > 1000 / 60 * 1.5).length;
console.log(`| What | Target | Measured |
|---|---|---|
| The page's size | < 2.5 MB | ${(bytes / 1e6).toFixed(2)} MB |
| Ready: engine compiled, first frame drawn (from opening the file; median of ${runs} loads) | < 1 s | ${f1(median(ready))} ms |
| A frame while playing, computed and drawn (median; 95th percentile; ${play.frames.length} frames) | < 4 ms | ${f1(median(play.frames))} ms; ${f1(pct(play.frames, 0.95))} ms |
| Frames late at 60 Hz while playing (an interval over 25 ms) | none | ${dropped} of ${play.gaps.length} |
| Q2 after a change (median of ${runs} changes of the width) | < 50 ms | ${f1(median(q2))} ms |
| All five answers after a change (median of ${runs}) | < 3 s | ${f1(median(all))} ms |
| Q2 and all answers on first opening (a fresh worker; median of ${runs}) | | ${f1(median(firstQ2))} ms; ${f1(median(firstAll))} ms |
| The minimum-pitch map, 525 cells, one worker per core (MAP=1) | < 60 s | ${Number.isNaN(mapSeconds) ? 'not run' : `${mapSeconds.toFixed(1)} s`} |
| Each search alone in the worker, median: ${Object.entries(searches).map(([c, v]) => `${c} ${f1(median(v))} ms`).join(', ')} | | |`);
