// The engine's calls as web/bindings.cpp offers them (embind), for the type checker.

/** A refused scenario or a question the library could not answer: its sentence and the flags it concerns. */
interface DragonRefusal { error: string; flags: string[] }
/** The end of the valid motion. */
interface DragonJam {
  time: number; travel: number; handle: number; kind: 'root_vanishes' | 'nearer_root'; ahead: boolean;
  x: number; y: number; sentence: string;
}
/** The valid motion, s and m of head travel; infinite ends are +-Infinity. */
interface DragonRange {
  from: number; to: number; from_travel: number; to_travel: number;
  before: DragonJam | null; after: DragonJam | null; end_time: number;
}
interface DragonOverlap { a: number; b: number; depth: number; x: number; y: number }
interface DragonGaps { distance: number; a: number; b: number; x: number; y: number; overlaps: DragonOverlap[] }
interface DragonNearest { bench: number; distance: number; x: number; y: number }
interface DragonSCurve {
  c1x: number; c1y: number; r1: number; c2x: number; c2y: number; r2: number;
  ax: number; ay: number; bx: number; by: number; jx: number; jy: number; length: number;
}
/** An answer: the command's --json text, and each leaf's text by its key path. */
interface DragonAnswer { json: string; leaves: Record<string, string> }
interface DragonEngine {
  setScenario(keys: Record<string, number | string>): DragonRefusal | null;
  range(): DragonRange;
  frame(t: number): Float64Array;
  headArc(): number;
  headArcAt(t: number): number;
  gaps(): DragonGaps;
  nearestTo(bench: number): DragonNearest;
  pathPoints(s0: number, s1: number, step: number): Float64Array;
  sCurve(): DragonSCurve;
  gapCurve(t0: number, t1: number, count: number): Float64Array;
  minPitchCell(width: number, bodyLength: number, lo: number, hi: number, grid: number):
    { pitch: number; below: boolean; above: boolean; error?: string };
  answer(command: string, progress: ((done: number, total: number) => void) | undefined): DragonAnswer | DragonRefusal;
}
interface DragonModule {
  Engine: { new (): DragonEngine; defaults(): Record<string, number> };
}
declare function createDragonEngine(options?: object): Promise<DragonModule>;
/** The gallery's themes (assets/themes/*.toml), put in by web/assemble.mjs. */
declare const DRAGON_THEMES: Record<string, Record<string, any>>;
