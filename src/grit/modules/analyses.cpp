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
#include "grit/core/error.hpp"
#include "grit/io/csv_file.hpp"
#include "grit/io/hdf5_file.hpp"
#include "grit/modules/cracks_table.hpp"
#include "grit/modules/crater_table.hpp"

namespace grit::modules {

namespace {

/// The crater of a 2D run (its profile) or of a 3D run (its map): each sub-domain's bins, combined by
/// their maximum over every sub-domain, then measured (the same on every rank).
template <int Dim>
auto crater_of(const sim::State<Dim>& state, const analysis::CraterRegion& region, double spacing,
               const domain::Comm& comm) {
    auto c = analysis::crater_bins(state.particles, region, spacing);
    comm.max_each(c.surface);
    if constexpr (Dim == 2) analysis::measure_profile(c, region.surface, spacing);
    else analysis::measure_map(c, region.surface, spacing);
    return c;
}

}  // namespace

template <int Dim>
CraterModule<Dim>::CraterModule(const sim::State<Dim>& state, const sim::RunSetup<Dim>& setup)
    : state_(state), setup_(setup), region_(crater_region(setup.spec).value()) {}

template <int Dim>
void CraterModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    // Measured from the combined bins: every sub-domain holds the same values.
    const auto c = crater_of(state_, region_, setup_.spacing, setup_.comm);
    out.push_back(sim::OutputValue::real("crater_depth", c.depth, domain::Combine::same));
    out.push_back(sim::OutputValue::real("crater_width", c.width, domain::Combine::same));
    out.push_back(sim::OutputValue::real("crater_rim_width", c.rim_width, domain::Combine::same));
    out.push_back(sim::OutputValue::real("crater_lip_height", c.lip_height, domain::Combine::same));
    out.push_back(sim::OutputValue::real("crater_area", c.area, domain::Combine::same));
    out.push_back(sim::OutputValue::real("crater_shape_factor", c.shape_factor, domain::Combine::same));
    if constexpr (Dim == 3) out.push_back(sim::OutputValue::real("crater_length", c.length, domain::Combine::same));
}

template <int Dim>
void CraterModule<Dim>::describe(nlohmann::ordered_json& summary) const {
    auto& region = summary["crater_region"];
    region = {{"surface", region_.surface}, {"x_min", region_.x_min}, {"x_max", region_.x_max},
              {"mirror", region_.mirror}};
    if constexpr (Dim == 3) {
        region["y_min"] = region_.y_min;
        region["y_max"] = region_.y_max;
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
    const auto c = crater_of(state_, region_, setup_.spacing, setup_.comm);
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
CracksModule<Dim>::CracksModule(const sim::State<Dim>& state, const sim::RunSetup<Dim>& setup)
    : state_(state), setup_(setup) {
    const double link = crack_options(setup.spec)->link_distance;
    for (int k = 0; k < Dim; ++k)
        if (setup.periodic_box.periodic[k] && !(2.0 * link < setup.periodic_box.length(k)))
            throw core::InputError(fmt::format(
                "key 'cracks.link_distance' = {} m: not less than half the period along the periodic axis {} ({} m): "
                "a damaged particle would link to two images of one; shorten it or lengthen the domain",
                link, "xyz"[k], setup.periodic_box.length(k)));
}

template <int Dim>
void CracksModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    const auto m = analysis::analyse_cracks(state_.particles,
                                            state_.particles.fields().template get<double>("damage").data(),
                                            *crack_options(setup_.spec), setup_.periodic_box);
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
std::vector<double> ProbesModule<Dim>::values() const {
    std::vector<double> sums, fronts;  // [value, weight] of each point probe; the furthest centre of each front
    std::vector<analysis::ProbeSample> samples;
    for (const auto& p : probes_) {
        samples.push_back(analysis::sample_probe(p, state_.particles, setup_.kernel, setup_.periodic_box));
        if (p.kind == "front") {
            fronts.push_back(samples.back().value);
        } else {
            sums.push_back(samples.back().value);
            sums.push_back(samples.back().weight);
        }
    }
    setup_.comm.sum_each(sums);
    setup_.comm.max_each(fronts);
    std::vector<double> out;
    std::size_t s = 0, f = 0;
    for (std::size_t k = 0; k < probes_.size(); ++k) {
        auto& sample = samples[k];
        if (probes_[k].kind == "front") {
            sample.value = fronts[f++];
        } else {
            sample.value = sums[s++];
            sample.weight = sums[s++];
        }
        out.push_back(analysis::probe_value(probes_[k], sample, setup_.spacing));
    }
    return out;
}

template <int Dim>
double ProbesModule<Dim>::value(std::size_t k) const {
    return values().at(k);
}

template <int Dim>
double ProbesModule<Dim>::value(const std::string& name) const {
    for (std::size_t k = 0; k < probes_.size(); ++k)
        if (probes_[k].name == name) return value(k);
    throw std::out_of_range("no probe named '" + name + "'");
}

template <int Dim>
void ProbesModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    const auto v = values();
    for (std::size_t k = 0; k < probes_.size(); ++k) {
        const auto& p = probes_[k];
        const char* unit = p.kind == "front"           ? "m"
                           : p.quantity == "pressure" ? "Pa"
                           : p.quantity == "density"  ? "kg/m^3"
                           : p.quantity == "velocity" ? "m/s"
                                                      : "-";
        // Combined in values(): every sub-domain holds the same value.
        out.push_back(sim::OutputValue::real(p.name, v[k], domain::Combine::same).in_group("probes").in_unit(unit));
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
