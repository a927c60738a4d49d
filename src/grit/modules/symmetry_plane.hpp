// The symmetry plane x = 0 (domain.symmetry, or jet.symmetric): a set-up symmetric about the plane is
// run on its x >= 0 half. The particles within reach of the plane have mirror images at x < 0 (LAMMPS'
// ghosts, a mirror instead of a periodic shift): the images stand in the SPH sums for the missing half
// and are refreshed from their sources at each stage that changes what the sums read, so they take no
// step of their own. An image has the id image_id(source's id) (negative): the modules that remove,
// count or write particles leave images out (integrating one is harmless: it is overwritten). Grains
// meet the plane as a frictionless wall (a grain meets its mirror twin there, the two surfaces sliding
// together); what a grain does to an image (contact, drag) its twin does to the image's source, so those
// forces go back to the sources mirrored.
// A grain that appears closer to the plane than its radius (a grain of the whole jet riding on its axis)
// straddles it: the plane lets it pass, it is reflected if its centre crosses, and it is an ordinary
// grain once it has moved a radius off the plane.
// Halves the particles of a normal-incidence jet (docs/performance.md, "The jet's axis as a symmetry
// plane").
#pragma once

#include <vector>

#include "grit/sim/module.hpp"

namespace grit::modules {

template <int Dim>
class SymmetryPlaneModule final : public sim::Module<Dim> {
public:
    /// Hooks the images into the state's neighbour-list builds; the particles (already laid) must start
    /// on the x >= 0 side.
    SymmetryPlaneModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);

    std::string name() const override { return "symmetry_plane"; }
    void install(sim::Pipeline& pipeline) override;

    /// The plane's normal axis (x).
    static constexpr int axis = 0;

private:
    /// Before each list build: the images of every particle within `depth_` of the plane, afresh.
    void make_images(particles::SphParticles<Dim>& ps);
    /// Images to their sources' mirror images (every field), images of removed particles removed; and
    /// particles that drifted across the plane reflected back (their twins crossed the other way).
    void refresh();
    /// The images' accelerations after the SPH sums, so that what grains add to them afterwards is known.
    void hold_image_rates();
    /// What grains added to each image's acceleration, mirrored onto its source.
    void return_image_forces();
    /// Each image with its source (state.ghosts), when the set changed since they were found.
    void find_sources();
    /// New grains straddle the plane or not; straddlers a radius off it no longer do; straddlers whose
    /// centre crossed are reflected (their twins crossed the other way).
    void sort_grains();

    sim::State<Dim>& state_;
    bool has_particles_;  ///< SPH particles (else grains only: no images)
    double depth_ = 0.0;  ///< images of the particles closer than this to the plane [m]
    std::vector<core::Vec<Dim>> held_;
    std::uint64_t sources_generation_ = ~std::uint64_t{0};
};

extern template class SymmetryPlaneModule<2>;
extern template class SymmetryPlaneModule<3>;

}  // namespace grit::modules
