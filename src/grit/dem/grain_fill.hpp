// Filling boxes with grains: a simple-cubic lattice (optionally jittered) and random non-overlapping
// placement, both with a seeded std::mt19937_64.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "grit/core/error.hpp"
#include "grit/core/vec.hpp"
#include "grit/dem/size_distribution.hpp"

namespace grit::dem {

/// A grain to be created: centre [m] and diameter [m].
template <int Dim>
struct GrainSeed {
    core::Vec<Dim> position;
    double diameter;
};

/// Lattice points lower + (i + 1/2) spacing inside [lower, upper], x fastest, each moved by up to
/// `jitter` [m] per axis (uniform), diameters from `sizes`. Deterministic for a given seed.
template <int Dim>
std::vector<GrainSeed<Dim>> lattice_fill(const core::Vec<Dim>& lower, const core::Vec<Dim>& upper, double spacing,
                                         const SizeDistribution& sizes, std::uint64_t seed, double jitter = 0.0) {
    validate(sizes);
    if (!(spacing > 0.0)) throw core::InputError("lattice fill: spacing must be > 0 [m]");
    std::array<long, Dim> count{};
    long total = 1;
    for (int k = 0; k < Dim; ++k) {
        count[k] = static_cast<long>(std::floor((upper[k] - lower[k]) / spacing + 1e-9));
        if (count[k] < 0) count[k] = 0;
        total *= count[k];
    }
    std::mt19937_64 rng(seed);
    auto uniform = [&]() { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    std::vector<GrainSeed<Dim>> seeds;
    seeds.reserve(static_cast<std::size_t>(total));
    for (long p = 0; p < total; ++p) {
        long rest = p;
        core::Vec<Dim> x = core::Vec<Dim>::zero();
        for (int k = 0; k < Dim; ++k) {
            x[k] = lower[k] + (static_cast<double>(rest % count[k]) + 0.5) * spacing;
            rest /= count[k];
        }
        for (int k = 0; k < Dim; ++k) x[k] += jitter * (2.0 * uniform() - 1.0);
        seeds.push_back({x, draw_diameter(sizes, rng)});
    }
    return seeds;
}

/// Up to `count` grains at random positions inside [lower, upper] (whole grains), none overlapping
/// another; stops after 100 failed tries per grain. Deterministic for a given seed.
template <int Dim>
std::vector<GrainSeed<Dim>> random_fill(const core::Vec<Dim>& lower, const core::Vec<Dim>& upper, std::size_t count,
                                        const SizeDistribution& sizes, std::uint64_t seed) {
    validate(sizes);
    std::mt19937_64 rng(seed);
    auto uniform = [&]() { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    std::vector<GrainSeed<Dim>> seeds;
    while (seeds.size() < count) {
        const double d = draw_diameter(sizes, rng);
        bool placed = false;
        for (int attempt = 0; attempt < 100 && !placed; ++attempt) {
            core::Vec<Dim> x = core::Vec<Dim>::zero();
            for (int k = 0; k < Dim; ++k) x[k] = lower[k] + 0.5 * d + (upper[k] - lower[k] - d) * uniform();
            placed = true;
            for (const auto& s : seeds) {
                const double reach = 0.5 * (d + s.diameter);
                if (core::norm2(x - s.position) < reach * reach) {
                    placed = false;
                    break;
                }
            }
            if (placed) seeds.push_back({x, d});
        }
        if (!placed) break;
    }
    return seeds;
}

}  // namespace grit::dem
