// The shortest periodic axis the neighbour grid can take (the refusal names the key and the lengths).
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <variant>

#include "grit/core/error.hpp"
#include "grit/sim/module.hpp"

namespace grit::sim {

/// Throws core::InputError when a periodic axis of `setup` is shorter than three neighbour-list radii: the
/// grid divides a periodic axis into whole cells of at least the list radius and scans one cell either side,
/// so with fewer than three a pair would be met twice.
template <int Dim>
void check_periodic_lengths(const RunSetup<Dim>& setup) {
    const io::CaseSpec& spec = setup.spec;
    const double skin = spec.neighbor_skin * setup.smoothing_length;
    const double radius = std::visit([](const auto& k) { return k.support(); }, setup.kernel) + skin;
    const char* axis = "xyz";
    for (int k = 0; k < Dim; ++k) {
        if (!setup.periodic_box.periodic[k]) continue;
        const double length = setup.periodic_box.length(k);
        if (std::floor(length / radius) < 3.0)
            throw core::InputError(fmt::format(
                "key '{}': the domain is {:.6g} m long along the periodic axis {}, less than three neighbour-list "
                "radii (3 x {:.6g} m = {:.6g} m: kernel support + numerics.neighbor_skin); lengthen the domain "
                "along {} or refine numerics.particle_spacing",
                spec.periodic_key, length, axis[k], radius, 3.0 * radius, axis[k]));
    }
}

}  // namespace grit::sim
