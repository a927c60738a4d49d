// The abrasive feed of a jet (first seed paper Fig. 9): the jet is cut into liquid columns of length
// y_dis, one entering the nozzle every y_dis / v_jet; each carries one grain at a random place, which
// enters through the nozzle section at the jet's velocity. The draws of column k come from a generator
// seeded with (seed, k), so a restart only needs the next column's index. A grain joins the run
// `lead` upstream of the section, already moving at the jet's velocity, and crosses the section at
// its entry time.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "grit/core/vec.hpp"
#include "grit/io/case_spec.hpp"

namespace grit::boundary {

template <int Dim>
class AbrasiveInlet {
public:
    using Vec = core::Vec<Dim>;

    /// One grain due to enter: where it is at the end of the step, its diameter and velocity.
    struct Grain {
        std::int64_t column;  ///< its liquid column's index: the grain's serial (its id by origin)
        Vec position;
        double diameter;
        Vec velocity;
    };

    /// `jet` is the inlet the grains ride (its section, direction, velocity and motion).
    AbrasiveInlet(const io::AbrasiveSpec& spec, const io::InletSpec& jet);

    /// The grains that join during (t, t + dt]: those whose entry time comes within spec.lead / v_jet
    /// of t + dt, placed where they are at t + dt (upstream of the section until they cross it).
    std::vector<Grain> emit(double t, double dt);

    /// Index of the next column to enter: the feed's whole state, for checkpoints.
    std::int64_t next_column() const noexcept { return next_column_; }
    void set_next_column(std::int64_t k) noexcept { next_column_ = k; }

private:
    /// Column k's grain: its entry time, diameter and offset across the jet.
    struct Draw {
        double entry_time;
        double diameter;
        Vec offset;
    };
    Draw draw(std::int64_t column) const;

    io::AbrasiveSpec spec_;
    double jet_velocity_, jet_radius_;
    Vec nozzle_, direction_, motion_;
    std::array<Vec, Dim - 1> across_;  ///< orthonormal directions spanning the nozzle section
    double column_;        ///< the liquid column of one grain: y_dis (2 y_dis on a symmetry plane's half jet) [m]
    double period_;        ///< column_ / v_jet [s]
    std::int64_t next_column_ = 0;
};

extern template class AbrasiveInlet<2>;
extern template class AbrasiveInlet<3>;

}  // namespace grit::boundary
