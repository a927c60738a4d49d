// ThinWallsModule: the fluid particles' wall normals, refreshed before each neighbour-list build.
#include "grit/modules/thin_walls.hpp"

#include <variant>

#include "grit/parallel/parallel.hpp"

namespace grit::modules {

template <int Dim>
ThinWallsModule<Dim>::ThinWallsModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup) : state_(state) {
    using Vec = core::Vec<Dim>;
    state.particles.fields().template add<Vec>(normal_field, Vec::zero(), true);
    state.particles.fields().template add<std::int32_t>(far_field, 0, true);
    if constexpr (Dim == 3) {
        // A fluid particle needs its normal wherever a wall particle of a thin wall may be in its list:
        // within the wall's thickness of the sheet, plus the list radius.
        const double skin = setup.spec.neighbor_skin * setup.smoothing_length;
        const double support = std::visit([](const auto& k) { return k.support(); }, setup.kernel);
        for (const auto& w : setup.spec.walls) {
            if (!w.shape.thin) continue;
            // The water is in front of the facets when the particles go behind them.
            walls_.push_back(
                {std::make_unique<mesh::SignedDistance>(*w.shape.mesh, false), w.shape.side == "back" ? 1.0 : -1.0});
            walls_.back().sheet->bin(w.shape.layers * setup.spacing + support + skin, 0.25);
        }
        state.neighbors.separate_sides(normal_field, far_field, far_cos,
                                       [this](particles::SphParticles<Dim>& ps) { refresh(ps); });
    }
}

template <int Dim>
void ThinWallsModule<Dim>::install(sim::Pipeline& /*pipeline*/) {}

template <int Dim>
void ThinWallsModule<Dim>::refresh(particles::SphParticles<Dim>& particles) {
    using Vec = core::Vec<Dim>;
    if constexpr (Dim == 3) {
        const Vec* x = particles.position();
        const std::int32_t* phase = particles.phase();
        Vec* normal = particles.fields().template get<Vec>(normal_field).data();
        const auto fluid = static_cast<std::int32_t>(Phase::fluid);
        parallel::for_each(particles.size(), [&](Index i) {
            if (phase[i] != fluid) return;
            // The normal at the closest point of the nearest thin wall within reach, turned to its water.
            // Of two walls on one sheet (a membrane, water on both sides), the one whose water the
            // particle is in. A particle behind a one-sided sheet (water pressed into a splitter's cusp)
            // gets none, so that it sees every wall particle round it, both sides' far walls too: of the
            // rules tried this let the least water into the cusp (docs/theory.md "Thin walls").
            double best = std::numeric_limits<double>::infinity();
            bool best_wet = false;
            Vec n = Vec::zero();
            for (const auto& wall : walls_) {
                const auto q = wall.sheet->query_near(x[i]);
                const double d = std::abs(q.distance);
                const bool wet = q.distance * wall.water >= 0.0;
                if (d < best || (d == best && wet && !best_wet)) {
                    best = d, best_wet = wet;
                    n = wet ? q.normal * wall.water : Vec::zero();
                }
            }
            normal[i] = n;
        });
    } else {
        (void)particles;
    }
}

template <int Dim>
void ThinWallsModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    // From the field (saved in checkpoints), so a restarted run reports what the straight one does.
    using Vec = core::Vec<Dim>;
    const auto& ps = state_.particles;
    const Vec* normal = ps.fields().template get<Vec>(normal_field).data();
    const std::int32_t* phase = ps.phase();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);
    const Index near = parallel::reduce(
        ps.size(), Index{0}, [&](Index i) -> Index { return phase[i] == fluid && core::norm2(normal[i]) > 0.0; },
        [](Index a, Index b) { return a + b; });
    out.push_back(sim::OutputValue::count("fluid_near_thin_walls", static_cast<double>(near), domain::Combine::sum).summary_only());
}

template class ThinWallsModule<2>;
template class ThinWallsModule<3>;

}  // namespace grit::modules
