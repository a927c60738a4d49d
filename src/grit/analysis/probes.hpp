// Probes: values sampled at output times and written as columns of series.csv.
#pragma once

#include <string>
#include <vector>

#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::analysis {

/// A probe written as a column of series.csv ([[probe]], read by modules/probes_table.cpp).
struct ProbeSpec {
    std::string key;
    std::string name;      ///< column name
    std::string kind;      ///< "point": Shepard interpolation; "front": furthest particle along an axis
    int phase = 0;         ///< the phase sampled: 0 fluid (default), 1 solid
    std::string quantity;  ///< point: "pressure", "density", "velocity"
    std::vector<double> position;  ///< point [m]
    int axis = 0;                  ///< front: 0 = x, 1 = y, 2 = z
    bool has_region = false;       ///< front: only particles inside [min, max]
    std::vector<double> min, max;
};


/// "point": Shepard-normalised SPH interpolation of the quantity from the fluid particles,
///   q(x) = sum_b q_b W(x - x_b) m_b/rho_b / sum_b W(x - x_b) m_b/rho_b (0 where no fluid is in reach);
/// "front": the furthest extent of fluid along an axis, the leading particle's centre plus half a
///   spacing (its edge), optionally only among particles inside a region; NaN when there are none.
/// Along the periodic axes of `box`, a point probe sees the particles across a face (nearest image).
template <int Dim>
double evaluate_probe(const ProbeSpec& probe, const particles::SphParticles<Dim>& particles,
                      const sph::Kernel<Dim>& kernel, double spacing, const neighbors::PeriodicBox<Dim>& box = {});

/// A probe's local pass over the particles one sub-domain holds: a point probe's two sums (`value`:
/// sum q W m/rho, `weight`: sum W m/rho), which sub-domains combine by adding; a front's furthest centre
/// (`value`, NaN when it has none; `weight` unused), which they combine by their maximum.
struct ProbeSample {
    double value = 0.0;
    double weight = 0.0;
};
template <int Dim>
ProbeSample sample_probe(const ProbeSpec& probe, const particles::SphParticles<Dim>& particles,
                         const sph::Kernel<Dim>& kernel, const neighbors::PeriodicBox<Dim>& box = {});
/// The probe's value from its combined sample (evaluate_probe is sample_probe, then this).
double probe_value(const ProbeSpec& probe, const ProbeSample& sample, double spacing);

extern template double evaluate_probe<2>(const ProbeSpec&, const particles::SphParticles<2>&,
                                         const sph::Kernel<2>&, double, const neighbors::PeriodicBox<2>&);
extern template double evaluate_probe<3>(const ProbeSpec&, const particles::SphParticles<3>&,
                                         const sph::Kernel<3>&, double, const neighbors::PeriodicBox<3>&);
extern template ProbeSample sample_probe<2>(const ProbeSpec&, const particles::SphParticles<2>&, const sph::Kernel<2>&,
                                            const neighbors::PeriodicBox<2>&);
extern template ProbeSample sample_probe<3>(const ProbeSpec&, const particles::SphParticles<3>&, const sph::Kernel<3>&,
                                            const neighbors::PeriodicBox<3>&);

}  // namespace grit::analysis
