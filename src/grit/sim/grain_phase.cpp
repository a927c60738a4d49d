// Grains in a run: set-up from the case, coupling, impact log and output.
#include "grit/sim/grain_phase.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "grit/core/error.hpp"
#include "grit/dem/grain_fill.hpp"
#include "grit/io/vtu_writer.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::sim {

namespace {

using core::to_vec;

// Bits of the per-grain `contact_targets` field: plane walls 0..27, SPH walls 28, SPH solids 29.
constexpr int max_planes = 28;
constexpr std::int32_t sph_wall_bit = 1 << 28, sph_solid_bit = 1 << 29;

// Angle between a relative velocity and the surface whose normal is n (any length) [deg]: 90 for a
// normal impact.
template <int Dim>
double impact_angle(const core::Vec<Dim>& v, const core::Vec<Dim>& n) {
    const double speed = core::norm(v), length = core::norm(n);
    if (!(speed > 0.0) || !(length > 0.0)) return 90.0;
    return std::asin(std::min(1.0, std::abs(core::dot(v, n)) / (speed * length))) * 180.0 / std::numbers::pi;
}

}  // namespace

template <int Dim>
GrainPhase<Dim>::GrainPhase(const io::CaseSpec& spec) {
    dem::DemParameters<Dim> p;
    p.contact_law = spec.dem.contact_law;
    p.gravity = to_vec<Dim>(spec.gravity);
    p.skin = spec.dem.skin;
    for (int k = 0; k < Dim; ++k) p.domain.periodic[k] = spec.dem.periodic[static_cast<std::size_t>(k)];
    p.domain.lower = to_vec<Dim>(spec.domain_min);
    p.domain.upper = to_vec<Dim>(spec.domain_max);
    system_ = std::make_unique<dem::DemSystem<Dim>>(p, spec.grain_materials);
    system_->grains().fields().template add<std::int32_t>("contact_targets", 0, false);

    if (static_cast<int>(spec.grain_walls.size()) > max_planes)
        throw core::InputError(fmt::format("key 'grain_wall': at most {} plane walls", max_planes));
    for (const auto& w : spec.grain_walls) {
        system_->add_wall({to_vec<Dim>(w.point), to_vec<Dim>(w.normal), w.material});
        wall_names_.push_back(w.name);
    }
    for (const auto& b : spec.grains) {
        std::vector<dem::GrainSeed<Dim>> seeds;
        if (b.arrangement == "single") {
            std::mt19937_64 rng(b.seed);
            seeds.push_back({to_vec<Dim>(b.position), dem::draw_diameter(b.size, rng)});
        } else if (b.arrangement == "lattice") {
            seeds = dem::lattice_fill<Dim>(to_vec<Dim>(b.min), to_vec<Dim>(b.max), b.spacing, b.size, b.seed, b.jitter);
        } else {
            seeds = dem::random_fill<Dim>(to_vec<Dim>(b.min), to_vec<Dim>(b.max), static_cast<std::size_t>(b.count),
                                          b.size, b.seed);
            if (seeds.size() < static_cast<std::size_t>(b.count))
                throw core::InputError(fmt::format("{}: only {} of count = {} grains fit in the box without overlap",
                                                   b.key, seeds.size(), b.count));
        }
        if (seeds.empty()) throw core::InputError(fmt::format("{}: the arrangement holds no grain", b.key));
        for (const auto& s : seeds) {
            for (int k = 0; k < Dim; ++k)
                if (!spec.dem.periodic[static_cast<std::size_t>(k)] &&
                    (s.position[k] < spec.domain_min[static_cast<std::size_t>(k)] ||
                     s.position[k] > spec.domain_max[static_cast<std::size_t>(k)]))
                    throw core::InputError(fmt::format(
                        "{}: a grain at ({}) lies outside the domain (domain.min/domain.max); enlarge the domain",
                        b.key, fmt::join(std::vector<double>(s.position.c, s.position.c + Dim), ", ")));
            system_->add_grain(s.position, 0.5 * s.diameter, b.material, to_vec<Dim>(b.velocity));
        }
    }

    coupling::PenaltyContactParameters c;
    c.spacing = spec.particle_spacing;
    c.overlap_coefficient = spec.dem.overlap_coefficient;
    c.friction = spec.dem.solid_friction >= 0.0 ? spec.dem.solid_friction
                                                : spec.grain_materials[static_cast<std::size_t>(spec.grains.front().material)].friction;
    contact_ = coupling::GrainBoundaryContact<Dim>(c);
}

template <int Dim>
void GrainPhase<Dim>::prime() {
    system_->compute_forces(0.0);
}

template <int Dim>
void GrainPhase<Dim>::couple(double time, particles::SphParticles<Dim>& particles, const std::int32_t* fixed,
                             double dt, const std::vector<material::Material>& materials) {
    auto& grains = system_->grains();
    contact_.compute(grains, particles, dt);
    contact_.apply(grains, particles, fixed);

    // First contacts with SPH solids and walls. A target counts as left only when no particle of it is
    // near (2 d_ini) any more, so a grain rattling on a surface logs one impact. The record's normal is
    // the sum of the normals of the step's contacts (two particles touched symmetrically give the
    // surface normal, not the direction to either of them).
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
            impacts_.push_back(
                {time, grains.id()[g], target, core::norm(vrel), impact_angle<Dim>(vrel, normal[2 * gi + kind])});
        }
        // Bits stay set while the target is near; new contacts set them.
        mask[g] = (mask[g] & ~(sph_wall_bit | sph_solid_bit)) | (mask[g] & near[gi]) | touching[gi];
    }
}

template <int Dim>
void GrainPhase<Dim>::advance(double time, double dt, bool first_step) {
    if (!first_step) system_->end_step(dt);
    system_->begin_step(dt);

    // First contacts with the plane walls, at the new positions.
    auto& grains = system_->grains();
    std::int32_t* mask = grains.fields().template get<std::int32_t>("contact_targets").data();
    const auto& walls = system_->walls();
    const Vec* x = grains.position();
    const Vec* v = grains.velocity();
    const double* r = grains.radius();
    for (Index g = 0; g < grains.size(); ++g) {
        for (std::size_t w = 0; w < walls.size(); ++w) {
            const std::int32_t bit = 1 << w;
            const bool touching = core::dot(x[g] - walls[w].point, walls[w].normal) < r[g];
            if (touching && !(mask[g] & bit))
                impacts_.push_back({time + dt, grains.id()[g], wall_names_[w], core::norm(v[g]),
                                    impact_angle<Dim>(v[g], walls[w].normal)});
            mask[g] = touching ? (mask[g] | bit) : (mask[g] & ~bit);
        }
    }
}

template <int Dim>
double GrainPhase<Dim>::stable_time_step() const {
    return system_->stable_time_step();
}

template <int Dim>
std::string GrainPhase<Dim>::check(const std::vector<double>& domain_min, const std::vector<double>& domain_max) const {
    const auto& grains = system_->grains();
    const Vec* x = grains.position();
    const Vec* v = grains.velocity();
    const auto& periodic = system_->parameters().domain.periodic;
    const Index bad = parallel::first_index(grains.size(), [&](Index i) {
        if (!core::all_finite(x[i]) || !core::all_finite(v[i])) return true;
        for (int k = 0; k < Dim; ++k)
            if (!periodic[k] && (x[i][k] < domain_min[static_cast<std::size_t>(k)] ||
                                 x[i][k] > domain_max[static_cast<std::size_t>(k)]))
                return true;
        return false;
    });
    if (bad < 0) return {};
    const std::string what = !core::all_finite(x[bad]) ? "position is not finite"
                             : !core::all_finite(v[bad]) ? "velocity is not finite"
                                                         : "escaped the domain (domain.min/domain.max)";
    return fmt::format("grain {} at ({:.6g}): {}", grains.id()[bad],
                       fmt::join(std::vector<double>(x[bad].c, x[bad].c + Dim), ", "), what);
}

template <int Dim>
typename GrainPhase<Dim>::Vec GrainPhase<Dim>::momentum() const {
    const auto& grains = system_->grains();
    const Vec* v = grains.velocity();
    const double* m = grains.mass();
    Vec p = Vec::zero();
    for (int k = 0; k < Dim; ++k) p[k] = parallel::sum(grains.size(), 0.0, [&](Index i) { return m[i] * v[i][k]; });
    return p;
}

template <int Dim>
void GrainPhase<Dim>::open_output(const std::filesystem::path& dir, const std::string& name) {
    namespace fs = std::filesystem;
    fs::create_directories(dir / "grains");
    for (const auto& e : fs::directory_iterator(dir / "grains"))
        if (e.path().extension() == ".vtu") fs::remove(e.path());
    pvd_ = std::make_unique<io::PvdWriter>(dir / (name + "_grains.pvd"));
    impacts_file_.open(dir / "impacts.csv");
    impacts_file_ << "time,grain,target,speed,angle\n";
    impacts_written_ = impacts_.size();
}

template <int Dim>
void GrainPhase<Dim>::write_snapshot(const std::filesystem::path& dir, const std::string& name, double time) {
    const auto file = fmt::format("grains/{}_grains_{:06}.vtu", name, snapshot_index_++);
    io::write_vtu(dir / file, system_->grains().snapshot());
    pvd_->add(time, file);
}

template <int Dim>
void GrainPhase<Dim>::flush_impacts() {
    if (!impacts_file_.is_open()) return;
    for (; impacts_written_ < impacts_.size(); ++impacts_written_) {
        const auto& r = impacts_[impacts_written_];
        impacts_file_ << fmt::format("{:.9g},{},{},{:.9g},{:.6g}\n", r.time, r.grain, r.target, r.speed, r.angle);
    }
    impacts_file_.flush();
}

template class GrainPhase<2>;
template class GrainPhase<3>;

}  // namespace grit::sim
