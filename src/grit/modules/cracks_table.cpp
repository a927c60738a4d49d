// The crack analysis' case table (cracks_table.hpp).
#include "grit/modules/cracks_table.hpp"

#include <memory>
#include <variant>

#include "grit/core/error.hpp"
#include "grit/io/case_section.hpp"

namespace grit::modules {

namespace {

analysis::CrackOptions default_options(const io::CaseSpec& c) {
    analysis::CrackOptions o;
    o.link_distance = 1.5 * c.particle_spacing;
    return o;
}

std::shared_ptr<const io::ModuleSpec> read_cracks(const io::Section& top, const io::CaseSpec& c) {
    const io::Section cracks = top.section(CracksSpec::key);
    if (c.solids.empty()) throw core::InputError("key 'cracks': the crack analysis needs a [[solid]]");
    auto spec = std::make_shared<CracksSpec>();
    auto& o = spec->options;
    o = default_options(c);
    o.damage_threshold = cracks.number_or("damage_threshold", o.damage_threshold, io::in_range(1e-9, 1.0));
    o.link_distance = cracks.number_or("link_distance", o.link_distance, io::positive("[m]"));
    o.min_particles = cracks.integer_or("min_particles", o.min_particles, 1, 1000000000);
    return spec;
}

}  // namespace

io::CaseTable cracks_table() {
    return {CracksSpec::key, read_cracks, {}};
}

std::optional<analysis::CrackOptions> crack_options(const io::CaseSpec& spec) {
    if (const auto* cracks = spec.module_spec<CracksSpec>(CracksSpec::key)) return cracks->options;
    if (spec.solids.empty()) return std::nullopt;
    for (const auto& m : spec.materials)
        if (std::holds_alternative<material::JH2>(m.solid_model)) return default_options(spec);
    return std::nullopt;
}

}  // namespace grit::modules
