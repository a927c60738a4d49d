// A snapshot of the SPH particles with the names behind their integer codes (material and phase), as the
// outputs, the last good state and an interrupted run's state write it.
#pragma once

#include <cstdint>

#include "grit/io/case_spec.hpp"
#include "grit/io/point_data.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::sim {

inline const char* phase_name(std::int32_t p) {
    switch (static_cast<Phase>(p)) {
        case Phase::fluid: return "fluid";
        case Phase::solid: return "solid";
        case Phase::wall: return "wall";
        case Phase::grain: return "grain";
    }
    return "unknown";
}

/// `particles` with `material_names` (the case's materials, by the `material` index) and `phase_names` (by
/// the `phase` code).
template <int Dim>
io::PointCloud named_snapshot(const particles::SphParticles<Dim>& particles, const io::CaseSpec& spec) {
    io::PointCloud cloud = particles.snapshot();
    io::NameList materials{"material_names", {}};
    for (const auto& m : spec.materials) materials.values.push_back(m.name);
    io::NameList phases{"phase_names", {}};
    for (const auto p : {Phase::fluid, Phase::solid, Phase::wall}) phases.values.push_back(phase_name(static_cast<std::int32_t>(p)));
    cloud.names.push_back(std::move(materials));
    cloud.names.push_back(std::move(phases));
    return cloud;
}

}  // namespace grit::sim
