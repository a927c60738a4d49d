// The crater analysis' case table (crater_table.hpp).
#include "grit/modules/crater_table.hpp"

#include <memory>

#include "grit/core/error.hpp"
#include "grit/io/case_section.hpp"

namespace grit::modules {

namespace {

std::shared_ptr<const io::ModuleSpec> read_crater(const io::Section& top, const io::CaseSpec& c) {
    const io::Section crater = top.section(CraterSpec::key);
    if (c.solids.empty()) throw core::InputError("key 'crater': a crater needs a [[solid]]");
    auto spec = std::make_shared<CraterSpec>();
    auto& r = spec->region;
    const double dx = c.particle_spacing;
    r.surface = crater.number("surface");
    r.x_min = crater.number("x_min");
    r.x_max = crater.number("x_max");
    if (r.x_max <= r.x_min + dx) crater.fail("x_max", "must exceed x_min by more than a spacing [m]");
    if (c.dimension == 3) {
        r.y_min = crater.number("y_min");
        r.y_max = crater.number("y_max");
        if (r.y_max <= r.y_min + dx) crater.fail("y_max", "must exceed y_min by more than a spacing [m]");
    }
    return spec;
}

}  // namespace

io::CaseTable crater_table() {
    return {CraterSpec::key, read_crater, {}};
}

std::optional<analysis::CraterRegion> crater_region(const io::CaseSpec& spec) {
    analysis::CraterRegion r;
    if (const auto* crater = spec.module_spec<CraterSpec>(CraterSpec::key)) {
        r = crater->region;
    } else if (spec.has_jet && spec.jet.crater) {
        const auto& j = *spec.jet.crater;
        r = {j.surface, j.x_min, j.x_max, false, j.y_min, j.y_max};
    } else {
        return std::nullopt;
    }
    if (spec.symmetry_plane) {  // the whole crater: the profile of the half, mirrored
        r.mirror = true;
        r.x_min = -r.x_max;
    }
    return r;
}

}  // namespace grit::modules
