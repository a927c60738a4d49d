// The module catalog: descriptors registered, made when a case wants them, and ordered by their `after`.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "grit/sim/module_catalog.hpp"

namespace grit::sim {
namespace {

/// A module that is only its name.
class Named final : public Module<2> {
public:
    explicit Named(std::string name) : name_(std::move(name)) {}
    std::string name() const override { return name_; }
    void install(Pipeline&) override {}

private:
    std::string name_;
};

/// Registers a descriptor no real case wants (its `wanted` looks for a title no case has).
void add(const std::string& name, std::vector<std::string> after, const std::string& made_name = "") {
    register_module<2>({name, BuildTime::after_particles, std::move(after),
                        [name](const io::CaseSpec& s) { return s.title == "catalog test: " + name; },
                        [name, made_name](const ModuleContext<2>&) -> std::unique_ptr<Module<2>> {
                            return std::make_unique<Named>(made_name.empty() ? name : made_name);
                        }});
}

std::vector<std::string> ordered(const std::vector<std::string>& made) {
    std::vector<std::unique_ptr<Module<2>>> modules;
    for (const auto& n : made) modules.push_back(std::make_unique<Named>(n));
    order_modules<2>(modules);
    std::vector<std::string> names;
    for (const auto& m : modules) names.push_back(m->name());
    return names;
}

TEST(ModuleCatalog, OrdersByAfterAndOtherwiseKeepsTheOrderMade) {
    add("t_a", {});
    add("t_b", {"t_c"});               // made before t_c, runs after it
    add("t_c", {});
    add("t_d", {"t_b", "t_missing"});  // a name the case does not run is ignored
    EXPECT_EQ(ordered({"t_a", "t_b", "t_c", "t_d"}), (std::vector<std::string>{"t_a", "t_c", "t_b", "t_d"}));
    EXPECT_EQ(ordered({"t_d", "t_c", "t_a"}), (std::vector<std::string>{"t_d", "t_c", "t_a"}));
}

TEST(ModuleCatalog, RefusesACycleADuplicateAndAnIncompleteDescriptor) {
    add("t_e", {"t_f"});
    add("t_f", {"t_e"});
    EXPECT_THROW(ordered({"t_e", "t_f"}), std::logic_error);
    EXPECT_THROW(add("t_e", {}), std::logic_error);
    EXPECT_THROW(register_module<2>({"t_g", BuildTime::after_particles, {}, {}, {}}), std::logic_error);
}

TEST(ModuleCatalog, TheModuleMadeMustCarryItsDescriptorsName) {
    add("t_h", {}, "another_name");
    add("t_i", {});
    io::CaseSpec spec;
    spec.title = "catalog test: t_h";
    State<2> state;
    const sph::Kernel<2> kernel = sph::CubicSpline<2>(1.0);
    const domain::SerialComm comm;
    const RunSetup<2> setup{spec, 1.0, 1.0, kernel, 1.0, {}, comm};
    std::vector<std::unique_ptr<Module<2>>> modules;
    EXPECT_THROW(make_modules<2>(BuildTime::after_particles, spec, state, setup, modules), std::logic_error);
    spec.title = "catalog test: t_i";
    make_modules<2>(BuildTime::after_particles, spec, state, setup, modules);
    ASSERT_EQ(modules.size(), 1u);
    EXPECT_EQ(modules[0]->name(), "t_i");
}

}  // namespace
}  // namespace grit::sim
