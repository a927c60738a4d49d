// The DEM settling's step time, block by block, for comparing two builds on a shared, noisy machine
// (docs/performance.md, "DEM: pairs added straight into the grains"). Settles the in.dem_settle bed for
// `warm` steps, then times `blocks` blocks of `steps` steps and prints the warm-up's mean and the
// blocks' minimum, 10th percentile and median, in ns per grain and step. Noise only adds time, so the
// low percentiles of short blocks compare two builds better than one long run does; run the two builds
// at once, one per core (taskset), then with the cores swapped.
//
//   grit_dem_step_blocks [nxy nz threads warm blocks steps]   (defaults 30 12 1 6000 200 10)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "dem_settle.hpp"
#include "grit/parallel/parallel.hpp"

int main(int argc, char** argv) {
    auto arg = [&](int k, int fallback) { return argc > k ? std::max(1, std::atoi(argv[k])) : fallback; };
    const int nxy = arg(1, 30), nz = arg(2, 12), threads = arg(3, 1), warm = arg(4, 6000);
    const int blocks = arg(5, 200), steps = arg(6, 10);
    grit::parallel::set_threads(threads);
    auto sys = grit::bench::dem_settle(nxy, nz);
    using clock = std::chrono::steady_clock;
    const double grains = static_cast<double>(sys.grains().size());
    const auto start = clock::now();
    double time = 0.0;  // no moving meshes here: the time only places them
    for (int k = 0; k < warm; ++k, time += 1e-5) sys.step(1e-5, time);
    const double warm_s = std::chrono::duration<double>(clock::now() - start).count();
    std::vector<double> ns;
    for (int b = 0; b < blocks; ++b) {
        const auto t0 = clock::now();
        for (int k = 0; k < steps; ++k, time += 1e-5) sys.step(1e-5, time);
        ns.push_back(std::chrono::duration<double>(clock::now() - t0).count() * 1e9 / (steps * grains));
    }
    std::sort(ns.begin(), ns.end());
    std::printf("grains %.0f  warm-up %d steps %.2f s (%.1f ns/grain-step)  blocks of %d steps: min %.1f  p10 %.1f  "
                "median %.1f ns/grain-step  contacts/grain %.3f  KE %.6e J\n",
                grains, warm, warm_s, warm_s * 1e9 / (warm * grains), steps, ns.front(), ns[ns.size() / 10],
                ns[ns.size() / 2], 2.0 * static_cast<double>(sys.contact_pairs()) / grains, sys.kinetic_energy());
}
