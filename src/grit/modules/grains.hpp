// The grains module: the DEM grains of a case (first seed paper section 2.1) built into the State,
// their leap-frog step with the SPH particles' dt, first contacts with the plane walls in the impact
// log, the DEM time step, and the grain outputs (grains/*.vtu, impacts.csv).
#pragma once

#include <memory>

#include "grit/io/pvd_writer.hpp"
#include "grit/sim/module.hpp"

namespace grit::modules {

/// Bits of the per-grain `contact_targets` field, the targets a grain is in contact with (set at first
/// contact, cleared when it has left): plane walls 0..27, SPH walls 28, SPH solids 29.
inline constexpr int max_grain_planes = 28;
inline constexpr std::int32_t sph_wall_bit = 1 << 28, sph_solid_bit = 1 << 29;

/// Angle between a relative velocity v and the surface whose normal is n (any length) [deg]: 90 for a
/// normal impact.
template <int Dim>
double impact_angle(const core::Vec<Dim>& v, const core::Vec<Dim>& n);

template <int Dim>
class GrainsModule final : public sim::Module<Dim> {
public:
    /// Builds the grains, plane walls and contact settings of the case into state.grains. Throws
    /// core::InputError for grains outside the domain or an impossible arrangement.
    GrainsModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);

    std::string name() const override { return "grains"; }
    void install(sim::Pipeline& pipeline) override;
    /// Forces at the first state (grain-grain and grain-plane).
    void prime() override;
    /// Eq. (51) for the linear law; Rayleigh/Hertz time for Hertz.
    double stable_time_step() const override;
    std::string check_health() const override;
    void output_values(std::vector<sim::OutputValue>& out) const override;
    void open_output(const sim::OutputPlace& place, bool restart) override;
    void write_output(const sim::OutputPlace& place) override;
    void save(io::Hdf5Group& group) const override;
    void load(const io::Hdf5Group& group) override;

private:
    /// The grains' leap-frog step, the SPH particles' scheme: v^(n+1/2) = v^(n-1/2) + dt a^n (two half
    /// kicks, the first half only on the first step), x^(n+1) = x^n + dt v^(n+1/2), then grain-grain and
    /// plane forces at x^(n+1), in three stages at three hooks (motion, neighbours, force) so that other
    /// stages can come between them. Kicking grains and SPH particles with the same dt makes the
    /// exchanged impulses equal and opposite.
    void move();
    void contact_forces();
    /// Logs first contacts with the planes at time + dt.
    void log_plane_contacts();

    /// Removes the grains inside an outlet or (domain.on_exit = "remove") outside the domain.
    void remove_leaving();

    sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    std::vector<std::string> wall_names_;
    std::unique_ptr<io::PvdWriter> pvd_;
    std::vector<io::PvdWriter::Entry> restored_pvd_;  ///< a checkpoint's entries, until open_output
    long snapshot_index_ = 0;
    std::int64_t grains_out_ = 0;   ///< grains removed through outlets and the domain's faces
    double grain_mass_out_ = 0.0;   ///< their mass [kg] (per metre in 2D)
    std::int64_t grain_collisions_out_ = 0;  ///< the collisions those grains had begun (grain_set.hpp)
};

extern template class GrainsModule<2>;
extern template class GrainsModule<3>;

}  // namespace grit::modules
