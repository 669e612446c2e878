// @ts-check
// The page: the scenario's keys, the time, the scene, the answers from the worker, the URL.
// Everything the page shows is computed by the engine (web/bindings.cpp over the library):
// frames here, on demand; the questions' searches in a Web Worker.

/**
 * A scenario key as the CLI's flag names it, with its unit and the slider's span (the number
 * field takes any value; the library says which it refuses).
 * @typedef {{ flag: string, unit: string, min: number, max: number, step: number, group: string, integer?: boolean }} KeySpec
 */
/** @type {KeySpec[]} */
const KEYS = [
  { flag: 'bench-count', unit: '', min: 3, max: 400, step: 1, group: 'bench', integer: true },
  { flag: 'head-length', unit: 'm', min: 1, max: 6, step: 0.01, group: 'bench' },
  { flag: 'body-length', unit: 'm', min: 0.8, max: 4, step: 0.01, group: 'bench' },
  { flag: 'width', unit: 'm', min: 0.1, max: 0.8, step: 0.005, group: 'bench' },
  { flag: 'hole-offset', unit: 'm', min: 0, max: 0.6, step: 0.005, group: 'bench' },
  { flag: 'speed', unit: 'm/s', min: 0.1, max: 3, step: 0.01, group: 'bench' },
  { flag: 'pitch', unit: 'm', min: 0.3, max: 1.2, step: 0.001, group: 'spiral' },
  { flag: 'start-turn', unit: '', min: 2, max: 32, step: 0.5, group: 'spiral' },
  { flag: 'turn-radius', unit: 'm', min: 1, max: 10, step: 0.05, group: 'turn' },
  { flag: 'turn-pitch', unit: 'm', min: 0.6, max: 3, step: 0.01, group: 'turn' },
  { flag: 'arc-ratio', unit: '', min: 0.25, max: 5, step: 0.05, group: 'turn' },
];
const BENCH_KEYS = ['bench-count', 'head-length', 'body-length', 'width', 'hole-offset', 'speed'];
/** The scenario flags each command takes (as `dragon <command> --help` lists them). */
const TAKES = {
  spiral: [...BENCH_KEYS, 'pitch', 'start-turn'],
  drawSpiral: [...BENCH_KEYS, 'pitch', 'start-turn', 'turn-radius'],
  turnaround: [...BENCH_KEYS, 'turn-radius', 'turn-pitch', 'arc-ratio'],
  'min-pitch': [...BENCH_KEYS, 'start-turn', 'turn-radius'],
};
/** The questions the worker answers, in the order it answers them (Q2 first: it is wanted at once). */
const COMMANDS = ['collide', 'gaps', 'max-speed', 'turnaround', 'min-pitch'];
/** The handles the paper's tables show. */
const PAPER_HANDLES = [0, 1, 51, 101, 151, 201, 223];

const $ = (/** @type {string} */ id) => /** @type {HTMLElement} */ (document.getElementById(id));

const state = {
  /** @type {Lang} */ lang: 'en',
  theme: 'light',
  path: 'spiral',
  /** @type {Record<string, number>} */ defaults: {},
  /** @type {Record<string, number>} */ keys: {},  // the last scenario the engine took
  t: 0,
  tmin: 0,
  tmax: 1,
  playing: false,
  rate: 1,
  speedColours: false,
  selected: 0,
  /** @type {Camera} */ cam: { cx: 0, cy: 0, k: 20 },
  fitted: true,  // the camera follows fit() until the reader pans or zooms
  version: 0,
  /** @type {DragonRange | null} */ range: null,
  /** @type {Record<string, any>} */ answers: {},
  /** @type {{ x: number, y: number, a: number, b: number, time: number } | null} */ contact: null,
  /** @type {{ points: Float64Array, pieces: { from: number, to: number, colour: string }[] }} */
  path_: { points: new Float64Array(0), pieces: [] },
  /** @type {SceneData | null} */ scene: null,
};

/** @type {DragonEngine} */
let engine;

const say = (/** @type {string} */ key, /** @type {(string | number)[]} */ ...args) => tr(state.lang, key, ...args);
const theme = () => DRAGON_THEMES[state.theme];

// ---------------------------------------------------------------------------------------------
// The scenario

/** The keys the engine and the worker are given: every value, and the path. */
function engineKeys(/** @type {Record<string, number>} */ keys) {
  return { ...keys, path: state.path };
}

/**
 * Offers the engine a scenario; on refusal shows it beside `field` and keeps the last good one.
 * @param {Record<string, number>} keys @param {string} field the flag just changed ('' for none)
 * @returns {boolean} whether the engine took it
 */
function applyScenario(keys, field) {
  const refused = engine.setScenario(engineKeys(keys));
  clearAlerts();
  if (refused) {
    const at = refused.flags.includes(field) ? field : refused.flags[0] ?? field;
    showAlert(at || 'pitch', refused.error);
    engine.setScenario(engineKeys(state.keys));  // the last good scene stays
    return false;
  }
  state.keys = { ...keys };
  state.version += 1;
  state.range = engine.range();
  setTimeRange();
  runAnswers();  // first: the worker searches while this thread prepares the scene
  mapFollow();
  buildPath();
  state.contact = null;
  if (state.fitted) fit();
  updateReadouts();
  requestDraw();
  scheduleHash();  // the URL follows within a quarter second, as it does while playing
  return true;
}

/** The scrubber's span: the spiral from t = 0 to the end of its valid motion; the turnaround's 100 m either side of the turn. */
function setTimeRange() {
  const r = /** @type {DragonRange} */ (state.range);
  const v = state.keys.speed;
  if (state.path === 'spiral') {
    state.tmin = Math.max(0, r.from);
    state.tmax = r.to;
  } else {
    state.tmin = Math.max(r.from, -100 / v);
    state.tmax = Math.min(r.to, 100 / v);
  }
  const s = /** @type {HTMLInputElement} */ ($('scrubber'));
  s.min = String(state.tmin);
  s.max = String(state.tmax);
  state.t = clamp(state.t, state.tmin, state.tmax);
}

function chainLength() {
  const k = state.keys;
  const link = (/** @type {number} */ len) => len - 2 * k['hole-offset'];
  return link(k['head-length']) + (k['bench-count'] - 1) * link(k['body-length']);
}

/** The values the path is made of (the library's PathSpec): the benches, the speed and the
 * other keys move the dragon along it, not the path itself. */
const PATH_KEYS = ['pitch', 'start-turn', 'turn-radius', 'turn-pitch', 'arc-ratio'];
let pathKey = '';
/** How many times the path's points were made: the backdrop is drawn again when they change. */
let pathVersion = 0;

/** The path's points for the backdrop, cut into its coloured pieces; kept while the path and the
 * stretch of it shown are the same (a change of a bench's width or the speed leaves both). */
function buildPath() {
  const th = theme();
  const chain = chainLength();
  const s0 = engine.headArcAt(state.tmin) - chain - 4;
  let s1 = state.path === 'spiral' ? 0 : engine.headArcAt(state.tmax) + 4;
  const step = Math.max(0.02, (s1 - s0) / 12000);  // enough for a smooth line at any zoom that shows the chain
  const key = [state.path, ...PATH_KEYS.map((f) => state.keys[f]), s0, s1, step, state.theme].join('|');
  if (key === pathKey) return;
  pathKey = key;
  pathVersion += 1;
  const points = engine.pathPoints(s0, s1, step).slice();
  const n = points.length / 2;
  /** @type {{ from: number, to: number, colour: string }[]} */
  let pieces = [{ from: 0, to: n, colour: th.guide }];
  if (state.path === 'turnaround' && n > 1) {
    const d = engine.sCurve();
    const a = engine.headArcAt(0), b = a + d.length;
    const at = (/** @type {number} */ s) => clamp(Math.round(((s - s0) / (s1 - s0)) * (n - 1)), 0, n - 1);
    pieces = [
      { from: 0, to: at(a) + 1, colour: th.guide },
      { from: at(a), to: at(b) + 1, colour: th.s_curve },
      { from: at(b), to: n, colour: th.guide_out },
    ];
  }
  state.path_ = { points, pieces };
}

// ---------------------------------------------------------------------------------------------
// The scenario's fields

function buildFields() {
  const box = $('fields');
  box.textContent = '';
  for (const group of ['bench', 'spiral', 'turn']) {
    const fs = document.createElement('fieldset');
    const lg = document.createElement('legend');
    lg.textContent = say(`group_${group}`);
    fs.append(lg);
    for (const spec of KEYS.filter((k) => k.group === group)) fs.append(fieldFor(spec));
    box.append(fs);
  }
}

/** @param {KeySpec} spec */
function fieldFor(spec) {
  const f = spec.flag;
  const row = document.createElement('div');
  row.className = 'field';
  row.dataset.flag = f;
  const label = document.createElement('label');
  label.htmlFor = `f-${f}`;
  label.textContent = say(`key.${f}`);
  if (spec.unit) {
    const u = document.createElement('span');
    u.className = 'unit';
    u.textContent = ` (${spec.unit})`;
    label.append(u);
  }
  const slider = document.createElement('input');
  slider.type = 'range';
  slider.id = `r-${f}`;
  slider.min = String(spec.min);
  slider.max = String(spec.max);
  slider.step = String(spec.step);
  slider.setAttribute('aria-label', say(`key.${f}`));
  const num = document.createElement('input');
  num.type = 'number';
  num.id = `f-${f}`;
  num.name = f;
  num.step = spec.integer ? '1' : 'any';
  num.inputMode = 'decimal';
  const reset = document.createElement('button');
  reset.type = 'button';
  reset.className = 'reset';
  reset.textContent = '↺';
  reset.title = say('reset', state.defaults[f]);
  reset.setAttribute('aria-label', say('reset', state.defaults[f]));
  const set = (/** @type {number} */ v) => {
    const keys = { ...state.keys, [f]: v };
    if (!applyScenario(keys, f)) return;
  };
  slider.addEventListener('input', () => {
    num.value = slider.value;
    set(Number(slider.value));
  });
  num.addEventListener('input', () => {
    const v = num.value.trim() === '' ? NaN : Number(num.value);
    if (Number.isFinite(v)) {
      slider.value = String(v);
      set(v);
    }
  });
  num.addEventListener('change', () => {
    const v = num.value.trim() === '' ? NaN : Number(num.value);
    if (!Number.isFinite(v)) {
      clearAlerts();
      showAlert(f, `${say(`key.${f}`)}: ${num.value === '' ? '""' : num.value} — ${state.lang === 'zh' ? '请输入数值' : 'give a number'}`);
    }
  });
  reset.addEventListener('click', () => {
    num.value = String(state.defaults[f]);
    slider.value = num.value;
    set(state.defaults[f]);
  });
  const controls = document.createElement('div');
  controls.className = 'controls';
  controls.append(slider, num, reset);
  row.append(label, controls);
  return row;
}

/** The fields show the scenario the engine has. */
function syncFields() {
  for (const spec of KEYS) {
    const v = state.keys[spec.flag];
    const num = /** @type {HTMLInputElement} */ ($(`f-${spec.flag}`));
    const slider = /** @type {HTMLInputElement} */ ($(`r-${spec.flag}`));
    if (document.activeElement !== num) num.value = String(v);
    slider.value = String(v);
    const used = state.path === 'spiral' ? TAKES.drawSpiral.includes(spec.flag) || spec.flag === 'turn-pitch' || spec.flag === 'arc-ratio'
      : true;
    num.closest('.field')?.classList.toggle('other-path', !used);
  }
}

/** @param {string} flag @param {string} message */
function showAlert(flag, message) {
  const row = document.querySelector(`.field[data-flag="${flag}"]`);
  const p = document.createElement('p');
  p.className = 'refusal';
  p.setAttribute('role', 'alert');
  p.dataset.field = flag;
  p.textContent = message;
  (row ?? $('fields')).append(p);
  row?.querySelector('input[type=number]')?.setAttribute('aria-invalid', 'true');
}

function clearAlerts() {
  document.querySelectorAll('[role=alert][data-field]').forEach((e) => e.remove());
  document.querySelectorAll('[aria-invalid]').forEach((e) => e.removeAttribute('aria-invalid'));
}

// ---------------------------------------------------------------------------------------------
// The answers, from a Web Worker. A change ends a running worker and takes the spare one.

/** @type {string} */
let workerSource = '';
/**
 * A worker, the promise of its engine, and whether that has come (`live`: a message can go at once).
 * @typedef {{ worker: Worker, ready: Promise<void>, live: boolean }} AnswerWorker
 */
/** @type {AnswerWorker | null} */
let current = null;
/** @type {AnswerWorker | null} */
let spare = null;
let busy = false;
let runId = 0;

/** @type {Promise<WebAssembly.Module>} */
let wasmModule;

function spawnWorker() {
  const url = URL.createObjectURL(new Blob([workerSource], { type: 'text/javascript' }));
  const worker = new Worker(url);
  wasmModule.then((module) => worker.postMessage({ type: 'init', module }));
  const ready = new Promise((resolve, reject) => {
    worker.addEventListener('message', function first(e) {
      if (e.data.type === 'ready') { worker.removeEventListener('message', first); resolve(undefined); }
      if (e.data.type === 'error') reject(new Error(e.data.message));
    });
  });
  worker.addEventListener('message', onWorkerMessage);
  worker.addEventListener('error', (e) => console.error('worker:', e.message));
  /** @type {AnswerWorker} */
  const w = { worker, ready, live: false };
  ready.then(() => { w.live = true; }, () => {});
  return w;
}

/** Sends `msg` to a worker: at once when its engine is ready (not after the task that asks, as a
 * promise's callback would: a change's search starts while this thread draws), else when it is.
 * @param {AnswerWorker} w @param {object} msg */
function postTo(w, msg) {
  if (w.live) w.worker.postMessage(msg);
  else w.ready.then(() => w.worker.postMessage(msg), (e) => showEngineError(e));
}

let restartTimer = 0;

/** Asks for the answers of the scenario now: at once when the worker is free; a running search is
 * ended and a spare worker takes over, once the changes pause (a dragged slider is many changes). */
function runAnswers() {
  clearTimeout(restartTimer);
  if (busy && current) {
    runId += 1;  // what the running search still sends is for an older scenario
    for (const c of COMMANDS) showPending(c);
    restartTimer = window.setTimeout(() => {
      if (!busy || !current) return postRun();
      current.worker.terminate();  // cancel the running search
      document.body.dataset.cancelled = String(Number(document.body.dataset.cancelled ?? 0) + 1);
      current = spare;
      spare = null;
      postRun();
    }, 60);
    return;
  }
  postRun();
}

function postRun() {
  if (!current) current = spawnWorker();
  if (!spare) spare = spawnWorker();
  runId += 1;
  busy = true;
  state.answers = {};
  for (const c of COMMANDS) showPending(c);
  const msg = { type: 'run', id: runId, keys: engineKeys(state.keys), commands: COMMANDS, window: [state.tmin, state.tmax] };
  postTo(current, msg);
}

/** @param {MessageEvent} e */
function onWorkerMessage(e) {
  const m = e.data;
  if (m.type === 'cell' || m.type === 'mapdone') return onMapMessage(m);
  if (m.type === 'done' && current && e.target === current.worker) busy = false;
  if (m.id !== runId) return;
  if (m.type === 'progress') {
    const box = document.querySelector(`[data-command="${m.command}"] .status`);
    if (box) box.textContent = say('progress', m.done, m.total);
  } else if (m.type === 'result') {
    // The search's own time, on this page's clock.
    const start = m.start - performance.timeOrigin, end = m.end - performance.timeOrigin;
    performance.measure(m.command, { start, end });
    performance.mark(`answer:${m.command}`);  // when the page has it: a change's latency ends here
    state.answers[m.command] = { ...m.result, ms: end - start };
    showAnswer(m.command);
  } else if (m.type === 'done') {
    performance.mark('answers:done');
    document.body.dataset.answers = 'done';
  }
}

/** @param {string} command */
function showPending(command) {
  document.body.dataset.answers = 'running';
  const box = document.querySelector(`[data-command="${command}"]`);
  if (!box) return;
  box.classList.add('pending');
  const status = box.querySelector('.status');
  if (status) status.textContent = say('computing');
}

/** @param {unknown} e */
function showEngineError(e) {
  $('status-line').textContent = say('engine_error', String(e));
}

/**
 * A value of an answer as the command's --json prints it, carrying data-key and data-value.
 * @param {string} command @param {string} key @param {string} shown
 */
function valueSpan(command, key, shown) {
  const a = state.answers[command];
  const span = document.createElement('span');
  span.className = 'value';
  span.dataset.key = `${command}.${key}`;
  if (a && a.leaves && key in a.leaves) span.dataset.value = a.leaves[key];
  span.textContent = shown;
  return span;
}

/**
 * A sentence whose {0}, {1}, ... are answer values (each its own element).
 * @param {string} template the words with {i} @param {(string | Node)[]} parts
 */
function sentence(template, parts) {
  const p = document.createElement('p');
  const bits = template.split(/\{(\d)\}/);
  bits.forEach((b, i) => {
    if (i % 2 === 0) p.append(b);
    else p.append(parts[Number(b)] ?? '');
  });
  return p;
}

/** @param {string} command */
function showAnswer(command) {
  const box = document.querySelector(`[data-command="${command}"]`);
  const a = state.answers[command];
  if (command === 'gaps') {
    drawGapChart();
    return;
  }
  if (!box) return;
  box.classList.remove('pending');
  /** @type {HTMLElement} */ (box.querySelector('.status')).textContent = say('computed_in', a.ms.toFixed(1));
  const body = /** @type {HTMLElement} */ (box.querySelector('.body'));
  body.textContent = '';
  if (a.error) {
    const p = document.createElement('p');
    p.className = 'refused';
    p.textContent = a.error;
    body.append(p);
    return;
  }
  const j = JSON.parse(a.json);
  const L = a.leaves;
  const v = (/** @type {string} */ key) => valueSpan(command, key, L[key] ?? '');
  if (command === 'collide') {
    if (j.overlap_at_start) {
      // The chain collides before it moves: the library's verdict, as the tool says it.
      const o = j.overlap_at_start;
      body.append(sentence(words(state.lang, 'q2_overlap'), [String(o.benches[0]), String(o.benches[1]), o.depth.toFixed(6)]));
      state.contact = null;
    } else if (j.time !== null) {
      body.append(sentence(words(state.lang, 'q2_at'), [v('time'), String(j.benches[0]), String(j.benches[1])]));
      body.querySelector('p')?.append(' ', valueSpan(command, 'benches', ''));
      body.append(sentence(words(state.lang, 'q2_radius'), [v('head_radius')]));
      const jump = document.createElement('button');
      jump.type = 'button';
      jump.textContent = say('jump');
      jump.addEventListener('click', () => { state.playing = false; setTime(j.time); });
      body.append(jump);
      state.contact = { x: j.point[0], y: j.point[1], a: j.benches[0], b: j.benches[1], time: j.time };
    } else {
      body.append(sentence(words(state.lang, 'q2_none'), []));
      state.contact = null;
    }
    requestDraw();
    drawGapChart();
  } else if (command === 'min-pitch') {
    if (j.below_range) body.append(sentence(words(state.lang, 'q3_below'), []));
    else if (j.above_range) body.append(sentence(words(state.lang, 'q3_above'), []));
    else body.append(sentence(words(state.lang, 'q3_pitch'), [v('pitch')]));
    const ul = document.createElement('ul');
    ul.className = 'intervals';
    for (const i of j.intervals) {
      const li = document.createElement('li');
      li.textContent = `[${i.lo.toFixed(10)}, ${i.hi.toFixed(10)}] m  ${say(i.feasible ? 'q3_free' : 'q3_collides')}`;
      li.className = i.feasible ? 'free' : 'collides';
      ul.append(li);
    }
    body.append(ul, valueSpan(command, 'intervals', ''));
  } else if (command === 'turnaround') {
    body.append(sentence(words(state.lang, 'q4_arcs'), [v('r1'), v('r2'), v('length')]));
    if (j.first_contact) {
      body.append(sentence(words(state.lang, 'q4_contact'), [v('first_contact.time'), String(j.first_contact.benches[0]), String(j.first_contact.benches[1])]));
    } else if (j.clearance) {
      body.append(sentence(words(state.lang, 'q4_clear'), [v('clearance.distance'), String(j.clearance.benches?.[0] ?? j.clearance.bench_a ?? ''), String(j.clearance.benches?.[1] ?? j.clearance.bench_b ?? '')]));
    }
  } else if (command === 'max-speed') {
    if (j.unbounded) body.append(sentence(words(state.lang, 'q5_unbounded'), []));
    else if (j.max_head_speed === null) body.append(sentence(words(state.lang, 'q5_no_turn'), []));
    else body.append(sentence(words(state.lang, 'q5_speed'), [v('max_head_speed'), v('ratio'), v('handle'), v('time')]));
  }
  // Every key of the answer, each with its data-key and data-value.
  const details = document.createElement('details');
  const summary = document.createElement('summary');
  summary.textContent = say('all_keys');
  details.append(summary);
  const table = document.createElement('table');
  table.className = 'leaves';
  for (const [key, text] of Object.entries(L)) {
    if (text.length > 160) continue;  // every handle: in the JSON
    const tr_ = table.insertRow();
    tr_.insertCell().textContent = key;
    tr_.insertCell().append(valueSpan(command, key, text));
  }
  const copyJson = document.createElement('button');
  copyJson.type = 'button';
  copyJson.textContent = say('copy_json');
  copyJson.addEventListener('click', () => copyText(a.json, copyJson));
  details.append(table, copyJson);
  body.append(details);
}

/** The answers' boxes, each with its command line. */
function buildAnswers() {
  const box = $('answer-list');
  box.textContent = '';
  for (const [command, title] of [['q1', 'q1'], ['collide', 'q2'], ['min-pitch', 'q3'], ['turnaround', 'q4'], ['max-speed', 'q5']]) {
    const sec = document.createElement('section');
    sec.className = 'answer';
    sec.dataset.command = command;
    const h = document.createElement('h3');
    h.className = 'title';
    h.textContent = say(title, '');
    const status = document.createElement('span');
    status.className = 'status';
    const head = document.createElement('div');
    head.className = 'answer-head';
    head.append(h, status);
    const body = document.createElement('div');
    body.className = 'body';
    const cmd = document.createElement('div');
    cmd.className = 'command';
    const code = document.createElement('code');
    const copy = document.createElement('button');
    copy.type = 'button';
    copy.className = 'small';
    copy.textContent = say('copy');
    copy.addEventListener('click', () => copyText(code.textContent ?? '', copy));
    cmd.append(code, copy);
    sec.append(head, body, cmd);
    box.append(sec);
  }
  const q1 = /** @type {HTMLElement} */ (document.querySelector('[data-command="q1"] .body'));
  const table = document.createElement('table');
  table.id = 'q1-table';
  q1.append(table);
  const buttons = document.createElement('div');
  buttons.className = 'buttons';
  const csv = document.createElement('button');
  csv.type = 'button';
  csv.textContent = say('q1_csv');
  csv.addEventListener('click', () => download(`dragon_t${+state.t.toFixed(3)}.csv`, frameCsv([state.t]), 'text/csv'));
  const full = document.createElement('button');
  full.type = 'button';
  full.textContent = say('q1_table');
  full.addEventListener('click', () => {
    const times = [];
    for (let t = Math.ceil(state.tmin); t <= Math.min(state.tmax, state.path === 'spiral' ? 300 : 100); t += 1) times.push(t);
    download('result1.csv', frameCsv(times), 'text/csv');
  });
  buttons.append(csv, full);
  q1.append(buttons);
  for (const c of COMMANDS) if (state.answers[c]) showAnswer(c); else showPending(c);
  updateCommands();
}

/** The dragon command of each answer, with the flags it takes that differ from the defaults. */
function updateCommands() {
  const flags = (/** @type {string[]} */ takes) =>
    takes.filter((f) => state.keys[f] !== state.defaults[f]).map((f) => ` --${f} ${state.keys[f]}`).join('');
  const onPath = state.path === 'spiral' ? TAKES.spiral : TAKES.turnaround;
  const pathFlag = state.path === 'turnaround' ? ' --path turnaround' : '';
  /** @type {Record<string, string>} */
  const lines = {
    q1: `dragon simulate${pathFlag}${flags(onPath)} --from ${+state.t.toPrecision(12)} --to ${+state.t.toPrecision(12)} -o frame.csv`,
    collide: `dragon collide --json${pathFlag}${flags(onPath)}`,
    'min-pitch': `dragon min-pitch --json${flags(TAKES['min-pitch'])}`,
    turnaround: `dragon turnaround --json${flags(TAKES.turnaround)}`,
    'max-speed': `dragon max-speed --json${flags(TAKES.turnaround)}`,
  };
  for (const [c, line] of Object.entries(lines)) {
    const code = document.querySelector(`[data-command="${c}"] .command code`);
    if (code) code.textContent = line;
  }
  const h = document.querySelector('[data-command="q1"] .title');
  if (h) h.textContent = say('q1', fmtTime(state.t));
  const q2 = document.querySelector('[data-command="collide"] .title');
  if (q2) q2.textContent = say(state.path === 'spiral' ? 'q2' : 'q2_path_turn');
}

/** The view's command: `dragon render` at this moment. */
function viewCommand() {
  const takes = state.path === 'spiral' ? TAKES.drawSpiral : TAKES.turnaround;
  const flags = takes.filter((f) => state.keys[f] !== state.defaults[f]).map((f) => ` --${f} ${state.keys[f]}`).join('');
  return `dragon render${state.path === 'turnaround' ? ' --path turnaround' : ''}${flags} --time ${+state.t.toPrecision(12)}` +
    `${state.speedColours ? ' --speed-colours' : ''}${state.lang === 'zh' ? ' --lang zh' : ''}${state.theme === 'dark' ? ' --theme dark' : ''} -o view.png`;
}

function pythonCall() {
  const takes = state.path === 'spiral' ? TAKES.drawSpiral : TAKES.turnaround;
  const args = takes.filter((f) => state.keys[f] !== state.defaults[f]).map((f) => `${f.replace(/-/g, '_')}=${state.keys[f]}`);
  return [
    'import benchdragon as bd',
    `sc = bd.Scenario(${args.join(', ')})`,
    `print(bd.collide(sc${state.path === 'turnaround' ? ', path="turnaround"' : ''}).to_dict())`,
    `bd.render(bd.Simulation(sc${state.path === 'turnaround' ? ', path="turnaround"' : ''}), t=${+state.t.toPrecision(12)}${state.speedColours ? ', speed_colours=True' : ''})`,
  ].join('\n');
}

/** The scenario as the tool reads it (--scenario FILE.toml): one key a value, each named as its
 * flag with underscores (the page's URL key is the flag's name: --bench-count, #bench-count=). */
function scenarioToml() {
  const k = state.keys;
  return [
    '# A scenario saved by docs/explorer.html: dragon <command> --scenario this.toml',
    `path = "${state.path}"`,
    ...KEYS.map(({ flag }) => `${flag.replace(/-/g, '_')} = ${k[flag]}`),
    '',
  ].join('\n');
}

/** The frames at `times` in the tool's long-form CSV (t,handle,x,y,speed; 6 decimals). @param {number[]} times */
function frameCsv(times) {
  const out = ['t,handle,x,y,speed'];
  for (const t of times) {
    const f = engine.frame(t);
    const n = state.keys['bench-count'] + 1;
    const ts = trimTime(t);
    for (let i = 0; i < n; ++i) out.push(`${ts},${i},${fixed6(f[3 * i])},${fixed6(f[3 * i + 1])},${fixed6(f[3 * i + 2])}`);
  }
  engine.frame(state.t);  // the engine's last frame is the scene's again
  return out.join('\n') + '\n';
}

/** @param {number} v */
function fixed6(v) {
  const s = v.toFixed(6);
  return s === '-0.000000' ? '0.000000' : s;
}
/** @param {number} t */
function trimTime(t) {
  const s = t.toFixed(6).replace(/0+$/, '').replace(/\.$/, '');
  return s === '-0' ? '0' : s;
}

/** @param {string} name @param {string | Blob} data @param {string} type */
function download(name, data, type) {
  const blob = typeof data === 'string' ? new Blob([data], { type }) : data;
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

/** @param {string} text @param {HTMLElement} button */
function copyText(text, button) {
  const done = () => {
    const was = button.textContent;
    button.textContent = say('copied');
    setTimeout(() => { button.textContent = was; }, 1200);
  };
  if (navigator.clipboard && window.isSecureContext) navigator.clipboard.writeText(text).then(done, () => fallbackCopy(text, done));
  else fallbackCopy(text, done);
}

/** @param {string} text @param {() => void} done */
function fallbackCopy(text, done) {
  const ta = document.createElement('textarea');
  ta.value = text;
  document.body.append(ta);
  ta.select();
  try { document.execCommand('copy'); } catch { /* nothing more to try */ }
  ta.remove();
  done();
}

// ---------------------------------------------------------------------------------------------
// The minimum-pitch map (assets/sweeps/min_pitch_map.toml's grid): on demand, in a worker of its
// own, cell by cell; started again when a value it depends on changes.

const linspace = (/** @type {number} */ a, /** @type {number} */ b, /** @type {number} */ n) =>
  Array.from({ length: n }, (_, i) => +(a + ((b - a) * i) / (n - 1)).toFixed(10));
const MAP = { widths: linspace(0.2, 0.4, 21), lengths: linspace(1.6, 2.8, 25), lo: 0.09, hi: 0.25, grid: 0.005 };
const MAP_WORKERS = Math.max(1, Math.min(4, navigator.hardwareConcurrency || 2));  // the map's cells split between them
const map = {
  /** @type {AnswerWorker[]} */ workers: [],
  running: 0,
  id: 0,
  key: '',
  /** @type {(number | null)[]} */ cells: [],
  done: 0,
  started: 0,
  seconds: 0,
};

/** The values a map's cells depend on (not the pitch, width, body length, speed or turnaround's). */
function mapKey() {
  return ['bench-count', 'head-length', 'hole-offset', 'start-turn', 'turn-radius'].map((f) => state.keys[f]).join('|');
}

function startMap() {
  for (const w of map.workers) w.worker.terminate();
  map.id += 1;
  map.key = mapKey();
  map.cells = new Array(MAP.widths.length * MAP.lengths.length).fill(null);
  map.done = 0;
  map.started = performance.now();
  /** @type {number[][][]} */
  const shares = Array.from({ length: MAP_WORKERS }, () => []);
  MAP.widths.forEach((w, i) => MAP.lengths.forEach((len, j) => shares[(i * MAP.lengths.length + j) % MAP_WORKERS].push([i, j, w, len])));
  map.workers = shares.map(() => spawnWorker());
  map.running = map.workers.length;
  map.workers.forEach((w, k) => {
    const msg = { type: 'map', id: map.id, keys: { ...engineKeys(state.keys), path: 'spiral' }, cells: shares[k], lo: MAP.lo, hi: MAP.hi, grid: MAP.grid };
    postTo(w, msg);
  });
  $('map-start').textContent = say('map_restart');
  drawMap();
}

/** @param {any} m */
function onMapMessage(m) {
  if (m.id !== map.id) return;
  if (m.type === 'cell') {
    map.cells[m.i * MAP.lengths.length + m.j] = m.error || Number.isNaN(m.pitch) ? NaN : m.pitch;
    map.done += 1;
  } else if (--map.running === 0) {
    map.seconds = (performance.now() - map.started) / 1000;
    for (const w of map.workers) w.worker.terminate();
    map.workers = [];
  }
  drawMap();
}

let mapTimer = 0;
/** A change of the scenario: a map of other values is computed again, once the changes pause. */
function mapFollow() {
  if (!map.cells.length || map.key === mapKey()) return drawMap();
  clearTimeout(mapTimer);
  mapTimer = window.setTimeout(startMap, 400);
}

function drawMap() {
  const c = /** @type {HTMLCanvasElement} */ (document.getElementById('map-chart'));
  if (!c || !boxSize(c).w) return;
  const { g, w, h, th } = chartContext('map-chart');
  const nw = MAP.widths.length, nl = MAP.lengths.length, total = nw * nl;
  $('map-status').textContent = !map.cells.length ? '' : map.done < total ? say('map_status', map.done, total)
    : say('map_done', total, map.seconds.toFixed(1));
  $('map-axes').textContent = say('map_axes', MAP.widths[0], MAP.widths[nw - 1], MAP.lengths[0], MAP.lengths[nl - 1]);
  const L = 44, R = 70, T = 6, B = 6;
  const cw = (w - L - R) / nw, ch = (h - T - B) / nl;
  const vals = /** @type {number[]} */ (map.cells.filter((v) => v !== null && !Number.isNaN(v)));
  const lo = vals.length ? Math.min(...vals) : 0, hi = vals.length ? Math.max(...vals) : 1;
  for (let i = 0; i < nw; ++i) for (let j = 0; j < nl; ++j) {
    const v = map.cells[i * nl + j];
    g.fillStyle = v === null || v === undefined ? th.grid : Number.isNaN(v) ? th.guide : rampColour(DRAGON_THEMES.light.speed_ramp, (v - lo) / (hi - lo || 1));
    g.fillRect(L + i * cw, h - B - (j + 1) * ch, Math.ceil(cw), Math.ceil(ch));
  }
  // This scenario's place on the map.
  const wi = (state.keys.width - MAP.widths[0]) / (MAP.widths[1] - MAP.widths[0]);
  const lj = (state.keys['body-length'] - MAP.lengths[0]) / (MAP.lengths[1] - MAP.lengths[0]);
  if (wi > -0.5 && wi < nw - 0.5 && lj > -0.5 && lj < nl - 0.5) {
    g.strokeStyle = th.text;
    g.lineWidth = 2;
    g.strokeRect(L + Math.round(wi) * cw, h - B - (Math.round(lj) + 1) * ch, cw, ch);
  }
  g.fillStyle = th.text;
  g.fillText(`${MAP.lengths[nl - 1]}`, 4, T + 10);
  g.fillText(`${MAP.lengths[0]}`, 4, h - B);
  if (vals.length) {
    g.fillText(`${hi.toFixed(4)} m`, w - R + 6, T + 10);
    g.fillText(`${lo.toFixed(4)} m`, w - R + 6, h - B);
  }
}

/** A click on the map loads that cell's width and body length. @param {MouseEvent} e */
function onMapClick(e) {
  const c = /** @type {HTMLCanvasElement} */ (e.currentTarget);
  const nw = MAP.widths.length, nl = MAP.lengths.length;
  const i = Math.floor(((e.offsetX - 44) / (c.clientWidth - 114)) * nw);
  const j = Math.floor(((c.clientHeight - 6 - e.offsetY) / (c.clientHeight - 12)) * nl);
  if (i < 0 || i >= nw || j < 0 || j >= nl) return;
  applyScenario({ ...state.keys, width: MAP.widths[i], 'body-length': MAP.lengths[j] }, 'width');
}

// ---------------------------------------------------------------------------------------------
// Time

/** @param {number} t */
function setTime(t) {
  state.t = clamp(t, state.tmin, state.tmax);
  requestDraw();
  scheduleHash();
}

/** @param {number} seconds of the motion */
function step(seconds) {
  state.playing = false;
  setTime(state.t + seconds);
}

let lastTick = 0;
/** @param {number} now */
function tick(now) {
  if (!state.playing) return;
  const dt = lastTick ? Math.min(0.1, (now - lastTick) / 1000) : 0;
  lastTick = now;
  let t = state.t + dt * state.rate;
  if (t >= state.tmax) { t = state.tmax; state.playing = false; }
  state.t = t;
  draw();
  scheduleHash();
  if (state.playing) requestAnimationFrame(tick);
  else updatePlay();
}

function togglePlay() {
  if (!state.playing && state.t >= state.tmax) state.t = state.tmin;
  state.playing = !state.playing;
  lastTick = 0;
  updatePlay();
  if (state.playing) requestAnimationFrame(tick);
}

function updatePlay() {
  const b = $('play');
  b.textContent = state.playing ? '❚❚' : '▶';
  b.setAttribute('aria-label', say(state.playing ? 'pause' : 'play'));
  b.title = say(state.playing ? 'pause' : 'play');
}

// ---------------------------------------------------------------------------------------------
// The scene

const canvas = /** @type {HTMLCanvasElement} */ (document.getElementById('scene'));
const ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));

/** Each canvas's size in CSS pixels as the last layout left it, told by a ResizeObserver. Reading
 * clientWidth while the page has changed since (a new value in a field, "computing…" in the
 * answers) lays the page out there and then: a forced layout in every change and every frame.
 * @type {Map<Element, { w: number, h: number }>} */
const boxSizes = new Map();
const sizeWatch = new ResizeObserver((entries) => {
  for (const e of entries) {
    const el = /** @type {HTMLElement} */ (e.target);
    boxSizes.set(el, { w: el.clientWidth, h: el.clientHeight });  // laid out now: no extra layout
  }
  if (state.fitted && entries.some((e) => e.target === canvas)) fit();  // the view fits the new size
  else requestDraw();
  // The map's words are written beside it: in the next frame, not while sizes are being told.
  if (entries.some((e) => e.target.id === 'map-chart')) requestAnimationFrame(drawMap);
});
/** A canvas's CSS size (its first time read directly, and watched from then on). @param {HTMLElement} el */
function boxSize(el) {
  let s = boxSizes.get(el);
  if (!s) {
    s = { w: el.clientWidth, h: el.clientHeight };
    boxSizes.set(el, s);
    sizeWatch.observe(el);
  }
  return s;
}
const backdrop = document.createElement('canvas');
let backdropKey = '';
let drawPending = false;

function requestDraw() {
  if (drawPending || state.playing) return;
  drawPending = true;
  requestAnimationFrame(() => { drawPending = false; draw(); });
}

function canvasSize() {
  const dpr = window.devicePixelRatio || 1;
  const { w, h } = boxSize(canvas);
  if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
    canvas.width = Math.round(w * dpr);
    canvas.height = Math.round(h * dpr);
  }
  return { w, h, dpr };
}

/** Computes the frame at state.t and draws it: one performance.measure("frame"). */
function draw() {
  if (!engine || !state.range) return;
  const t0 = performance.now();
  const { w, h, dpr } = canvasSize();
  if (!canvas.width || !canvas.height) return;  // not laid out
  const data = engine.frame(state.t).slice();  // a copy: a view of the engine's memory ends if it grows
  const gaps = engine.gaps();
  const n = state.keys['bench-count'];
  /** @type {SceneData} */
  const d = {
    handles: n + 1, benches: n, data, headSpeed: state.keys.speed, turnRadius: state.keys['turn-radius'],
    path: state.path_, gaps, contact: state.contact, t: state.t, selected: state.selected,
    nearest: state.selected > 0 && state.selected <= n ? engine.nearestTo(state.selected) : null,
    speedColours: state.speedColours, lang: state.lang,
  };
  state.scene = d;
  const th = theme();
  // The backdrop is the turning space and the path (their values are the path's): drawn again
  // only when the path, the theme, the size or the view changed.
  const key = `${pathVersion}|${state.theme}|${w}x${h}@${dpr}|${state.cam.cx},${state.cam.cy},${state.cam.k}`;
  if (key !== backdropKey) {
    backdrop.width = canvas.width;
    backdrop.height = canvas.height;
    const b = /** @type {CanvasRenderingContext2D} */ (backdrop.getContext('2d'));
    b.setTransform(dpr, 0, 0, dpr, 0, 0);
    drawBackdrop(b, w, h, state.cam, th, d);
    backdropKey = key;
  }
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.drawImage(backdrop, 0, 0);
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  drawChain(ctx, w, h, state.cam, th, d, say);
  updateFrameReadouts(d);
  performance.measure('frame', { start: t0, end: performance.now() });
  if (++frameCount % 1000 === 0) performance.clearMeasures('frame');
}
let frameCount = 0;

/** Fits the whole chain now and the turning space in the view. */
function fit() {
  if (!engine || !state.range) return;
  const f = engine.frame(state.t);
  let x0 = -state.keys['turn-radius'], x1 = -x0, y0 = x0, y1 = x1;
  const n = state.keys['bench-count'] + 1;
  for (let i = 0; i < n; ++i) {
    x0 = Math.min(x0, f[3 * i]); x1 = Math.max(x1, f[3 * i]);
    y0 = Math.min(y0, f[3 * i + 1]); y1 = Math.max(y1, f[3 * i + 1]);
  }
  const pad = 1.5;
  const w = boxSize(canvas).w || 600, h = boxSize(canvas).h || 600;
  state.cam = { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, k: Math.min(w / (x1 - x0 + 2 * pad), h / (y1 - y0 + 2 * pad)) };
  state.fitted = true;
  requestDraw();
}

/** @param {number} factor @param {number} sx @param {number} sy screen point kept in place */
function zoom(factor, sx, sy) {
  const { w, h } = boxSize(canvas);
  const [wx, wy] = toWorld(state.cam, w, h, sx, sy);
  const k = clamp(state.cam.k * factor, 0.5, 5e4);
  state.cam = { k, cx: wx - (sx - w / 2) / k, cy: wy + (sy - h / 2) / k };
  state.fitted = false;
  requestDraw();
}

function setupPointer() {
  /** @type {Map<number, { x: number, y: number }>} */
  const pointers = new Map();
  let moved = 0;
  let pinch = 0;
  canvas.addEventListener('pointerdown', (e) => {
    canvas.setPointerCapture(e.pointerId);
    pointers.set(e.pointerId, { x: e.offsetX, y: e.offsetY });
    moved = 0;
    if (pointers.size === 2) {
      const [a, b] = [...pointers.values()];
      pinch = Math.hypot(a.x - b.x, a.y - b.y);
    }
  });
  canvas.addEventListener('pointermove', (e) => {
    const p = pointers.get(e.pointerId);
    if (!p) return;
    const dx = e.offsetX - p.x, dy = e.offsetY - p.y;
    moved += Math.abs(dx) + Math.abs(dy);
    if (pointers.size === 2) {
      p.x = e.offsetX; p.y = e.offsetY;
      const [a, b] = [...pointers.values()];
      const dist = Math.hypot(a.x - b.x, a.y - b.y);
      if (pinch > 0) zoom(dist / pinch, (a.x + b.x) / 2, (a.y + b.y) / 2);
      pinch = dist;
      return;
    }
    p.x = e.offsetX; p.y = e.offsetY;
    state.cam = { ...state.cam, cx: state.cam.cx - dx / state.cam.k, cy: state.cam.cy + dy / state.cam.k };
    state.fitted = false;
    requestDraw();
  });
  const up = (/** @type {PointerEvent} */ e) => {
    if (pointers.size === 1 && moved < 4 && state.scene) {
      const [x, y] = toWorld(state.cam, canvas.clientWidth, canvas.clientHeight, e.offsetX, e.offsetY);
      const k = benchAt(state.scene, x, y, 3 / state.cam.k);
      state.selected = k === state.selected ? 0 : k;
      requestDraw();
      scheduleHash();
    }
    pointers.delete(e.pointerId);
    if (pointers.size < 2) pinch = 0;
  };
  canvas.addEventListener('pointerup', up);
  canvas.addEventListener('pointercancel', (e) => pointers.delete(e.pointerId));
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    zoom(Math.exp(-e.deltaY * 0.0015), e.offsetX, e.offsetY);
  }, { passive: false });
  canvas.addEventListener('dblclick', (e) => zoom(2, e.offsetX, e.offsetY));
}

// ---------------------------------------------------------------------------------------------
// Readouts and linked views

function updateReadouts() {
  syncFields();
  updateCommands();
  const r = state.range;
  if (!r) return;
  const jam = r.after;
  const why = jam && (state.lang === 'zh' ? say(`jam_${jam.kind}`, jam.handle, jam.handle - 1) : jam.sentence);
  const end = jam && state.path === 'spiral'
    ? say('valid_until', fmtTime(state.tmin), fmtTime(r.to), why ?? '')
    : say('valid_window', fmtTime(state.tmin), fmtTime(state.tmax));
  $('valid').textContent = end;
}

/** @param {SceneData} d */
function updateFrameReadouts(d) {
  const s = /** @type {HTMLInputElement} */ ($('scrubber'));
  s.value = String(state.t);
  const tf = /** @type {HTMLInputElement} */ ($('time'));
  if (document.activeElement !== tf) tf.value = fmtTime(state.t);
  $('travel').textContent = say('travel', (state.t * state.keys.speed).toFixed(3));
  const g = d.gaps;
  const line = $('status-line');
  if (g && g.distance < 0 && g.overlaps.length) {
    const o = g.overlaps[0];
    line.textContent = say('overlap_now', o.depth.toFixed(6), o.a, o.b);
    line.classList.add('past');
  } else if (g && g.a > 0) {
    line.textContent = say('nearest_now', g.distance.toFixed(6), g.a, g.b);
    line.classList.remove('past');
  } else line.textContent = '';
  // Q1: the paper's handles now (ten times a second while playing).
  const table = /** @type {HTMLTableElement | null} */ (document.getElementById('q1-table'));
  const now = performance.now();
  if (table && (!state.playing || now - lastTable > 100)) {
    lastTable = now;
    const n = d.handles - 1;
    const handles = PAPER_HANDLES.filter((i) => i <= n);
    if (!handles.includes(n)) handles.push(n);
    let html = `<tr><th>${say('q1_handle')}</th><th>x (m)</th><th>y (m)</th><th>v (m/s)</th></tr>`;
    for (const i of handles)
      html += `<tr><td>${i}</td><td>${fixed6(d.data[3 * i])}</td><td>${fixed6(d.data[3 * i + 1])}</td><td>${fixed6(d.data[3 * i + 2])}</td></tr>`;
    table.innerHTML = html;
    const h = document.querySelector('[data-command="q1"] .title');
    if (h) h.textContent = say('q1', fmtTime(state.t));
  }
  // The followed bench.
  const info = $('bench-info');
  if (d.selected > 0 && d.selected <= d.benches && d.nearest) {
    const k = d.selected;
    const v = (Math.abs(d.data[3 * (k - 1) + 2]) + Math.abs(d.data[3 * k + 2])) / 2;
    const role = say(k === 1 ? 'head' : k === d.benches ? 'tail' : 'body');
    info.textContent = say('bench_info', k, role, k - 1, k, v.toFixed(6), d.nearest.bench, d.nearest.distance.toFixed(6));
  } else info.textContent = say('bench_pick');
  drawSpeedChart(d);
  drawGapChart();
}

let lastTable = 0;

/** @param {number} t */
function fmtTime(t) {
  return String(+t.toFixed(3));
}

/**
 * A small chart's canvas, sized for the screen, and its context in CSS pixels.
 * @param {string} id
 */
function chartContext(id) {
  const c = /** @type {HTMLCanvasElement} */ (document.getElementById(id));
  const dpr = window.devicePixelRatio || 1;
  const { w, h } = boxSize(c);
  if (c.width !== Math.round(w * dpr)) { c.width = Math.round(w * dpr); c.height = Math.round(h * dpr); }
  const g = /** @type {CanvasRenderingContext2D} */ (c.getContext('2d'));
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  const th = theme();
  g.fillStyle = th.background;
  g.fillRect(0, 0, w, h);
  g.font = '11px system-ui, sans-serif';
  return { g, w, h, th };
}

/** The speed of every handle at this moment, against its number. @param {SceneData} d */
function drawSpeedChart(d) {
  const { g, w, h, th } = chartContext('speed-chart');
  let lo = Infinity, hi = -Infinity;
  for (let i = 0; i < d.handles; ++i) { const v = d.data[3 * i + 2]; lo = Math.min(lo, v); hi = Math.max(hi, v); }
  const span = Math.max(hi - lo, 0.02 * d.headSpeed);
  lo = (hi + lo) / 2 - span * 0.6; hi = lo + span * 1.2;
  const L = 46, R = 8, T = 18, B = 16;
  const X = (/** @type {number} */ i) => L + (i / Math.max(1, d.handles - 1)) * (w - L - R);
  const Y = (/** @type {number} */ v) => T + (1 - (v - lo) / (hi - lo)) * (h - T - B);
  g.fillStyle = th.text;
  g.fillText(say('speed_chart'), L, 12);
  g.fillText(hi.toFixed(3), 2, T + 4);
  g.fillText(lo.toFixed(3), 2, h - B);
  g.fillText(`${say('chart_handle')} 0 … ${d.handles - 1}`, w - 110, h - 3);
  if (d.selected > 0) {
    g.fillStyle = cssColour(th.highlight + '55');
    g.fillRect(X(d.selected - 1), T, Math.max(2, X(d.selected) - X(d.selected - 1)), h - T - B);
  }
  g.strokeStyle = th.head;
  g.lineWidth = 1.5;
  g.beginPath();
  for (let i = 0; i < d.handles; ++i) {
    const x = X(i), y = Y(d.data[3 * i + 2]);
    if (i) g.lineTo(x, y); else g.moveTo(x, y);
  }
  g.stroke();
}

const gapLayer = document.createElement('canvas');
let gapLayerKey = '';

/** The nearest gap over the shown motion (from the worker), drawn once per answer; this moment on it each frame. */
function drawGapChart() {
  const a = state.answers.gaps;
  const c = /** @type {HTMLCanvasElement} */ (document.getElementById('gap-chart'));
  const box = boxSize(c);
  if (!box.w || !box.h) return;  // not laid out (yet)
  const key = `${state.version}|${a ? a.t0 : ''}|${state.theme}|${state.lang}|${box.w}x${box.h}|${state.contact?.time}`;
  if (key !== gapLayerKey || !a) {
    drawGapLayer();
    gapLayer.width = c.width;
    gapLayer.height = c.height;
    if (c.width && c.height) /** @type {CanvasRenderingContext2D} */ (gapLayer.getContext('2d')).drawImage(c, 0, 0);
    gapLayerKey = a ? key : '';
  }
  const g = /** @type {CanvasRenderingContext2D} */ (c.getContext('2d'));
  g.setTransform(1, 0, 0, 1, 0, 0);
  if (gapLayer.width && gapLayer.height) g.drawImage(gapLayer, 0, 0);
  if (!a || a.error || !a.gaps.length) return;
  const dpr = window.devicePixelRatio || 1;
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  const x = 46 + ((state.t - a.t0) / (a.t1 - a.t0 || 1)) * (box.w - 54);
  g.strokeStyle = theme().text;
  g.lineWidth = 1;
  g.beginPath(); g.moveTo(x, 18); g.lineTo(x, box.h - 16); g.stroke();
}

/** The gap chart without the moment. */
function drawGapLayer() {
  const a = state.answers.gaps;
  const { g, w, h, th } = chartContext('gap-chart');
  const L = 46, R = 8, T = 18, B = 16;
  g.fillStyle = th.text;
  g.fillText(say('gap_chart'), L, 12);
  if (!a || a.error || !a.gaps.length) return;
  const gaps = /** @type {number[]} */ (a.gaps);
  let lo = Math.min(0, ...gaps), hi = Math.max(...gaps, 0.05);
  const X = (/** @type {number} */ t) => L + ((t - a.t0) / (a.t1 - a.t0 || 1)) * (w - L - R);
  const Y = (/** @type {number} */ v) => T + (1 - (v - lo) / (hi - lo)) * (h - T - B);
  g.fillText(`${hi.toFixed(2)} m`, 2, T + 4);
  g.fillText(`${lo.toFixed(2)}`, 2, h - B);
  g.fillText(`${fmtTime(a.t0)} … ${fmtTime(a.t1)} s`, w - 110, h - 3);
  g.strokeStyle = th.grid;
  g.beginPath(); g.moveTo(L, Y(0)); g.lineTo(w - R, Y(0)); g.stroke();
  g.strokeStyle = th.tail;
  g.lineWidth = 1.5;
  g.beginPath();
  gaps.forEach((v, i) => {
    const x = X(a.t0 + ((a.t1 - a.t0) * i) / (gaps.length - 1)), y = Y(v);
    if (i) g.lineTo(x, y); else g.moveTo(x, y);
  });
  g.stroke();
  if (state.contact) {
    g.strokeStyle = th.collision;
    g.setLineDash([3, 3]);
    g.beginPath(); g.moveTo(X(state.contact.time), T); g.lineTo(X(state.contact.time), h - B); g.stroke();
    g.setLineDash([]);
  }
}

// ---------------------------------------------------------------------------------------------
// The URL: #pitch=0.5&width=0.28&t=300&lang=zh (keys as the CLI's flags; only those off their defaults)

let hashTimer = 0;
function scheduleHash() {
  if (hashTimer) return;
  hashTimer = window.setTimeout(() => { hashTimer = 0; writeHash(); }, 250);
}

function writeHash() {
  const parts = [];
  for (const spec of KEYS) if (state.keys[spec.flag] !== state.defaults[spec.flag]) parts.push(`${spec.flag}=${state.keys[spec.flag]}`);
  if (state.path !== 'spiral') parts.push(`path=${state.path}`);
  parts.push(`t=${+state.t.toPrecision(12)}`);
  if (state.lang !== 'en') parts.push(`lang=${state.lang}`);
  if (state.theme !== 'light') parts.push(`theme=${state.theme}`);
  if (state.speedColours) parts.push('speed-colours=1');
  if (state.selected) parts.push(`bench=${state.selected}`);
  const hash = `#${parts.join('&')}`;
  if (location.hash !== hash) history.replaceState(null, '', hash);
}

/** Reads the URL's hash: the scenario, time, language, theme. */
function readHash() {
  const p = new URLSearchParams(location.hash.slice(1));
  const keys = { ...state.defaults };
  for (const spec of KEYS) {
    const v = p.get(spec.flag);
    if (v !== null && v.trim() !== '' && Number.isFinite(Number(v))) keys[spec.flag] = Number(v);
  }
  const lang = p.get('lang');
  state.lang = lang === 'zh' ? 'zh' : 'en';
  state.theme = p.get('theme') === 'dark' ? 'dark' : 'light';
  state.path = p.get('path') === 'turnaround' ? 'turnaround' : 'spiral';
  state.speedColours = p.get('speed-colours') === '1';
  state.selected = Number(p.get('bench')) || 0;
  const t = Number(p.get('t'));
  return { keys, t: p.has('t') && Number.isFinite(t) ? t : null };
}

// ---------------------------------------------------------------------------------------------
// Language, theme, keyboard

function applyLanguage() {
  document.documentElement.lang = state.lang === 'zh' ? 'zh-CN' : 'en';
  document.title = say('title');
  document.querySelectorAll('[data-i18n]').forEach((e) => { e.textContent = say(/** @type {HTMLElement} */ (e).dataset.i18n ?? ''); });
  document.querySelectorAll('[data-i18n-label]').forEach((e) => {
    const text = say(/** @type {HTMLElement} */ (e).dataset.i18nLabel ?? '');
    e.setAttribute('aria-label', text);
    e.setAttribute('title', text);
  });
  buildFields();
  buildAnswers();
  syncFields();
  updatePlay();
  updateReadouts();
  backdropKey = '';
  requestDraw();
}

function applyTheme() {
  document.documentElement.dataset.theme = state.theme;
  /** @type {HTMLSelectElement} */ ($('theme')).value = state.theme;
  if (state.range) buildPath();
  requestDraw();
}

function setupControls() {
  $('lang').addEventListener('click', () => {
    state.lang = state.lang === 'en' ? 'zh' : 'en';
    applyLanguage();
    writeHash();
  });
  $('theme').addEventListener('change', (e) => {
    state.theme = /** @type {HTMLSelectElement} */ (e.target).value === 'dark' ? 'dark' : 'light';
    applyTheme();
    writeHash();
  });
  const path = /** @type {HTMLSelectElement} */ ($('path'));
  path.addEventListener('change', () => {
    const before = state.path;
    state.path = path.value === 'turnaround' ? 'turnaround' : 'spiral';
    state.t = state.path === 'turnaround' ? -100 / state.keys.speed : 0;
    state.fitted = true;
    if (!applyScenario(state.keys, '')) { state.path = before; path.value = before; }
  });
  $('play').addEventListener('click', togglePlay);
  $('back').addEventListener('click', () => step(-1 / state.keys.speed));
  $('forward').addEventListener('click', () => step(1 / state.keys.speed));
  $('scrubber').addEventListener('input', (e) => {
    state.playing = false;
    updatePlay();
    setTime(Number(/** @type {HTMLInputElement} */ (e.target).value));
  });
  $('time').addEventListener('change', (e) => {
    const v = Number(/** @type {HTMLInputElement} */ (e.target).value);
    if (Number.isFinite(v)) setTime(v);
  });
  $('rate').addEventListener('change', (e) => { state.rate = Number(/** @type {HTMLSelectElement} */ (e.target).value); });
  $('fit').addEventListener('click', fit);
  $('zoom-in').addEventListener('click', () => zoom(1.5, canvas.clientWidth / 2, canvas.clientHeight / 2));
  $('zoom-out').addEventListener('click', () => zoom(1 / 1.5, canvas.clientWidth / 2, canvas.clientHeight / 2));
  const sc = /** @type {HTMLInputElement} */ ($('speed-colours'));
  sc.addEventListener('change', () => { state.speedColours = sc.checked; requestDraw(); writeHash(); });
  $('reset-all').addEventListener('click', () => { state.fitted = true; applyScenario({ ...state.defaults }, ''); });
  $('copy-link').addEventListener('click', (e) => { writeHash(); copyText(location.href, /** @type {HTMLElement} */ (e.currentTarget)); });
  $('copy-command').addEventListener('click', (e) => copyText(viewCommand(), /** @type {HTMLElement} */ (e.currentTarget)));
  $('copy-python').addEventListener('click', (e) => copyText(pythonCall(), /** @type {HTMLElement} */ (e.currentTarget)));
  $('save-png').addEventListener('click', () => canvas.toBlob((b) => b && download(`dragon_t${+state.t.toFixed(3)}.png`, b, 'image/png')));
  $('save-toml').addEventListener('click', () => download('scenario.toml', scenarioToml(), 'application/toml'));
  $('map-start').addEventListener('click', startMap);
  $('map-chart').addEventListener('click', onMapClick);
  $('gap-chart').addEventListener('click', (e) => {
    const a = state.answers.gaps;
    if (!a) return;
    const c = /** @type {HTMLCanvasElement} */ (e.target);
    const f = (e.offsetX - 46) / (c.clientWidth - 54);
    state.playing = false;
    setTime(a.t0 + clamp(f, 0, 1) * (a.t1 - a.t0));
  });
  document.addEventListener('keydown', (e) => {
    const target = /** @type {HTMLElement} */ (e.target);
    const typing = target.tagName === 'INPUT' && /** @type {HTMLInputElement} */ (target).type !== 'range' || target.tagName === 'SELECT' || target.tagName === 'TEXTAREA';
    if (typing || e.ctrlKey || e.metaKey || e.altKey) return;
    const onSlider = target.tagName === 'INPUT' && target.id !== 'scrubber';  // a key's slider keeps its arrows
    const unit = (e.shiftKey ? 10 : 1) / state.keys.speed;
    if (e.key === ' ' && target.tagName !== 'BUTTON') { e.preventDefault(); togglePlay(); }
    else if (e.key === 'ArrowRight' && !onSlider) { e.preventDefault(); step(unit); }
    else if (e.key === 'ArrowLeft' && !onSlider) { e.preventDefault(); step(-unit); }
    else if (e.key === 'Home' && !onSlider) { e.preventDefault(); step(state.tmin - state.t); }
    else if (e.key === 'End' && !onSlider) { e.preventDefault(); step(state.tmax - state.t); }
    else if (e.key === 'f' || e.key === 'F') fit();
    else if (e.key === '+' || e.key === '=') zoom(1.5, canvas.clientWidth / 2, canvas.clientHeight / 2);
    else if (e.key === '-') zoom(1 / 1.5, canvas.clientWidth / 2, canvas.clientHeight / 2);
  });
  window.addEventListener('resize', () => { if (state.fitted) fit(); else requestDraw(); });
  window.addEventListener('hashchange', () => {
    const { keys, t } = readHash();
    /** @type {HTMLSelectElement} */ ($('path')).value = state.path;
    /** @type {HTMLInputElement} */ ($('speed-colours')).checked = state.speedColours;
    applyTheme();
    applyLanguage();
    if (t !== null) state.t = t;
    applyScenario(keys, '');
  });
}

/** @param {number} v @param {number} lo @param {number} hi */
function clamp(v, lo, hi) {
  return Math.min(hi, Math.max(lo, v));
}

// ---------------------------------------------------------------------------------------------
// Start: the engine on this thread (frames), the worker (answers), the URL's state, first frame.

async function start() {
  performance.mark('start');
  // The engine's wasm, compiled once here and handed to each worker: emscripten's file holds it
  // as base64, which the workers' copy of that file leaves out.
  const engineText = /** @type {HTMLElement} */ (document.getElementById('engine-js')).textContent ?? '';
  const base64 = engineText.match(/data:application\/octet-stream;base64,([A-Za-z0-9+/=]+)/)?.[1] ?? '';
  wasmModule = WebAssembly.compile(Uint8Array.from(atob(base64), (c) => c.charCodeAt(0)));
  workerSource = engineText.replace(base64, '') + '\n' + /** @type {HTMLElement} */ (document.getElementById('worker-js')).textContent;
  current = spawnWorker();
  const compiled = await wasmModule;
  const module = await createDragonEngine({
    instantiateWasm(/** @type {WebAssembly.Imports} */ imports, /** @type {(i: WebAssembly.Instance, m: WebAssembly.Module) => void} */ ok) {
      WebAssembly.instantiate(compiled, imports).then((instance) => ok(instance, compiled));
      return {};
    },
  });
  engine = new module.Engine();
  state.defaults = module.Engine.defaults();
  const { keys, t } = readHash();
  /** @type {HTMLSelectElement} */ ($('path')).value = state.path;
  /** @type {HTMLInputElement} */ ($('speed-colours')).checked = state.speedColours;
  setupControls();
  setupPointer();
  state.t = t ?? 0;
  applyLanguage();
  applyTheme();
  state.keys = { ...state.defaults };
  if (!applyScenario(keys, '')) applyScenario({ ...state.defaults }, '');
  if (t === null && state.path === 'turnaround') setTime(state.tmin);
  draw();
  performance.measure('ready', { start: 0, end: performance.now() });  // from opening the page
  document.body.dataset.ready = 'true';
  document.body.classList.remove('loading');
}

start().catch((e) => {
  console.error(e);
  document.body.dataset.ready = 'error';
  showEngineError(e);
});
