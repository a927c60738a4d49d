// A case split into sub-domains, each run by grit's own SPH module on the particles it owns plus ghosts of
// its neighbours', over a loopback communicator (sub-domains in threads of one process): the path a run
// over many processes will take, tested before MPI exists. The WCSPH dam break (cases/dambreak_2d at 1 cm)
// cut in two, and in three, where the collapsing column and its surge carry particles across the cuts, is
// the one-domain run to round-off: every particle's position, velocity, density and pressure, and every
// time step, within 1e-12 of the case's scales, for 2000 steps (0.17 s, the surge a third of the way along
// the floor) that migrate about a hundred particles and rebuild the ghosts 156 times; so is the 3D dam
// break (cases/dambreak_3d at 2 cm) cut across its falling column, for 500 steps.
//
// A sub-domain's step is the module's pipeline with two stages of the domain layer: at the end of the step
// the ghosts take their owners' values (forward); before the neighbour stage every sub-domain rebuilds when
// any needs to (Comm::any), migrating the particles that left its slab and making its ghosts afresh. The
// ghosts reach two list radii into the neighbour: a ghost a particle reads then has its own whole kernel
// of particles and ghosts, so a value it derives (its wall pressure) is its owner's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "grit/domain/process_halo.hpp"
#include "grit/modules/sph_fluid.hpp"
#include "grit/sim/pipeline.hpp"
#include "grit/sim/simulation.hpp"
#include "support/case_fixture.hpp"
#include "support/loopback_comm.hpp"

namespace {

using grit::Index;

/// What a run leaves of each particle, by id.
template <int Dim>
struct ParticleState {
    grit::core::Vec<Dim> x, v;
    double rho, p;
};
template <int Dim>
using Snapshot = std::map<grit::domain::ParticleId, ParticleState<Dim>>;

template <int Dim>
void record(const grit::particles::SphParticles<Dim>& ps, Snapshot<Dim>& out) {
    const std::int32_t* ghost = grit::domain::ProcessHalo<Dim>::ghost_marks(ps);
    for (Index i = 0; i < ps.size(); ++i)
        if (!ghost || !ghost[i])
            out[ps.id()[i]] = {ps.position()[i], ps.velocity()[i], ps.density()[i], ps.pressure()[i]};
}

/// One sub-domain: its particles (owned, then ghosts after each rebuild, interleaved by the sort), the
/// SPH module on them, and the domain layer's stages around the module's.
template <int Dim>
class SubDomain {
public:
    SubDomain(const grit::io::CaseSpec& spec, const grit::particles::SphParticles<Dim>& whole,
              const grit::domain::SlabPartition<Dim>& partition, const grit::domain::Comm& comm)
        : spec_(spec), partition_(partition), comm_(comm),
          setup_{spec, spec.particle_spacing, spec.smoothing_ratio * spec.particle_spacing, kernel_, 100.0, {}, comm} {
        grit::sph::make_kernel<Dim>(spec.kernel, setup_.smoothing_length, kernel_);
        std::vector<Index> mine;
        for (Index i = 0; i < whole.size(); ++i)
            if (partition.owner(whole.position()[i]) == comm.rank()) mine.push_back(i);
        state_.particles = whole;
        state_.particles.gather(mine);
        const double skin = spec.neighbor_skin * setup_.smoothing_length;
        const double support = std::visit([](const auto& k) { return k.support(); }, kernel_);
        radius_ = support + skin;
        skin_ = skin;
        // Two list radii: a ghost within one of the cut has every particle within one of it here.
        state_.neighbors.before_build([this](grit::particles::SphParticles<Dim>& ps) {
            halo_.drop_ghosts(ps);
            migrated_ += halo_.migrate(ps, partition_, comm_);
            halo_.make_ghosts(ps, partition_, 2.0 * radius_, comm_);
            ++rebuilds_;
        });
        sph_ = std::make_unique<grit::modules::SphModule<Dim>>(state_, setup_);
        sph_->install(pipeline_);
        using grit::sim::Hook;
        // At the end of a step the ghosts become their owners again in every field (the sums gave them
        // rates of their own, from kernels cut short at the ghosts' edge): the next time step, the
        // predictor and any output see ghosts equal to their owners.
        pipeline_.add(Hook::end_step, "halo_forward", [this] { halo_.forward(state_.particles, comm_); });
        pipeline_.add(Hook::boundaries, "reneighbour", [this] { reneighbour(); });
        pipeline_.add(Hook::check, "time_step", [this] {
            state_.clock.dt = std::min(comm_.min(sph_->stable_time_step()), spec_.max_time_step);
        }, true);
    }

    void prime() {
        sph_->prime();
        halo_.resolve(state_.particles);
        pipeline_.run_prime();
    }
    void step() {
        const double dt = state_.clock.dt;
        pipeline_.run();
        state_.clock.time += dt;
        ++state_.clock.step;
    }
    double dt() const { return state_.clock.dt; }
    const grit::particles::SphParticles<Dim>& particles() const { return state_.particles; }
    long migrated() const { return migrated_; }
    long rebuilds() const { return rebuilds_; }
    std::size_t ghosts() const { return halo_.ghost_count(); }

private:
    /// One decision for every sub-domain: rebuild when any particle of any has moved half the skin.
    void reneighbour() {
        auto& ps = state_.particles;
        const auto& nb = state_.neighbors;
        const bool stale = !nb.valid_for(ps) ||
                           nb.list().max_displacement2(ps.position(), ps.size(), {}) >= 0.25 * skin_ * skin_;
        if (!comm_.any(stale)) return;
        state_.neighbors.update(ps, radius_, skin_, true);
        halo_.resolve(ps);
    }

    const grit::io::CaseSpec& spec_;
    grit::domain::SlabPartition<Dim> partition_;
    const grit::domain::Comm& comm_;
    grit::sph::Kernel<Dim> kernel_ = grit::sph::CubicSpline<Dim>(1.0);
    grit::sim::RunSetup<Dim> setup_;
    grit::sim::State<Dim> state_;
    std::unique_ptr<grit::modules::SphModule<Dim>> sph_;
    grit::sim::Pipeline pipeline_;
    grit::domain::ProcessHalo<Dim> halo_;
    double radius_ = 0.0, skin_ = 0.0;
    long migrated_ = 0, rebuilds_ = 0;
};

/// The case `file` at `spacing` run `steps` steps in one domain and cut at `cuts` along `axis`.
template <int Dim>
void split_dam_break_matches_one_domain(const std::string& file, double spacing, int steps, int axis,
                                        std::vector<double> cuts) {
    const auto spec = grit::testing::load_case(file, {"numerics.particle_spacing=" + std::to_string(spacing)});

    grit::sim::Simulation<Dim> whole(spec, grit::testing::in_memory());
    const auto initial = whole.particles();
    whole.prime();
    std::vector<double> whole_dt;
    for (int s = 0; s < steps; ++s) {
        whole_dt.push_back(whole.time_step());
        whole.step();
    }
    Snapshot<Dim> expected;
    record<Dim>(whole.particles(), expected);

    const double skin = spec.neighbor_skin * spec.smoothing_ratio * spec.particle_spacing;
    const grit::domain::SlabPartition<Dim> partition{axis, cuts};
    const int ranks = partition.size();
    Snapshot<Dim> got;
    std::vector<std::vector<double>> dts(static_cast<std::size_t>(ranks));
    std::vector<long> migrated(static_cast<std::size_t>(ranks)), rebuilds(static_cast<std::size_t>(ranks));
    std::vector<std::size_t> ghosts(static_cast<std::size_t>(ranks)), owned(static_cast<std::size_t>(ranks));
    std::mutex lock;
    grit::testing::run_loopback(ranks, [&](const grit::domain::Comm& comm) {
        SubDomain<Dim> sub(spec, initial, partition, comm);
        sub.prime();
        const auto r = static_cast<std::size_t>(comm.rank());
        for (int s = 0; s < steps; ++s) {
            dts[r].push_back(sub.dt());
            sub.step();
        }
        Snapshot<Dim> mine;
        record<Dim>(sub.particles(), mine);
        const std::lock_guard guard(lock);
        for (const auto& [id, state] : mine) {
            // Particles migrate at rebuilds: in between, one strays from its slab by less than half the skin.
            EXPECT_LT(partition.distance(state.x, comm.rank()), 0.5 * skin) << "particle " << id << " strayed";
            EXPECT_TRUE(got.emplace(id, state).second) << "particle " << id << " owned twice";
        }
        migrated[r] = sub.migrated();
        rebuilds[r] = sub.rebuilds();
        ghosts[r] = sub.ghosts();
        owned[r] = mine.size();
    });

    long moved = 0;
    for (int r = 0; r < ranks; ++r) {
        const auto k = static_cast<std::size_t>(r);
        moved += migrated[k];
        EXPECT_GT(owned[k], 0u) << "rank " << r;
        EXPECT_GT(ghosts[k], 0u) << "rank " << r;
        EXPECT_EQ(rebuilds[k], rebuilds[0]) << "rank " << r << " rebuilt on its own";
        for (int s = 0; s < steps; ++s)
            EXPECT_NEAR(dts[k][static_cast<std::size_t>(s)], whole_dt[static_cast<std::size_t>(s)],
                        1e-12 * whole_dt[static_cast<std::size_t>(s)])
                << "rank " << r << ", step " << s;
    }
    EXPECT_GT(moved, 0) << "no particle crossed a cut: the test would not see migration";
    EXPECT_GT(rebuilds[0], 5) << "the ghosts were made too few times to test their rebuild";

    // The case's scales: the tank's width, the sound speed, the water's density and rho c0^2.
    const double length = 0.8, c0 = spec.materials[0].sound_speed(), rho0 = spec.materials[0].reference_density();
    ASSERT_EQ(got.size(), expected.size());
    double worst_x = 0.0, worst_v = 0.0, worst_rho = 0.0, worst_p = 0.0;
    for (const auto& [id, e] : expected) {
        const auto it = got.find(id);
        ASSERT_NE(it, got.end()) << "particle " << id << " lost";
        const auto& g = it->second;
        worst_x = std::max(worst_x, grit::core::norm(g.x - e.x) / length);
        worst_v = std::max(worst_v, grit::core::norm(g.v - e.v) / c0);
        worst_rho = std::max(worst_rho, std::abs(g.rho - e.rho) / rho0);
        worst_p = std::max(worst_p, std::abs(g.p - e.p) / (rho0 * c0 * c0));
    }
    EXPECT_LT(worst_x, 1e-12);
    EXPECT_LT(worst_v, 1e-12);
    EXPECT_LT(worst_rho, 1e-12);
    EXPECT_LT(worst_p, 1e-12);
    std::printf("%dD, %d sub-domains, %d steps: %ld migrations, %ld rebuilds; largest differences %.2e (x), %.2e (v), "
                "%.2e (rho), %.2e (p)\n",
                Dim, ranks, steps, moved, rebuilds[0], worst_x, worst_v, worst_rho, worst_p);
}

TEST(SubDomains, DamBreakCutInTwoIsTheOneDomainRun) {
    split_dam_break_matches_one_domain<2>("dambreak_2d/case.toml", 0.01, 2000, 0, {0.1});
}

TEST(SubDomains, DamBreakCutInThreeIsTheOneDomainRun) {
    split_dam_break_matches_one_domain<2>("dambreak_2d/case.toml", 0.01, 2000, 0, {0.07, 0.14});
}

// In 3D, cut across the falling column (the cut is horizontal: the water migrates downwards).
TEST(SubDomains, DamBreak3DCutAcrossTheColumnIsTheOneDomainRun) {
    split_dam_break_matches_one_domain<3>("dambreak_3d/case.toml", 0.02, 500, 2, {0.15});
}

}  // namespace
