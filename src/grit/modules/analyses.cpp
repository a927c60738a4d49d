// Crater, cracks, fluid in solids and probes: output values at output times.
#include "grit/modules/analyses.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

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

analysis::CraterRegion crater_region(const io::CaseSpec& spec) {
    return {spec.crater_surface, spec.crater_x_min, spec.crater_x_max, spec.crater_mirror, spec.crater_y_min,
            spec.crater_y_max};
}

/// The crater of a 2D run (its profile) or of a 3D run (its map).
template <int Dim>
auto crater_of(const sim::State<Dim>& state, const io::CaseSpec& spec, double spacing) {
    return analysis::analyse_crater(state.particles, crater_region(spec), spacing);
}

}  // namespace

template <int Dim>
void CraterModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    const auto c = crater_of(state_, setup_.spec, setup_.spacing);
    out.push_back(sim::OutputValue::real("crater_depth", c.depth, domain::Combine::whole_set));
    out.push_back(sim::OutputValue::real("crater_width", c.width, domain::Combine::whole_set));
    out.push_back(sim::OutputValue::real("crater_rim_width", c.rim_width, domain::Combine::whole_set));
    out.push_back(sim::OutputValue::real("crater_lip_height", c.lip_height, domain::Combine::whole_set));
    out.push_back(sim::OutputValue::real("crater_area", c.area, domain::Combine::whole_set));
    out.push_back(sim::OutputValue::real("crater_shape_factor", c.shape_factor, domain::Combine::whole_set));
    if constexpr (Dim == 3) out.push_back(sim::OutputValue::real("crater_length", c.length, domain::Combine::whole_set));
}

template <int Dim>
void CraterModule<Dim>::describe(nlohmann::ordered_json& summary) const {
    const auto& spec = setup_.spec;
    auto& region = summary["crater_region"];
    region = {{"surface", spec.crater_surface}, {"x_min", spec.crater_x_min}, {"x_max", spec.crater_x_max},
              {"mirror", spec.crater_mirror}};
    if constexpr (Dim == 3) {
        region["y_min"] = spec.crater_y_min;
        region["y_max"] = spec.crater_y_max;
    }
}

template <int Dim>
void CraterModule<Dim>::open_output(const sim::OutputPlace& place, bool restart) {
    io::open_csv_log(history_, place.dir / "crater_history.csv", header(),
                     restart && history_restored_ ? history_rows_ : -1);
    if (!(restart && history_restored_)) history_rows_ = 0;
}

template <int Dim>
std::string CraterModule<Dim>::header() {
    return Dim == 2 ? "x,surface,time" : "x,y,surface,time";
}

template <int Dim>
void CraterModule<Dim>::write_output(const sim::OutputPlace& place) {
    const auto c = crater_of(state_, setup_.spec, setup_.spacing);
    // Header first (numpy's genfromtxt(names=True), pandas' read_csv); the time is a column.
    std::string rows;
    const std::string time = fmt::format("{:.9g}", state_.clock.time);
    long count = 0;
    if constexpr (Dim == 2) {
        for (std::size_t b = 0; b < c.x.size(); ++b) rows += fmt::format("{:.9g},{:.9g},{}\n", c.x[b], c.surface[b], time);
        count = static_cast<long>(c.x.size());
    } else {
        for (std::size_t j = 0; j < c.y.size(); ++j)
            for (std::size_t i = 0; i < c.x.size(); ++i)
                rows += fmt::format("{:.9g},{:.9g},{:.9g},{}\n", c.x[i], c.y[j], c.surface[j * c.x.size() + i], time);
        count = static_cast<long>(c.surface.size());
    }
    std::ofstream out(place.dir / "crater.csv");
    out << header() << "\n" << rows;
    if (history_.is_open()) {
        history_ << rows;
        history_.flush();
        history_rows_ += count;
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
    out.push_back(sim::OutputValue::real("damaged_area", m.damaged_area, domain::Combine::sum));
    out.push_back(sim::OutputValue::count("crack_count", static_cast<double>(m.crack_count), domain::Combine::whole_set));
}

template <int Dim>
void FluidInSolidModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    const double reach = std::visit([](const auto& k) { return k.support(); }, setup_.kernel);
    const auto n = analysis::count_fluid_in_solids(state_.particles, reach, setup_.periodic_box);
    out.push_back(sim::OutputValue::count("fluid_in_solid", static_cast<double>(n), domain::Combine::sum));
}

template <int Dim>
ProbesModule<Dim>::ProbesModule(const sim::State<Dim>& state, const sim::RunSetup<Dim>& setup)
    : state_(state), setup_(setup), probes_(setup.spec.template module_spec<ProbesSpec>(ProbesSpec::key)->probes) {}

template <int Dim>
double ProbesModule<Dim>::value(std::size_t k) const {
    return analysis::evaluate_probe(probes_.at(k), state_.particles, setup_.kernel, setup_.spacing, setup_.periodic_box);
}

template <int Dim>
double ProbesModule<Dim>::value(const std::string& name) const {
    for (std::size_t k = 0; k < probes_.size(); ++k)
        if (probes_[k].name == name) return value(k);
    throw std::out_of_range("no probe named '" + name + "'");
}

template <int Dim>
void ProbesModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    for (std::size_t k = 0; k < probes_.size(); ++k) {
        const auto& p = probes_[k];
        const char* unit = p.kind == "front"           ? "m"
                           : p.quantity == "pressure" ? "Pa"
                           : p.quantity == "density"  ? "kg/m^3"
                           : p.quantity == "velocity" ? "m/s"
                                                      : "-";
        out.push_back(sim::OutputValue::real(p.name, value(k), domain::Combine::whole_set).in_group("probes").in_unit(unit));
    }
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
