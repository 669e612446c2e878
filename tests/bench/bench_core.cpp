// Core timings: one frame, the Q1 table, the Q2 first contact, the Q3 minimum pitch.
// Run: build/tests/bench/dragon_bench --benchmark_filter='Frame|Q1|Q2|Q3'
#include <benchmark/benchmark.h>

#include "dragon/analyses.hpp"

using namespace dragon;

static void BM_Frame(benchmark::State& state) {
    const Simulation sim(Scenario{});
    Frame f;
    double t = 0.0;
    for (auto _ : state) {
        sim.frame_into(t, f);
        benchmark::DoNotOptimize(f.handles.data());
        t = t >= 400.0 ? 0.0 : t + 1.37;
    }
}
BENCHMARK(BM_Frame)->Unit(benchmark::kMicrosecond);

// The Q1 table computed into frames kept from the last iteration (as a caller making many
// tables would), and freshly allocated each time (as the one table of `dragon solve` is).
static void BM_Q1Table(benchmark::State& state) {
    const Simulation sim(Scenario{});
    std::vector<Frame> frames;
    for (auto _ : state) {
        simulate_table_into(sim, 0.0, 300.0, 1.0, frames);
        benchmark::DoNotOptimize(frames.data());
    }
}
BENCHMARK(BM_Q1Table)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_Q1TableFreshMemory(benchmark::State& state) {
    const Simulation sim(Scenario{});
    for (auto _ : state) benchmark::DoNotOptimize(simulate_table(sim, 0.0, 300.0, 1.0));
}
BENCHMARK(BM_Q1TableFreshMemory)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_Clearance(benchmark::State& state) {
    const Frame f = Simulation(Scenario{}).frame(400.0);
    for (auto _ : state) benchmark::DoNotOptimize(clearance(f));
}
BENCHMARK(BM_Clearance)->Unit(benchmark::kMicrosecond);

static void BM_Q2FirstContact(benchmark::State& state) {
    const Simulation sim(Scenario{});
    const double end = sim.valid_end();  // found once, as the CLI does before its search
    for (auto _ : state) benchmark::DoNotOptimize(first_contact(sim, 0.0, end));
}
BENCHMARK(BM_Q2FirstContact)->Unit(benchmark::kMillisecond);

// The same with every step proved by enclosures (dragon collide --prove).
static void BM_Q2FirstContactProved(benchmark::State& state) {
    const Simulation sim(Scenario{});
    const double end = sim.valid_end();
    ContactSearchOptions o;
    o.prove_steps = true;
    for (auto _ : state) benchmark::DoNotOptimize(first_contact(sim, 0.0, end, o));
}
BENCHMARK(BM_Q2FirstContactProved)->Unit(benchmark::kMillisecond);

// The end of the valid motion on the contest's spiral, searched from scratch each time.
static void BM_ValidRange(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(Simulation(Scenario{}).valid_range());
}
BENCHMARK(BM_ValidRange)->Unit(benchmark::kMillisecond);

// The same search with every step proved (JamSearchOptions::prove, docs/methods.md section 4.1).
static void BM_ValidRangeProved(benchmark::State& state) {
    const Simulation sim{Scenario{}};
    JamSearchOptions o;
    o.prove = true;
    for (auto _ : state)
        benchmark::DoNotOptimize(find_jam(sim.path(), sim.scenario().bench, sim.start_arc(), sim.scenario().head_speed, 0.0,
                                                  sim.end_time(), nullptr, o));
}
BENCHMARK(BM_ValidRangeProved)->Unit(benchmark::kMillisecond);

static void BM_Q3MinPitch(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(min_pitch(Scenario{}, 0.35, 0.55));
}
BENCHMARK(BM_Q3MinPitch)->Unit(benchmark::kMillisecond)->Iterations(1);

// The same search with every pitch of the range proved (MinPitchOptions::prove), on the calling
// thread alone as above.
static void BM_Q3MinPitchProved(benchmark::State& state) {
    MinPitchOptions o;
    o.prove = true;
    for (auto _ : state) benchmark::DoNotOptimize(min_pitch(Scenario{}, 0.35, 0.55, o));
}
BENCHMARK(BM_Q3MinPitchProved)->Unit(benchmark::kMillisecond)->Iterations(1);
