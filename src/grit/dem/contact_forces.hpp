// The grain contact loops: grain-grain over the full neighbour lists and grain-wall over the planes, in
// gather form (each grain writes only its own force, torque and history), so results are bit-identical
// for any thread count. Law formulas live in contact_laws.hpp; this file holds geometry and loops.
#pragma once

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/dem/contact_history.hpp"
#include "grit/dem/contact_laws.hpp"
#include "grit/dem/grain_neighbors.hpp"
#include "grit/dem/grain_set.hpp"
#include "grit/dem/plane_wall.hpp"
#include "grit/dem/spin.hpp"
#include "grit/dem/grain_loop.hpp"

namespace grit::dem {

/// Pair properties of every material pair, row-major: at(a, b) = table[a * count + b].
struct PairMaterialTable {
    std::vector<PairMaterial> table;
    std::int32_t count = 0;
    const PairMaterial& at(std::int32_t a, std::int32_t b) const noexcept {
        return table[static_cast<std::size_t>(a) * static_cast<std::size_t>(count) + static_cast<std::size_t>(b)];
    }
};

/// What one contact gives body a: its force, n x F_t (body k's torque is R_k n x F_t for both bodies,
/// since F_t and the lever both flip sign for b), and the new tangential history.
template <int Dim>
struct ContactResponse {
    core::Vec<Dim> force;
    Spin<Dim> lever_moment;
    core::Vec<Dim> history;
};

/// One contact in canonical orientation: n from a to b, `relative_velocity` = v_a - v_b at the contact
/// (eq. 7). The tangential history is carried into the current tangent plane, then grows by v_t dt
/// (eq. 9).
template <int Dim, class Law>
inline ContactResponse<Dim> contact_response(const Law& law, const PairMaterial& pair, const core::Vec<Dim>& n,
                                             const core::Vec<Dim>& relative_velocity, const ContactKinematics& c,
                                             const core::Vec<Dim>& history, double dt) noexcept {
    const double vn = core::dot(relative_velocity, n);
    const core::Vec<Dim> vt = relative_velocity - n * vn;
    ContactKinematics k = c;
    k.approach_speed = vn;
    const NormalContact normal = law.normal(k, pair);
    core::Vec<Dim> h = history + vt * dt;
    h -= n * core::dot(h, n);
    const TangentialContact<Dim> t = law.template tangential<Dim>(h, vt, normal, pair);
    return {t.force - n * normal.force, moment<Dim>(n, t.force), t.history};
}

/// Per-entry results of the pair pass, reused between steps (sized by the neighbour list).
template <int Dim>
struct PairScratch {
    std::vector<core::Vec<Dim>> force;   ///< force on body a of the entry's pair
    std::vector<Spin<Dim>> lever_moment; ///< n x F_t of the entry's pair
};

/// Adds every grain-grain contact force and torque to force/torque, updating `history`.
/// Each pair is evaluated once, by the grain with the lower id (body a), in the pair pass, which
/// writes only that grain's list entries; the gather pass then adds to each grain the results of its
/// entries, the grain that is body b taking the exact negative of the force (read through the mirror
/// entry). So the two grains receive equal and opposite forces bit for bit, and no thread writes where
/// another reads.
template <int Dim, class Law>
void add_grain_contacts(GrainSet<Dim>& grains, const GrainNeighborList<Dim>& list, ContactHistory<Dim>& history,
                        const GrainDomain<Dim>& domain, const PairMaterialTable& materials, const Law& law,
                        double dt, PairScratch<Dim>& scratch) {
    using Vec = core::Vec<Dim>;
    const Vec* x = std::as_const(grains).position();
    const Vec* v = std::as_const(grains).velocity();
    const Spin<Dim>* w = std::as_const(grains).angular_velocity();
    const double* radius = std::as_const(grains).radius();
    const double* mass = std::as_const(grains).mass();
    const std::int32_t* material = std::as_const(grains).material();
    Vec* force = grains.force();
    Spin<Dim>* torque = grains.torque();
    Vec* h = history.values();
    const Index* neighbor = list.indices();
    const Index* mirror = list.mirrors();
    scratch.force.resize(list.entry_count());
    scratch.lever_moment.resize(list.entry_count());
    Vec* pair_force = scratch.force.data();
    Spin<Dim>* pair_moment = scratch.lever_moment.data();
    for_each_grain(grains.size(), [&](Index a) {
        const Vec xa = x[a];
        const double ra = radius[a];
        for (Index k = list.begin(a); k < list.split(a); ++k) {  // partners of higher id
            const Index b = neighbor[k];
            const Vec d = domain.nearest_image(x[b] - xa);
            const double reach = ra + radius[b];
            const double r2 = core::norm2(d);
            if (r2 >= reach * reach) {
                h[k] = Vec::zero();
                pair_force[k] = Vec::zero();
                pair_moment[k] = zero_spin<Dim>();
                continue;
            }
            const double r = std::sqrt(r2);
            const Vec n = d * (1.0 / r);
            const Vec vab = v[a] - v[b] + spin_cross<Dim>(w[a] * ra + w[b] * radius[b], n);
            const ContactKinematics c{reach - r, 0.0, ra, radius[b], mass[a], mass[b]};
            const ContactResponse<Dim> res =
                contact_response<Dim>(law, materials.at(material[a], material[b]), n, vab, c, h[k], dt);
            h[k] = res.history;
            pair_force[k] = res.force;
            pair_moment[k] = res.lever_moment;
        }
    });
    for_each_grain(grains.size(), [&](Index i) {
        Vec f = Vec::zero();
        Spin<Dim> t = zero_spin<Dim>();
        for (Index k = list.begin(i); k < list.split(i); ++k) {  // i is body a
            f += pair_force[k];
            t += pair_moment[k];
        }
        for (Index k = list.split(i); k < list.end(i); ++k) {  // i is body b: the exact negative
            f -= pair_force[mirror[k]];
            t += pair_moment[mirror[k]];
        }
        force[i] += f;
        torque[i] += t * radius[i];
    });
}

/// Adds the contact force and torque of every plane wall to each grain; wall_history[w][i] is grain i's
/// tangential history against wall w. The wall is body b: infinite radius and mass, at rest.
template <int Dim, class Law>
void add_wall_contacts(GrainSet<Dim>& grains, const std::vector<PlaneWall<Dim>>& walls,
                       const std::vector<core::Vec<Dim>*>& wall_history, const PairMaterialTable& materials,
                       const Law& law, double dt) {
    using Vec = core::Vec<Dim>;
    const Vec* x = std::as_const(grains).position();
    const Vec* v = std::as_const(grains).velocity();
    const Spin<Dim>* w = std::as_const(grains).angular_velocity();
    const double* radius = std::as_const(grains).radius();
    const double* mass = std::as_const(grains).mass();
    const std::int32_t* material = std::as_const(grains).material();
    Vec* force = grains.force();
    Spin<Dim>* torque = grains.torque();
    constexpr double infinite = std::numeric_limits<double>::infinity();
    for_each_grain(grains.size(), [&](Index i) {
        for (std::size_t s = 0; s < walls.size(); ++s) {
            const PlaneWall<Dim>& wall = walls[s];
            Vec& h = wall_history[s][i];
            const double gap = core::dot(x[i] - wall.point, wall.normal);
            if (gap >= radius[i]) {
                h = Vec::zero();
                continue;
            }
            const Vec n = -wall.normal;  // from the grain (a) to the wall (b)
            const Vec vab = v[i] + spin_cross<Dim>(w[i] * radius[i], n);
            const ContactKinematics c{radius[i] - gap, 0.0, radius[i], infinite, mass[i], infinite};
            const ContactResponse<Dim> res =
                contact_response<Dim>(law, materials.at(material[i], wall.material), n, vab, c, h, dt);
            h = res.history;
            force[i] += res.force;
            torque[i] += res.lever_moment * radius[i];
        }
    });
}

}  // namespace grit::dem
