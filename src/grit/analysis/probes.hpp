// Probes: values sampled at output times and written as columns of series.csv.
#pragma once

#include "grit/io/case_spec.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::analysis {

/// "point": Shepard-normalised SPH interpolation of the quantity from the fluid particles,
///   q(x) = sum_b q_b W(x - x_b) m_b/rho_b / sum_b W(x - x_b) m_b/rho_b (0 where no fluid is in reach);
/// "front": the furthest extent of fluid along an axis, the leading particle's centre plus half a
///   spacing (its edge), optionally only among particles inside a region; NaN when there are none.
/// Along the periodic axes of `box`, a point probe sees the particles across a face (nearest image).
template <int Dim>
double evaluate_probe(const io::ProbeSpec& probe, const particles::SphParticles<Dim>& particles,
                      const sph::Kernel<Dim>& kernel, double spacing, const neighbors::PeriodicBox<Dim>& box = {});

extern template double evaluate_probe<2>(const io::ProbeSpec&, const particles::SphParticles<2>&,
                                         const sph::Kernel<2>&, double, const neighbors::PeriodicBox<2>&);
extern template double evaluate_probe<3>(const io::ProbeSpec&, const particles::SphParticles<3>&,
                                         const sph::Kernel<3>&, double, const neighbors::PeriodicBox<3>&);

}  // namespace grit::analysis
