// Abrasive feed.
#include "grit/boundary/abrasive_inlet.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "grit/boundary/section_axes.hpp"

namespace grit::boundary {

namespace {
/// A uniform number in [0, 1) from the raw 64-bit stream (the standard's distributions are not
/// reproducible across standard libraries; see dem/size_distribution.hpp).
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
}  // namespace

template <int Dim>
AbrasiveInlet<Dim>::AbrasiveInlet(const io::AbrasiveSpec& spec, const io::InletSpec& jet)
    : spec_(spec), jet_velocity_(jet.velocity), jet_radius_(0.5 * jet.diameter) {
    for (int k = 0; k < Dim; ++k) {
        nozzle_[k] = jet.position[static_cast<std::size_t>(k)];
        direction_[k] = jet.direction[static_cast<std::size_t>(k)];
        motion_[k] = jet.motion.empty() ? 0.0 : jet.motion[static_cast<std::size_t>(k)];
    }
    across_ = section_axes<Dim>(direction_);
    column_ = spec.feed_spacing > 0.0 ? spec.feed_spacing : spec.spacing;
    period_ = column_ / jet_velocity_;
}

template <int Dim>
typename AbrasiveInlet<Dim>::Draw AbrasiveInlet<Dim>::draw(std::int64_t column) const {
    std::seed_seq seq{static_cast<std::uint32_t>(spec_.seed), static_cast<std::uint32_t>(spec_.seed >> 32),
                      static_cast<std::uint32_t>(column), static_cast<std::uint32_t>(column >> 32)};
    std::mt19937_64 rng(seq);
    Draw d;
    d.diameter = std::visit([&](const auto& s) { return s.draw(rng); }, spec_.size);
    // The grain lies in its column with at least one diameter of water before the next column's
    // front, so two grains never overlap as they enter (the reader checks y_dis >= the largest
    // diameter).
    const double free_length = std::max(0.0, column_ - d.diameter);
    d.entry_time = spec_.start + (static_cast<double>(column) * column_ + unit(rng) * free_length) / jet_velocity_;
    // Across the jet: uniform over the part of the section that holds the whole grain.
    const double reach = std::max(0.0, jet_radius_ - 0.5 * d.diameter);
    d.offset = Vec::zero();
    if constexpr (Dim == 2) {
        if (spec_.half_jet) {
            // The half section of a symmetry plane at x = 0 (the inlet's centre is d_jet/4 off it): the
            // centre's distance from the plane uniform over [0, d_jet/2 - d/2], as |x| in the whole jet.
            const double from_plane = unit(rng) * std::max(0.0, 2.0 * jet_radius_ - 0.5 * d.diameter);
            d.offset = Vec::zero();
            d.offset[0] = from_plane - nozzle_[0];
            return d;
        }
        d.offset = across_[0] * ((2.0 * unit(rng) - 1.0) * reach);
    } else {
        for (;;) {
            const double a = 2.0 * unit(rng) - 1.0, b = 2.0 * unit(rng) - 1.0;
            if (a * a + b * b > 1.0) continue;
            d.offset = across_[0] * (a * reach) + across_[1] * (b * reach);
            break;
        }
    }
    return d;
}

template <int Dim>
std::vector<typename AbrasiveInlet<Dim>::Grain> AbrasiveInlet<Dim>::emit(double t, double dt) {
    std::vector<Grain> out;
    const double end = t + dt;
    const double lead_time = spec_.lead / jet_velocity_;
    for (;;) {
        if (spec_.start + static_cast<double>(next_column_) * period_ - lead_time > std::min(end, spec_.stop)) break;
        const Draw d = draw(next_column_);
        if (d.entry_time - lead_time > end) break;  // this column's grain joins in a later step
        const std::int64_t column = next_column_++;
        if (d.entry_time >= spec_.stop) break;
        const Vec velocity = direction_ * jet_velocity_ + motion_;
        // It crosses the section where the nozzle is at entry_time (upstream of it until then).
        const Vec at_entry = nozzle_ + motion_ * d.entry_time + d.offset;
        out.push_back({column, at_entry + velocity * (end - d.entry_time), d.diameter, velocity});
    }
    return out;
}

template class AbrasiveInlet<2>;
template class AbrasiveInlet<3>;

}  // namespace grit::boundary
