// Wear accumulated per triangle of the mesh walls: removed mass, impacts and their mean angle and speed.
#pragma once

#include <cstdint>
#include <vector>

#include "grit/io/hdf5_file.hpp"

namespace grit::wear {

class WearMap {
  public:
    explicit WearMap(std::size_t triangles = 0)
        : mass_(triangles, 0.0), impacts_(triangles, 0), angle_sum_(triangles, 0.0), speed_sum_(triangles, 0.0) {}

    std::size_t size() const noexcept { return mass_.size(); }
    /// An impact on triangle t: its angle [deg] and speed [m/s] join the means.
    void add_impact(std::size_t t, double angle, double speed) {
        ++impacts_[t];
        angle_sum_[t] += angle;
        speed_sum_[t] += speed;
    }
    /// Mass removed from triangle t [kg].
    void add_mass(std::size_t t, double mass) { mass_[t] += mass; }

    double mass(std::size_t t) const noexcept { return mass_[t]; }
    std::int64_t impacts(std::size_t t) const noexcept { return impacts_[t]; }
    /// Mean impact angle [deg] and speed [m/s] on triangle t; 0 before its first impact.
    double mean_angle(std::size_t t) const noexcept {
        return impacts_[t] ? angle_sum_[t] / static_cast<double>(impacts_[t]) : 0.0;
    }
    double mean_speed(std::size_t t) const noexcept {
        return impacts_[t] ? speed_sum_[t] / static_cast<double>(impacts_[t]) : 0.0;
    }
    /// Adds what `other` booked on its triangle `from` to this map's triangle `to`.
    void add_from(const WearMap& other, std::size_t from, std::size_t to) {
        mass_[to] += other.mass_[from];
        impacts_[to] += other.impacts_[from];
        angle_sum_[to] += other.angle_sum_[from];
        speed_sum_[to] += other.speed_sum_[from];
    }
    /// Removed mass over triangles [first, last).
    double total_mass(std::size_t first, std::size_t last) const {
        double m = 0.0;
        for (std::size_t t = first; t < last; ++t)
            m += mass_[t];
        return m;
    }

    void save(io::Hdf5Group& group) const {
        group.write("mass", mass_.data(), mass_.size(), 1);
        group.write("impacts", impacts_.data(), impacts_.size(), 1);
        group.write("angle_sum", angle_sum_.data(), angle_sum_.size(), 1);
        group.write("speed_sum", speed_sum_.data(), speed_sum_.size(), 1);
    }
    void load(const io::Hdf5Group& group) {
        std::size_t n = 0;
        mass_ = group.read_doubles("mass", 1, n);
        impacts_ = group.read_int64("impacts", 1, n);
        angle_sum_ = group.read_doubles("angle_sum", 1, n);
        speed_sum_ = group.read_doubles("speed_sum", 1, n);
    }

  private:
    std::vector<double> mass_;
    std::vector<std::int64_t> impacts_;
    std::vector<double> angle_sum_, speed_sum_;
};

}  // namespace grit::wear
