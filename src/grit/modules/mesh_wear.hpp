// Mesh walls and their wear (3D): the [[mesh]] STL walls of the case joined to the grains' DEM system
// (contact on faces, edges and corners, prescribed motion), each grain's first contact with a mesh in
// the impact log, the wear models of the second seed paper (eqs. 22-26), Oka's and LIGGGHTS' booked per
// triangle, and the wear maps (walls/*.vtu, <case>_walls.pvd; series wear_mass_total, wear_mass_<name>).
#pragma once

#include <memory>
#include <vector>

#include "grit/io/pvd_writer.hpp"
#include "grit/sim/module.hpp"
#include "grit/wear/wear_map.hpp"

namespace grit::modules {

template <int Dim>
class MeshWearModule final : public sim::Module<Dim> {
  public:
    /// Adds the case's meshes to state.grains (built by the grains module before).
    MeshWearModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);

    std::string name() const override { return "mesh_walls"; }
    void install(sim::Pipeline& pipeline) override;
    void output_values(std::vector<sim::OutputValue>& out) const override;
    void open_output(const sim::OutputPlace& place, bool restart) override;
    void write_output(const sim::OutputPlace& place) override;
    void save(io::Hdf5Group& group) const override;
    void load(const io::Hdf5Group& group) override;

    const wear::WearMap& wear_map() const noexcept { return map_; }

  private:
    /// After the grains' step: impacts (fresh contacts) into the log and, by the mesh's model, the wear
    /// they cause; LIGGGHTS' form for every approaching contact of the step.
    void book();

    sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    wear::WearMap map_;
    std::vector<std::size_t> first_triangle_;  ///< per mesh, its first triangle over all meshes
    std::unique_ptr<io::PvdWriter> pvd_;
    std::vector<io::PvdWriter::Entry> restored_pvd_;
    long snapshot_index_ = 0;
};

extern template class MeshWearModule<2>;
extern template class MeshWearModule<3>;

}  // namespace grit::modules
