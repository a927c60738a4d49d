// How far a non-local damage average reaches: the ghost width and the shortest period depend on it.
#pragma once

#include <string>
#include <variant>

#include "grit/io/case_spec.hpp"

namespace grit::sim {

/// The longest non-local damage length among the case's materials [m] (0 if none averages its damage),
/// and that material's name.
struct DamageReach {
    double length = 0.0;
    std::string material;
};

inline DamageReach longest_damage_reach(const io::CaseSpec& spec) {
    DamageReach out;
    for (const auto& m : spec.materials)
        if (const auto* jc = std::get_if<material::JohnsonCook>(&m.solid_model);
            jc && jc->nonlocal_damage() && jc->damage_length > out.length)
            out = {jc->damage_length, m.name};
    return out;
}

}  // namespace grit::sim
