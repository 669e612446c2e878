#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz) into build-fuzz/ with clang, ASan and UBSan, and
# runs each for a bounded time (default 60 s each):
#
#   scripts/fuzz.sh [seconds per target]
#
# Each target starts from its seeds in tests/fuzz/corpus/<target>/ (kept small, in git) and
# grows a working corpus in build-fuzz/corpus/<target>/ (not in git; reused by the next run).
# A crash, a failed property, an input slower than 10 s or a leak stops the target, saves the
# input in build-fuzz/crashes/<target>/ and fails the script; replay it with
#   build-fuzz/tests/fuzz/<target> build-fuzz/crashes/<target>/<file>
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
targets=(fuzz_scenario fuzz_chain fuzz_rows fuzz_theme fuzz_contact)

cmake -S . -B build-fuzz -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DDRAGON_FUZZ=ON -DDRAGON_BUILD_TESTS=OFF \
  -DDRAGON_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build-fuzz -j2 --target "${targets[@]}"

export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# fontconfig's process-wide caches (the theme reader asks it whether a font is installed) are
# never freed; the suppressions list them (full stacks: the library has no frame pointers).
export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp:fast_unwind_on_malloc=0
status=0
for t in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$t crashes=build-fuzz/crashes/$t
  mkdir -p "$corpus" "$crashes"
  echo "fuzz.sh: $t for $seconds s"
  if ! "build-fuzz/tests/fuzz/$t" "$corpus" "tests/fuzz/corpus/$t" -max_total_time="$seconds" \
       -timeout=10 -max_len=4096 -rss_limit_mb=2048 -artifact_prefix="$crashes/" \
       -print_final_stats=1 2>"build-fuzz/$t.log"; then
    tail -n 40 "build-fuzz/$t.log"
    echo "fuzz.sh: $t FAILED (input saved in $crashes/, log in build-fuzz/$t.log)"
    status=1
  else
    grep -E '^stat::number_of_executed_units|^stat::new_units_added' "build-fuzz/$t.log" | sed "s/^/  /"
  fi
done
exit $status
