// The modules grit can run, as descriptors: when a case wants one, how to make it, when in the set-up it is
// made, and which modules its stages follow. The Simulation assembles a case's modules from this table;
// adding a module is its own files plus one descriptor (modules/catalog.cpp, or register_module from outside).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "grit/sim/module.hpp"

namespace grit::sim {

/// When in the set-up a module is made.
enum class BuildTime {
    /// Before the initial SPH particles are placed: it registers SPH fields (whose order is the snapshot's
    /// and the checkpoint's), and its initialise() sees the placed particles.
    before_particles,
    /// Once the SPH particles are placed and wrapped into the periodic box (the grains, and what registers
    /// fields on them or reads both sets).
    after_particles,
};

/// What a module's factory may use: the run's state and set-up, and the modules made before it.
template <int Dim>
struct ModuleContext {
    State<Dim>& state;
    const RunSetup<Dim>& setup;
    const std::vector<std::unique_ptr<Module<Dim>>>& made;

    /// The module of type M made before this one, or null.
    template <class M>
    M* find() const {
        for (const auto& m : made)
            if (auto* found = dynamic_cast<M*>(m.get())) return found;
        return nullptr;
    }
};

template <int Dim>
struct ModuleDescriptor {
    std::string name;  ///< as Module::name() says it (checkpoint group, `grit check --pipeline`)
    BuildTime build_time = BuildTime::before_particles;
    /// Its stages run after those of these modules, at every hook where both have one (names of modules the
    /// case does not run are ignored). Otherwise modules keep the table's order.
    std::vector<std::string> after;
    std::function<bool(const io::CaseSpec&)> wanted;
    std::function<std::unique_ptr<Module<Dim>>(const ModuleContext<Dim>&)> make;
};

/// Every module grit knows, in table order: the built-in ones (modules/catalog.cpp), then the registered.
template <int Dim>
const std::vector<ModuleDescriptor<Dim>>& module_catalog();

/// Adds a module to the catalog (before any Simulation is made: a registrar object at namespace scope).
/// Throws std::logic_error for a name the catalog already holds.
template <int Dim>
void register_module(ModuleDescriptor<Dim> descriptor);

/// The modules `spec` wants, made at `when` (in table order), appended to `modules`. Throws std::logic_error
/// for a module whose name() is not its descriptor's.
template <int Dim>
void make_modules(BuildTime when, const io::CaseSpec& spec, State<Dim>& state, const RunSetup<Dim>& setup,
                  std::vector<std::unique_ptr<Module<Dim>>>& modules);

/// Reorders `modules` (in the order they were made) so that each comes after every module its descriptor
/// names in `after`, and otherwise keeps the order they were made in (the earliest ready module goes
/// first). Throws std::logic_error for a cycle.
template <int Dim>
void order_modules(std::vector<std::unique_ptr<Module<Dim>>>& modules);

}  // namespace grit::sim
