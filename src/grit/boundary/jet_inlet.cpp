// Jet inlet.
#include "grit/boundary/jet_inlet.hpp"

#include <fmt/format.h>

#include <cmath>

#include "grit/boundary/section_axes.hpp"
#include "grit/core/error.hpp"

namespace grit::boundary {

template <int Dim>
JetInlet<Dim>::JetInlet(const io::InletSpec& spec, std::int32_t index, double spacing, double density, double mass)
    : spec_(spec), index_(index), spacing_(spacing), density_(density), mass_(mass), travelled_(spacing) {
    for (int k = 0; k < Dim; ++k) {
        position_[k] = spec.position[static_cast<std::size_t>(k)];
        direction_[k] = spec.direction[static_cast<std::size_t>(k)];
        motion_[k] = spec.motion.empty() ? 0.0 : spec.motion[static_cast<std::size_t>(k)];
    }
    const auto axes = section_axes<Dim>(direction_);  // spanning the inlet section
    const double radius = 0.5 * spec.diameter;
    const long n = std::lround(std::floor(spec.diameter / spacing + 1e-6));
    for (long i = 0; i < n; ++i) {
        const double s = (static_cast<double>(i) + 0.5) * spacing - 0.5 * static_cast<double>(n) * spacing;
        if constexpr (Dim == 2) {
            layer_.push_back(axes[0] * s);
        } else {
            for (long j = 0; j < n; ++j) {
                const double u = (static_cast<double>(j) + 0.5) * spacing - 0.5 * static_cast<double>(n) * spacing;
                if (s * s + u * u <= radius * radius) layer_.push_back(axes[0] * s + axes[1] * u);
            }
        }
    }
    if (spec.half) {  // a symmetry plane through the centre: the slots at x > 0 (section_axes: the first is x)
        std::vector<Vec> half;
        for (const Vec& slot : layer_) {
            if (std::abs(slot[0]) < 1e-6 * spacing)
                throw core::InputError(fmt::format(
                    "key '{}.diameter' = {} m: {} particle columns across the inlet, an odd number, so one stands on "
                    "the symmetry plane (where its mirror image would be itself); make the diameter an even number "
                    "of particle spacings",
                    spec.key, spec.diameter, n));
            if (slot[0] > 0.0) half.push_back(slot);
        }
        layer_ = std::move(half);
    }
}

template <int Dim>
double JetInlet<Dim>::emit(particles::SphParticles<Dim>& ps, double t, double dt) {
    if (t + dt <= spec_.start || t >= spec_.stop) return 0.0;
    const double active = std::min(t + dt, spec_.stop) - std::max(t, spec_.start);
    travelled_ += spec_.velocity * active;
    double emitted = 0.0;
    while (travelled_ >= spacing_) {
        travelled_ -= spacing_;
        const auto count = static_cast<Index>(layer_.size());
        // Slot k of layer L has serial L * count + k: its id does not depend on which process emits it.
        const Index first = ps.append(count, {domain::IdKind::inlet, index_}, layers_++ * count);
        // The layer left the section travelled_ / velocity ago, from where the nozzle was then; it has
        // moved with the nozzle since, so it lies ahead of the nozzle's place at t + dt.
        const Vec nozzle = position_ + motion_ * (t + dt);
        for (Index k = 0; k < count; ++k)
            ps.start(first + k, nozzle + layer_[static_cast<std::size_t>(k)] + direction_ * travelled_,
                     direction_ * spec_.velocity + motion_, density_, mass_, Phase::fluid, spec_.material);
        emitted += mass_ * count;
    }
    return emitted;
}

template class JetInlet<2>;
template class JetInlet<3>;

}  // namespace grit::boundary
