// The turnaround path's costs: the result4 table (201 frames x 224 handles), one chord search,
// and the Q5 search (proved, and sampled alone).
#include <vector>

#include <benchmark/benchmark.h>

#include "dragon/chain.hpp"
#include "dragon/turnaround.hpp"

using namespace dragon;

namespace {

Scenario turnaround() {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    return s;
}

// Target: under 20 ms for the whole table.
void BM_TurnaroundResult4Table(benchmark::State& state) {
    const Simulation sim(turnaround());
    std::vector<Frame> frames(201);
    for (auto _ : state) {
        for (int k = 0; k <= 200; ++k) sim.frame_into(-100.0 + k, frames[static_cast<size_t>(k)]);
        benchmark::DoNotOptimize(frames.data());
    }
    state.SetItemsProcessed(state.iterations() * 201 * 223);  // chord searches
}
BENCHMARK(BM_TurnaroundResult4Table)->Unit(benchmark::kMillisecond);

// One chord search, averaged over the places the result4 table visits (every piece).
void BM_TurnaroundBehind(benchmark::State& state) {
    const Scenario sc = turnaround();
    const TurnaroundPath path(design_s_curve(sc));
    std::vector<std::pair<Located, double>> cases;
    Frame f;
    for (int k = 0; k <= 200; k += 5) {
        solve_chain(path, sc.bench, -100.0 + k, 1.0, f);
        for (size_t i = 0; i + 1 < f.handles.size(); ++i) {
            const Handle& h = f.handles[i];
            cases.push_back({{h.place, h.pos, h.tangent}, sc.bench.link_after(static_cast<int>(i))});
        }
    }
    size_t i = 0;
    for (auto _ : state) {
        const auto& [from, chord] = cases[i];
        benchmark::DoNotOptimize(path.behind(from, chord));
        if (++i == cases.size()) i = 0;
    }
}
BENCHMARK(BM_TurnaroundBehind)->Unit(benchmark::kNanosecond);

// The chord search on each piece on its own: from places on piece `range(0)`.
void BM_TurnaroundBehindOnPiece(benchmark::State& state) {
    const Scenario sc = turnaround();
    const TurnaroundPath path(design_s_curve(sc));
    const int piece = static_cast<int>(state.range(0));
    std::vector<Located> from;
    for (double s = -60.0; s <= 60.0; s += 0.01) {
        const Located l = path.at_arc(s);
        if (l.place.piece == piece) from.push_back(l);
    }
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(path.behind(from[i], 1.65));
        if (++i == from.size()) i = 0;
    }
}
BENCHMARK(BM_TurnaroundBehindOnPiece)->DenseRange(0, 3)->Unit(benchmark::kNanosecond);

// Target: under 0.5 s.
void BM_TurnaroundMaxSpeed(benchmark::State& state) {
    const Scenario sc = turnaround();
    for (auto _ : state) benchmark::DoNotOptimize(max_head_speed(sc, 2.0));
}
BENCHMARK(BM_TurnaroundMaxSpeed)->Unit(benchmark::kMillisecond)->Iterations(3);

// The same search with its maximum proved (MaxSpeedOptions::prove; dragon max-speed --prove),
// on the calling thread as above.
void BM_TurnaroundMaxSpeedProved(benchmark::State& state) {
    const Scenario sc = turnaround();
    MaxSpeedOptions o;
    o.prove = true;
    for (auto _ : state) benchmark::DoNotOptimize(max_head_speed(sc, 2.0, kTurnaroundWindow, nullptr, o));
}
BENCHMARK(BM_TurnaroundMaxSpeedProved)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
