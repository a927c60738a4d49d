// Single-point driver: integrates a prescribed, constant velocity-gradient history through update_solid_point.
#pragma once

#include <cstddef>
#include <type_traits>
#include <variant>
#include <vector>

#include "grit/core/sym_tensor.hpp"
#include "grit/material/material.hpp"
#include "grit/material/solid_model.hpp"

namespace grit::material {

/// A solid material point and the pressure it is held at.
struct DrivenPoint {
    SolidPointState state;  ///< deviatoric stress, plastic strain, damage, temperature
    double pressure = 0.0;  ///< p [Pa], positive in compression; enters the triaxiality -p / sigma_vm of eq. (35)
};

/// The state at rest of a point of material `m`: zero stress, no plastic strain or damage, T = T0 [K].
inline SolidPointState rest_state(const Material& m) {
    SolidPointState s;
    s.temperature = m.solid.room_temperature;
    return s;
}

/// Drives `point` for `steps` steps of dt [s] under a constant strain rate [1/s] (eq. 31, symmetric part
/// of the velocity gradient) and spin [1/s] (antisymmetric part) at constant pressure, calling
/// update_solid_point (eqs. 30, 32, 36) once per step with the reference density of `m`.
/// Returns the states after every `record_every`-th step, preceded by the initial state, and always
/// ending with the final state: steps / record_every + 1 entries (+1 when record_every does not divide
/// steps). The model is dispatched once (std::visit on m.solid_model), not per step.
inline std::vector<SolidPointState> drive_point(const Material& m, const DrivenPoint& point,
                                                const core::SymTensor3& strain_rate, const Spin& spin, double dt,
                                                int steps, int record_every = 1) {
    if (record_every < 1) record_every = 1;
    std::vector<SolidPointState> history;
    history.reserve(static_cast<std::size_t>(steps > 0 ? steps / record_every + 2 : 1));
    history.push_back(point.state);
    const double density = m.reference_density();
    std::visit(
        [&](const auto& model) {
            SolidPointState s = point.state;
            for (int k = 1; k <= steps; ++k) {
                s = update_solid_point(model, m.solid, s, strain_rate, spin, point.pressure, density, dt);
                // A uniform field's non-local average is the point's own increment.
                if constexpr (std::is_same_v<std::decay_t<decltype(model)>, JohnsonCook>)
                    if (model.nonlocal_damage()) accumulate_ductile_damage(s, s.damage_increment);
                if (k % record_every == 0 || k == steps) history.push_back(s);
            }
        },
        m.solid_model);
    return history;
}

/// As above, starting from rest_state(m) at pressure p [Pa]; returns steps + 1 states (initial first).
inline std::vector<SolidPointState> drive_point(const Material& m, const core::SymTensor3& strain_rate,
                                                const Spin& spin, double pressure, double dt, int steps) {
    return drive_point(m, DrivenPoint{rest_state(m), pressure}, strain_rate, spin, dt, steps);
}

}  // namespace grit::material
