// The run's health: the check after each step (finite, positive density, below numerics.max_speed, inside
// the domain, each module's own), the last good state it keeps, the blow-up report that writes it, and
// whether the run fits this machine before it starts.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "grit/core/error.hpp"
#include "grit/domain/particle_id.hpp"
#include "grit/io/vtu_writer.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sim/geometry.hpp"
#include "grit/sim/named_snapshot.hpp"
#include "grit/sim/run_log.hpp"
#include "grit/sim/simulation.hpp"

namespace grit::sim {

template <int Dim>
std::string Simulation<Dim>::find_unhealthy() const {
    const auto& ps = state_.particles;
    const Vec* x = ps.position();
    const Vec* v = ps.velocity();
    const double* rho = ps.density();
    const double* p = ps.pressure();
    const std::int32_t* ph = ps.phase();
    const auto wall = static_cast<std::int32_t>(Phase::wall);
    const double vmax2 = setup_.max_speed * setup_.max_speed;
    const bool check_domain = !spec_.remove_leaving;
    const Index bad = parallel::first_index(ps.size(), [&](Index i) {
        if (ph[i] == wall || ps.is_image(i)) return false;  // an image is checked as its source
        return !core::all_finite(x[i]) || !core::all_finite(v[i]) || !(rho[i] > 0.0) || !std::isfinite(rho[i]) ||
               !std::isfinite(p[i]) || core::norm2(v[i]) > vmax2 ||
               (check_domain && !inside<Dim>(x[i], spec_.domain_min, spec_.domain_max));
    });
    std::string what;
    if (bad >= 0) {
        if (!core::all_finite(x[bad]))
            what = "position is not finite";
        else if (!core::all_finite(v[bad]))
            what = "velocity is not finite";
        else if (!(rho[bad] > 0.0) || !std::isfinite(rho[bad]))
            what = fmt::format("density = {:.6g} kg/m^3 is not positive and finite", rho[bad]);
        else if (!std::isfinite(p[bad]))
            what = "pressure is not finite";
        else if (core::norm2(v[bad]) > vmax2)
            what = fmt::format("speed = {:.6g} m/s exceeds numerics.max_speed = {:.6g} m/s (runaway)",
                               core::norm(v[bad]), setup_.max_speed);
        else
            what = "escaped the domain (domain.min/domain.max)";
        what = fmt::format("{} particle {} ({}) at ({:.6g}): {}", phase_name(ph[bad]), ps.id()[bad],
                           domain::describe_id(ps.id()[bad]),
                           fmt::join(std::vector<double>(x[bad].c, x[bad].c + Dim), ", "), what);
    }
    for (auto it = modules_.begin(); what.empty() && it != modules_.end(); ++it) what = (*it)->check_health();
    return what;
}

template <int Dim>
void Simulation<Dim>::check_health() {
    const std::string what = find_unhealthy();
    if (!what.empty()) report_blow_up(what);
    const auto& clock = state_.clock;
    if (clock.step % spec_.check_interval == 0) {
        last_good_ = state_.particles;
        last_good_time_ = clock.time;
        last_good_step_ = clock.step;
    }
}

template <int Dim>
void Simulation<Dim>::report_blow_up(const std::string& what) {
    const auto& clock = state_.clock;
    std::string message = fmt::format("numerical blow-up at step {} (t = {:.9g} s): {}", clock.step, clock.time, what);
    if (options_.write_files && has_sph_) {
        const auto file = fmt::format("snapshots/{}_last_good_{:06}.vtu", spec_.name, last_good_step_);
        io::write_vtu(options_.output_dir / file, named_snapshot(last_good_, spec_));
        pvd_->add(last_good_time_, file);
        message += fmt::format("; last good state (step {}, t = {:.9g} s) written to {}", last_good_step_,
                               last_good_time_, (options_.output_dir / file).string());
    }
    blow_up_reported_ = true;
    throw core::BlowUpError(message);
}

template <int Dim>
void Simulation<Dim>::check_plan(RunLog* log) {
    const RunEstimate plan = estimate();
    if (!options_.quiet) fmt::print(stderr, "estimate: {}\n", plan.text());
    if (log) log->info("estimate: " + plan.text());
    std::error_code no_space;
    const double free_bytes =
        options_.write_files ? static_cast<double>(std::filesystem::space(options_.output_dir, no_space).available)
                             : -1.0;
    const MachineMemory memory = machine_memory();
    // A run that cannot fit this machine stops here, not hours in with the kernel's out-of-memory kill.
    if (const std::string why = plan.does_not_fit(spec_, memory.total); !why.empty()) throw core::InputError(why);
    for (const std::string& warning : plan.warnings(spec_, no_space ? -1.0 : free_bytes, memory.available)) {
        if (!options_.quiet) fmt::print(stderr, "{}\n", warning);
        if (log) log->warn(warning);
    }
}

template std::string Simulation<2>::find_unhealthy() const;
template void Simulation<2>::check_health();
template void Simulation<2>::report_blow_up(const std::string&);
template void Simulation<2>::check_plan(RunLog*);
template std::string Simulation<3>::find_unhealthy() const;
template void Simulation<3>::check_health();
template void Simulation<3>::report_blow_up(const std::string&);
template void Simulation<3>::check_plan(RunLog*);

}  // namespace grit::sim
