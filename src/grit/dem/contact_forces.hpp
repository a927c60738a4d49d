// The grain contact loops: grain-grain over each pair once (the grain of lower index evaluates the pair
// and both receive its force, summed in an order the lists fix: SlabBlocks) and
// grain-wall over the planes (each grain writes only its own force, torque and history), so results are
// bit-identical for any thread count. Law formulas live in contact_laws.hpp; this file holds geometry and
// loops.
//
// 2D: a disc collides like the sphere of its diameter. The law is evaluated with the sphere masses
// (contact_mass) and gives a force in N; the discs receive that force times s = m*_disc / m*_sphere, in
// N per metre of thickness, so that their relative motion (overlap, contact duration, restitution) is
// the spheres' and both receive equal and opposite forces (docs/theory.md).
#pragma once

#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/dem/contact_history.hpp"
#include "grit/dem/contact_laws.hpp"
#include "grit/dem/grain_neighbors.hpp"
#include "grit/dem/grain_set.hpp"
#include "grit/dem/pair_images.hpp"
#include "grit/dem/plane_wall.hpp"
#include "grit/dem/slab_blocks.hpp"
#include "grit/dem/spin.hpp"
#include "grit/dem/grain_loop.hpp"
#include "grit/neighbors/half_lists.hpp"

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

/// The factor s = m*_disc / m*_sphere from the law's force [N] between two spheres to the force [N/m]
/// between the two discs of their diameters (2D; 1 in 3D): with it the discs' relative acceleration,
/// s F / m*_disc = F / m*_sphere, is the spheres'. `mass` is the grain's own mass, `sphere` its
/// contact_mass; body b of infinite mass is a wall, where s = m_a / M_a. One division.
template <int Dim>
inline double disc_force_scale(double mass_a, double sphere_a, double mass_b, double sphere_b) noexcept {
    if constexpr (Dim == 3) {
        return 1.0;
    } else {
        if (mass_b == std::numeric_limits<double>::infinity()) return mass_a / sphere_a;
        return mass_a * mass_b * (sphere_a + sphere_b) / ((mass_a + mass_b) * (sphere_a * sphere_b));
    }
}

/// One contact in canonical orientation: n from a to b, `relative_velocity` = v_a - v_b at the contact
/// (eq. 7). The tangential history is carried into the current tangent plane, then grows by v_t dt
/// (eq. 9). In 2D the force and moment are the law's times `force_scale` (disc_force_scale: normal and
/// tangential alike, so the Coulomb cap and the history are the sphere's); 3D ignores it.
template <int Dim, class Law>
[[gnu::always_inline]] inline ContactResponse<Dim> contact_response(const Law& law, const PairMaterial& pair, const core::Vec<Dim>& n,
                                             const core::Vec<Dim>& relative_velocity, const ContactKinematics& c,
                                             const core::Vec<Dim>& history, double dt, double force_scale) noexcept {
    const double vn = core::dot(relative_velocity, n);
    const core::Vec<Dim> vt = relative_velocity - n * vn;
    ContactKinematics k = c;
    k.approach_speed = vn;
    const NormalContact normal = law.normal(k, pair);
    core::Vec<Dim> h = history + vt * dt;
    h -= n * core::dot(h, n);
    const TangentialContact<Dim> t = law.template tangential<Dim>(h, vt, normal, pair);
    if constexpr (Dim == 2) {
        const core::Vec<Dim> ft = t.force * force_scale;
        return {ft - n * (normal.force * force_scale), moment<Dim>(n, ft), t.history};
    } else {
        (void)force_scale;
        return {t.force - n * normal.force, moment<Dim>(n, t.force), t.history};
    }
}

/// Scratch of the pair pass, kept between steps: per pair entry 1 where the pair touched at the last pass
/// (so a pair apart costs a byte, not its history), and per grain its touching pairs and w R.
template <int Dim>
struct PairScratch {
    std::vector<std::uint8_t> touching;
    /// How many pairs of each grain touch at this pass.
    std::vector<std::int32_t> touching_pairs;
    /// w_i R_i of every grain, rounded before the pairs add them: a pair then sees the same sum
    /// w_a R_a + w_b R_b whichever of its grains evaluates it (a contracted w_b * R_b + w_a R_a would not be).
    std::vector<Spin<Dim>> spin_radius;

    /// Set where PairSumsClearing has run over the grains as they will be at the pair pass (DemSystem's
    /// first half kick and drift run it in their pass); the pair pass then skips its own clearing pass,
    /// and unsets it. reset() (fresh lists: the grains were reordered) unsets it too.
    bool sums_cleared = false;

    /// For fresh lists of `entries` pairs: all 1 (unknown), so the first pass settles every pair.
    void reset(std::size_t entries) {
        touching.assign(entries, 1);
        sums_cleared = false;
    }
};

/// What the pair pass starts from, for grain i: force and torque zero, no touching pair, w R rounded.
/// `scratch` must be sized to the grains (prepare_pair_sums).
template <int Dim>
struct PairSumsClearing {
    core::Vec<Dim>* force;
    Spin<Dim>* torque;
    std::int32_t* count;
    Spin<Dim>* spin_radius;
    const Spin<Dim>* w;
    const double* radius;

    PairSumsClearing(GrainSet<Dim>& grains, PairScratch<Dim>& scratch)
        : force(grains.force()), torque(grains.torque()), count(scratch.touching_pairs.data()),
          spin_radius(scratch.spin_radius.data()), w(std::as_const(grains).angular_velocity()),
          radius(std::as_const(grains).radius()) {}
    void operator()(Index i) const noexcept {
        spin_radius[i] = w[i] * radius[i];
        force[i] = core::Vec<Dim>::zero();
        torque[i] = zero_spin<Dim>();
        count[i] = 0;
    }
};

/// Sizes the pair pass's per-grain scratch to the grains.
template <int Dim>
void prepare_pair_sums(const GrainSet<Dim>& grains, PairScratch<Dim>& scratch) {
    scratch.spin_radius.resize(static_cast<std::size_t>(grains.size()));
    scratch.touching_pairs.resize(static_cast<std::size_t>(grains.size()));
}

/// The pair pass of the grain-grain contacts: each pair of `pairs` (the grain lists cut into each pair
/// once) is evaluated by its grain of lower index, body a, with the tangential history of its entry;
/// body a receives the force and b its exact negative (bit for bit), both the lever moment n x F_t (the
/// torque of body k is R_k n x F_t for both: F_t and the lever flip together). Sets force[i] = the sum of
/// i's pair forces, torque[i] = the sum of their lever moments (not yet times R_i) and
/// scratch.touching_pairs[i] for every grain. The pairs add straight into both grains, block by block of
/// `blocks` (SlabBlocks: the blocks of one colour add to disjoint grains), a's own pairs summed first; so
/// each grain's sum runs in an order the lists fix. A pair apart costs one distance test, and clears its
/// history when it parts. With `complete` (GrainCompletion), each grain is completed inside the pass as
/// soon as no block adds to it any more (SlabBlocks::completed_after), while its block's lines are cached;
/// without, the caller completes every grain after the pass (after the mesh walls' contacts, say).
template <int Dim, class Law, class Complete = NoGrainWork>
void grain_pair_pass(GrainSet<Dim>& grains, const neighbors::HalfLists& pairs, const SlabBlocks& blocks,
                     const PairImages<Dim>& images, ContactHistory<Dim>& history, const PairMaterialTable& materials,
                     const Law& law, double dt, PairScratch<Dim>& scratch, const Complete& complete = {}) {
    using Vec = core::Vec<Dim>;
    const Index grain_count = grains.size();
    if (scratch.touching.size() != pairs.upper_size()) scratch.reset(pairs.upper_size());
    if (!scratch.sums_cleared) {
        prepare_pair_sums(grains, scratch);
        const PairSumsClearing<Dim> clear(grains, scratch);
        for_each_grain(grain_count, [&](Index i) { clear(i); });
    }
    scratch.sums_cleared = false;
    Vec* force = grains.force();
    Spin<Dim>* torque = grains.torque();
    // The arrays, copied into each grain's call: a local copy stays in registers, where pointers read
    // through the closure would be reloaded after every store (which may alias them).
    const struct {
        const Vec* x;
        const Vec* v;
        const Spin<Dim>* wr;
        const double* radius;
        const double* mass;
        const std::int32_t* material;
        Vec* h;
        const Index* partner;
        const std::uint8_t* image;
        const Vec* shift;
        std::uint8_t* touching;
        Vec* force;
        Spin<Dim>* torque;
        std::int32_t* count;
    } arrays{std::as_const(grains).position(), std::as_const(grains).velocity(),
             std::as_const(scratch.spin_radius).data(), std::as_const(grains).radius(),
             std::as_const(grains).mass(), std::as_const(grains).material(), history.values(), pairs.upper(),
             images.codes_per_pair(), images.shifts(), scratch.touching.data(), force, torque,
             scratch.touching_pairs.data()};
    auto visit = [&](Index a) {
        const auto p = arrays;
        const Vec xa = p.x[a], va = p.v[a];
        const Spin<Dim> wra = p.wr[a];
        const double ra = p.radius[a], ma = p.mass[a];
        const double sphere_a = contact_mass<Dim>(ma, ra);
        const std::int32_t mat_a = p.material[a];
        Vec fa = Vec::zero();
        Spin<Dim> ta = zero_spin<Dim>();
        std::int32_t touching_a = 0;
        for (Index k = pairs.upper_begin(a); k < pairs.upper_end(a); ++k) {  // partners of higher index
            const Index b = p.partner[k];
            const Vec d = (p.x[b] - xa) + p.shift[p.image[k]];  // the pair's nearest periodic image
            const double reach = ra + p.radius[b];
            const double r2 = core::norm2(d);
            if (r2 >= reach * reach) {
                if (p.touching[k]) {
                    p.h[k] = Vec::zero();
                    p.touching[k] = 0;
                }
                continue;
            }
            const double r = std::sqrt(r2);
            const Vec n = d * (1.0 / r);
            const Vec vab = va - p.v[b] + spin_cross<Dim>(wra + p.wr[b], n);
            const double mb = p.mass[b], sphere_b = contact_mass<Dim>(mb, p.radius[b]);
            const ContactKinematics c{reach - r, 0.0, ra, p.radius[b], sphere_a, sphere_b};
            const ContactResponse<Dim> res =
                contact_response<Dim>(law, materials.at(mat_a, p.material[b]), n, vab, c, p.h[k], dt,
                                      disc_force_scale<Dim>(ma, sphere_a, mb, sphere_b));
            p.h[k] = res.history;
            p.touching[k] = 1;
            p.force[b] -= res.force;
            p.torque[b] += res.lever_moment;
            ++p.count[b];
            fa += res.force;
            ta += res.lever_moment;
            ++touching_a;
        }
        p.force[a] += fa;
        p.torque[a] += ta;
        p.count[a] += touching_a;
    };
    blocks.for_each_block(grain_count, [&](Index j) {
        for (Index a = blocks.begin(j); a < blocks.end(j); ++a) visit(a);
        // Each grain completed as soon as no block adds to it any more, while its block's lines are cached.
        if constexpr (!std::is_same_v<Complete, NoGrainWork>) {
            const auto [first, last] = blocks.completed_after(j);
            if (first < last)
                for (Index i = blocks.begin(first); i < blocks.end(last - 1); ++i) complete(i);
        }
    });
}

/// Completes grain i's force stage once grain_pair_pass() has summed its pairs: adds its weight m g and the
/// contacts of the plane walls (wall_history[w][i] is grain i's tangential history against wall w; a wall
/// is body b of infinite radius and mass, at rest). With half_kick != 0 it then kicks the grain, v += half_kick F/m,
/// w += half_kick T/I (the second half kick of a step no external stage adds forces to). With
/// `touching_pairs` (the pair pass's count per grain; null when grains pass through one another) it sets
/// grain_contact[i] (touches another grain) and adds one to collisions[i] where that contact begins.
/// Writes only grain i's data.
template <int Dim, class Law>
class GrainCompletion {
public:
    GrainCompletion(GrainSet<Dim>& grains, const core::Vec<Dim>& gravity, const std::vector<PlaneWall<Dim>>& walls,
                    const std::vector<core::Vec<Dim>*>& wall_history, const PairMaterialTable& materials,
                    const Law& law, double dt, double half_kick, const std::int32_t* touching_pairs)
        : gravity_(gravity), walls_(walls), wall_history_(wall_history), materials_(materials), law_(law), dt_(dt),
          half_kick_(half_kick), touching_pairs_(touching_pairs), x_(std::as_const(grains).position()),
          v_(grains.velocity()), w_(grains.angular_velocity()), radius_(std::as_const(grains).radius()),
          mass_(std::as_const(grains).mass()), inertia_(std::as_const(grains).inertia()),
          material_(std::as_const(grains).material()), force_(grains.force()), torque_(grains.torque()),
          fixed_(fixed_flags(std::as_const(grains))), in_contact_(grains.grain_contact()),
          collisions_(grains.collisions()) {
        const auto& fields = std::as_const(grains).fields();
        if (fields.has(straddling_field)) straddling_ = fields.template get<std::int32_t>(straddling_field).data();
    }

    void operator()(Index i) const noexcept {
        using Vec = core::Vec<Dim>;
        constexpr double infinite = std::numeric_limits<double>::infinity();
        if (touching_pairs_) {
            // A contact that begins at this pass is a collision (a repeated pass over the same state, dt =
            // 0, finds the flag already set).
            const std::int32_t now = touching_pairs_[i] > 0;
            collisions_[i] += now & (in_contact_[i] == 0);
            in_contact_[i] = now;
        }
        Vec f = gravity_ * mass_[i] + force_[i];
        Spin<Dim> t = torque_[i] * radius_[i];
        for (std::size_t s = 0; s < walls_.size(); ++s) {
            const PlaneWall<Dim>& wall = walls_[s];
            Vec& h = wall_history_[s][i];
            const double gap = core::dot(x_[i] - wall.point, wall.normal);
            if (gap >= radius_[i] || (wall.frictionless && straddling_ && straddling_[i] > 0)) {
                // Most grains are off most walls: clearing only a history that is set keeps their lines clean.
                if (core::norm2(h) != 0.0) h = Vec::zero();
                continue;
            }
            const Vec n = -wall.normal;  // from the grain (a) to the wall (b)
            const Vec vab = v_[i] + spin_cross<Dim>(w_[i] * radius_[i], n);
            const double sphere = contact_mass<Dim>(mass_[i], radius_[i]);
            const ContactKinematics c{radius_[i] - gap, 0.0, radius_[i], infinite, sphere, infinite};
            PairMaterial pair = materials_.at(material_[i], wall.material);
            if (wall.frictionless) pair.friction = 0.0;
            const ContactResponse<Dim> res = contact_response<Dim>(
                law_, pair, n, vab, c, h, dt_, disc_force_scale<Dim>(mass_[i], sphere, infinite, infinite));
            h = res.history;
            f += res.force;
            t += res.lever_moment * radius_[i];
        }
        force_[i] = f;
        torque_[i] = t;
        if (half_kick_ != 0.0 && !(fixed_ && fixed_[i])) {
            v_[i] += f * (half_kick_ / mass_[i]);
            w_[i] += t * (half_kick_ / inertia_[i]);
        }
    }

private:
    core::Vec<Dim> gravity_;
    const std::vector<PlaneWall<Dim>>& walls_;
    const std::vector<core::Vec<Dim>*>& wall_history_;
    const PairMaterialTable& materials_;
    const Law& law_;
    double dt_, half_kick_;
    const std::int32_t* touching_pairs_;
    const core::Vec<Dim>* x_;
    core::Vec<Dim>* v_;
    Spin<Dim>* w_;
    const double* radius_;
    const double* mass_;
    const double* inertia_;
    const std::int32_t* material_;
    core::Vec<Dim>* force_;
    Spin<Dim>* torque_;
    const std::int32_t* fixed_;
    const std::int32_t* straddling_ = nullptr;
    std::int32_t* in_contact_;
    std::int32_t* collisions_;
};

}  // namespace grit::dem
