// The case's particle blocks laid out as lattices with their starting state.
#include "grit/sim/particle_blocks.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "grit/core/error.hpp"
#include "grit/material/equation_of_state.hpp"
#include "grit/modules/thin_walls.hpp"
#include "grit/sim/geometry.hpp"
#include "grit/sim/initial_velocity.hpp"
#include "grit/sim/named_snapshot.hpp"

namespace grit::sim {

namespace {

template <int Dim>
void add_block(const io::CaseSpec& spec, const io::BlockSpec& b, domain::IdSource source, Phase phase, double dx,
               particles::SphParticles<Dim>& particles, const LatticeFilter<Dim>& keep) {
    using Vec = core::Vec<Dim>;
    WallNormals<Dim> normals;  // thin walls: each particle's wall normal (ThinWallsModule)
    const auto points = lattice_points<Dim>(b.shape, dx, &normals);
    if (points.empty())
        throw core::InputError(
            fmt::format("{}: the shape holds no particle at numerics.particle_spacing = {} m", b.key, dx));
    const auto& mat = spec.materials[static_cast<std::size_t>(b.material)];
    const double rho0 = mat.reference_density();
    const double cell_volume = std::pow(dx, Dim);
    const Vec g = core::to_vec<Dim>(spec.gravity);
    const double g_norm = core::norm(g);
    // Hydrostatic start: p = rho0 |g| depth below the block's free surface (its highest point).
    double top = 0.0;
    if (b.hydrostatic && g_norm > 0.0) {
        top = -1e300;
        for (const auto& x : points)
            top = std::max(top, -core::dot(g, x) / g_norm);
        top += 0.5 * dx;
    }
    // A lattice point's index in its block is its serial, kept or not: the ids of a part are those of
    // the whole block.
    std::vector<std::int64_t> serials;
    serials.reserve(points.size());
    for (std::size_t k = 0; k < points.size(); ++k)
        if (!keep || keep(points[k])) serials.push_back(static_cast<std::int64_t>(k));
    const Index first = particles.append(source, serials);
    double* p = particles.pressure();
    for (std::size_t s = 0; s < serials.size(); ++s) {
        const auto k = static_cast<std::size_t>(serials[s]);
        const Index i = first + static_cast<Index>(s);
        Vec v = phase != Phase::wall ? core::to_vec<Dim>(b.velocity) : Vec::zero();
        if (b.velocity_profile == "cantilever_mode")
            v[1] += b.mode_tip_velocity * cantilever_mode_shape(points[k][0] - b.mode_origin, b.mode_length) /
                    cantilever_mode_shape(b.mode_length, b.mode_length);
        else if (b.velocity_profile == "longitudinal_wave")
            v[b.wave_axis] += b.wave_amplitude * std::sin(2.0 * std::numbers::pi * points[k][b.wave_axis] / b.wave_length);
        p[i] = b.hydrostatic && g_norm > 0.0 ? rho0 * g_norm * (top - (-core::dot(g, points[k]) / g_norm)) : 0.0;
        particles.start(i, points[k], v, material::density_from_pressure(mat.eos, p[i]), rho0 * cell_volume, phase,
                        b.material);
    }
    if (!normals.normal.empty()) {
        auto& fields = particles.fields();
        Vec* n = fields.template get<Vec>(modules::ThinWallsModule<Dim>::normal_field).data();
        std::int32_t* far = fields.template get<std::int32_t>(modules::ThinWallsModule<Dim>::far_field).data();
        for (std::size_t s = 0; s < serials.size(); ++s) {
            n[first + static_cast<Index>(s)] = normals.normal[static_cast<std::size_t>(serials[s])];
            far[first + static_cast<Index>(s)] = normals.far_side[static_cast<std::size_t>(serials[s])];
        }
    }
}

}  // namespace

template <int Dim>
void add_particle_blocks(const io::CaseSpec& spec, double dx, particles::SphParticles<Dim>& particles,
                         const LatticeFilter<Dim>& keep) {
    auto add_all = [&](const std::vector<io::BlockSpec>& blocks, domain::IdKind kind, Phase phase) {
        for (std::size_t k = 0; k < blocks.size(); ++k)
            add_block(spec, blocks[k], {kind, static_cast<std::int32_t>(k)}, phase, dx, particles, keep);
    };
    add_all(spec.fluids, domain::IdKind::fluid_block, Phase::fluid);
    add_all(spec.solids, domain::IdKind::solid_block, Phase::solid);
    add_all(spec.walls, domain::IdKind::wall_block, Phase::wall);
}

template <int Dim>
void check_and_wrap_into_domain(const io::CaseSpec& spec, const neighbors::PeriodicBox<Dim>& box,
                                particles::SphParticles<Dim>& particles) {
    auto* x = particles.position();
    for (Index i = 0; i < particles.size(); ++i)
        if (!inside<Dim>(x[i], spec.domain_min, spec.domain_max))
            throw core::InputError(fmt::format(
                "key 'domain.min'/'domain.max': a {} particle at ({}) lies outside the domain; enlarge the domain",
                phase_name(particles.phase()[i]), fmt::join(std::vector<double>(x[i].c, x[i].c + Dim), ", ")));
    if (box.any())
        for (Index i = 0; i < particles.size(); ++i) x[i] = box.wrap(x[i]);
}

template void add_particle_blocks<2>(const io::CaseSpec&, double, particles::SphParticles<2>&,
                                     const LatticeFilter<2>&);
template void add_particle_blocks<3>(const io::CaseSpec&, double, particles::SphParticles<3>&,
                                     const LatticeFilter<3>&);
template void check_and_wrap_into_domain<2>(const io::CaseSpec&, const neighbors::PeriodicBox<2>&,
                                            particles::SphParticles<2>&);
template void check_and_wrap_into_domain<3>(const io::CaseSpec&, const neighbors::PeriodicBox<3>&,
                                            particles::SphParticles<3>&);

}  // namespace grit::sim
