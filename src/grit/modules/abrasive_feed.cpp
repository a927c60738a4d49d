// Abrasive feed module.
#include "grit/modules/abrasive_feed.hpp"

#include "grit/domain/particle_id.hpp"

namespace grit::modules {

template <int Dim>
AbrasiveFeedModule<Dim>::AbrasiveFeedModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup)
    : state_(state),
      setup_(setup),
      inlet_(setup.spec.abrasive, setup.spec.inlets[static_cast<std::size_t>(setup.spec.abrasive.inlet)]) {}

template <int Dim>
void AbrasiveFeedModule<Dim>::install(sim::Pipeline& pipeline) {
    pipeline.add(sim::Hook::boundaries, "abrasive_feed", [this] { feed(); });
}

template <int Dim>
void AbrasiveFeedModule<Dim>::feed() {
    const auto material = static_cast<std::int32_t>(setup_.spec.abrasive.material);
    for (const auto& g : inlet_.emit(state_.clock.time, state_.clock.dt)) {
        // One grain per column: the column's index is its serial.
        state_.grains->inject_grain(domain::make_particle_id({domain::IdKind::abrasive_feed, 0}, g.column), g.position,
                                    0.5 * g.diameter, material, g.velocity);
        ++injected_;
    }
}

template <int Dim>
void AbrasiveFeedModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    const auto& a = setup_.spec.abrasive;
    out.push_back(sim::OutputValue::count("grains_injected", static_cast<double>(injected_), domain::Combine::sum));
    out.push_back(sim::OutputValue::real("abrasive_mass_flow_rate", a.mass_flow_rate, domain::Combine::same).summary_only());
    out.push_back(sim::OutputValue::real("abrasive_spacing", a.spacing, domain::Combine::same).summary_only());
    out.push_back(sim::OutputValue::real("abrasive_volume_fraction", a.volume_fraction, domain::Combine::same).summary_only());
}

template <int Dim>
void AbrasiveFeedModule<Dim>::save(io::Hdf5Group& group) const {
    group.write("next_column", inlet_.next_column());
    group.write("injected", injected_);
}

template <int Dim>
void AbrasiveFeedModule<Dim>::load(const io::Hdf5Group& group) {
    inlet_.set_next_column(group.read_int("next_column"));
    injected_ = group.read_int("injected");
}

template class AbrasiveFeedModule<2>;
template class AbrasiveFeedModule<3>;

}  // namespace grit::modules
