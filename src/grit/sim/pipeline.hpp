// The step pipeline: named stages at named hook points, run in hook order (and, within a hook, in the
// order the modules installed them), each timed by name. A module adds its stages at its hooks without
// touching the others'.
#pragma once

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "grit/core/timer.hpp"

namespace grit::sim {

/// The hook points of one time step, in the order they run.
enum class Hook {
    begin_step,  ///< first half of the integrator (predict to the whole step)
    boundaries,  ///< particles enter and leave (inlets, outlets)
    neighbors,   ///< neighbour lists
    pressure,    ///< equations of state
    pre_force,   ///< what the force sums read (wall pressure, per-step scratch)
    force,       ///< the SPH sums
    post_force,  ///< forces between particle sets (grain contact, coupling), then the grains' step
    integrate,   ///< second half of the integrator
    end_step,    ///< material updates, removals
    check,       ///< health check and the next time step (the Simulation's own)
};

class Pipeline {
public:
    /// Adds a stage at `hook`, after the stages already there. `prime`: it also runs before the first
    /// step to compute the rates of the initial state (pressures and forces, the first time step).
    void add(Hook hook, std::string name, std::function<void()> run, bool prime = false) {
        if (has(name)) throw std::logic_error("stage '" + name + "' installed twice");
        auto it = std::find_if(stages_.begin(), stages_.end(), [&](const Stage& s) { return s.hook > hook; });
        stages_.insert(it, {{std::move(name), 0.0, 0}, hook, prime, std::move(run)});
    }
    bool has(const std::string& name) const {
        return std::any_of(stages_.begin(), stages_.end(), [&](const Stage& s) { return s.timer.name == name; });
    }
    /// Runs every stage in order.
    void run() {
        for (auto& s : stages_) run_stage(s);
    }
    /// Runs the stages marked `prime`, in pipeline order.
    void run_prime() {
        for (auto& s : stages_)
            if (s.prime) run_stage(s);
    }
    std::vector<core::TimerEntry> timers() const {
        std::vector<core::TimerEntry> out;
        for (const auto& s : stages_) out.push_back(s.timer);
        return out;
    }
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto& s : stages_) out.push_back(s.timer.name);
        return out;
    }

private:
    struct Stage {
        core::TimerEntry timer;
        Hook hook;
        bool prime;
        std::function<void()> run;
    };
    static void run_stage(Stage& s) {
        core::Stopwatch w;
        s.run();
        s.timer.seconds += w.seconds();
        ++s.timer.calls;
    }
    std::vector<Stage> stages_;
};

}  // namespace grit::sim
