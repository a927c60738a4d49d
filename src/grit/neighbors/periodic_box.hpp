// The periodic box of a run: which axes wrap, and between which bounds. One type for the SPH particles,
// the grains (dem::GrainDomain is this type) and anything that pairs points of the two sets, so that all
// of them agree on the images (case key domain.periodic; docs/architecture.md, "Periodic axes").
#pragma once

#include <array>
#include <cmath>

#include "grit/core/vec.hpp"

namespace grit::neighbors {

/// Periodic axes wrap between lower and upper; other axes are open (their bounds are not used here).
/// Set `periodic`, `lower` and `upper`, then call finalise() (or build one with make()).
template <int Dim>
struct PeriodicBox {
    using Vec = core::Vec<Dim>;

    std::array<bool, Dim> periodic{};
    Vec lower = Vec::zero();
    Vec upper = Vec::zero();

    static PeriodicBox make(const std::array<bool, Dim>& axes, const Vec& lo, const Vec& hi) noexcept {
        PeriodicBox b;
        b.periodic = axes;
        b.lower = lo;
        b.upper = hi;
        b.finalise();
        return b;
    }

    /// Recomputes the cached lengths; call after changing periodic/lower/upper.
    void finalise() noexcept {
        for (int k = 0; k < Dim; ++k) {
            length_[k] = periodic[k] ? upper[k] - lower[k] : 0.0;
            inverse_length_[k] = periodic[k] ? 1.0 / length_[k] : 0.0;
        }
    }

    /// True when some axis is periodic.
    bool any() const noexcept {
        for (int k = 0; k < Dim; ++k)
            if (periodic[k]) return true;
        return false;
    }
    /// The period along axis k (0 for an open axis), and its inverse (0 for an open axis).
    double length(int k) const noexcept { return length_[k]; }
    double inverse_length(int k) const noexcept { return inverse_length_[k]; }

    /// d (a difference of two positions) moved to its nearest periodic image (minimum-image convention).
    /// Branch-free: open axes have length 0 and inverse length 0, so they pass unchanged.
    Vec nearest_image(Vec d) const noexcept {
        for (int k = 0; k < Dim; ++k) d[k] -= length_[k] * std::nearbyint(d[k] * inverse_length_[k]);
        return d;
    }

    /// x moved into [lower, upper) along the periodic axes (open axes unchanged). Exact for a point
    /// already inside; a point that rounding would put on `upper` goes to `lower`, its image.
    Vec wrap(Vec x) const noexcept {
        for (int k = 0; k < Dim; ++k) {
            if (!periodic[k] || (x[k] >= lower[k] && x[k] < upper[k])) continue;
            x[k] -= length_[k] * std::floor((x[k] - lower[k]) * inverse_length_[k]);
            if (x[k] < lower[k]) x[k] += length_[k];
            if (x[k] >= upper[k]) x[k] = lower[k];
        }
        return x;
    }

private:
    Vec length_ = Vec::zero();
    Vec inverse_length_ = Vec::zero();
};

/// The identity image: what pair loops use when no axis is periodic (compiles to nothing).
template <int Dim>
struct OpenImage {
    core::Vec<Dim> operator()(const core::Vec<Dim>& d) const noexcept { return d; }
};

/// The nearest image along the periodic axes of a box, by value (for loops that vectorise).
template <int Dim>
struct PeriodicImage {
    explicit PeriodicImage(const PeriodicBox<Dim>& box) noexcept {
        for (int k = 0; k < Dim; ++k) {
            length[k] = box.length(k);
            inverse_length[k] = box.inverse_length(k);
        }
    }
    core::Vec<Dim> operator()(core::Vec<Dim> d) const noexcept {
        for (int k = 0; k < Dim; ++k) d[k] -= length[k] * std::nearbyint(d[k] * inverse_length[k]);
        return d;
    }
    core::Vec<Dim> length = core::Vec<Dim>::zero();
    core::Vec<Dim> inverse_length = core::Vec<Dim>::zero();
};

/// Calls f(image) with OpenImage when no axis of `box` is periodic, else with PeriodicImage: a loop
/// templated on the image is compiled twice, and the open one is the loop as it was without periodic axes.
template <int Dim, class F>
decltype(auto) with_image(const PeriodicBox<Dim>& box, F&& f) {
    if (box.any()) return f(PeriodicImage<Dim>(box));
    return f(OpenImage<Dim>{});
}

}  // namespace grit::neighbors
