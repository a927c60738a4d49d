// How grit's OpenMP threads wait: see thread_waits.hpp.
#include "thread_waits.hpp"

#include <unistd.h>

#include <cstdlib>

namespace grit::app {

void use_short_spin_waits(char** argv) {
    if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
    if (setenv("GOMP_SPINCOUNT", short_spin_count, 0) != 0) return;
    execv("/proc/self/exe", argv);
    unsetenv("GOMP_SPINCOUNT");  // no /proc: run on with the default, and leave children's environment as it was
}

}  // namespace grit::app
