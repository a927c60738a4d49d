// Grain size distributions (fixed, uniform, normal with cut-offs) drawn with a seeded std::mt19937_64,
// so a case gives the same grains on every machine and thread count.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "grit/core/error.hpp"

namespace grit::dem {

/// Every grain has the same diameter [m].
struct FixedSize {
    static constexpr std::string_view name = "fixed";
    double diameter = 0.0;
    double draw(std::mt19937_64&) const noexcept { return diameter; }
    double smallest() const noexcept { return diameter; }
    double largest() const noexcept { return diameter; }
};

/// Diameters uniform in [min, max] [m].
struct UniformSize {
    static constexpr std::string_view name = "uniform";
    double min = 0.0, max = 0.0;
    double draw(std::mt19937_64& rng) const {
        // Drawn from the raw 64-bit stream (std::uniform_real_distribution's algorithm is not fixed by
        // the standard, so its values could differ between standard libraries).
        const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
        return min + (max - min) * u;
    }
    double smallest() const noexcept { return min; }
    double largest() const noexcept { return max; }
};

/// Normal diameters (mean, standard deviation) [m], redrawn until inside [min, max].
struct NormalSize {
    static constexpr std::string_view name = "normal";
    double mean = 0.0, deviation = 0.0, min = 0.0, max = 0.0;
    double draw(std::mt19937_64& rng) const {
        // Box-Muller on the raw stream, for the same reason as UniformSize.
        for (;;) {
            const double u1 = (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53;
            const double u2 = static_cast<double>(rng() >> 11) * 0x1.0p-53;
            const double z = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.141592653589793 * u2);
            const double d = mean + deviation * z;
            if (d >= min && d <= max) return d;
        }
    }
    double smallest() const noexcept { return min; }
    double largest() const noexcept { return max; }
};

/// A few diameters [m] in given mass fractions (LIGGGHTS' particledistribution/discrete): a grain takes
/// diameter d_i with the number probability w_i / d_i^3 / sum_j (w_j / d_j^3), so that the mass drawn
/// is in the fractions w_i.
struct DiscreteSize {
    static constexpr std::string_view name = "discrete";
    std::vector<double> diameters, mass_fractions;
    double draw(std::mt19937_64& rng) const {
        double total = 0.0;
        for (std::size_t i = 0; i < diameters.size(); ++i)
            total += mass_fractions[i] / std::pow(diameters[i], 3);
        double u = static_cast<double>(rng() >> 11) * 0x1.0p-53 * total;
        for (std::size_t i = 0; i + 1 < diameters.size(); ++i) {
            u -= mass_fractions[i] / std::pow(diameters[i], 3);
            if (u < 0.0) return diameters[i];
        }
        return diameters.back();
    }
    /// The number-weighted mean diameter [m].
    double mean() const {
        double count = 0.0, sum = 0.0;
        for (std::size_t i = 0; i < diameters.size(); ++i) {
            const double n = mass_fractions[i] / std::pow(diameters[i], 3);
            count += n;
            sum += n * diameters[i];
        }
        return sum / count;
    }
    double smallest() const noexcept {
        double d = diameters.empty() ? 0.0 : diameters.front();
        for (const double x : diameters)
            d = std::min(d, x);
        return d;
    }
    double largest() const noexcept {
        double d = 0.0;
        for (const double x : diameters)
            d = std::max(d, x);
        return d;
    }
};

using SizeDistribution = std::variant<FixedSize, UniformSize, NormalSize, DiscreteSize>;

/// Checks the parameters (positive diameters, min <= max, mean inside the cut-offs); InputError naming
/// the distribution otherwise.
inline void validate(const SizeDistribution& distribution) {
    std::visit(
        [](const auto& d) {
            using T = std::decay_t<decltype(d)>;
            bool ok = true;
            if constexpr (std::is_same_v<T, FixedSize>)
                ok = d.diameter > 0.0;
            else if constexpr (std::is_same_v<T, UniformSize>)
                ok = d.min > 0.0 && d.max >= d.min;
            else if constexpr (std::is_same_v<T, NormalSize>)
                ok = d.min > 0.0 && d.max >= d.min && d.deviation >= 0.0 && d.mean >= d.min && d.mean <= d.max;
            else {
                double sum = 0.0;
                ok = !d.diameters.empty() && d.diameters.size() == d.mass_fractions.size();
                for (std::size_t i = 0; ok && i < d.diameters.size(); ++i) {
                    ok = d.diameters[i] > 0.0 && d.mass_fractions[i] >= 0.0;
                    sum += d.mass_fractions[i];
                }
                ok = ok && std::abs(sum - 1.0) < 1e-9;
                if (!ok)
                    throw core::InputError(
                        "grain size distribution 'discrete': needs diameters > 0 [m] and as many "
                        "mass_fractions >= 0 summing to 1");
            }
            if (!ok)
                throw core::InputError("grain size distribution '" + std::string(T::name) +
                                       "': diameters must be > 0 [m] with min <= (mean <=) max");
        },
        distribution);
}

/// One diameter [m] from the distribution.
inline double draw_diameter(const SizeDistribution& distribution, std::mt19937_64& rng) {
    return std::visit([&](const auto& d) { return d.draw(rng); }, distribution);
}

/// The smallest diameter the distribution can give [m].
inline double smallest_diameter(const SizeDistribution& distribution) {
    return std::visit([](const auto& d) { return d.smallest(); }, distribution);
}

/// The largest diameter the distribution can give [m].
inline double largest_diameter(const SizeDistribution& distribution) {
    return std::visit([](const auto& d) { return d.largest(); }, distribution);
}

}  // namespace grit::dem
