// The impact log: each first contact of a grain with a target (a plane wall, an SPH solid, SPH wall
// particles, a mesh wall), with what wear models need: the relative speed and the impact angle, and where
// the grain was. Written to impacts.csv as it grows.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "grit/domain/comm.hpp"
#include "grit/domain/particle_id.hpp"
#include "grit/io/hdf5_file.hpp"

namespace grit::wear {

/// A grain's first contact with a target. Angle between the relative velocity and the target's surface
/// [degrees] (90 = normal).
struct ImpactRecord {
    double time = 0.0;
    domain::ParticleId grain = 0;  ///< persistent grain id (by origin, domain/particle_id.hpp)
    std::string target;
    double speed = 0.0;  ///< [m/s]
    double angle = 0.0;  ///< [deg]
    std::array<double, 3> position{};  ///< the grain's centre at the contact [m] (x, y in 2D)
    std::int32_t grain_collisions = 0;  ///< times the grain had begun to touch another grain before
};

class ImpactLog {
public:
    void add(ImpactRecord r) {
        // The earliest, and of impacts in one step the lowest grain id: which one is first then does not
        // depend on the order the contacts were found in, nor on how the grains are split over sub-domains.
        if (r.time < first_time_ || (r.time == first_time_ && r.grain < first_grain_)) {
            first_time_ = r.time;
            first_grain_ = r.grain;
            first_speed_ = r.speed;
        }
        records_.push_back(std::move(r));
    }
    /// Speed of the run's first impact [m/s] (the contact velocity of a single grain); NaN before it. Over
    /// sub-domains, that of the earliest impact of any (a local pass, the earliest impact each holds, and
    /// three reductions).
    double first_speed(const domain::Comm& comm) const;
    /// The records of this run since it started or was restarted (earlier ones are in impacts.csv).
    const std::vector<ImpactRecord>& records() const noexcept { return records_; }
    /// Every impact of the run, restarts included.
    std::size_t total() const noexcept { return earlier_ + records_.size(); }

    /// Creates impacts.csv with its header (the position as x, y in 2D; x, y, z in 3D; then
    /// grain_collisions), or, on a restart
    /// (`rows` >= 0), keeps its header and first `rows` records (those written before the checkpoint)
    /// and appends after them.
    void open(const std::filesystem::path& file, int dimension, long rows = -1);
    /// Appends the records not yet written.
    void flush();

    /// For a checkpoint: the number of impacts so far (flush() first, so that the file holds them all).
    void save(io::Hdf5Group& group) const;
    void load(const io::Hdf5Group& group);

private:
    std::vector<ImpactRecord> records_;
    std::size_t written_ = 0;  ///< records_ already in the file
    std::size_t earlier_ = 0;  ///< impacts before the restart this run continues
    double first_time_ = std::numeric_limits<double>::infinity();
    domain::ParticleId first_grain_ = std::numeric_limits<domain::ParticleId>::max();
    double first_speed_ = std::numeric_limits<double>::quiet_NaN();
    int dimension_ = 2;
    std::ofstream file_;
};

}  // namespace grit::wear
