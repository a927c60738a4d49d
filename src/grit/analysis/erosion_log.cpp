// Erosion log: records, eroded.csv.
#include "grit/analysis/erosion_log.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "grit/io/csv_file.hpp"

namespace grit::analysis {

template <int Dim>
ErosionRecord erosion_record(const particles::SphParticles<Dim>& ps, Index i, double time, double reference_density) {
    const auto& f = ps.fields();
    ErosionRecord r;
    r.time = time;
    r.id = ps.id()[i];
    r.material = ps.material()[i];
    r.position = core::to_array3(ps.position()[i]);
    r.mass = ps.mass()[i];
    r.plastic_strain = f.template get<double>("plastic_strain").data()[i];
    r.damage = f.template get<double>("damage").data()[i];
    r.pressure = ps.pressure()[i];
    r.von_mises = f.template get<double>("von_mises").data()[i];
    r.triaxiality = r.von_mises > 0.0 ? -r.pressure / r.von_mises : std::numeric_limits<double>::quiet_NaN();
    r.temperature = f.template get<double>("temperature").data()[i];
    r.density = ps.density()[i];
    r.density_ratio = r.density / reference_density;
    r.speed = core::norm(ps.velocity()[i]);
    return r;
}

template ErosionRecord erosion_record<2>(const particles::SphParticles<2>&, Index, double, double);
template ErosionRecord erosion_record<3>(const particles::SphParticles<3>&, Index, double, double);

void ErosionLog::open(const std::filesystem::path& file, int dimension, std::vector<std::string> material_names,
                      long rows) {
    dimension_ = dimension;
    material_names_ = std::move(material_names);
    // A restart keeps the rows its checkpoint had seen; one from a checkpoint older than the log (no rows,
    // no file) starts the file.
    const bool resume = rows > 0 || (rows == 0 && std::filesystem::exists(file));
    const std::string header = std::string("time,id,material,cause,") + (dimension_ == 3 ? "x,y,z," : "x,y,") +
                               "mass,plastic_strain,damage,pressure,von_mises,triaxiality,temperature,density," +
                               "density_ratio,speed,surface";
    io::open_csv_log(file_, file, header, resume ? rows : -1);
    written_ = records_.size();
}

void ErosionLog::flush() {
    if (!file_.is_open()) return;
    for (; written_ < records_.size(); ++written_) {
        const auto& r = records_[written_];
        const auto m = static_cast<std::size_t>(r.material);
        file_ << fmt::format("{:.9g},{},{},{},", r.time, r.id,
                             m < material_names_.size() ? material_names_[m] : std::to_string(r.material), r.cause);
        for (int d = 0; d < dimension_; ++d) file_ << fmt::format("{:.9g},", r.position[static_cast<std::size_t>(d)]);
        file_ << fmt::format("{:.9g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{}\n", r.mass,
                             r.plastic_strain, r.damage, r.pressure, r.von_mises, r.triaxiality, r.temperature,
                             r.density, r.density_ratio, r.speed, r.surface);
    }
    file_.flush();
}

}  // namespace grit::analysis
