// Grain-boundary contact module: penalty forces and the impact log's SPH targets.
#include "grit/modules/grain_contact.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <string>
#include <vector>

#include "grit/domain/particle_id.hpp"
#include "grit/modules/grains.hpp"

namespace grit::modules {

template <int Dim>
GrainContactModule<Dim>::GrainContactModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup)
    : state_(state), setup_(setup) {
    const auto& spec = setup.spec;
    coupling::PenaltyContactParameters c;
    c.spacing = spec.particle_spacing;
    c.overlap_coefficient = spec.dem.overlap_coefficient;
    c.walls = spec.dem.wall_particle_contact;
    c.friction = spec.dem.solid_friction >= 0.0
                     ? spec.dem.solid_friction
                     : spec.grain_materials[static_cast<std::size_t>(spec.first_grain_material())].friction;
    contact_ = coupling::GrainBoundaryContact<Dim>(c);
}

template <int Dim>
void GrainContactModule<Dim>::install(sim::Pipeline& pipeline) {
    // Grains and SPH solids/walls push each other at the state the SPH sums saw (eqs. 12-14); then the
    // grains take their step with the same dt (the grains module's stage, after this one).
    pipeline.add(sim::Hook::post_force, "grain_contact", [this] { couple(); });
}

template <int Dim>
void GrainContactModule<Dim>::couple() {
    using Vec = core::Vec<Dim>;
    auto& particles = state_.particles;
    auto& grains = state_.grains->grains();
    const std::int32_t* fixed =
        particles.fields().has("fixed") ? particles.fields().template get<std::int32_t>("fixed").data() : nullptr;
    // dt of eq. (13)'s stiffness 2 m_a / dt^2: the stable step, not one shortened to land on an output
    // time (a short step would make the penalty force, and the impulse, blow up).
    contact_.compute(grains, particles, state_.clock.dt_stable, setup_.periodic_box);
    if (state_.clock.step == 0 && !start_checked_) warn_of_grains_starting_in_contact();
    contact_.apply(grains, particles, fixed);

    // First contacts with SPH solids and walls. A target counts as left only when no particle of it is
    // near (2 d_ini) any more, so a grain rattling on a surface logs one impact. The record's normal is
    // the sum of the normals of the step's contacts (two particles touched symmetrically give the
    // surface normal, not the direction to either of them).
    const double time = state_.clock.time;
    const auto& materials = setup_.spec.materials;
    std::int32_t* mask = grains.fields().template get<std::int32_t>("contact_targets").data();
    const Index n = grains.size();
    std::vector<std::int32_t> near(static_cast<std::size_t>(n), 0), touching(static_cast<std::size_t>(n), 0);
    // Per grain and target kind (0: SPH solid, 1: SPH wall): the summed normals of the new contacts and
    // the first of them (particle order), which names the target and gives the relative velocity.
    std::vector<Vec> normal(2 * static_cast<std::size_t>(n), Vec::zero());
    std::vector<Index> first(2 * static_cast<std::size_t>(n), -1);
    const std::int32_t* phase = particles.phase();
    const auto& contacts = contact_.contacts();
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const auto& c = contacts[k];
        const bool wall = phase[c.particle] == static_cast<std::int32_t>(Phase::wall);
        const std::int32_t bit = wall ? sph_wall_bit : sph_solid_bit;
        const auto g = static_cast<std::size_t>(c.grain);
        near[g] |= bit;
        if (!c.touching) continue;
        touching[g] |= bit;
        if (mask[c.grain] & bit) continue;  // already in contact with this target
        const std::size_t slot = 2 * g + (wall ? 1 : 0);
        normal[slot] += c.normal;
        if (first[slot] < 0) first[slot] = static_cast<Index>(k);
    }
    for (Index g = 0; g < n; ++g) {
        const auto gi = static_cast<std::size_t>(g);
        for (const std::size_t kind : {std::size_t{0}, std::size_t{1}}) {
            const Index k = first[2 * gi + kind];
            if (k < 0) continue;
            const auto& c = contacts[static_cast<std::size_t>(k)];
            const Vec vrel = grains.velocity()[g] - particles.velocity()[c.particle];
            const std::string target =
                kind == 1 ? std::string("wall") : materials[static_cast<std::size_t>(particles.material()[c.particle])].name;
            state_.impacts.add(
                {time, grains.id()[g], target, core::norm(vrel), impact_angle<Dim>(vrel, normal[2 * gi + kind]),
                 core::to_array3(grains.position()[g]), grains.collisions()[g]});
        }
        // Bits stay set while the target is near; new contacts set them.
        mask[g] = (mask[g] & ~(sph_wall_bit | sph_solid_bit)) | (mask[g] & near[gi]) | touching[gi];
    }
}

template <int Dim>
void GrainContactModule<Dim>::warn_of_grains_starting_in_contact() {
    // A grain placed closer than d_ini to a wall or solid particle starts in contact: eqs. (12)-(14)
    // push it out within a step, which throws a light grain off at tens of m/s (a 0.1 mm grain of the
    // water's density half a spacing into the contact zone of 0.2 mm wall particles left at 80 m/s).
    start_checked_ = true;
    const auto& grains = state_.grains->grains();
    std::vector<std::uint8_t> in_contact(static_cast<std::size_t>(grains.size()), 0);
    Index count = 0, first = -1;
    for (const auto& c : contact_.contacts()) {
        if (!c.touching || in_contact[static_cast<std::size_t>(c.grain)]) continue;
        in_contact[static_cast<std::size_t>(c.grain)] = 1;
        ++count;
        if (first < 0 || grains.id()[c.grain] < grains.id()[first]) first = c.grain;
    }
    if (count == 0) return;
    const auto& x = grains.position()[first];
    spdlog::warn(
        "{} grain(s) start in contact with SPH wall or solid particles (closer than the particle spacing "
        "{:.4g} m to a grain's surface; the first: grain {} ({}) at ({}) m): the contact of eqs. (12)-(14) "
        "pushes them out in a step, which can throw them off fast. Place grains at least a spacing from walls "
        "and solids.",
        count, setup_.spec.particle_spacing, grains.id()[first], domain::describe_id(grains.id()[first]), fmt::join(std::vector<double>(x.c, x.c + Dim), ", "));
}

template class GrainContactModule<2>;
template class GrainContactModule<3>;

}  // namespace grit::modules
