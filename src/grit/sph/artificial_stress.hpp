// Artificial stress against the tensile instability of solid SPH (law only): Monaghan (2000),
// Gray, Monaghan & Swift (2001).
#pragma once

#include <Eigen/Eigenvalues>
#include <cmath>

#include "grit/core/sym_tensor.hpp"

namespace grit::sph {

/// R_a = Q diag(R'_i) Q^T with R'_i = -epsilon sigma'_i / rho^2 for each tensile principal stress
/// sigma'_i > 0 (0 otherwise); the pair term is m_b (R_a + R_b) f_ab^n . grad W with
/// f_ab = W(r_ab) / W(dx) (Gray et al. 2001, eqs. 19-23, epsilon = 0.3, n = 4).
/// `plane` = true takes the principal stresses of the in-plane (x, y) block only (2D, plane strain).
inline core::SymTensor3 artificial_stress(const core::SymTensor3& sigma, double rho, double epsilon, bool plane) {
    const double scale = -epsilon / (rho * rho);
    if (plane) {
        const double c = 0.5 * (sigma.xx + sigma.yy), d = 0.5 * (sigma.xx - sigma.yy);
        const double rad = std::sqrt(d * d + sigma.xy * sigma.xy);
        const double s1 = c + rad, s2 = c - rad;  // principal stresses
        if (s1 <= 0.0) return core::SymTensor3::zero();  // compression: no artificial stress
        const double r1 = scale * s1, r2 = s2 > 0.0 ? scale * s2 : 0.0;
        // Q diag(r1, r2) Q^T through the double angle of the principal axis, cos 2theta = d / rad and
        // sin 2theta = sigma_xy / rad: no trigonometric calls (atan2, sin and cos were 4 % of an AWJ step).
        const double cos2 = rad > 0.0 ? d / rad : 1.0, sin2 = rad > 0.0 ? sigma.xy / rad : 0.0;
        const double mean = 0.5 * (r1 + r2), half_diff = 0.5 * (r1 - r2);
        core::SymTensor3 r = core::SymTensor3::zero();
        r.xx = mean + half_diff * cos2;
        r.yy = mean - half_diff * cos2;
        r.xy = half_diff * sin2;
        return r;
    }
    Eigen::Matrix3d m;
    m << sigma.xx, sigma.xy, sigma.zx, sigma.xy, sigma.yy, sigma.yz, sigma.zx, sigma.yz, sigma.zz;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(m);
    Eigen::Vector3d r = eig.eigenvalues();
    for (int i = 0; i < 3; ++i) r[i] = r[i] > 0.0 ? scale * r[i] : 0.0;
    const Eigen::Matrix3d q = eig.eigenvectors();
    const Eigen::Matrix3d out = q * r.asDiagonal() * q.transpose();
    return {out(0, 0), out(1, 1), out(2, 2), out(0, 1), out(1, 2), out(2, 0)};
}

}  // namespace grit::sph
