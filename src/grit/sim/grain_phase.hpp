// The grains of a run: the DEM system built from the case, their penalty contact with SPH solids and
// walls, the impact log, and the grain outputs (grains/*.vtu, impacts.csv). The Simulation calls it
// from its pipeline; the grains advance with the same time step as the SPH particles.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "grit/coupling/grain_boundary_contact.hpp"
#include "grit/dem/dem_system.hpp"
#include "grit/io/case_spec.hpp"
#include "grit/io/pvd_writer.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::sim {

/// A grain's first contact with a target (a plane wall, SPH solid or SPH wall particles): what wear
/// models need. Angle between the relative velocity and the target's surface [degrees] (90 = normal).
struct ImpactRecord {
    double time = 0.0;
    std::int32_t grain = 0;  ///< persistent grain id
    std::string target;
    double speed = 0.0;  ///< [m/s]
    double angle = 0.0;  ///< [deg]
};

template <int Dim>
class GrainPhase {
public:
    using Vec = core::Vec<Dim>;

    /// Builds the grains, plane walls and contact settings of `spec` (which must have grains). Throws
    /// core::InputError for grains outside the domain or an impossible arrangement.
    explicit GrainPhase(const io::CaseSpec& spec);

    /// Forces at the first state (grain-grain and grain-plane).
    void prime();
    /// Penalty contact with SPH solid and wall particles at the current state (eqs. 12-14): forces on
    /// both sides; logs first contacts. `fixed` marks clamped solid particles (may be null). `dt` is the
    /// step of eq. (13)'s stiffness 2 m_a / dt^2: the stable step, not one shortened to land on an
    /// output time (a short step would make the penalty force, and the impulse, blow up).
    void couple(double time, particles::SphParticles<Dim>& particles, const std::int32_t* fixed, double dt,
                const std::vector<material::Material>& materials);
    /// The grains' leap-frog step, the SPH particles' scheme: v^(n+1/2) = v^(n-1/2) + dt a^n (two half
    /// kicks, the first half only on the first step), x^(n+1) = x^n + dt v^(n+1/2), then grain-grain and
    /// plane forces at x^(n+1). Kicking grains and SPH particles with the same dt makes the exchanged
    /// impulses equal and opposite. Logs first contacts with the planes at time + dt.
    void advance(double time, double dt, bool first_step);
    /// Largest stable step of the grains (eq. 51 for the linear law; Rayleigh/Hertz time for Hertz).
    double stable_time_step() const;
    /// An empty string, or what went wrong with which grain (non-finite state, outside the domain).
    std::string check(const std::vector<double>& domain_min, const std::vector<double>& domain_max) const;

    /// Output: a snapshot in grains/ listed in NAME_grains.pvd, new impact records appended to impacts.csv.
    void open_output(const std::filesystem::path& dir, const std::string& name);
    void write_snapshot(const std::filesystem::path& dir, const std::string& name, double time);
    void flush_impacts();

    dem::DemSystem<Dim>& system() noexcept { return *system_; }
    const dem::DemSystem<Dim>& system() const noexcept { return *system_; }
    const coupling::GrainBoundaryContact<Dim>& contact() const noexcept { return contact_; }
    const std::vector<ImpactRecord>& impacts() const noexcept { return impacts_; }
    Index size() const noexcept { return system_->grains().size(); }
    double kinetic_energy() const { return system_->kinetic_energy(); }
    Vec momentum() const;

private:
    std::unique_ptr<dem::DemSystem<Dim>> system_;
    coupling::GrainBoundaryContact<Dim> contact_;
    std::vector<std::string> wall_names_;
    std::vector<ImpactRecord> impacts_;
    std::size_t impacts_written_ = 0;
    std::ofstream impacts_file_;
    std::unique_ptr<io::PvdWriter> pvd_;
    long snapshot_index_ = 0;
};

extern template class GrainPhase<2>;
extern template class GrainPhase<3>;

}  // namespace grit::sim
