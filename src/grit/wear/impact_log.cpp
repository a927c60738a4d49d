// Impact log: records, impacts.csv, checkpoint count.
#include "grit/wear/impact_log.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "grit/io/csv_file.hpp"

namespace grit::wear {

void ImpactLog::open(const std::filesystem::path& file, int dimension, long rows) {
    dimension_ = dimension;
    io::open_csv_log(file_, file, dimension == 3 ? "time,grain,target,speed,angle,x,y,z,grain_collisions"
                                                   : "time,grain,target,speed,angle,x,y,grain_collisions",
                     rows);
    written_ = records_.size();
}

void ImpactLog::flush() {
    if (!file_.is_open()) return;
    for (; written_ < records_.size(); ++written_) {
        const auto& r = records_[written_];
        file_ << fmt::format("{:.9g},{},{},{:.9g},{:.6g},{:.9g},{:.9g}", r.time, r.grain, r.target, r.speed, r.angle,
                             r.position[0], r.position[1]);
        if (dimension_ == 3) file_ << fmt::format(",{:.9g}", r.position[2]);
        file_ << fmt::format(",{}\n", r.grain_collisions);
    }
    file_.flush();
}

double ImpactLog::first_speed(const domain::Comm& comm) const {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double time = comm.min(first_time_ == std::numeric_limits<double>::infinity() ? nan : first_time_);
    if (std::isnan(time)) return nan;  // no impact anywhere yet
    const auto none = std::numeric_limits<domain::ParticleId>::max();
    const domain::ParticleId grain = comm.min_id(first_time_ == time ? first_grain_ : none);
    return comm.max(first_time_ == time && first_grain_ == grain ? first_speed_ : nan);
}

void ImpactLog::save(io::Hdf5Group& group) const {
    group.write("impacts", static_cast<std::int64_t>(total()));
    group.write("first_speed", first_speed_);
    group.write("first_time", first_time_);
    group.write("first_grain", static_cast<std::int64_t>(first_grain_));
}

void ImpactLog::load(const io::Hdf5Group& group) {
    records_.clear();
    written_ = 0;
    earlier_ = static_cast<std::size_t>(group.read_int("impacts"));
    first_speed_ = group.read_double("first_speed");
    // A checkpoint written before the first impact's time and grain were kept holds only its speed: an
    // impact before the checkpoint comes before every later one.
    const bool before = !std::isnan(first_speed_);
    first_time_ = group.has_attribute("first_time") ? group.read_double("first_time")
                  : before                         ? -std::numeric_limits<double>::infinity()
                                                   : std::numeric_limits<double>::infinity();
    first_grain_ = group.has_attribute("first_grain") ? static_cast<domain::ParticleId>(group.read_int("first_grain"))
                                                      : std::numeric_limits<domain::ParticleId>::max();
}

}  // namespace grit::wear
