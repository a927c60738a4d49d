// Mesh walls and their wear (3D): the [[mesh]] STL walls of the case joined to the grains' DEM system
// (contact on faces, edges and corners, prescribed motion), each grain's first contact with a mesh in
// the impact log, the wear models of the second seed paper (eqs. 22-26), Oka's and LIGGGHTS' booked per
// triangle, and the wear maps (walls/*.vtu, <case>_walls.pvd; series wear_mass_total, wear_mass_<name>).
// On a symmetry plane (x = 0) the grains are the x >= 0 half's, and each has a mirror twin at x < 0 that
// wears the mirror image of every triangle it wears: the meshes must be symmetric about the plane (each
// triangle reaching x < 0 has its mirror image in the meshes) or lie at x >= 0, and a triangle's wear is
// what the grains did to it and to its mirror image. A grain straddling the plane (one of the whole
// jet, riding on its axis) has no twin: its wear is booked once.
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

    /// The wear of the whole set-up: on a symmetry plane, each triangle's with its mirror image's.
    wear::WearMap wear_map() const;

  private:
    /// After the grains' step: impacts (fresh contacts) into the log and, by the mesh's model, the wear
    /// they cause; LIGGGHTS' form for every approaching contact of the step.
    void book();

    sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    /// Pairs the triangles with their mirror images across x = 0, and refuses meshes that are not
    /// symmetric about it or move otherwise than symmetrically.
    void pair_mirror_images();

    wear::WearMap map_;
    /// On a symmetry plane: what the grains that straddle it booked (no twin), and each triangle's mirror
    /// image among all meshes' triangles (-1: none, a triangle at x >= 0 of a mesh laid as a half).
    wear::WearMap lone_;
    std::vector<std::int64_t> mirror_;
    std::vector<std::size_t> first_triangle_;  ///< per mesh, its first triangle over all meshes
    std::unique_ptr<io::PvdWriter> pvd_;
    std::vector<io::PvdWriter::Entry> restored_pvd_;
    long snapshot_index_ = 0;
};

extern template class MeshWearModule<2>;
extern template class MeshWearModule<3>;

}  // namespace grit::modules
