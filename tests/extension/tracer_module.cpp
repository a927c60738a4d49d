// The tracer module and its case table (tracer_module.hpp).
#include "tracer_module.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>

#include "grit/core/error.hpp"
#include "grit/io/case_section.hpp"
#include "grit/io/case_tables.hpp"
#include "grit/sim/module_catalog.hpp"

namespace grit::testing {

namespace {

template <int Dim>
class TracerModule final : public sim::Module<Dim> {
public:
    TracerModule(const sim::State<Dim>& state, const TracerSpec& spec) : state_(state), spec_(spec) {}
    std::string name() const override { return "tracer"; }
    void install(sim::Pipeline& pipeline) override {
        pipeline.add(sim::Hook::end_step, "tracer_count", [this] { count(); });
    }
    void initialise() override { count(); }
    void output_values(std::vector<sim::OutputValue>& out) const override {
        out.push_back(sim::OutputValue::count("tracer_particles", static_cast<double>(count_), domain::Combine::sum)
                          .in_unit("1"));
    }

private:
    void count() {
        const auto& ps = state_.particles;
        const auto* x = ps.position();
        const auto* phase = ps.phase();
        Index n = 0;
        for (Index i = 0; i < ps.size(); ++i) {
            if (phase[i] != spec_.phase) continue;
            double d2 = 0.0;
            for (int k = 0; k < Dim; ++k) d2 += std::pow(x[i][k] - spec_.centre[static_cast<std::size_t>(k)], 2);
            if (d2 <= spec_.radius * spec_.radius) ++n;
        }
        count_ = n;
    }

    const sim::State<Dim>& state_;
    const TracerSpec& spec_;
    Index count_ = 0;
};

std::shared_ptr<const io::ModuleSpec> read_tracer(const io::Section& top, const io::CaseSpec& c) {
    const io::Section t = top.section("tracer");
    auto spec = std::make_shared<TracerSpec>();
    spec->centre = t.vector("centre", c.dimension, "[m]");
    spec->radius = t.number("radius", io::positive("[m]"));
    if (spec->radius < c.particle_spacing)
        t.fail("radius", fmt::format("is less than numerics.particle_spacing = {} m", c.particle_spacing));
    spec->phase = static_cast<int>(t.choice("phase", "fluid", {"fluid", "solid"}) == "solid" ? Phase::solid : Phase::fluid);
    return spec;
}

/// The tracer's own rules across the case: its centre in the domain, its phase present.
void check_tracer(const io::CaseSpec& c) {
    const auto* spec = c.module_spec<TracerSpec>("tracer");
    if (!spec) return;
    for (std::size_t k = 0; k < spec->centre.size(); ++k)
        if (spec->centre[k] < c.domain_min[k] || spec->centre[k] > c.domain_max[k])
            throw core::InputError(fmt::format("key 'tracer.centre': the point lies outside domain.min/domain.max"));
    if (spec->phase == static_cast<int>(Phase::solid) && c.solids.empty())
        throw core::InputError("key 'tracer.phase' = \"solid\": the case has no [[solid]]");
}

template <int Dim>
sim::ModuleDescriptor<Dim> tracer_descriptor() {
    return {"tracer", sim::BuildTime::after_particles, {},
            [](const io::CaseSpec& s) { return s.module_spec<TracerSpec>("tracer") != nullptr; },
            [](const sim::ModuleContext<Dim>& c) -> std::unique_ptr<sim::Module<Dim>> {
                return std::make_unique<TracerModule<Dim>>(c.state, *c.setup.spec.template module_spec<TracerSpec>("tracer"));
            }};
}

}  // namespace

void register_tracer() {
    static const bool registered = [] {
        io::register_case_table({"tracer", read_tracer, check_tracer});
        sim::register_module<2>(tracer_descriptor<2>());
        sim::register_module<3>(tracer_descriptor<3>());
        return true;
    }();
    (void)registered;
}

namespace {
/// Registered when the test program starts, as a plug-in module would be.
const struct TracerRegistrar {
    TracerRegistrar() { register_tracer(); }
} registrar;
}  // namespace

}  // namespace grit::testing
