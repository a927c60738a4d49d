// The module catalog, the making of a case's modules from it, and their order (module_catalog.hpp).
#include "grit/sim/module_catalog.hpp"

#include <algorithm>
#include <stdexcept>

#include "grit/modules/catalog.hpp"

namespace grit::sim {

namespace {

template <int Dim>
std::vector<ModuleDescriptor<Dim>>& catalog() {
    static std::vector<ModuleDescriptor<Dim>> table = modules::builtin_modules<Dim>();
    return table;
}

template <int Dim>
const ModuleDescriptor<Dim>& descriptor(const std::string& name) {
    for (const auto& d : catalog<Dim>())
        if (d.name == name) return d;
    throw std::logic_error("no module named '" + name + "' in the catalog");
}

}  // namespace

template <int Dim>
const std::vector<ModuleDescriptor<Dim>>& module_catalog() {
    return catalog<Dim>();
}

template <int Dim>
void register_module(ModuleDescriptor<Dim> d) {
    if (d.name.empty() || !d.wanted || !d.make)
        throw std::logic_error("a module descriptor needs a name, a wanted predicate and a factory");
    auto& table = catalog<Dim>();
    if (std::any_of(table.begin(), table.end(), [&](const auto& e) { return e.name == d.name; }))
        throw std::logic_error("a module named '" + d.name + "' is already in the catalog");
    table.push_back(std::move(d));
}

template <int Dim>
void make_modules(BuildTime when, const io::CaseSpec& spec, State<Dim>& state, const RunSetup<Dim>& setup,
                  std::vector<std::unique_ptr<Module<Dim>>>& modules) {
    for (const auto& d : catalog<Dim>()) {
        if (d.build_time != when || !d.wanted(spec)) continue;
        auto made = d.make(ModuleContext<Dim>{state, setup, modules});
        // The order and the pipeline go by the descriptor's name, checkpoints by the module's: one name.
        if (!made || made->name() != d.name)
            throw std::logic_error("the module made by descriptor '" + d.name + "' is named '" +
                                   (made ? made->name() : std::string("(none)")) + "'");
        modules.push_back(std::move(made));
    }
}

template <int Dim>
void order_modules(std::vector<std::unique_ptr<Module<Dim>>>& modules) {
    const std::size_t n = modules.size();
    std::vector<std::string> names;
    for (const auto& m : modules) names.push_back(m->name());
    std::vector<bool> placed(n, false);
    std::vector<std::size_t> order;
    auto index_of = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    auto ready = [&](std::size_t i) {
        for (const auto& before : descriptor<Dim>(names[i]).after)
            if (const std::size_t j = index_of(before); j < n && !placed[j]) return false;
        return true;
    };
    while (order.size() < n) {
        std::size_t next = n;
        for (std::size_t i = 0; i < n && next == n; ++i)
            if (!placed[i] && ready(i)) next = i;
        if (next == n) throw std::logic_error("the modules' order constraints ('after') form a cycle");
        placed[next] = true;
        order.push_back(next);
    }
    std::vector<std::unique_ptr<Module<Dim>>> sorted;
    for (const std::size_t i : order) sorted.push_back(std::move(modules[i]));
    modules = std::move(sorted);
}

template const std::vector<ModuleDescriptor<2>>& module_catalog<2>();
template void register_module<2>(ModuleDescriptor<2>);
template void make_modules<2>(BuildTime, const io::CaseSpec&, State<2>&, const RunSetup<2>&,
                               std::vector<std::unique_ptr<Module<2>>>&);
template void order_modules<2>(std::vector<std::unique_ptr<Module<2>>>&);
template const std::vector<ModuleDescriptor<3>>& module_catalog<3>();
template void register_module<3>(ModuleDescriptor<3>);
template void make_modules<3>(BuildTime, const io::CaseSpec&, State<3>&, const RunSetup<3>&,
                               std::vector<std::unique_ptr<Module<3>>>&);
template void order_modules<3>(std::vector<std::unique_ptr<Module<3>>>&);

}  // namespace grit::sim
