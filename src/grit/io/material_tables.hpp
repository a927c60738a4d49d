// The case's materials by name, read on first use: SPH materials ([materials.<name>] or the built-in
// library), grain materials ([grain_materials.<name>]), wear materials ([wear_materials.<name>]) and grain
// size distributions.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "grit/dem/grain_material.hpp"
#include "grit/dem/size_distribution.hpp"
#include "grit/io/case_section.hpp"
#include "grit/material/library.hpp"
#include "grit/wear/wear_models.hpp"

namespace grit::io {

/// The material defined by section `s` ([materials.<name>], on top of its `base` if it names one).
material::Material read_material(const Section& s, const std::string& name);

/// SPH materials by name: [materials.<name>] in the case first, else the built-in library.
class MaterialTable {
public:
    MaterialTable(const Section& defined, std::vector<material::Material>& used) : defined_(defined), used_(used) {}

    /// Index of the material named by key `key` of section `s`, which must be of phase `phase`.
    int resolve(const Section& s, std::string_view key, const std::string& name, Phase phase = Phase::fluid) {
        for (std::size_t k = 0; k < used_.size(); ++k)
            if (used_[k].name == name) return check(s, key, static_cast<int>(k), phase);
        if (defined_.has(name)) {
            used_.push_back(read_material(defined_.section(name), name));
        } else if (auto m = material::find_in_library(name)) {
            used_.push_back(*m);
        } else {
            std::string known;
            for (const auto& m2 : material::library()) known += (known.empty() ? "" : ", ") + m2.name;
            for (const auto& k : defined_.keys()) known += ", " + k;
            s.fail(key, "unknown material (known: " + known + ")");
        }
        return check(s, key, static_cast<int>(used_.size()) - 1, phase);
    }

private:
    int check(const Section& s, std::string_view key, int index, Phase phase) const {
        const Phase has = used_[static_cast<std::size_t>(index)].phase;
        if (has != phase)
            s.fail(key, phase == Phase::solid ? "is not a solid material (a solid needs shear_modulus and a model)"
                                              : "is a solid material; this block needs a fluid");
        return index;
    }

private:
    const Section& defined_;
    std::vector<material::Material>& used_;
};

/// The grain material defined by section `s` ([grain_materials.<name>]).
dem::GrainMaterial read_grain_material(const Section& s, const std::string& name);

/// Grain materials by name: [grain_materials.<name>] in the case first, else the built-in library.
class GrainMaterialTable {
public:
    GrainMaterialTable(const Section& defined, std::vector<dem::GrainMaterial>& used) : defined_(defined), used_(used) {}

    int resolve(const Section& s, std::string_view key, const std::string& name) {
        for (std::size_t i = 0; i < used_.size(); ++i)
            if (used_[i].name == name) return static_cast<int>(i);
        if (defined_.has(name)) {
            used_.push_back(read_grain_material(defined_.section(name), name));
        } else if (auto m = dem::find_grain_material(name)) {
            used_.push_back(*m);
        } else {
            std::string known;
            for (const auto& l : dem::grain_material_library()) known += (known.empty() ? "" : ", ") + l.name;
            s.fail(key, "is neither a [grain_materials] entry of the case nor a built-in grain material (" + known + ")");
        }
        return static_cast<int>(used_.size()) - 1;
    }

private:
    const Section& defined_;
    std::vector<dem::GrainMaterial>& used_;
};

/// A wear material: [wear_materials.<name>] (its keys on top of the built-in material `based_on`, if
/// given), else the built-in one of that name; `key` of `s` named it.
wear::WearMaterial read_wear_material(const Section& top, const Section& s, std::string_view key, const std::string& name);

/// Grain diameters: `diameter` (all equal) or a [..size] table with `distribution` = "fixed",
/// "uniform" (min, max) or "normal" (mean, deviation, min, max); else the material's nominal diameter.
dem::SizeDistribution read_grain_size(const Section& s, const dem::GrainMaterial& material);

}  // namespace grit::io
