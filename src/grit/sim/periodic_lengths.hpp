// The shortest periodic axis a case can have (the refusal names the key and the lengths).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <variant>

#include "grit/core/error.hpp"
#include "grit/sim/damage_reach.hpp"
#include "grit/sim/module.hpp"

namespace grit::sim {

/// Throws core::InputError when a periodic axis of `setup` is not longer than twice the reach of the
/// particles' sums (the kernel support, or a non-local damage length if longer): a pair is taken at its
/// nearest image, so over a shorter period a particle would meet two images of one neighbour and count
/// only one. (The neighbour grid takes any longer period: below three list radii it is one cell along
/// that axis.)
template <int Dim>
void check_periodic_lengths(const RunSetup<Dim>& setup) {
    const io::CaseSpec& spec = setup.spec;
    const double support = std::visit([](const auto& k) { return k.support(); }, setup.kernel);
    double reach = support;
    std::string what = "the kernel support";
    if (const DamageReach damage = longest_damage_reach(spec); damage.length > reach) {
        reach = damage.length;
        what = "the non-local damage length of material '" + damage.material + "'";
    }
    const char* axis = "xyz";
    for (int k = 0; k < Dim; ++k) {
        if (!setup.periodic_box.periodic[k]) continue;
        const double length = setup.periodic_box.length(k);
        if (!(length > 2.0 * reach * (1.0 + 1e-12)))
            throw core::InputError(fmt::format(
                "key '{}': the domain is {:.6g} m long along the periodic axis {}, not more than twice {} "
                "(2 x {:.6g} m = {:.6g} m): a particle would meet two periodic images of one neighbour; lengthen "
                "the domain along {} or refine numerics.particle_spacing",
                spec.periodic_key, length, axis[k], what, reach, 2.0 * reach, axis[k]));
    }
}

}  // namespace grit::sim
