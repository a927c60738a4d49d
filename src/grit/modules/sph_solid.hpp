// The solid SPH module (first seed paper section 2.2): the solid fields, the solids' equations of state
// with the JH-2 bulking and tension limit, the solid sums, the material update (Jaumann rate, J-C or
// JH-2 return, damage) and erosion (removal of failed or detached particles, booked as eroded mass).
#pragma once

#include <vector>

#include "grit/modules/sph_fluid.hpp"
#include "grit/sph/nonlocal_damage.hpp"
#include "grit/sph/solid_rates.hpp"

namespace grit::modules {

template <int Dim>
class SolidModule final : public sim::Module<Dim> {
public:
    /// Registers the solid fields on state.particles (before any particle is built).
    SolidModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup, const SphModule<Dim>& sph);

    std::string name() const override { return "solid"; }
    /// Solids start at their room temperature.
    void initialise() override;
    void install(sim::Pipeline& pipeline) override;
    void output_values(std::vector<sim::OutputValue>& out) const override;
    /// eroded.csv: every removed solid particle (state.erosion; analysis/erosion_log.hpp).
    void open_output(const sim::OutputPlace& place, bool restart) override;
    void write_output(const sim::OutputPlace& place) override;
    void flush_logs() override;
    void save(io::Hdf5Group& group) const override;
    void load(const io::Hdf5Group& group) override;

private:
    void update_pressure();
    void update_stress();
    void remove_failed();

    sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    const SphModule<Dim>& sph_;
    sph::SolidRateParameters<Dim> parameters_;
    sph::SolidWorkspace<Dim> workspace_;
    std::uint64_t workspace_generation_ = 0;
    std::vector<bool> brittle_;  ///< per material: a JH-2 solid (fractured particles stay until detached)
    std::vector<double> rubble_density_;  ///< per JH-2 material: below it a fractured particle has come apart
    /// Per particle, this step: the von Mises stress before a ductile particle failed (its failure zeroes it).
    std::vector<double> failure_von_mises_;
    sph::NonlocalDamage<Dim> nonlocal_damage_;
    /// Per particle, this step: the local damage increments of eq. (36), and their non-local averages.
    std::vector<double> damage_increment_, averaged_increment_;
};

extern template class SolidModule<2>;
extern template class SolidModule<3>;

}  // namespace grit::modules
