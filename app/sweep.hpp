// `grit sweep`: a case run over the product of parameter lists, each run a `grit run` of its own in
// its own folder, the results gathered in one sweep.csv. Finished runs are not redone.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace grit::app {

/// One swept key and its values, from --param key=v1,v2,...
struct SweepParameter {
    std::string key;
    std::vector<std::string> values;
};

/// Parses "key=v1,v2,..." (throws core::InputError naming the option for a malformed one).
SweepParameter parse_sweep_parameter(const std::string& text);

/// The product of the lists, first parameter slowest: each row holds one value per parameter.
std::vector<std::vector<std::string>> sweep_points(const std::vector<SweepParameter>& parameters);

/// A run's folder name: key=value pairs joined by "_" ("jet.velocity=383_abrasive.seed=2").
std::string sweep_run_name(const std::vector<SweepParameter>& parameters, const std::vector<std::string>& point);

struct SweepOptions {
    std::filesystem::path grit;           ///< the grit executable the runs use
    std::filesystem::path case_file;
    std::vector<std::string> sets;        ///< --set overrides applied to every run
    std::vector<SweepParameter> parameters;
    std::filesystem::path out;
    int jobs = 1;                         ///< runs at once
    int threads = 0;                      ///< threads in all (0: all cores), shared among the jobs
    bool quiet = false;
};

/// Runs the sweep; returns the exit code (0: every run completed; 3: some did not, see sweep.csv).
int run_sweep(const SweepOptions& options);

}  // namespace grit::app
