// grit's own modules, as descriptors for the module catalog (sim/module_catalog.hpp).
#pragma once

#include <vector>

#include "grit/sim/module_catalog.hpp"

namespace grit::modules {

/// One descriptor per built-in module. Table order is the order they are made in (and so the order their
/// fields are registered in) and, where no `after` says otherwise, the order of their stages and columns.
template <int Dim>
std::vector<sim::ModuleDescriptor<Dim>> builtin_modules();

extern template std::vector<sim::ModuleDescriptor<2>> builtin_modules<2>();
extern template std::vector<sim::ModuleDescriptor<3>> builtin_modules<3>();

}  // namespace grit::modules
