// The grain feed module: grains poured in during the run at a mass flow rate ([[grain_feed]], the
// insertion stream of LIGGGHTS' insert/stream): every interval, the mass due is drawn from the size
// distribution and placed at random, without overlap, in the feed's box.
#pragma once

#include <vector>

#include "grit/sim/module.hpp"

namespace grit::modules {

template <int Dim>
class GrainFeedModule final : public sim::Module<Dim> {
  public:
    /// The grains module must exist (state.grains).
    GrainFeedModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);

    std::string name() const override { return "grain_feed"; }
    void install(sim::Pipeline& pipeline) override;
    /// grains_fed, and grains_not_placed (summary) when a box was too full to take a grain.
    void output_values(std::vector<sim::OutputValue>& out) const override;
    void save(io::Hdf5Group& group) const override;
    void load(const io::Hdf5Group& group) override;

  private:
    void feed();
    /// Insertion `k` of feed `f`: the draws are keyed by (seed, k), so a restart continues them.
    void insert(std::size_t f, std::int64_t k);

    sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    std::vector<std::int64_t> next_;  ///< per feed, the next insertion's index
    std::vector<double> carried_;     ///< per feed, the mass due but not yet inserted [kg]
    std::vector<std::int64_t> fed_;   ///< per feed, grains inserted
    std::int64_t not_placed_ = 0;
};

extern template class GrainFeedModule<2>;
extern template class GrainFeedModule<3>;

}  // namespace grit::modules
