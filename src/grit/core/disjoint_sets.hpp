// Union-find (disjoint sets) over indices 0..n-1: the clusters of the crack analysis and of brittle
// fragments.
#pragma once

#include <utility>
#include <vector>

#include "grit/core/types.hpp"

namespace grit::core {

/// Union-find with path compression (halving); the smaller index becomes the root, so the forest,
/// like the clusters, does not depend on the order of the unions.
struct DisjointSets {
    std::vector<Index> parent;
    explicit DisjointSets(Index n) : parent(static_cast<std::size_t>(n)) {
        for (Index i = 0; i < n; ++i) parent[static_cast<std::size_t>(i)] = i;
    }
    Index find(Index i) {
        while (parent[static_cast<std::size_t>(i)] != i) {
            auto& p = parent[static_cast<std::size_t>(i)];
            p = parent[static_cast<std::size_t>(p)];
            i = p;
        }
        return i;
    }
    void unite(Index a, Index b) {
        a = find(a);
        b = find(b);
        if (a == b) return;
        if (b < a) std::swap(a, b);
        parent[static_cast<std::size_t>(b)] = a;
    }
};

}  // namespace grit::core
