// A jet inlet: emits layers of fluid particles through a segment (2D) or disc (3D) at a set velocity,
// one layer each time the previous one has travelled one particle spacing. A traversing nozzle moves at
// `motion` (its section is at position + motion t).
#pragma once

#include <cstdint>
#include <vector>

#include "grit/core/vec.hpp"
#include "grit/io/case_spec.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::boundary {

template <int Dim>
class JetInlet {
public:
    using Vec = core::Vec<Dim>;

    /// `density` and `mass` are those of each emitted particle; `index` is the inlet's place among the
    /// case's inlets (its particles' ids are by origin: this inlet, layer and slot).
    JetInlet(const io::InletSpec& spec, std::int32_t index, double spacing, double density, double mass);

    /// Emits the layers due during (t, t + dt]; returns the mass emitted [kg] (per metre in 2D).
    double emit(particles::SphParticles<Dim>& particles, double t, double dt);

    /// Distance the last emitted layer has moved [m] and the number of layers emitted: the inlet's whole
    /// state, for checkpoints.
    double travelled() const noexcept { return travelled_; }
    void set_travelled(double d) noexcept { travelled_ = d; }
    std::int64_t layers() const noexcept { return layers_; }
    void set_layers(std::int64_t n) noexcept { layers_ = n; }

    /// Offsets of one layer's particles within the inlet section (perpendicular to the jet).
    const std::vector<Vec>& layer() const { return layer_; }

private:
    io::InletSpec spec_;
    std::int32_t index_;
    Vec position_, direction_;
    Vec motion_;  ///< the nozzle's velocity (traverse) [m/s]
    double spacing_, density_, mass_;
    std::vector<Vec> layer_;
    double travelled_;        ///< distance the last emitted layer has moved [m]
    std::int64_t layers_ = 0;  ///< layers emitted so far: the next layer's number
};

extern template class JetInlet<2>;
extern template class JetInlet<3>;

}  // namespace grit::boundary
