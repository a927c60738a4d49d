// Loop shapes of the grain stages: those of grit/parallel (parallel over grains, serial below
// parallel::serial_below grains, where OpenMP barriers would cost more than the work, far more on a
// machine whose cores are busy). Results do not depend on the choice: every loop is in gather form and
// max/min are exact.
#pragma once

#include <utility>

#include "grit/core/types.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::dem {

/// Does nothing to a grain: the default of the stages that take more work per grain.
struct NoGrainWork {
    void operator()(Index) const noexcept {}
};

/// Calls f(i) for i in [0, n); f writes only to grain i.
template <class F>
void for_each_grain(Index n, F&& f) {
    parallel::for_each(n, std::forward<F>(f));
}

/// Largest f(i) over [0, n); `lowest` when n == 0.
template <class F>
double max_over_grains(Index n, double lowest, F&& f) {
    return parallel::max(n, lowest, std::forward<F>(f));
}

/// Smallest f(i) over [0, n); `highest` when n == 0.
template <class F>
double min_over_grains(Index n, double highest, F&& f) {
    return parallel::min(n, highest, std::forward<F>(f));
}

}  // namespace grit::dem
