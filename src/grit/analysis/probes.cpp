// Probes.
#include "grit/analysis/probes.hpp"

#include <cmath>
#include <limits>

#include "grit/parallel/parallel.hpp"

namespace grit::analysis {

namespace {

template <int Dim>
struct WeightedSum {
    double weight = 0.0, value = 0.0;
    WeightedSum& operator+=(const WeightedSum& o) {
        weight += o.weight;
        value += o.value;
        return *this;
    }
};

}  // namespace

template <int Dim>
ProbeSample sample_probe(const ProbeSpec& probe, const particles::SphParticles<Dim>& ps, const sph::Kernel<Dim>& kernel,
                         const neighbors::PeriodicBox<Dim>& box) {
    using Vec = core::Vec<Dim>;
    const Vec* x = ps.position();
    const auto* phase = ps.phase();
    const std::int32_t fluid = probe.phase;  // the sampled phase (fluid by default)

    if (probe.kind == "front") {
        const double lowest = -std::numeric_limits<double>::infinity();
        const double m = parallel::max(ps.size(), lowest, [&](Index i) {
            if (phase[i] != fluid) return lowest;
            if (probe.has_region)
                for (int k = 0; k < Dim; ++k)
                    if (x[i][k] < probe.min[static_cast<std::size_t>(k)] || x[i][k] > probe.max[static_cast<std::size_t>(k)])
                        return lowest;
            return x[i][probe.axis];
        });
        return {m == lowest ? std::numeric_limits<double>::quiet_NaN() : m, 0.0};
    }

    Vec at{};
    for (int k = 0; k < Dim; ++k) at[k] = probe.position[static_cast<std::size_t>(k)];
    const double* rho = ps.density();
    const double* p = ps.pressure();
    const double* m = ps.mass();
    const Vec* v = ps.velocity();
    const bool periodic = box.any();
    const auto s = std::visit(
        [&](const auto& k) {
            return parallel::sum(ps.size(), WeightedSum<Dim>{}, [&](Index i) {
                WeightedSum<Dim> w;
                if (phase[i] != fluid) return w;
                const double r = core::norm(periodic ? box.nearest_image(at - x[i]) : at - x[i]);
                if (r >= k.support()) return w;
                w.weight = k.value(r) * m[i] / rho[i];
                const double q = probe.quantity == "pressure" ? p[i]
                                 : probe.quantity == "density" ? rho[i]
                                                               : core::norm(v[i]);
                w.value = w.weight * q;
                return w;
            });
        },
        kernel);
    return {s.value, s.weight};
}

double probe_value(const ProbeSpec& probe, const ProbeSample& sample, double spacing) {
    if (probe.kind == "front") return std::isnan(sample.value) ? sample.value : sample.value + 0.5 * spacing;
    return sample.weight > 0.0 ? sample.value / sample.weight : 0.0;
}

template <int Dim>
double evaluate_probe(const ProbeSpec& probe, const particles::SphParticles<Dim>& ps, const sph::Kernel<Dim>& kernel,
                      double spacing, const neighbors::PeriodicBox<Dim>& box) {
    return probe_value(probe, sample_probe(probe, ps, kernel, box), spacing);
}

template double evaluate_probe<2>(const ProbeSpec&, const particles::SphParticles<2>&, const sph::Kernel<2>&, double,
                                  const neighbors::PeriodicBox<2>&);
template double evaluate_probe<3>(const ProbeSpec&, const particles::SphParticles<3>&, const sph::Kernel<3>&, double,
                                  const neighbors::PeriodicBox<3>&);
template ProbeSample sample_probe<2>(const ProbeSpec&, const particles::SphParticles<2>&, const sph::Kernel<2>&,
                                     const neighbors::PeriodicBox<2>&);
template ProbeSample sample_probe<3>(const ProbeSpec&, const particles::SphParticles<3>&, const sph::Kernel<3>&,
                                     const neighbors::PeriodicBox<3>&);

}  // namespace grit::analysis
