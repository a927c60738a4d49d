// Particle and grain ids by origin. An id says which source made the particle (a block, an inlet, a feed,
// numbered by the case, never by the order sources run) and its serial within that source (a block's
// lattice index, an inlet's layer and slot, a feed's column or fill number). Which id a particle gets
// therefore never depends on how the work is split: a process that builds only its part of a block, or
// sources that run in another order, give every particle the id one process would (docs/architecture.md,
// "Particle ids").
//
// Layout of the 63 bits of a non-negative id: kind (7 bits) | index of the source within its kind
// (16 bits) | serial (40 bits, 1.1e12 per source). Negative ids are a symmetry plane's mirror images.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace grit::domain {

using ParticleId = std::int64_t;

/// The kinds of source that make particles and grains.
enum class IdKind : std::int32_t {
    hand_built = 0,  ///< appended by hand (tests, tools): numbered in the order of appending
    fluid_block = 1,
    solid_block = 2,
    wall_block = 3,
    inlet = 4,
    grain_block = 5,
    grain_feed = 6,
    abrasive_feed = 7,
};

/// Which source made a particle: its kind and the source's index among the case's sources of that kind.
struct IdSource {
    IdKind kind = IdKind::hand_built;
    std::int32_t index = 0;
};

inline constexpr int id_serial_bits = 40;
inline constexpr int id_index_bits = 16;
inline constexpr std::int64_t id_serial_limit = std::int64_t{1} << id_serial_bits;
inline constexpr std::int32_t id_index_limit = std::int32_t{1} << id_index_bits;

/// The id of the particle with `serial` from `source`. Throws std::overflow_error when the serial or the
/// source's index does not fit its bits (a source that made more than 2^40 particles).
inline ParticleId make_particle_id(IdSource source, std::int64_t serial) {
    if (serial < 0 || serial >= id_serial_limit)
        throw std::overflow_error("particle ids exhausted: serial " + std::to_string(serial) +
                                  " of one source is beyond 2^40");
    if (source.index < 0 || source.index >= id_index_limit)
        throw std::overflow_error("particle ids exhausted: more than 2^16 sources of one kind (source " +
                                  std::to_string(source.index) + ")");
    return (static_cast<ParticleId>(source.kind) << (id_index_bits + id_serial_bits)) |
           (static_cast<ParticleId>(source.index) << id_serial_bits) | serial;
}

/// The source and serial an id was made from (for messages and tests); the id must be non-negative.
inline IdSource id_source(ParticleId id) noexcept {
    return {static_cast<IdKind>(id >> (id_index_bits + id_serial_bits)),
            static_cast<std::int32_t>((id >> id_serial_bits) & (id_index_limit - 1))};
}
inline std::int64_t id_serial(ParticleId id) noexcept { return id & (id_serial_limit - 1); }

/// The name of a kind of source, as messages write it.
inline const char* id_kind_name(IdKind kind) noexcept {
    switch (kind) {
        case IdKind::hand_built: return "hand-built";
        case IdKind::fluid_block: return "fluid block";
        case IdKind::solid_block: return "solid block";
        case IdKind::wall_block: return "wall block";
        case IdKind::inlet: return "inlet";
        case IdKind::grain_block: return "grain block";
        case IdKind::grain_feed: return "grain feed";
        case IdKind::abrasive_feed: return "abrasive feed";
    }
    return "unknown source";
}

/// "solid block 1, serial 1234": where the particle with this id came from.
inline std::string describe_id(ParticleId id) {
    if (id < 0) return "mirror image of id " + std::to_string(-2 - id);
    const IdSource s = id_source(id);
    return std::string(id_kind_name(s.kind)) + " " + std::to_string(s.index) + ", serial " +
           std::to_string(id_serial(id));
}

}  // namespace grit::domain
