// Products of a SymTensor3 with Vec<Dim> over the Dim in-plane components only. In 2D (plane strain)
// the out-of-plane rows of stresses, corrections and velocity gradients meet a zero gradient, so the
// pair loops spend no flops on them; sigma_zz itself still lives in the tensor for the yield laws.
#pragma once

#include "grit/core/sym_tensor.hpp"
#include "grit/core/vec.hpp"
#include "grit/material/solid_model.hpp"

namespace grit::sph {

/// t . g over the first Dim rows and columns.
template <int Dim>
inline core::Vec<Dim> dot(const core::SymTensor3& t, const core::Vec<Dim>& g) noexcept {
    core::Vec<Dim> r;
    if constexpr (Dim == 2) {
        r[0] = t.xx * g[0] + t.xy * g[1];
        r[1] = t.xy * g[0] + t.yy * g[1];
    } else {
        r[0] = t.xx * g[0] + t.xy * g[1] + t.zx * g[2];
        r[1] = t.xy * g[0] + t.yy * g[1] + t.yz * g[2];
        r[2] = t.zx * g[0] + t.yz * g[1] + t.zz * g[2];
    }
    return r;
}

/// s += sym(u (x) c): the symmetric part of one pair's velocity-gradient contribution.
template <int Dim>
inline void add_symmetric_outer(core::SymTensor3& s, const core::Vec<Dim>& u, const core::Vec<Dim>& c) noexcept {
    s.xx += u[0] * c[0];
    s.yy += u[1] * c[1];
    s.xy += 0.5 * (u[0] * c[1] + u[1] * c[0]);
    if constexpr (Dim == 3) {
        s.zz += u[2] * c[2];
        s.yz += 0.5 * (u[1] * c[2] + u[2] * c[1]);
        s.zx += 0.5 * (u[2] * c[0] + u[0] * c[2]);
    }
}

/// w += skew(u (x) c): the antisymmetric part (spin, eq. 31).
template <int Dim>
inline void add_skew_outer(material::Spin& w, const core::Vec<Dim>& u, const core::Vec<Dim>& c) noexcept {
    w.xy += 0.5 * (u[0] * c[1] - u[1] * c[0]);
    if constexpr (Dim == 3) {
        w.yz += 0.5 * (u[1] * c[2] - u[2] * c[1]);
        w.zx += 0.5 * (u[2] * c[0] - u[0] * c[2]);
    }
}

}  // namespace grit::sph
