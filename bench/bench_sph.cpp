// Throughput benchmarks: the 2D dam break at ~10k, 50k, 200k and 1M fluid particles and the 3D dam break
// at ~50k, 200k and 1M fluid particles, at 1 and 2 threads (the scaling table of docs/performance.md).
// Counters: particle-steps per second (all particles, walls included, as
// the peers count them) and pair interactions per second (neighbour-list entries per second).
// The set-up matches bench/peers/liggghts/in.sph_dambreak2d: column 0.2 x 0.4 m, c0 = 30 m/s,
// tank 0.8 m long with walls up to 0.45 m, the first steps of the collapse from rest.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "grit/io/case_reader.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sim/simulation.hpp"

namespace {

grit::io::CaseSpec dambreak(int dim, double dx) {
    const std::filesystem::path root(GRIT_SOURCE_DIR);
    std::vector<std::string> o = {"numerics.particle_spacing=" + std::to_string(dx)};
    if (dim == 2) {
        o.push_back("wall[0].max=[0.8, 0.45]");
        return grit::io::read_case(root / "cases/dambreak_2d/case.toml", o);
    }
    o.push_back("wall[0].max=[0.8, 0.1, 0.45]");
    return grit::io::read_case(root / "cases/dambreak_3d/case.toml", o);
}

template <int Dim>
void run_steps(benchmark::State& state, double dx) {
    grit::parallel::set_threads(static_cast<int>(state.range(0)));
    grit::sim::RunOptions options;
    options.write_files = false;
    options.quiet = true;
    grit::sim::Simulation<Dim> sim(dambreak(Dim, dx), options);
    sim.advance_to(0.0);  // primes the rates
    for (int k = 0; k < 20; ++k) sim.step();  // warm caches and the neighbour lists
    double pairs = 0.0;
    for (auto _ : state) {
        sim.step();
        pairs += static_cast<double>(sim.pair_count());
    }
    const double n = sim.particles().size();
    state.counters["particles"] = n;
    state.counters["threads"] = static_cast<double>(state.range(0));
    state.counters["particle_steps_per_second"] =
        benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["pairs_per_second"] = benchmark::Counter(pairs, benchmark::Counter::kIsRate);
    state.counters["neighbors_per_particle"] = pairs / state.iterations() / n;
}

void DamBreak2D_10k(benchmark::State& s) { run_steps<2>(s, 0.0028); }
void DamBreak2D_50k(benchmark::State& s) { run_steps<2>(s, 0.00126); }
void DamBreak2D_200k(benchmark::State& s) { run_steps<2>(s, 0.00063); }
void DamBreak2D_1M(benchmark::State& s) { run_steps<2>(s, 0.000283); }
void DamBreak3D_50k(benchmark::State& s) { run_steps<3>(s, 0.0055); }
void DamBreak3D_200k(benchmark::State& s) { run_steps<3>(s, 0.00342); }
void DamBreak3D_1M(benchmark::State& s) { run_steps<3>(s, 0.002); }

}  // namespace

BENCHMARK(DamBreak2D_10k)->Arg(1)->Arg(2)->Iterations(1500)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(DamBreak2D_50k)->Arg(1)->Arg(2)->Iterations(400)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(DamBreak2D_200k)->Arg(1)->Arg(2)->Iterations(100)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(DamBreak2D_1M)->Arg(1)->Arg(2)->Iterations(20)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(DamBreak3D_50k)->Arg(1)->Arg(2)->Iterations(100)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(DamBreak3D_200k)->Arg(1)->Arg(2)->Iterations(40)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(DamBreak3D_1M)->Arg(1)->Arg(2)->Iterations(10)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
