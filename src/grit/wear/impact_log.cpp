// Impact log: records, impacts.csv, checkpoint count.
#include "grit/wear/impact_log.hpp"

#include <fmt/format.h>

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

void ImpactLog::save(io::Hdf5Group& group) const {
    group.write("impacts", static_cast<std::int64_t>(total()));
    group.write("first_speed", first_speed_);
}

void ImpactLog::load(const io::Hdf5Group& group) {
    records_.clear();
    written_ = 0;
    earlier_ = static_cast<std::size_t>(group.read_int("impacts"));
    first_speed_ = group.read_double("first_speed");
}

}  // namespace grit::wear
