// The symmetry plane: mirror images of the particles near x = 0.
#include "grit/modules/symmetry_plane.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "grit/core/error.hpp"
#include "grit/dem/plane_wall.hpp"
#include "grit/domain/id_index.hpp"
#include "grit/sim/damage_reach.hpp"

namespace grit::modules {

namespace {
template <int Dim>
using Particles = particles::SphParticles<Dim>;
}  // namespace

template <int Dim>
SymmetryPlaneModule<Dim>::SymmetryPlaneModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup)
    : state_(state), has_particles_(setup.spec.has_sph()) {
    const double support = std::visit([](const auto& k) { return k.support(); }, setup.kernel);
    const double skin = setup.spec.neighbor_skin * setup.smoothing_length;
    // A particle reads an image up to a support away, and that image's own sums (a correction matrix,
    // the wall pressure, the Shepard density) must see a whole kernel of images: two supports, and a
    // skin for each, as both move by up to half a skin between builds.
    depth_ = 2.0 * (support + skin);
    // A non-local damage average (sph/nonlocal_damage.hpp) reads images up to its length away.
    if (const double damage = sim::longest_damage_reach(setup.spec).length; damage > 0.0)
        depth_ = std::max(depth_, damage + skin);
    state.neighbors.before_build([this](particles::SphParticles<Dim>& ps) { make_images(ps); });
    if (state_.grains) {  // grains laid at the start: the x >= 0 half, a grain on the plane straddling it
        const auto& grains = state_.grains->grains();
        for (Index g = 0; g < grains.size(); ++g)
            if (grains.position()[g][axis] < 0.0)
                throw core::InputError(fmt::format(
                    "key '{}': grain {} ({}) starts at x = {:.6g} m, on the mirrored side of the plane x = 0; place "
                    "only the x >= 0 half of the set-up (a grain whose centre is within its radius of the plane "
                    "straddles it)",
                    setup.spec.symmetry_key, grains.id()[g], domain::describe_id(grains.id()[g]),
                    grains.position()[g][axis]));
    }
    sort_grains();
    const auto& ps = state_.particles;
    const auto* x = ps.position();
    for (Index i = 0; i < ps.size(); ++i)
        if (!ps.is_image(i) && x[i][axis] < 0.0)
            throw core::InputError(fmt::format(
                "key '{}': a {} particle starts at x = {:.6g} m, on the mirrored side of the "
                "plane x = 0; place only the x >= 0 half of the set-up",
                setup.spec.symmetry_key, ps.phase()[i] == static_cast<std::int32_t>(Phase::solid) ? "solid"
                : ps.phase()[i] == static_cast<std::int32_t>(Phase::wall) ? "wall"
                                                                           : "fluid",
                x[i][axis]));
}

template <int Dim>
void SymmetryPlaneModule<Dim>::install(sim::Pipeline& pipeline) {
    using sim::Hook;
    // After the inlets and outlets (a removed source takes its image along, a particle that crossed is
    // reflected before the lists see it).
    if (!has_particles_) {  // grains only: the straddlers
        pipeline.add(Hook::boundaries, "symmetry_grains", [this] { sort_grains(); });
        return;
    }
    pipeline.add(Hook::boundaries, "symmetry_refresh", [this] {
        refresh();
        sort_grains();  // after the feeds
    });
    // After the lists, the Shepard filter and the porosity: the images' densities, masses and porosity
    // are their sources'.
    pipeline.add(Hook::neighbors, "symmetry_images", [this] { refresh(); }, true);
    pipeline.add(Hook::force, "symmetry_hold", [this] { hold_image_rates(); }, true);
    pipeline.add(Hook::post_force, "symmetry_forces", [this] { return_image_forces(); }, true);
    // After the material update and the erosion: outputs, the health check and the next time step see
    // images that are mirror images in every field.
    pipeline.add(Hook::end_step, "symmetry_end", [this] { refresh(); });
}

template <int Dim>
void SymmetryPlaneModule<Dim>::make_images(particles::SphParticles<Dim>& ps) {
    // Drop the old images, then one image per particle within depth_ of the plane.
    std::vector<Index> keep;
    keep.reserve(static_cast<std::size_t>(ps.size()));
    for (Index i = 0; i < ps.size(); ++i)
        if (!ps.is_image(i)) keep.push_back(i);
    if (static_cast<Index>(keep.size()) != ps.size()) ps.remove(keep);
    std::vector<Index> near;
    const auto* x = ps.position();
    for (Index i = 0; i < ps.size(); ++i)
        if (x[i][axis] < depth_) near.push_back(i);
    if (near.empty()) return;
    const Index first = ps.append_images(static_cast<Index>(near.size()));
    std::vector<Index> made(near.size());
    for (std::size_t k = 0; k < near.size(); ++k) made[k] = first + static_cast<Index>(k);
    ps.fields().mirror_copy(near, made, axis);
    domain::ParticleId* id = ps.id();
    for (std::size_t k = 0; k < near.size(); ++k) id[made[k]] = Particles<Dim>::image_id(id[near[k]]);
}

template <int Dim>
void SymmetryPlaneModule<Dim>::find_sources() {
    auto& ps = state_.particles;
    if (sources_generation_ == ps.generation()) return;
    std::vector<Index> images;
    const domain::ParticleId* id = ps.id();
    const auto* x = ps.position();
    domain::IdIndex near;
    for (Index i = 0; i < ps.size(); ++i) {
        if (ps.is_image(i)) {
            images.push_back(i);
        } else if (x[i][axis] < 2.0 * depth_) {  // a source moves less than half a skin between builds
            near.add(id[i], i);
        }
    }
    state_.ghosts.clear();
    std::vector<Index> orphans;
    for (const Index image : images) {
        const Index source = near.find(Particles<Dim>::image_source(id[image]));
        if (source < 0)
            orphans.push_back(image);
        else
            state_.ghosts.add(source, image, domain::GhostTransform<Dim>::mirror(axis));
    }
    if (!orphans.empty()) {  // their sources left (outlets, erosion): the images go too
        std::vector<Index> keep;
        keep.reserve(static_cast<std::size_t>(ps.size()));
        std::size_t o = 0;
        for (Index i = 0; i < ps.size(); ++i) {
            if (o < orphans.size() && orphans[o] == i) {
                ++o;
                continue;
            }
            keep.push_back(i);
        }
        ps.remove(keep);
        find_sources();
        return;
    }
    sources_generation_ = ps.generation();
}

template <int Dim>
void SymmetryPlaneModule<Dim>::refresh() {
    auto& ps = state_.particles;
    // A particle that drifted across the plane: its twin drifted across the other way; take the twin's
    // place (walls do not move).
    {
        auto* x = ps.position();
        auto& fields = ps.fields();
        const std::int32_t* ph = ps.phase();
        const auto wall = static_cast<std::int32_t>(Phase::wall);
        for (Index i = 0; i < ps.size(); ++i)
            if (x[i][axis] < 0.0 && ph[i] != wall && !ps.is_image(i)) fields.mirror_copy(i, i, axis);
    }
    find_sources();
    state_.ghosts.forward(ps.fields(), ps.position());
    domain::ParticleId* id = ps.id();
    const auto& images = state_.ghosts.ghosts();
    const auto& sources = state_.ghosts.owners();
    for (std::size_t k = 0; k < images.size(); ++k) id[images[k]] = Particles<Dim>::image_id(id[sources[k]]);
}

template <int Dim>
void SymmetryPlaneModule<Dim>::sort_grains() {
    if (!state_.grains) return;
    auto& grains = state_.grains->grains();
    auto& fields = grains.fields();
    if (!fields.has(dem::straddling_field)) return;
    std::int32_t* straddling = fields.template get<std::int32_t>(dem::straddling_field).data();
    auto* x = grains.position();
    auto* v = grains.velocity();
    auto* w = grains.angular_velocity();
    const double* r = std::as_const(grains).radius();
    for (Index g = 0; g < grains.size(); ++g) {
        if (straddling[g] < 0) straddling[g] = x[g][axis] < r[g] ? 1 : 0;
        if (straddling[g] > 0 && x[g][axis] >= r[g]) straddling[g] = 0;
        if (x[g][axis] < 0.0) {  // a mirror image in every kinematic quantity (spin is an axial vector)
            x[g][axis] = -x[g][axis];
            v[g][axis] = -v[g][axis];
            if constexpr (Dim == 2) {
                w[g] = -w[g];
            } else {
                for (int k = 0; k < 3; ++k)
                    if (k != axis) w[g][k] = -w[g][k];
            }
        }
    }
}

template <int Dim>
void SymmetryPlaneModule<Dim>::hold_image_rates() {
    find_sources();
    const auto* a = state_.particles.acceleration();
    const auto& images = state_.ghosts.ghosts();
    held_.resize(images.size());
    for (std::size_t k = 0; k < images.size(); ++k) held_[k] = a[images[k]];
}

template <int Dim>
void SymmetryPlaneModule<Dim>::return_image_forces() {
    auto& ps = state_.particles;
    const auto& images = state_.ghosts.ghosts();
    if (sources_generation_ != ps.generation() || held_.size() != images.size())
        throw std::logic_error("symmetry plane: the particle set changed between the sums and the grain forces");
    auto* a = ps.acceleration();
    // What the grains added to each image since the sums (held_ becomes it), back onto the sources.
    for (std::size_t k = 0; k < images.size(); ++k) held_[k] = a[images[k]] - held_[k];
    state_.ghosts.reverse_add(held_.data(), a);
}

template class SymmetryPlaneModule<2>;
template class SymmetryPlaneModule<3>;

}  // namespace grit::modules
