// Error types: bad input (a case-file problem, exit code 2) and numerical failure during a run.
#pragma once

#include <stdexcept>
#include <string>

namespace grit::core {

/// Bad input: names the case-file key, the value and the reason. The CLI exits with code 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A numerical blow-up (NaN, negative density, runaway or escaped particle) detected during a run.
class BlowUpError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace grit::core
