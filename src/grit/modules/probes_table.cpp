// The probes' case table (probes_table.hpp).
#include "grit/modules/probes_table.hpp"

#include "grit/io/case_section.hpp"

#include <memory>
#include <set>
#include <string>

namespace grit::modules {

namespace {

std::shared_ptr<const io::ModuleSpec> read_probes(const io::Section& top, const io::CaseSpec& c) {
    const int dim = c.dimension;
    auto spec = std::make_shared<ProbesSpec>();
    std::set<std::string> probe_names;
    for (const io::Section& s : top.sections(ProbesSpec::key)) {
        analysis::ProbeSpec p;
        p.key = s.path();
        p.name = s.text("name");
        if (p.name.empty() || p.name.find_first_of(", \t\"") != std::string::npos)
            s.fail("name", "must be a non-empty column name without commas, spaces or quotes");
        if (!probe_names.insert(p.name).second) s.fail("name", "is used by another probe");
        p.kind = s.choice("kind", "point", {"point", "front"});
        p.phase = s.choice("phase", "fluid", {"fluid", "solid"}) == "solid" ? 1 : 0;
        if (p.kind == "point") {
            p.quantity = s.choice("quantity", "pressure", {"pressure", "density", "velocity"});
            p.position = s.vector("position", dim, "[m]");
        } else {
            const std::string axis = s.choice("axis", "x", dim == 2 ? std::vector<std::string>{"x", "y"}
                                                                    : std::vector<std::string>{"x", "y", "z"});
            p.axis = axis[0] - 'x';
            if (s.has("min") || s.has("max")) {
                p.has_region = true;
                p.min = s.vector("min", dim, "[m]");
                p.max = s.vector("max", dim, "[m]");
            }
        }
        spec->probes.push_back(std::move(p));
    }
    return spec;
}

}  // namespace

io::CaseTable probes_table() {
    return {ProbesSpec::key, read_probes, {}};
}

}  // namespace grit::modules
