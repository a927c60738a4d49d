// How grit's OpenMP threads wait at the end of a parallel loop.
#pragma once

namespace grit::app {

/// The spin count grit gives libgomp: what libgomp itself uses when it knows it has more threads than
/// free cores (its "throttled" count), and within the noise of its default on an idle machine.
inline constexpr const char* short_spin_count = "1000";

/// Unless the user chose how OpenMP threads wait (OMP_WAIT_POLICY or GOMP_SPINCOUNT), sets
/// GOMP_SPINCOUNT=1000 and executes grit again with the same arguments: libgomp reads its environment
/// once, when it is loaded, before main. Returns only if nothing was changed or the exec failed.
///
/// Why: libgomp's default spins up to 300,000 times at every barrier before it sleeps. When another
/// process holds one of the cores (another terminal's job; the scheduler then gives grit's session one
/// core for its two threads), a thread spins away the time slice its partner needs: the coarse AWJ on
/// copper ran 35x slower than on one thread (docs/performance.md, "Threads that wait for a descheduled
/// partner").
void use_short_spin_waits(char** argv);

}  // namespace grit::app
