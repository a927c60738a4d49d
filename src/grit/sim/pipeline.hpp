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
    post_force,  ///< forces between particle sets (grain contact, coupling)
    grain_motion,     ///< the grains' kicks (the step before's second half, this one's first) and drift
    grain_neighbors,  ///< the grains' lists, when a grain has moved more than half the skin
    grain_force,      ///< the grains' contact forces at their new positions, and what reads them
    integrate,   ///< second half of the integrator
    end_step,    ///< material updates, removals
    check,       ///< health check and the next time step (the Simulation's own)
};

/// The name of a hook point, as `grit check --pipeline` prints it.
inline const char* hook_name(Hook h) {
    switch (h) {
        case Hook::begin_step: return "begin_step";
        case Hook::boundaries: return "boundaries";
        case Hook::neighbors: return "neighbors";
        case Hook::pressure: return "pressure";
        case Hook::pre_force: return "pre_force";
        case Hook::force: return "force";
        case Hook::post_force: return "post_force";
        case Hook::grain_motion: return "grain_motion";
        case Hook::grain_neighbors: return "grain_neighbors";
        case Hook::grain_force: return "grain_force";
        case Hook::integrate: return "integrate";
        case Hook::end_step: return "end_step";
        case Hook::check: return "check";
    }
    return "unknown";
}

/// One stage as installed: where it runs, its name, the module that installed it, and whether it primes.
struct StageInfo {
    Hook hook;
    std::string name;
    std::string module;
    bool prime;
};

class Pipeline {
public:
    /// The module whose stages the next add() calls install (the Simulation sets it around each install()).
    void set_installer(std::string module) { installer_ = std::move(module); }
    /// Adds a stage at `hook`, after the stages already there. `prime`: it also runs before the first
    /// step to compute the rates of the initial state (pressures and forces, the first time step).
    void add(Hook hook, std::string name, std::function<void()> run, bool prime = false) {
        if (has(name)) throw std::logic_error("stage '" + name + "' installed twice");
        auto it = std::find_if(stages_.begin(), stages_.end(), [&](const Stage& s) { return s.hook > hook; });
        Stage stage;
        stage.timer.name = std::move(name);
        stage.hook = hook;
        stage.prime = prime;
        stage.module = installer_;
        stage.run = std::move(run);
        stages_.insert(it, std::move(stage));
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
    /// Every stage in the order a step runs them.
    std::vector<StageInfo> stages() const {
        std::vector<StageInfo> out;
        for (const auto& s : stages_) out.push_back({s.hook, s.timer.name, s.module, s.prime});
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
        Hook hook = Hook::begin_step;
        bool prime = false;
        std::string module;
        std::function<void()> run;
    };
    static void run_stage(Stage& s) {
        core::Stopwatch w;
        s.run();
        s.timer.seconds += w.seconds();
        ++s.timer.calls;
    }
    std::vector<Stage> stages_;
    std::string installer_;
};

}  // namespace grit::sim
