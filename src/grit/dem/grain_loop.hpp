// Loop shapes of the grain stages: parallel over grains once there are enough of them to pay for the
// threads' start and barrier. A few grains (a drop test, a feed of single abrasives) run serially,
// where OpenMP barriers would cost more than the work (far more on a machine whose cores are busy).
// Results do not depend on the choice: every loop is in gather form and max/min are exact.
#pragma once

#include <algorithm>

#include "grit/core/types.hpp"

namespace grit::dem {

/// Fewest grains for which a grain loop runs in parallel.
inline constexpr Index parallel_grain_threshold = 512;

/// Calls f(i) for i in [0, n); f writes only to grain i.
template <class F>
void for_each_grain(Index n, F&& f) {
#pragma omp parallel for schedule(static) if (n >= parallel_grain_threshold)
    for (Index i = 0; i < n; ++i) f(i);
}

/// Largest f(i) over [0, n); `lowest` when n == 0.
template <class F>
double max_over_grains(Index n, double lowest, F&& f) {
    double m = lowest;
#pragma omp parallel for schedule(static) reduction(max : m) if (n >= parallel_grain_threshold)
    for (Index i = 0; i < n; ++i) m = std::max(m, f(i));
    return m;
}

/// Smallest f(i) over [0, n); `highest` when n == 0.
template <class F>
double min_over_grains(Index n, double highest, F&& f) {
    double m = highest;
#pragma omp parallel for schedule(static) reduction(min : m) if (n >= parallel_grain_threshold)
    for (Index i = 0; i < n; ++i) m = std::min(m, f(i));
    return m;
}

}  // namespace grit::dem
