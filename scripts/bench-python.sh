#!/usr/bin/env bash
# The Python package's speed against the C++ it wraps (issue 21's targets), on the build in
# build/: the Q1 table's 301 frames into numpy against BM_Q1Table, import time, a trivial call's
# overhead, and a 100-scenario min-pitch sweep on a ProcessPoolExecutor against `dragon sweep`.
# Each figure is the median of several runs; run it on an idle machine.
set -euo pipefail
cd "$(dirname "$0")/.."
py=/usr/bin/python3
[[ -x $py ]] || py=$(command -v python3)
export PYTHONPATH=$PWD/build/python
table_ms=$(./build/tests/bench/dragon_bench --benchmark_filter='^BM_Q1Table/' --benchmark_repetitions=5 \
  --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null | grep '_median' | cut -d, -f3)
imports=()
for _ in 1 2 3 4 5; do
  imports+=("$("$py" -X importtime -c 'import benchdragon' 2>&1 | tail -1 | awk -F'|' '{print $2 / 1e6}')")
done
import_s=$(printf '%s\n' "${imports[@]}" | sort -g | sed -n 3p)
start=$(date +%s.%N)
./build/src/dragon sweep --vary body-length=1.6:2.6:100 --measure min-pitch --quiet >/dev/null
tool_sweep=$(echo "$(date +%s.%N) - $start" | bc)
"$py" - "$table_ms" "$import_s" "$tool_sweep" <<'PY'
import statistics, sys, time
from concurrent.futures import ProcessPoolExecutor
import numpy as np
import benchdragon as bd

table_ms, import_s, tool_sweep = (float(v) for v in sys.argv[1:])
sim = bd.Simulation()
times = np.arange(0.0, 301.0)
sim.frames(times)
runs = []
for _ in range(30):
    t = time.perf_counter(); sim.frames(times); runs.append(time.perf_counter() - t)
frames_ms = 1e3 * statistics.median(runs)
calls = []
for _ in range(7):
    t = time.perf_counter()
    for _ in range(20000):
        sim.time_of(1.0)
    calls.append((time.perf_counter() - t) / 20000)
call_us = 1e6 * statistics.median(calls)
with ProcessPoolExecutor(max_workers=2) as ex:
    bd.sweep({"body_length": [2.0]}, "min-pitch", executor=ex, progress=False)  # workers started
    t = time.perf_counter()
    bd.sweep({"body_length": "1.6:2.6:100"}, "min-pitch", executor=ex, progress=False)
    py_sweep = time.perf_counter() - t
print("| what | target | measured |")
print("|---|---|---|")
print(f"| Simulation.frames, 0..300 s (301 x 224) into numpy | < 5 ms, within 1.5x of C++ | {frames_ms:.2f} ms "
      f"(C++ BM_Q1Table {table_ms:.2f} ms: {frames_ms / table_ms:.2f}x) |")
print(f"| import benchdragon | < 0.2 s | {import_s:.3f} s |")
print(f"| a trivial call (Simulation.time_of) | < 20 us | {call_us:.2f} us |")
print(f"| 100-scenario min-pitch sweep, ProcessPoolExecutor(2) | within 1.3x of dragon sweep | {py_sweep:.2f} s "
      f"(dragon sweep {tool_sweep:.2f} s: {py_sweep / tool_sweep:.2f}x) |")
PY
