// The artificial stress of Gray, Monaghan & Swift (2001): R = Q diag(R'_i) Q^T with R'_i = -eps sigma'_i /
// rho^2 for tensile principal stresses only. The plane (2D) form, written without trigonometric calls,
// is checked against a uniaxial tension along a rotated axis (exact) and against the 3D eigen-solver
// path on in-plane stress states.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "grit/sph/artificial_stress.hpp"

namespace {

using grit::core::SymTensor3;
using grit::sph::artificial_stress;

TEST(ArtificialStress, UniaxialTensionAlongARotatedAxis) {
    // sigma = s n n^T with n at 30 degrees: R = -eps s / rho^2 n n^T.
    const double s = 2.0e8, rho = 8960.0, eps = 0.3, theta = std::numbers::pi / 6.0;
    const double c = std::cos(theta), n = std::sin(theta);
    const SymTensor3 sigma{s * c * c, s * n * n, 0.0, s * c * n, 0.0, 0.0};
    const SymTensor3 r = artificial_stress(sigma, rho, eps, true);
    const double r1 = -eps * s / (rho * rho);
    EXPECT_NEAR(r.xx, r1 * c * c, 1e-12 * std::abs(r1));
    EXPECT_NEAR(r.yy, r1 * n * n, 1e-12 * std::abs(r1));
    EXPECT_NEAR(r.xy, r1 * c * n, 1e-12 * std::abs(r1));
}

TEST(ArtificialStress, ZeroUnderCompressionAndIsotropicUnderEqualTension) {
    const SymTensor3 compressed{-1.0e8, -3.0e8, 0.0, 5.0e7, 0.0, 0.0};
    const SymTensor3 r = artificial_stress(compressed, 8960.0, 0.3, true);
    EXPECT_EQ(r.xx, 0.0);
    EXPECT_EQ(r.yy, 0.0);
    EXPECT_EQ(r.xy, 0.0);
    // Equal principal stresses: no principal axis (rad = 0), R = R' I.
    const SymTensor3 equal{1.0e8, 1.0e8, 0.0, 0.0, 0.0, 0.0};
    const SymTensor3 q = artificial_stress(equal, 1000.0, 0.3, true);
    EXPECT_DOUBLE_EQ(q.xx, -0.3 * 1.0e8 / 1.0e6);
    EXPECT_DOUBLE_EQ(q.yy, q.xx);
    EXPECT_EQ(q.xy, 0.0);
}

TEST(ArtificialStress, PlaneFormMatchesTheEigenSolverOnInPlaneStates) {
    // With no out-of-plane shear and sigma_zz in compression, the 3D path's principal stresses are the
    // in-plane ones and sigma_zz (which adds nothing): both forms must give the same in-plane R.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < 200; ++k) {
        const SymTensor3 sigma{3e8 * u(rng), 3e8 * u(rng), -1e9, 3e8 * u(rng), 0.0, 0.0};
        const SymTensor3 plane = artificial_stress(sigma, 2650.0, 0.3, true);
        const SymTensor3 full = artificial_stress(sigma, 2650.0, 0.3, false);
        const double scale = 0.3 * 6e8 / (2650.0 * 2650.0);
        EXPECT_NEAR(plane.xx, full.xx, 1e-9 * scale) << k;
        EXPECT_NEAR(plane.yy, full.yy, 1e-9 * scale) << k;
        EXPECT_NEAR(plane.xy, full.xy, 1e-9 * scale) << k;
        EXPECT_NEAR(full.zz, 0.0, 1e-9 * scale) << k;
    }
}

}  // namespace
