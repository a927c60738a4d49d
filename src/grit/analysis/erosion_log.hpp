// The erosion log: each solid particle the erosion stage removes, with the state it failed in, so that
// where, when and why a specimen loses mass can be read after the run (eroded.csv). The eroded mass of
// series.csv is the sum of its `mass` column.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "grit/domain/particle_id.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::analysis {

/// One removed solid particle. `cause`: "failed" (a ductile particle at D >= 1, eq. 36), "fragment" (fractured
/// rock with no intact rock attached), "rubble" (fractured rock dilated past the rubble density) or "outlet"
/// (solid torn off before it failed, carried into an outlet or out of the domain).
struct ErosionRecord {
    double time = 0.0;  ///< end of the step that removed it [s]
    domain::ParticleId id = -1;
    std::int32_t material = 0;
    const char* cause = "";
    std::array<double, 3> position{};  ///< [m]
    double mass = 0.0;                 ///< [kg] (per metre of thickness in 2D)
    double plastic_strain = 0.0;
    double damage = 0.0;
    double pressure = 0.0;     ///< [Pa], positive in compression
    double von_mises = 0.0;    ///< [Pa]: of the step before a ductile failure (failure zeroes the stress)
    double triaxiality = 0.0;  ///< -p / sigma_vm of eq. (35), from the two above; NaN without shear
    double temperature = 0.0;  ///< [K]
    double density = 0.0;      ///< [kg/m^3]
    double density_ratio = 0.0;  ///< rho / rho0: below 1 the particle has dilated (tension, voids)
    double speed = 0.0;        ///< [m/s]
    /// 1 where the particle was on the solid's surface in its last step (sph::at_solid_surface: eq. 35
    /// then took at most `failure_surface_triaxiality`), 0 inside, -1 unknown.
    int surface = -1;
};

/// The record of solid particle i as it is now: where, its mass, state and speed (`cause`, the stress
/// before a failure and `surface` are the caller's). The solid fields must be registered.
template <int Dim>
ErosionRecord erosion_record(const particles::SphParticles<Dim>& ps, Index i, double time, double reference_density);

class ErosionLog {
public:
    void add(const ErosionRecord& r) {
        if (total() == 0) first_time_ = r.time;
        records_.push_back(r);
    }
    /// Every removal of the run, restarts included.
    std::size_t total() const noexcept { return earlier_ + records_.size(); }
    /// When the run first lost solid mass, restarts included (the end of the paper's Stage One, Fig. 13);
    /// NaN while nothing has gone (and after a restart from a checkpoint that predates this record).
    double first_time() const noexcept { return first_time_; }

    /// Creates eroded.csv with its header (coordinates x, y in 2D; x, y, z in 3D), or, on a restart
    /// (`rows` >= 0), keeps the header and the first `rows` records and appends after them.
    void open(const std::filesystem::path& file, int dimension, std::vector<std::string> material_names,
              long rows = -1);
    /// Appends the records not yet written.
    void flush();
    /// After a checkpoint load: the removals before it (all in the file) and the first one's time.
    void restore(std::size_t earlier, double first_time) {
        records_.clear();
        written_ = 0;
        earlier_ = earlier;
        first_time_ = first_time;
    }

private:
    std::vector<ErosionRecord> records_;
    std::size_t written_ = 0;
    std::size_t earlier_ = 0;
    double first_time_ = std::numeric_limits<double>::quiet_NaN();
    int dimension_ = 2;
    std::vector<std::string> material_names_;
    std::ofstream file_;
};

}  // namespace grit::analysis
