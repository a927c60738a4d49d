// Time to crater: the first seed paper's AWJ on OFHC copper (cases/awj_copper_2d, Figs. 12-15) stepped
// for a fixed number of steps once the jet has reached the plate, at the case's 0.1 mm spacing and at
// the paper's 0.05 mm. Counters: particle-steps per second, milliseconds per step, the time step, and
// the projected wall time of the paper's 30 ms at this rate (30 ms / dt steps; issue 15's target is
// 2 hours at 0.1 mm on the project's 2-core machine). The `Half` forms run the x >= 0 half on the jet's
// symmetry plane (jet.symmetric; `particles` counts the images too); `Paper30ms` runs
// cases/awj_copper_2d/paper_30ms.toml, the half on a 10 x 3 mm section: the set-up for the paper's 30 ms.
#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "grit/io/case_reader.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sim/simulation.hpp"

namespace {

constexpr double paper_impact_time = 0.03;  // [s] T of Figs. 12-15

void awj_copper(benchmark::State& state, double dx, double warm_up_time, bool half = false,
                const char* case_file = "cases/awj_copper_2d/case.toml") {
    grit::parallel::set_threads(static_cast<int>(state.range(0)));
    const std::filesystem::path root(GRIT_SOURCE_DIR);
    std::vector<std::string> overrides = {"numerics.particle_spacing=" + std::to_string(dx), "output.snapshots=false"};
    if (half) overrides.push_back("jet.symmetric=true");
    grit::sim::RunOptions options;
    options.write_files = false;
    options.quiet = true;
    grit::sim::Simulation<2> sim(grit::io::read_case(root / case_file, overrides), options);
    // The jet reaches the plate (2 mm at 500 m/s) after 4 us; by the warm-up time it has spread over the
    // surface and the first grains are in the water, as in the steady part of a 30 ms run.
    sim.advance_to(warm_up_time);
    double particle_steps = 0.0, time_step = 0.0;
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) {
        sim.step();
        particle_steps += static_cast<double>(sim.particles().size());
        time_step += sim.time_step();
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double steps = static_cast<double>(state.iterations());
    time_step /= steps;
    state.counters["particles"] = particle_steps / steps;
    state.counters["threads"] = static_cast<double>(state.range(0));
    state.counters["dt_ns"] = time_step * 1e9;
    state.counters["particle_steps_per_second"] = benchmark::Counter(particle_steps, benchmark::Counter::kIsRate);
    state.counters["steps_per_second"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
    // (30 ms / dt) steps at the measured wall time per step.
    state.counters["hours_for_30ms"] = paper_impact_time / time_step * (wall / steps) / 3600.0;
}

void AwjCopper2D_0p1mm(benchmark::State& s) { awj_copper(s, 1.0e-4, 1.0e-5); }
void AwjCopper2D_0p05mm(benchmark::State& s) { awj_copper(s, 5.0e-5, 6.0e-6); }
void AwjCopper2DHalf_0p1mm(benchmark::State& s) { awj_copper(s, 1.0e-4, 1.0e-5, true); }
void AwjCopper2DHalf_0p05mm(benchmark::State& s) { awj_copper(s, 5.0e-5, 6.0e-6, true); }
void AwjCopper2DPaper30ms_0p1mm(benchmark::State& s) {
    awj_copper(s, 1.0e-4, 1.0e-5, true, "cases/awj_copper_2d/paper_30ms.toml");
}

}  // namespace

BENCHMARK(AwjCopper2D_0p1mm)->Arg(1)->Arg(2)->Iterations(1000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(AwjCopper2D_0p05mm)->Arg(2)->Iterations(300)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(AwjCopper2DHalf_0p1mm)->Arg(1)->Arg(2)->Iterations(1000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(AwjCopper2DHalf_0p05mm)->Arg(2)->Iterations(300)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(AwjCopper2DPaper30ms_0p1mm)->Arg(1)->Arg(2)->Iterations(1000)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
