// The figures the validation tests measure, recorded for docs/validation.md: each call writes (or
// updates) build/validation/<Suite.Test>.json with the figure's value, unit, tolerance and reference.
// scripts/validation_table.py builds the "Figures CI measures" table from these files, and the
// validation_table test checks the committed table against them at the table's digits. Recording does
// not replace the test's own assertion.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace grit::testing {

struct Figure {
    std::string name;       ///< what is measured: "largest front error, 1.5 <= T <= 2.5"
    double value;           ///< in `unit`
    std::string unit;       ///< "%", "MPa", "m/s", "-"
    std::string tolerance;  ///< the test's bound, as the test asserts it: "< 10 %"
    std::string reference;  ///< the source: "Martin & Moyce (1952)"
    int digits = 3;         ///< significant digits in the table
};

inline void record_figure(const Figure& f) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string test = std::string(info->test_suite_name()) + "." + info->name();
    const std::filesystem::path dir(GRIT_VALIDATION_DIR);
    std::filesystem::create_directories(dir);
    const auto file = dir / (test + ".json");
    nlohmann::ordered_json j;
    if (std::ifstream in(file); in) {
        try {
            j = nlohmann::ordered_json::parse(in);
        } catch (const nlohmann::json::exception&) {
            j = nullptr;
        }
    }
    if (!j.is_object() || !j.contains("figures")) j = {{"test", test}, {"figures", nlohmann::ordered_json::array()}};
    nlohmann::ordered_json entry = {{"name", f.name},           {"value", f.value},
                                    {"unit", f.unit},           {"tolerance", f.tolerance},
                                    {"reference", f.reference}, {"digits", f.digits}};
    bool replaced = false;
    for (auto& e : j["figures"])
        if (e["name"] == f.name) {
            e = entry;
            replaced = true;
        }
    if (!replaced) j["figures"].push_back(entry);
    std::ofstream(file) << j.dump(2) << '\n';
}

}  // namespace grit::testing
