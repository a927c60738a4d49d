// The pressure projection of incompressible SPH (second seed paper eq. 6; Cummins & Rudman 1999):
//   div(grad p / rho) = div v* / dt + gamma (rho0 - rho_s) / (rho_s tau^2)
// the second term the density invariance of Asai et al. (2012) on the summation density rho_s, with
// the SPH Laplacian  sum_b m_b 8/(rho_a+rho_b)^2 (p_a - p_b) x_ab . grad W_ab / (r^2 + eta^2)  and the
// divergence  -(1/rho_a) sum_b m_b v*_ab . grad W_ab  over fluid and wall neighbours, p = 0 half a
// spacing outside the free-surface particles, and the wall particles' pressure from their fluid
// neighbours (Adami et al. 2012) as unknowns of the same system. Each row is divided by its
// diagonal; the system is solved by Eigen's BiCGSTAB with a diagonal preconditioner.
#pragma once

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "grit/core/vec.hpp"
#include "grit/domain/halo.hpp"
#include "grit/neighbors/neighbor_list.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sph/kernel_correction.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::sph {

template <int Dim>
struct ProjectionSettings {
    core::Vec<Dim> gravity = core::Vec<Dim>::zero();  ///< [m/s^2]
    double tolerance = 1e-8;                          ///< relative residual |b - A p| / |b|
    int max_iterations = 1000;
    double free_surface_divergence = 1.5;  ///< div r below this: a free-surface particle
    /// How far outside a free-surface particle, along its normal, the pressure vanishes: half the
    /// particle spacing, the edge of the particle's volume [m]; 0: p = 0 on the particle itself.
    double surface_offset = 0.0;
    /// det L_a above which a free-surface particle's gradient is not corrected (its neighbours fill
    /// less than a quarter of the kernel's moments: the tip of a surge); there p = 0 on the particle.
    double max_surface_correction = 4.0;
    double density_relaxation = 0.0;       ///< gamma of the density-invariance source
    neighbors::PeriodicBox<Dim> periodic_box;
    std::vector<double> reference_density;  ///< rho0 per material [kg/m^3]
};

struct ProjectionResult {
    int iterations = 0;
    double residual = 0.0;  ///< relative residual reached
    bool converged = true;
    Index surface_particles = 0;
    /// BiCGSTAB broke down (a non-finite iterate) and the solve was restarted from p = 0 (once).
    bool restarted = false;
    /// The first row of the system with a non-finite entry (its particle), or -1.
    Index bad_row = -1;
};

/// div r_a = -sum_b V_b x_ab . grad W_ab over fluid and wall neighbours (D inside a full kernel)
/// and the summation density sum_b m_b W_ab (the particle itself included); fluid particles only.
template <int Dim>
void position_divergence(const particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                         const Kernel<Dim>& kernel, const neighbors::PeriodicBox<Dim>& box,
                         std::vector<double>& divergence, std::vector<double>& summation_density);

/// div v_a = -(1/rho_a) sum_b m_b (v_a - v_b) . grad W_ab of every fluid
/// particle over its fluid and wall neighbours (L_a grad W_ab with
/// `correction`); 0 for the others.
template <int Dim>
void velocity_divergence(const particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                         const Kernel<Dim>& kernel, const neighbors::PeriodicBox<Dim>& box,
                         const core::Vec<Dim>* velocity, const GradientCorrection<Dim>* correction,
                         std::vector<double>& out);

/// -grad p_a / rho_a of every fluid particle in the difference form -(1/rho_a) sum_b V_b (p_b - p_a)
/// L_a grad W_ab over fluid and wall neighbours (L_a = I without `correction`), exact for a linear
/// pressure with it. Not the symmetric form of WCSPH, -sum_b m_b (p_a/rho_a^2 + p_b/rho_b^2) grad
/// W_ab: below a free surface its truncated kernel pushes a particle outwards by ~p_a / (rho h),
/// which no equation of state pulls back here (the dam break's column top ran away at 0.06 s).
/// Zero for the others.
template <int Dim>
void pressure_acceleration(const particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                           const Kernel<Dim>& kernel, const neighbors::PeriodicBox<Dim>& box,
                           const GradientCorrection<Dim>* correction, std::vector<core::Vec<Dim>>& out);

/// Assembles and solves the pressure system; reuses its storage from step to
/// step.
template <int Dim>
class PressureProjection {
  public:
    /// Solves for the pressure of the fluid and wall particles from the predicted
    /// velocities `v_star` (walls: their own velocity plus g dt) and writes it to the
    /// particles' pressure; the previous pressure is the initial guess.
    /// `free_surface` gets 1 for the surface particles. The divergence the particles carry in from
    /// the last step (div v^n: the projection's residual, the motion since, the shifting) is removed
    /// over `relaxation_time` (>= dt: the step the fluid's own limits allow, not a shorter DEM step
    /// or a step cut for an output time), the divergence of the
    /// step's own forces over dt: a step cut short to land on an output time then does not turn
    /// that divergence into a pressure ~ 1/dt (-6 kPa in the tank at rest at a 1e-6 s step).
    /// `porosity` (grains coupled to the fluid, else nullptr): the particles' density is then the
    /// locally averaged one, rho_bar = eps rho0 (eq. 21); the density invariance aims the summation
    /// density at eps_a rho0 and the wall rows take the fluid's own density rho_bar / eps.
    /// `ghosts` (a symmetry plane's mirror images, else nullptr): a ghost's pressure is its owner's, so
    /// a row that reads a ghost reads the owner's unknown, the ghosts' own rows keep their pressure, and
    /// the solved pressure is forwarded to them (v_star must hold the ghosts' forwarded values).
    ProjectionResult solve(particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                           const Kernel<Dim>& kernel, const ProjectionSettings<Dim>& settings,
                           const core::Vec<Dim>* v_star, const GradientCorrection<Dim>* correction, double dt,
                           double relaxation_time, std::int32_t* free_surface, const double* porosity = nullptr,
                           const domain::Halo<Dim>* ghosts = nullptr);

    /// The system of the last solve (tests).
    const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& matrix() const { return matrix_; }

  private:
    Eigen::SparseMatrix<double, Eigen::RowMajor, int> matrix_;
    Eigen::VectorXd rhs_, guess_, solution_;
    std::vector<Index> row_count_, row_start_;
    std::vector<Index> owner_;  ///< per particle: itself, or a ghost's owner (the unknown it stands for)
    std::vector<int> padded_columns_;
    std::vector<double> padded_values_;
    std::vector<double> divergence_r_, divergence_v_, divergence_v0_, summation_density_;
};

extern template class PressureProjection<2>;
extern template class PressureProjection<3>;

}  // namespace grit::sph
