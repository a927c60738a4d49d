// DEM throughput: the settling benchmark of bench/peers/liggghts/in.dem_settle (Hertz-Mindlin with
// tangential history, periodic x and y, a plane at z = 0), reproduced grain for grain (dem_settle.hpp),
// at 10,800 (30 x 30 x 12) and 50,000 (50 x 50 x 20) grains, 1 and 2 threads. One iteration runs the
// whole settling from the lattice, GRIT_DEM_STEPS steps of 1e-5 s (default 10000, as the LIGGGHTS
// runs), so the counters compare with LIGGGHTS' atoms x steps / 'Loop time'.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>

#include "dem_settle.hpp"
#include "grit/parallel/parallel.hpp"

namespace {

int steps_from_environment() {
    const char* s = std::getenv("GRIT_DEM_STEPS");
    return s ? std::max(1, std::atoi(s)) : 10000;
}

void DemSettle(benchmark::State& state) {
    const int nxy = static_cast<int>(state.range(0)), nz = static_cast<int>(state.range(1));
    grit::parallel::set_threads(static_cast<int>(state.range(2)));
    const int steps = steps_from_environment();
    double grains = 0.0, kinetic = 0.0, zmax = 0.0, rebuilds = 0.0, contacts = 0.0, entries = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        grit::dem::DemSystem<3> sys = grit::bench::dem_settle(nxy, nz);
        state.ResumeTiming();
        for (int k = 0; k < steps; ++k) sys.step(1e-5, k * 1e-5);
        state.PauseTiming();
        grains = sys.grains().size();
        kinetic = sys.kinetic_energy();
        zmax = 0.0;
        for (grit::Index i = 0; i < sys.grains().size(); ++i) zmax = std::max(zmax, sys.grains().position()[i][2]);
        rebuilds = static_cast<double>(sys.counters().rebuilds);
        contacts = static_cast<double>(sys.contact_pairs());
        entries = static_cast<double>(sys.list_entries());
        state.ResumeTiming();
    }
    state.counters["grains"] = grains;
    state.counters["steps"] = steps;
    state.counters["threads"] = static_cast<double>(state.range(2));
    state.counters["grain_steps_per_second"] =
        benchmark::Counter(grains * steps, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["final_kinetic_energy"] = kinetic;
    state.counters["final_zmax"] = zmax;
    state.counters["rebuilds"] = rebuilds;
    state.counters["contacts_per_grain"] = 2.0 * contacts / grains;
    state.counters["list_entries_per_grain"] = 2.0 * entries / grains;  // each pair in both grains' rows, as before
}

}  // namespace

BENCHMARK(DemSettle)
    ->ArgNames({"nxy", "nz", "threads"})
    ->Args({30, 12, 1})
    ->Args({30, 12, 2})
    ->Args({50, 20, 1})
    ->Args({50, 20, 2})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

BENCHMARK_MAIN();
