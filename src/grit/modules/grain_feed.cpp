// Grain feed module.
#include "grit/modules/grain_feed.hpp"

#include <random>

#include "grit/dem/grain_set.hpp"
#include "grit/domain/particle_id.hpp"

namespace grit::modules {

template <int Dim>
GrainFeedModule<Dim>::GrainFeedModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup)
    : state_(state),
      setup_(setup),
      next_(setup.spec.grain_feeds.size(), 0),
      carried_(setup.spec.grain_feeds.size(), 0.0),
      fed_(setup.spec.grain_feeds.size(), 0) {}

template <int Dim>
void GrainFeedModule<Dim>::install(sim::Pipeline& pipeline) {
    pipeline.add(sim::Hook::boundaries, "grain_feed", [this] { feed(); });
}

template <int Dim>
void GrainFeedModule<Dim>::feed() {
    const auto& feeds = setup_.spec.grain_feeds;
    // Insertions are due at start + k interval; one whose time falls in this step is made now.
    const double now = state_.clock.time + 0.5 * state_.clock.dt;
    for (std::size_t f = 0; f < feeds.size(); ++f) {
        const auto& s = feeds[f];
        for (;;) {
            const double due = s.start + static_cast<double>(next_[f]) * s.interval;
            if (due > now || due > s.stop || (s.count > 0 && fed_[f] >= s.count)) break;
            insert(f, next_[f]++);
        }
    }
}

template <int Dim>
void GrainFeedModule<Dim>::insert(std::size_t f, std::int64_t k) {
    using Vec = core::Vec<Dim>;
    const auto& s = setup_.spec.grain_feeds[f];
    auto& system = *state_.grains;
    const auto& material = system.materials()[static_cast<std::size_t>(s.material)];
    std::mt19937_64 rng(s.seed * 1000003ULL + static_cast<std::uint64_t>(k));
    auto uniform = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    const Vec lo = core::to_vec<Dim>(s.min), hi = core::to_vec<Dim>(s.max), velocity = core::to_vec<Dim>(s.velocity);
    const double largest = dem::largest_diameter(s.size);
    // The grains already near the box, and those placed now: a new grain must not overlap any.
    std::vector<Vec> centre;
    std::vector<double> radius;
    const auto& grains = system.grains();
    for (Index i = 0; i < grains.size(); ++i) {
        bool near = true;
        for (int d = 0; d < Dim; ++d)
            near = near && grains.position()[i][d] > lo[d] - largest && grains.position()[i][d] < hi[d] + largest;
        if (near) {
            centre.push_back(grains.position()[i]);
            radius.push_back(grains.radius()[i]);
        }
    }
    double due = carried_[f] + s.mass_flow_rate * s.interval;
    for (;;) {
        if (s.count > 0 && fed_[f] >= s.count) break;
        const double d = dem::draw_diameter(s.size, rng);
        const double mass = dem::grain_mass<Dim>(material.density, 0.5 * d);
        if (mass > due + 0.5 * mass) break;  // the nearest whole number of grains; the rest is carried
        due -= mass;
        bool placed = false;
        for (int attempt = 0; attempt < 100 && !placed; ++attempt) {
            Vec x;
            for (int a = 0; a < Dim; ++a)
                x[a] = lo[a] + (hi[a] - lo[a]) * uniform();
            placed = true;
            for (std::size_t j = 0; j < centre.size() && placed; ++j) {
                const double reach = 0.5 * d + radius[j];
                placed = core::norm2(x - centre[j]) >= reach * reach;
            }
            if (placed) {
                // The feed's fill number (how many grains it placed before) is the grain's serial.
                const auto id = domain::make_particle_id({domain::IdKind::grain_feed, static_cast<std::int32_t>(f)}, fed_[f]);
                system.inject_grain(id, x, 0.5 * d, s.material, velocity);
                centre.push_back(x);
                radius.push_back(0.5 * d);
                ++fed_[f];
            }
        }
        if (!placed) ++not_placed_;
    }
    carried_[f] = due;
}

template <int Dim>
void GrainFeedModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    std::int64_t fed = 0;
    for (const auto n : fed_)
        fed += n;
    out.push_back(sim::OutputValue::count("grains_fed", static_cast<double>(fed), domain::Combine::sum));
    out.push_back(sim::OutputValue::count("grains_not_placed", static_cast<double>(not_placed_), domain::Combine::sum).summary_only());
}

template <int Dim>
void GrainFeedModule<Dim>::save(io::Hdf5Group& group) const {
    group.write("next", next_.data(), next_.size(), 1);
    group.write("carried", carried_.data(), carried_.size(), 1);
    group.write("fed", fed_.data(), fed_.size(), 1);
    group.write("not_placed", not_placed_);
}

template <int Dim>
void GrainFeedModule<Dim>::load(const io::Hdf5Group& group) {
    std::size_t n = 0;
    next_ = group.read_int64("next", 1, n);
    carried_ = group.read_doubles("carried", 1, n);
    fed_ = group.read_int64("fed", 1, n);
    not_placed_ = group.read_int("not_placed");
}

template class GrainFeedModule<2>;
template class GrainFeedModule<3>;

}  // namespace grit::modules
