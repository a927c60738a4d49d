// Kernel-gradient correction (second seed paper eq. 8; Bonet & Lok 1999): the
// corrected gradient L_a grad W_ab with L_a = (sum_b V_b grad W_ab (x) (x_b -
// x_a))^-1 makes the difference-form gradient sum_b V_b (phi_b - phi_a) L_a
// grad_a W_ab exact for every linear field phi, whatever the disorder of the
// particles or the truncation of the kernel at a free surface or a wall.
#pragma once

#include <vector>

#include "grit/core/vec.hpp"
#include "grit/neighbors/neighbor_list.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::sph {

/// L_a, a symmetric Dim x Dim matrix (grad W_ab is along x_ab, so the sum is
/// -sum_b V_b f_ab x_ab x_ab^T).
template <int Dim>
struct GradientCorrection {
    double m[Dim][Dim];

    static GradientCorrection identity() noexcept {
        GradientCorrection c{};
        for (int i = 0; i < Dim; ++i)
            c.m[i][i] = 1.0;
        return c;
    }
    /// det L_a = 1 / det M_a: 1 for a full kernel, large where the neighbours fill little of it.
    double determinant() const noexcept {
        if constexpr (Dim == 2) {
            return m[0][0] * m[1][1] - m[0][1] * m[1][0];
        } else {
            return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                   m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                   m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        }
    }
    core::Vec<Dim> apply(const core::Vec<Dim>& g) const noexcept {
        core::Vec<Dim> out = core::Vec<Dim>::zero();
        for (int i = 0; i < Dim; ++i)
            for (int j = 0; j < Dim; ++j)
                out[i] += m[i][j] * g[j];
        return out;
    }
};

/// Below this determinant of the moment matrix (1 for a full kernel on a
/// regular lattice, a few 1e-3 at the corner of a 3D block) a particle's
/// neighbours do not span the space (a lone splash particle, a line of
/// particles): L_a is the identity.
inline constexpr double min_correction_determinant = 1e-3;

/// L_a of every particle of phase `phase` (the identity for the others), from
/// its neighbours of the phases in `neighbour_phases` (a bit mask over Phase
/// values).
template <int Dim>
void compute_gradient_correction(const particles::SphParticles<Dim>& particles,
                                 const neighbors::NeighborList<Dim>& neighbors, const Kernel<Dim>& kernel,
                                 const neighbors::PeriodicBox<Dim>& box, Phase phase, unsigned neighbour_phases,
                                 std::vector<GradientCorrection<Dim>>& out);

/// The mask of one phase, for `neighbour_phases`.
constexpr unsigned phase_bit(Phase p) noexcept {
    return 1u << static_cast<unsigned>(p);
}

extern template void compute_gradient_correction<2>(const particles::SphParticles<2>&,
                                                    const neighbors::NeighborList<2>&, const Kernel<2>&,
                                                    const neighbors::PeriodicBox<2>&, Phase, unsigned,
                                                    std::vector<GradientCorrection<2>>&);
extern template void compute_gradient_correction<3>(const particles::SphParticles<3>&,
                                                    const neighbors::NeighborList<3>&, const Kernel<3>&,
                                                    const neighbors::PeriodicBox<3>&, Phase, unsigned,
                                                    std::vector<GradientCorrection<3>>&);

}  // namespace grit::sph
