// The step pipeline: named stages run in order, each timed by name. Later physics adds stages
// (material update, DEM contacts, coupling) without touching the others.
#pragma once

#include <algorithm>
#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "grit/core/timer.hpp"

namespace grit::sim {

class Pipeline {
public:
    /// Appends a stage.
    void add(std::string name, std::function<void()> run) {
        stages_.push_back({{std::move(name), 0.0, 0}, std::move(run)});
    }
    /// Inserts a stage just before the stage named `before`.
    void insert_before(const std::string& before, std::string name, std::function<void()> run) {
        auto it = std::find_if(stages_.begin(), stages_.end(), [&](const Stage& s) { return s.timer.name == before; });
        if (it == stages_.end()) throw std::logic_error("no stage '" + before + "'");
        stages_.insert(it, {{std::move(name), 0.0, 0}, std::move(run)});
    }
    /// Runs every stage in order.
    void run() {
        for (auto& s : stages_) run_stage(s);
    }
    /// Runs only the named stages, in pipeline order (e.g. the force stages before the first step).
    void run_only(std::initializer_list<const char*> names) {
        for (auto& s : stages_)
            for (const char* n : names)
                if (s.timer.name == n) run_stage(s);
    }
    std::vector<core::TimerEntry> timers() const {
        std::vector<core::TimerEntry> out;
        for (const auto& s : stages_) out.push_back(s.timer);
        return out;
    }

private:
    struct Stage {
        core::TimerEntry timer;
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
