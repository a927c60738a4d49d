// The thin walls module: SPH walls from STL sheets thinner than the kernel ([[wall]] shape = "mesh",
// thin = true), such as the splitter edge of a Pelton bucket. The second seed paper (sec. 3.2) stores
// the boundary's normal with each SPH particle next to it and lets two particles interact only when
// their normals agree: so the jet divided at the splitter does not feel the water on the other side.
// Here every particle carries the field `wall_normal`: wall particles the unit normal of the facet they
// stand behind (set when laid, sim/geometry), fluid particles within reach of a thin wall the normal of
// the closest point of its sheet, turned to its water (refreshed before each neighbour-list build), zero
// elsewhere. Water on both sides of a membrane: two thin walls on the same sheet, "front" and "back". Pairs
// with n_a . n_b < 0 are left out of the neighbour lists, so every SPH sum (density, forces, wall
// pressure, filters, the ISPH matrix) respects the separation.
#pragma once

#include <memory>
#include <vector>

#include "grit/mesh/signed_distance.hpp"
#include "grit/sim/module.hpp"

namespace grit::modules {

template <int Dim>
class ThinWallsModule final : public sim::Module<Dim> {
  public:
    /// Registers `wall_normal` and hooks the refresh into the state's neighbour lists.
    ThinWallsModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);

    std::string name() const override { return "thin_walls"; }
    void install(sim::Pipeline& pipeline) override;
    /// Fluid particles with a wall normal (summary: fluid_near_thin_walls).
    void output_values(std::vector<sim::OutputValue>& out) const override;

    static constexpr const char* normal_field = "wall_normal";
    static constexpr const char* far_field = "far_side";
    /// A far-side wall particle and a particle whose normals differ by more than 60 degrees do not
    /// interact: water at a fold's edge, whose normal is the edge's, sees neither side's far wall (which
    /// stands in the other side's water), only the fold itself.
    static constexpr double far_cos = 0.5;

  private:
    /// The normals of the fluid particles (the lists are built right after).
    void refresh(particles::SphParticles<Dim>& particles);

    struct Wall {
        std::unique_ptr<mesh::SignedDistance> sheet;  ///< binned over the reach
        double water = 1.0;                           ///< +1: the water is in front of the facets
    };
    std::vector<Wall> walls_;
    sim::State<Dim>& state_;
};

extern template class ThinWallsModule<2>;
extern template class ThinWallsModule<3>;

}  // namespace grit::modules
