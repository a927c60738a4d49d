// Crater, cracks, fluid in solids and probes: output values at output times.
#include "grit/modules/analyses.hpp"

#include <fmt/format.h>

#include <fstream>
#include <variant>

#include "grit/analysis/cracks.hpp"
#include "grit/analysis/crater.hpp"
#include "grit/analysis/fluid_in_solid.hpp"
#include "grit/analysis/probes.hpp"
#include "grit/io/csv_file.hpp"
#include "grit/io/hdf5_file.hpp"

namespace grit::modules {

namespace {

template <int Dim>
analysis::CraterProfile crater_of(const sim::State<Dim>& state, const io::CaseSpec& spec, double spacing) {
    if constexpr (Dim == 2)
        return analysis::analyse_crater(state.particles, {spec.crater_surface, spec.crater_x_min, spec.crater_x_max, spec.crater_mirror},
                                        spacing);
    else
        return {};  // the crater profile is 2D; the 3D kerf analysis comes with the 3D AWJ case
}

}  // namespace

template <int Dim>
void CraterModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    const auto c = crater_of(state_, setup_.spec, setup_.spacing);
    out.push_back(sim::OutputValue::real("crater_depth", c.depth));
    out.push_back(sim::OutputValue::real("crater_width", c.width));
    out.push_back(sim::OutputValue::real("crater_rim_width", c.rim_width));
    out.push_back(sim::OutputValue::real("crater_lip_height", c.lip_height));
}

template <int Dim>
void CraterModule<Dim>::open_output(const sim::OutputPlace& place, bool restart) {
    io::open_csv_log(history_, place.dir / "crater_history.csv", "x,surface,time",
                     restart && history_restored_ ? history_rows_ : -1);
    if (!(restart && history_restored_)) history_rows_ = 0;
}

template <int Dim>
void CraterModule<Dim>::write_output(const sim::OutputPlace& place) {
    const auto c = crater_of(state_, setup_.spec, setup_.spacing);
    // Header first (numpy's genfromtxt(names=True), pandas' read_csv); the time is a column.
    std::string rows;
    const std::string time = fmt::format("{:.9g}", state_.clock.time);
    for (std::size_t b = 0; b < c.x.size(); ++b) rows += fmt::format("{:.9g},{:.9g},{}\n", c.x[b], c.surface[b], time);
    std::ofstream out(place.dir / "crater.csv");
    out << "x,surface,time\n" << rows;
    if (history_.is_open()) {
        history_ << rows;
        history_.flush();
        history_rows_ += static_cast<long>(c.x.size());
    }
}

template <int Dim>
void CraterModule<Dim>::save(io::Hdf5Group& group) const {
    group.write("crater_history_rows", static_cast<std::int64_t>(history_rows_));
}

template <int Dim>
void CraterModule<Dim>::load(const io::Hdf5Group& group) {
    history_restored_ = group.has_attribute("crater_history_rows");
    history_rows_ = history_restored_ ? static_cast<long>(group.read_int("crater_history_rows")) : 0;
}

template <int Dim>
void CracksModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    const auto& spec = setup_.spec;
    const auto m = analysis::analyse_cracks(
        state_.particles, state_.particles.fields().template get<double>("damage").data(),
        {spec.crack_damage_threshold, spec.crack_link_distance, spec.crack_min_particles});
    out.push_back(sim::OutputValue::real("damaged_area", m.damaged_area));
    out.push_back(sim::OutputValue::count("crack_count", static_cast<double>(m.crack_count)));
}

template <int Dim>
void FluidInSolidModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    const double reach = std::visit([](const auto& k) { return k.support(); }, setup_.kernel);
    const auto n = analysis::count_fluid_in_solids(state_.particles, reach, setup_.periodic_box);
    out.push_back(sim::OutputValue::count("fluid_in_solid", static_cast<double>(n)));
}

template <int Dim>
double ProbesModule<Dim>::value(std::size_t k) const {
    return analysis::evaluate_probe(setup_.spec.probes[k], state_.particles, setup_.kernel, setup_.spacing,
                                    setup_.periodic_box);
}

template <int Dim>
void ProbesModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    for (std::size_t k = 0; k < setup_.spec.probes.size(); ++k)
        out.push_back(sim::OutputValue::real(setup_.spec.probes[k].name, value(k)).in_group("probes"));
}

template class CraterModule<2>;
template class CraterModule<3>;
template class CracksModule<2>;
template class CracksModule<3>;
template class FluidInSolidModule<2>;
template class FluidInSolidModule<3>;
template class ProbesModule<2>;
template class ProbesModule<3>;

}  // namespace grit::modules
