// The solid's kernel-gradient correction L = M^-1 (Randles & Libersky 1996; second seed paper eq. 8),
// with M's eigenvalues bounded below so that L stays bounded where a particle has few solid neighbours.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "grit/core/sym_tensor.hpp"

namespace grit::sph {

/// Smallest eigenvalue of the moment matrix M = sum_b V_b grad W (x) (x_b - x_a) taken as it is; below
/// it, the eigenvalue is raised to this value. M is the identity inside a body; its eigenvalues are about
/// 1/2 across a flat free surface and 0.28 at the corners of the AWJ specimens' lattices (0.1 or more at
/// the corners of the jittered test blocks, whose strain rates stay exact). A fragment of two or three
/// particles (copper torn from a crater rim and carried by the water) had 0.075, its pressure swinging
/// between -1.3 and +2.5 GPa every ten steps, then 0.002 as a neighbour left: L amplified the velocity
/// differences 700 times, its density went from 8,700 to 13,000 kg/m^3 in one step and the run blew up
/// (docs/validation.md, "The AWJ on copper beyond 0.4 ms"). With the bound, L amplifies no direction
/// more than 10 times.
inline constexpr double min_moment_eigenvalue = 0.1;

/// L = M^-1 for the symmetric moment matrix `mm` (Dim x Dim of a 3 x 3 array), as a SymTensor3 (zz = 1 in
/// 2D). Where M's smallest eigenvalue is at least min_moment_eigenvalue, the plain inverse (the same
/// bits as without the bound); else V diag(1 / max(lambda_i, min_moment_eigenvalue)) V^T.
template <int Dim>
core::SymTensor3 bounded_correction(const double (&mm)[3][3]) {
    const double floor = min_moment_eigenvalue;
    if constexpr (Dim == 2) {
        const double a = mm[0][0], b = mm[0][1], d = mm[1][1];
        const double mean = 0.5 * (a + d), spread = std::sqrt(0.25 * (a - d) * (a - d) + b * b);
        const double low = mean - spread, high = mean + spread;
        if (low >= floor) {
            const double det = a * d - b * b;
            return {d / det, a / det, 1.0, -b / det, 0.0, 0.0};
        }
        // Unit eigenvector of `high`: (b, high - a) or (high - d, b), whichever is longer.
        double ex = b, ey = high - a;
        if (ex * ex + ey * ey < (high - d) * (high - d) + b * b) {
            ex = high - d;
            ey = b;
        }
        const double norm = std::sqrt(ex * ex + ey * ey);
        if (!(norm > 0.0)) {  // M a multiple of the identity
            const double s = 1.0 / std::max(low, floor);
            return {s, s, 1.0, 0.0, 0.0, 0.0};
        }
        ex /= norm;
        ey /= norm;
        const double s_high = 1.0 / std::max(high, floor), s_low = 1.0 / std::max(low, floor);
        // L = s_high e e^T + s_low (I - e e^T)
        return {s_low + (s_high - s_low) * ex * ex,
                s_low + (s_high - s_low) * ey * ey,
                1.0,
                (s_high - s_low) * ex * ey,
                0.0,
                0.0};
    } else {
        Eigen::Matrix3d m3;
        m3 << mm[0][0], mm[0][1], mm[0][2], mm[1][0], mm[1][1], mm[1][2], mm[2][0], mm[2][1], mm[2][2];
        auto plain_inverse = [&m3]() -> core::SymTensor3 {
            const Eigen::Matrix3d inv = m3.inverse();
            return {inv(0, 0), inv(1, 1), inv(2, 2), inv(0, 1), inv(1, 2), inv(2, 0)};
        };
        // Gershgorin's lower bound of the eigenvalues settles it for almost every particle without the
        // eigen-decomposition (which cost 9 % of the Taylor bar's run when made for each).
        double gershgorin = mm[0][0];
        for (int i = 0; i < 3; ++i)
            gershgorin = std::min(gershgorin, mm[i][i] - std::abs(mm[i][(i + 1) % 3]) - std::abs(mm[i][(i + 2) % 3]));
        if (gershgorin >= floor) return plain_inverse();
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
        eig.computeDirect(m3);
        if (eig.eigenvalues()(0) >= floor) return plain_inverse();
        const Eigen::Vector3d scale = eig.eigenvalues().cwiseMax(floor).cwiseInverse();
        const Eigen::Matrix3d& v = eig.eigenvectors();
        const Eigen::Matrix3d l = v * scale.asDiagonal() * v.transpose();
        return {l(0, 0), l(1, 1), l(2, 2), l(0, 1), l(1, 2), l(2, 0)};
    }
}

/// Whether a particle with correction L (bounded_correction) is on the solid's surface: M's eigenvalues
/// are 1 inside a body and about 1/2 across a flat surface (less at edges, corners and fragments), so
/// tr L is Dim inside and about Dim + 1 at a surface; the threshold Dim + 1/3 is M's normal eigenvalue
/// at 3/4 with the others at 1, between the two and clear of the disorder of a flowing interior.
template <int Dim>
bool at_solid_surface(const core::SymTensor3& l) noexcept {
    const double trace = Dim == 2 ? l.xx + l.yy : l.xx + l.yy + l.zz;  // in 2D, zz is 1, not a direction
    return trace > Dim + 1.0 / 3.0;
}

}  // namespace grit::sph
