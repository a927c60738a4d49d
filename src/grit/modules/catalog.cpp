// grit's own modules: when a case wants each, how it is made, and which modules its stages follow.
#include "grit/modules/catalog.hpp"

#include <algorithm>
#include <stdexcept>

#include "grit/io/case_tables.hpp"
#include "grit/modules/abrasive_feed.hpp"
#include "grit/modules/analyses.hpp"
#include "grit/modules/coupling.hpp"
#include "grit/modules/cracks_table.hpp"
#include "grit/modules/crater_table.hpp"
#include "grit/modules/grain_contact.hpp"
#include "grit/modules/grain_feed.hpp"
#include "grit/modules/grains.hpp"
#include "grit/modules/isph_fluid.hpp"
#include "grit/modules/mesh_wear.hpp"
#include "grit/modules/open_boundaries.hpp"
#include "grit/modules/probes_table.hpp"
#include "grit/modules/sph_fluid.hpp"
#include "grit/modules/sph_solid.hpp"
#include "grit/modules/symmetry_plane.hpp"
#include "grit/modules/thin_walls.hpp"

namespace grit::modules {

namespace {

using sim::BuildTime;
using Spec = io::CaseSpec;

/// True when the case has a fluid material (the coupling and the fluid-in-solid measure need one).
bool has_fluid(const Spec& spec) {
    return std::any_of(spec.materials.begin(), spec.materials.end(),
                       [](const material::Material& m) { return m.phase == Phase::fluid; });
}

/// A descriptor whose module is made from the state and set-up alone.
template <int Dim, template <int> class M>
sim::ModuleDescriptor<Dim> plain(std::string name, BuildTime when, std::function<bool(const Spec&)> wanted,
                                 std::vector<std::string> after = {}) {
    return {std::move(name), when, std::move(after), std::move(wanted),
            [](const sim::ModuleContext<Dim>& c) -> std::unique_ptr<sim::Module<Dim>> {
                return std::make_unique<M<Dim>>(c.state, c.setup);
            }};
}

}  // namespace

template <int Dim>
std::vector<sim::ModuleDescriptor<Dim>> builtin_modules() {
    constexpr auto before = BuildTime::before_particles;
    constexpr auto after = BuildTime::after_particles;
    // The forces on the SPH particles: what the symmetry plane mirrors must be complete before its stages.
    const std::vector<std::string> particle_forces = {"sph",           "isph",          "solid",    "open_boundaries",
                                                      "thin_walls",    "grain_contact", "coupling", "grains",
                                                      "mesh_walls",    "grain_feed",    "abrasive_feed"};
    std::vector<sim::ModuleDescriptor<Dim>> table;
    table.push_back(plain<Dim, IsphModule>("isph", before, [](const Spec& s) {
        return s.has_sph() && s.fluid_solver == "isph";  // the fluid and the walls; the reader refuses the rest
    }));
    table.push_back(plain<Dim, SphModule>("sph", before, [](const Spec& s) {
        return s.has_sph() && s.fluid_solver != "isph";
    }));
    table.push_back({"solid", before, {"sph"}, [](const Spec& s) { return !s.solids.empty(); },
                     [](const sim::ModuleContext<Dim>& c) -> std::unique_ptr<sim::Module<Dim>> {
                         const auto* sph = c.template find<SphModule<Dim>>();
                         if (!sph) throw std::logic_error("the solid module needs the weakly compressible SPH module");
                         return std::make_unique<SolidModule<Dim>>(c.state, c.setup, *sph);
                     }});
    table.push_back(plain<Dim, CraterModule>("crater", before, [](const Spec& s) {
        return !s.solids.empty() && crater_region(s).has_value();
    }));
    table.push_back(plain<Dim, CracksModule>("cracks", before, [](const Spec& s) { return crack_options(s).has_value(); }));
    table.push_back(plain<Dim, FluidInSolidModule>("fluid_in_solid", before, [](const Spec& s) {
        return !s.solids.empty() && has_fluid(s);
    }));
    table.push_back(plain<Dim, OpenBoundariesModule>("open_boundaries", before, [](const Spec& s) { return s.has_sph(); }));
    table.push_back(plain<Dim, ThinWallsModule>("thin_walls", before, [](const Spec& s) { return s.has_thin_walls(); }));
    // The grains module builds the grains the next ones register fields on. Its phases have hooks of their
    // own after theirs; ordered after them, it keeps its place in the outputs' columns and the checkpoint.
    table.push_back(plain<Dim, GrainsModule>("grains", after, [](const Spec& s) { return s.has_grains(); },
                                             {"grain_contact", "coupling"}));
    table.push_back(plain<Dim, GrainContactModule>("grain_contact", after, [](const Spec& s) {
        return s.has_grains() && s.has_sph();
    }));
    table.push_back(plain<Dim, CouplingModule>("coupling", after, [](const Spec& s) {
        return s.has_grains() && s.has_sph() && s.coupling.enabled && has_fluid(s);
    }));
    // The wear books the impacts the grains' forces found; the feeds add grains after the grains' own exits.
    table.push_back(plain<Dim, MeshWearModule>("mesh_walls", after, [](const Spec& s) {
        return s.has_grains() && !s.meshes.empty();
    }, {"grains"}));
    table.push_back(plain<Dim, GrainFeedModule>("grain_feed", after, [](const Spec& s) {
        return s.has_grains() && !s.grain_feeds.empty();
    }, {"grains"}));
    table.push_back(plain<Dim, AbrasiveFeedModule>("abrasive_feed", after, [](const Spec& s) {
        return s.has_grains() && s.abrasive.enabled;
    }, {"grains"}));
    // Also without SPH particles: the grains that straddle the plane are its to sort.
    table.push_back(plain<Dim, SymmetryPlaneModule>("symmetry_plane", after, [](const Spec& s) {
        return s.symmetry_plane;
    }, particle_forces));
    table.push_back(plain<Dim, ProbesModule>("probes", after, [](const Spec& s) {
        const auto* probes = s.module_spec<ProbesSpec>(ProbesSpec::key);
        return probes && !probes->probes.empty();
    }));
    return table;
}

template std::vector<sim::ModuleDescriptor<2>> builtin_modules<2>();
template std::vector<sim::ModuleDescriptor<3>> builtin_modules<3>();

}  // namespace grit::modules

namespace grit::io {

// The tables grit's modules read themselves; the others are still read by io/case_reader.cpp into
// CaseSpec's own members.
std::vector<CaseTable> builtin_case_tables() {
    return {modules::probes_table(), modules::cracks_table(), modules::crater_table()};
}

}  // namespace grit::io
