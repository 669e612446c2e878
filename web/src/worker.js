// @ts-check
// The answers' worker: the engine's searches, off the page's thread. Its script is the engine
// (createDragonEngine) followed by this file, made into a Blob by the page. A run is cancelled by
// ending the worker (app.js keeps a spare one ready), so each run here goes to its end.
//
// In:  {type: 'init', module} first: the engine's WebAssembly.Module, compiled once by the page;
//      then {type: 'run', id, keys, commands: string[], window: [t0, t1]}
// Out: {type: 'ready'} once; per command {type: 'progress', id, command, done, total} and
//      {type: 'result', id, command, result, start, end} (start and end on the shared clock,
//      performance.timeOrigin + now, ms); {type: 'done', id}; {type: 'error', message}.

/** @type {any} */
const scope = self;

/** @type {(engine: DragonEngine) => void} */
let engineReady = () => {};
/** @type {Promise<DragonEngine>} */
const workerEngine = new Promise((resolve) => { engineReady = resolve; });

/** @returns {number} ms on a clock the page shares */
function clock() {
  return performance.timeOrigin + performance.now();
}

scope.onmessage = async (/** @type {MessageEvent} */ event) => {
  const msg = event.data;
  if (msg.type === 'init') {
    /** @type {WebAssembly.Module} */
    const module = msg.module;
    createDragonEngine({
      instantiateWasm(/** @type {WebAssembly.Imports} */ imports, /** @type {(i: WebAssembly.Instance, m: WebAssembly.Module) => void} */ ok) {
        WebAssembly.instantiate(module, imports).then((instance) => ok(instance, module));
        return {};
      },
    }).then((m) => {
      engineReady(new m.Engine());
      scope.postMessage({ type: 'ready' });
    }, (e) => scope.postMessage({ type: 'error', message: String(e) }));
    return;
  }
  if (msg.type === 'map') {
    // Cells of a minimum-pitch map, [i, j, width, body length] each (the page splits the map's
    // cells between its map workers).
    const engine = await workerEngine;
    const refused = engine.setScenario(msg.keys);
    for (const [i, j, w, len] of msg.cells) {
      const cell = refused ? { error: refused.error } : engine.minPitchCell(w, len, w + msg.lo, w + msg.hi, msg.grid);
      scope.postMessage({ type: 'cell', id: msg.id, i, j, ...cell });
    }
    scope.postMessage({ type: 'mapdone', id: msg.id });
    return;
  }
  if (msg.type !== 'run') return;
  const engine = await workerEngine;
  const refused = engine.setScenario(msg.keys);
  for (const command of msg.commands) {
    const start = clock();
    /** @type {any} */
    let result;
    if (refused) {
      result = refused;
    } else if (command === 'gaps') {
      const [t0, t1] = msg.window;
      result = { t0, t1, gaps: Array.from(engine.gapCurve(t0, t1, 400)) };
    } else {
      let last = 0;
      result = engine.answer(command, (done, total) => {
        const now = clock();
        if (now - last < 100 && done < total) return;
        last = now;
        scope.postMessage({ type: 'progress', id: msg.id, command, done, total });
      });
    }
    scope.postMessage({ type: 'result', id: msg.id, command, result, start, end: clock() });
  }
  scope.postMessage({ type: 'done', id: msg.id });
};
