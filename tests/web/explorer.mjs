// The page in a real browser (Debian's chromium-headless-shell through playwright-core), opened
// from file:// with the network cut off:
//  - it loads with no request leaving file:// and no error on the console;
//  - its answers (data-value) are the text `dragon <command> --json` prints for the same
//    scenario, for several scenarios, running the very command line the page shows;
//  - a refused value shows the library's refusal (role=alert, data-field) and keeps the scene;
//  - the URL's state round-trips; Chinese; a bench click; a change cancels a running search.
// Skips (exit 77) when there is no browser or no playwright-core; the comparisons with the tool
// are left out, saying so, when there is no dragon tool.
//   node tests/web/explorer.mjs [--dragon build/src/dragon]
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { jsonLeafText, launch, pageUrl, root } from './browser.mjs';

const argv = process.argv.slice(2);
const dragonArg = argv.indexOf('--dragon') >= 0 ? argv[argv.indexOf('--dragon') + 1] : null;
const dragon = [dragonArg, join(root, 'build/src/dragon'), '/work/main/build/src/dragon'].find((p) => p && existsSync(p)) ?? null;

let failures = 0;
let checks = 0;
/** @param {boolean} ok @param {string} what */
function check(ok, what) {
  ++checks;
  if (ok) return;
  ++failures;
  console.log(`FAIL: ${what}`);
}

const browser = await launch();
const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
await context.setOffline(true);
/** @type {string[]} */
const problems = [];
await context.route('**/*', (route) => {
  const url = route.request().url();
  if (/^(file|blob|data):/.test(url)) return route.continue();
  problems.push(`request to ${url}`);
  return route.abort();
});

/** A fresh page at `hash`, ready, its answers computed. @param {string} hash */
async function open(hash) {
  const page = await context.newPage();
  page.on('console', (m) => { if (m.type() === 'error' || m.type() === 'warning') problems.push(`console ${m.type()}: ${m.text().slice(0, 300)}`); });
  page.on('pageerror', (e) => problems.push(`uncaught: ${e.message}`));
  await page.goto(pageUrl + hash);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  await answersDone(page);
  return page;
}

/** @param {import('playwright-core').Page} page */
async function answersDone(page) {
  await page.waitForFunction(() => document.body.dataset.answers === 'done', null, { timeout: 60000 });
}

/** @param {import('playwright-core').Page} page @param {string} key */
async function valueOf(page, key) {
  return page.getAttribute(`[data-key="${key}"]`, 'data-value');
}

/**
 * Runs the command line an answer shows with the dragon tool and compares every listed key.
 * @param {import('playwright-core').Page} page @param {string} command @param {string[]} keys @param {string} label
 */
async function compareWithTool(page, command, keys, label) {
  const line = (await page.textContent(`[data-command="${command}"] .command code`)) ?? '';
  check(line.startsWith(`dragon ${command} --json`), `${label}: the page's command line for ${command}: ${line}`);
  if (!dragon) return;
  const args = line.split(/\s+/).slice(1);
  let out = '';
  try {
    out = execFileSync(dragon, [...args, '-q'], { encoding: 'utf8', maxBuffer: 64 << 20 });
  } catch (e) {
    check(false, `${label}: ${line} failed: ${/** @type {any} */ (e).stderr}`);
    return;
  }
  for (const key of keys) {
    const mine = await valueOf(page, `${command}.${key}`);
    const tool = jsonLeafText(out, key);
    // Every value's text as the tool prints it, to the last digit: the page and the tool compute
    // with the library's own elementary functions (dragon/portable_math.hpp), not their C
    // libraries' (musl's and glibc's round sin, atan2, asinh, ... differently in the last bit).
    check(mine !== null && mine === tool, `${label}: ${command}.${key}: page ${mine}, dragon ${tool} (${line})`);
  }
}


const Q = {
  collide: ['time', 'benches', 'head_radius', 'point', 'travel', 'evaluations', 'to', 'jam'],
  'min-pitch': ['pitch', 'intervals', 'below_range', 'above_range', 'grid'],
  turnaround: ['r1', 'r2', 'length', 'first_contact', 'clearance.distance', 'clearance.benches', 'clearance.time', 'followable'],
  'max-speed': ['max_head_speed', 'ratio', 'handle', 'time', 'tied'],
};

// 1. The contest's scenario, then others, each against the tool.
if (!dragon) console.log('NOTE: no dragon tool (build/src/dragon): the answers are not compared with its --json');
const scenarios = ['', '#pitch=0.5&width=0.28&t=300', '#bench-count=120&body-length=1.8&turn-radius=4.2&turn-pitch=1.5&arc-ratio=1.5',
  '#path=turnaround&speed=1.5&width=0.32'];
for (const hash of scenarios) {
  const page = await open(hash);
  const label = hash || 'the contest';
  for (const [command, keys] of Object.entries(Q)) await compareWithTool(page, command, keys, label);
  if (hash === '') {
    check((await valueOf(page, 'collide.time')) === '412.473837682117', `the contest's Q2: ${await valueOf(page, 'collide.time')}`);
    check((await valueOf(page, 'collide.benches')) === '[1,9]', 'the contest\'s Q2 benches');
    const measures = await page.evaluate(() => performance.getEntriesByType('measure').map((m) => m.name));
    for (const name of ['frame', 'collide', 'min-pitch', 'turnaround', 'max-speed'])
      check(measures.includes(name), `performance.measure("${name}") missing`);
  }
  await page.close();
}

// 2. A refused value: the library's sentence beside the field, the last good scene kept.
{
  const page = await open('#t=100');
  const before = await valueOf(page, 'collide.time');
  await page.fill('#f-width', '0.6');
  const alert = page.locator('[role="alert"][data-field="width"]');
  await alert.waitFor({ timeout: 5000 });
  const text = (await alert.textContent()) ?? '';
  check(text.includes('pitch 0.55 is not allowed with width 0.6'), `the refusal's words: ${text}`);
  check((await page.evaluate(() => state.keys.width)) === 0.3, 'the last good scene stays after a refusal');
  check((await valueOf(page, 'collide.time')) === before, 'the answers stay after a refusal');
  check(!(await page.evaluate(() => location.hash)).includes('width=0.6'), 'a refused value stays out of the URL');
  await page.fill('#f-pitch', '-1');
  await page.locator('[role="alert"][data-field="pitch"]').waitFor({ timeout: 5000 });
  check((await page.locator('[role="alert"][data-field="width"]').count()) === 0, 'an earlier refusal is cleared');
  await page.fill('#f-pitch', '0.55');
  await page.fill('#f-width', '0.3');
  check((await page.locator('[role="alert"]').count()) === 0, 'a good value clears the refusals');
  await page.close();
}

// 3. The URL round-trips: the state read from it is written back; a change goes into it.
{
  const page = await open('#pitch=0.5&width=0.28&t=300&lang=zh');
  check((await page.inputValue('#f-pitch')) === '0.5', 'pitch from the URL');
  check((await page.inputValue('#f-width')) === '0.28', 'width from the URL');
  check((await page.inputValue('#time')) === '300', 'time from the URL');
  check((await page.evaluate(() => document.documentElement.lang)) === 'zh-CN', 'lang=zh sets the language');
  check(((await page.textContent('h1')) ?? '').includes('板凳龙'), 'the title in Chinese');
  check(((await page.textContent('#answers')) ?? '').includes('首次碰撞'), 'the answers in Chinese');
  await page.waitForTimeout(400);
  const hash = await page.evaluate(() => location.hash);
  for (const part of ['pitch=0.5', 'width=0.28', 't=300', 'lang=zh']) check(hash.includes(part), `the URL keeps ${part}: ${hash}`);
  await page.fill('#f-body-length', '2.1');
  await answersDone(page);
  await page.waitForTimeout(400);
  const changed = await page.evaluate(() => location.hash);
  check(changed.includes('body-length=2.1'), `a change goes into the URL: ${changed}`);
  const again = await open(changed);
  check((await again.inputValue('#f-body-length')) === '2.1', 'the changed URL opens the same scenario');
  check((await valueOf(again, 'collide.time')) === (await valueOf(page, 'collide.time')), 'the same answers from the same URL');
  await again.close();
  await page.close();
}

// 4. A bench clicked is followed; a change cancels a running search and the answers are the last scenario's.
{
  const page = await open('#t=0');
  const at = await page.evaluate(() => {
    const d = /** @type {any} */ (state.scene);
    const o = 3 * d.handles + 6 * 9;  // bench 10's centre
    const c = /** @type {HTMLCanvasElement} */ (document.getElementById('scene'));
    const r = c.getBoundingClientRect();
    const [x, y] = toScreen(state.cam, c.clientWidth, c.clientHeight, d.data[o], d.data[o + 1]);
    return { x: r.left + x, y: r.top + y };
  });
  await page.mouse.click(at.x, at.y);
  await page.waitForTimeout(200);
  check((await page.evaluate(() => state.selected)) === 10, 'a click selects the bench under it');
  check(((await page.textContent('#bench-info')) ?? '').startsWith('Bench 10'), 'the followed bench is described');
  // Keys: space plays and pauses, arrows step.
  await page.focus('#scene');
  await page.keyboard.press('Space');
  await page.waitForTimeout(400);
  check(await page.evaluate(() => state.playing && state.t > 0), 'space plays');
  await page.keyboard.press('Space');
  const t = await page.evaluate(() => state.t);
  check(await page.evaluate(() => !state.playing), 'space pauses');
  await page.keyboard.press('ArrowRight');
  check(Math.abs((await page.evaluate(() => state.t)) - (t + 1)) < 1e-9, 'the right arrow steps 1 s');
  // A change while the answers are searched (Q4 takes the longest) ends that search.
  await page.fill('#f-start-turn', '14');
  await page.waitForFunction(() => document.querySelector('[data-command="turnaround"].pending') !== null);
  await page.waitForTimeout(50);
  const before = Number(await page.evaluate(() => document.body.dataset.cancelled ?? 0));
  await page.fill('#f-start-turn', '15');
  await answersDone(page);
  check(Number(await page.evaluate(() => document.body.dataset.cancelled ?? 0)) === before + 1, 'a change ends the running search');
  await compareWithTool(page, 'min-pitch', ['pitch'], 'after a cancelled search');
  await compareWithTool(page, 'collide', ['time'], 'after a cancelled search');
  await page.close();
}

// 5. The scene at the first contact against a stored picture, within a tolerance (fonts and
// anti-aliasing may move a few pixels); DRAGON_REBASELINE=1 stores it anew (look at it!).
{
  const page = await context.newPage();
  await page.setViewportSize({ width: 1280, height: 900 });
  await page.goto(pageUrl + '#t=412.473837682');
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  await answersDone(page);
  await page.waitForTimeout(200);
  const shot = await page.locator('#scene').screenshot();
  await page.close();
  const golden = join(root, 'tests/web/golden/scene_contact.png');
  if (process.env.DRAGON_REBASELINE === '1' || !existsSync(golden)) {
    mkdirSync(join(root, 'tests/web/golden'), { recursive: true });
    writeFileSync(golden, shot);
    console.log(`NOTE: stored ${golden}`);
  } else {
    const blank = await context.newPage();
    const diff = await blank.evaluate(async ([a, b]) => {
      const pixels = async (/** @type {string} */ b64) => {
        const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
        const c = new OffscreenCanvas(bitmap.width, bitmap.height);
        const g = /** @type {OffscreenCanvasRenderingContext2D} */ (c.getContext('2d'));
        g.drawImage(bitmap, 0, 0);
        return g.getImageData(0, 0, bitmap.width, bitmap.height);
      };
      const [x, y] = [await pixels(a), await pixels(b)];
      if (x.width !== y.width || x.height !== y.height) return { size: `${x.width}x${x.height} against ${y.width}x${y.height}`, fraction: 1 };
      let off = 0;
      for (let i = 0; i < x.data.length; i += 4) {
        const d = Math.max(Math.abs(x.data[i] - y.data[i]), Math.abs(x.data[i + 1] - y.data[i + 1]), Math.abs(x.data[i + 2] - y.data[i + 2]));
        if (d > 48) ++off;
      }
      return { size: '', fraction: off / (x.width * x.height) };
    }, [shot.toString('base64'), readFileSync(golden).toString('base64')]);
    await blank.close();
    check(diff.fraction < 0.005, `the scene at the first contact differs from tests/web/golden/scene_contact.png: ${diff.size || `${(100 * diff.fraction).toFixed(2)} % of its pixels`}`);
  }
}

check(problems.length === 0, `offline and quiet: ${problems.join('; ')}`);
await browser.close();
console.log(`${checks - failures} of ${checks} checks passed${dragon ? ` (answers compared with ${dragon})` : ''}`);
process.exit(failures ? 1 : 0);
