// Index types shared by all modules.
#pragma once

#include <cstdint>

namespace grit {

/// Particle index within a particle set.
using Index = std::int32_t;

/// Particle phase, stored per particle and written to the `phase` output array.
enum class Phase : std::int32_t { fluid = 0, solid = 1, wall = 2, grain = 3 };

/// The phase codes as the `phase` array holds them, for comparisons in the pair loops.
inline constexpr std::int32_t fluid_phase = static_cast<std::int32_t>(Phase::fluid);
inline constexpr std::int32_t wall_phase = static_cast<std::int32_t>(Phase::wall);

}  // namespace grit
