// Loop shapes used by every physics stage: for_each over an index range and deterministic reductions.
//
// Results never depend on the number of threads: for_each writes only to index i (gather form), and
// reductions add fixed-size blocks in a fixed order, so 1 and N threads give bit-identical sums.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "grit/core/types.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace grit::parallel {

/// Number of threads the parallel loops will use.
inline int max_threads() {
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

/// Sets the number of threads for the parallel loops (n >= 1).
inline void set_threads(int n) {
#ifdef _OPENMP
    omp_set_num_threads(n);
#else
    (void)n;
#endif
}

/// Loops shorter than this run on the calling thread, outside OpenMP: entering a parallel region costs
/// microseconds and futex calls even with an `if(false)` clause, and far more when another process
/// holds a core (the region waits for every thread); a one-grain DEM run spent 95 % of its time there.
inline constexpr Index serial_below = 2048;

/// Calls f(i) for i in [0, n), in parallel. f must write only to per-i data.
template <class F>
void for_each(Index n, F&& f) {
    if (n < serial_below) {
        for (Index i = 0; i < n; ++i) f(i);
        return;
    }
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) f(i);
}

/// Calls f(i) for i in [0, n) with dynamic scheduling (for loops whose cost varies a lot per i).
template <class F>
void for_each_dynamic(Index n, F&& f) {
    if (n < serial_below) {
        for (Index i = 0; i < n; ++i) f(i);
        return;
    }
#pragma omp parallel for schedule(dynamic, 256)
    for (Index i = 0; i < n; ++i) f(i);
}

/// Splits [0, n) into one contiguous chunk per thread, in thread order, and calls f(chunk, begin, end)
/// for each (chunk < max_threads()). For loops that collect a variable amount per i into per-chunk
/// buffers, joined afterwards in chunk order: the joined result does not depend on the thread count.
template <class F>
void for_each_chunk(Index n, F&& f) {
    if (n < serial_below) {
        f(0, Index{0}, n);
        return;
    }
#pragma omp parallel
    {
#ifdef _OPENMP
        const int chunk = omp_get_thread_num(), chunks = omp_get_num_threads();
#else
        const int chunk = 0, chunks = 1;
#endif
        const auto begin = static_cast<Index>(static_cast<long long>(n) * chunk / chunks);
        const auto end = static_cast<Index>(static_cast<long long>(n) * (chunk + 1) / chunks);
        f(chunk, begin, end);
    }
}

inline constexpr Index reduction_block = 4096;

/// Reduction of f(i) over [0, n) with `combine`, in fixed blocks combined in a fixed order, so the
/// result does not depend on the thread count even for non-associative combinations.
template <class T, class F, class C>
T reduce(Index n, T identity, F&& f, C&& combine) {
    const Index blocks = (n + reduction_block - 1) / reduction_block;
    if (blocks <= 1) {  // one block: the same order as below, without a parallel region
        T s = identity;
        for (Index i = 0; i < n; ++i) s = combine(s, f(i));
        return s;
    }
    std::vector<T> partial(static_cast<std::size_t>(blocks), identity);
#pragma omp parallel for schedule(static)
    for (Index b = 0; b < blocks; ++b) {
        T s = identity;
        const Index end = std::min(n, (b + 1) * reduction_block);
        for (Index i = b * reduction_block; i < end; ++i) s = combine(s, f(i));
        partial[static_cast<std::size_t>(b)] = s;
    }
    T total = identity;
    for (const T& s : partial) total = combine(total, s);
    return total;
}

/// Sum of f(i) over [0, n) in a thread-count-independent order (blocks of `reduction_block`).
template <class T, class F>
T sum(Index n, T zero, F&& f) {
    return reduce(n, zero, std::forward<F>(f), [](T a, const T& b) { return a += b; });
}

/// Maximum of f(i) over [0, n); `lowest` when n == 0. Exact whatever the order.
template <class F>
double max(Index n, double lowest, F&& f) {
    double m = lowest;
    if (n < serial_below) {
        for (Index i = 0; i < n; ++i) m = std::max(m, f(i));
        return m;
    }
#pragma omp parallel for schedule(static) reduction(max : m)
    for (Index i = 0; i < n; ++i) m = std::max(m, f(i));
    return m;
}

/// Minimum of f(i) over [0, n); `highest` when n == 0. Exact whatever the order.
template <class F>
double min(Index n, double highest, F&& f) {
    double m = highest;
    if (n < serial_below) {
        for (Index i = 0; i < n; ++i) m = std::min(m, f(i));
        return m;
    }
#pragma omp parallel for schedule(static) reduction(min : m)
    for (Index i = 0; i < n; ++i) m = std::min(m, f(i));
    return m;
}

/// Smallest i in [0, n) with pred(i) true, or -1. Deterministic whatever the thread count.
template <class P>
Index first_index(Index n, P&& pred) {
    if (n < serial_below) {
        for (Index i = 0; i < n; ++i)
            if (pred(i)) return i;
        return -1;
    }
    Index first = n;
#pragma omp parallel for schedule(static) reduction(min : first)
    for (Index i = 0; i < n; ++i)
        if (i < first && pred(i)) first = i;
    return first == n ? Index{-1} : first;
}

}  // namespace grit::parallel
