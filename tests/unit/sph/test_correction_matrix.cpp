// The solid's kernel correction with M's eigenvalues bounded below (sph/correction_matrix.hpp).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "grit/sph/correction_matrix.hpp"
#include "grit/sph/kernels.hpp"

namespace {

using grit::core::SymTensor3;
using grit::sph::at_solid_surface;
using grit::sph::bounded_correction;
using grit::sph::min_moment_eigenvalue;

Eigen::Matrix3d full(const SymTensor3& l) {
    Eigen::Matrix3d m;
    m << l.xx, l.xy, l.zx, l.xy, l.yy, l.yz, l.zx, l.yz, l.zz;
    return m;
}

/// R diag(eigenvalues) R^T as the 3 x 3 array bounded_correction takes, R a rotation by `angle` about z
/// and then about x (2D: about z only, the third row and column 0).
void rotated(const Eigen::Vector3d& eigenvalues, double angle, bool three_d, double (&mm)[3][3]) {
    Eigen::Matrix3d r = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    if (three_d) r = Eigen::AngleAxisd(0.7 * angle, Eigen::Vector3d::UnitX()).toRotationMatrix() * r;
    Eigen::Vector3d lambda = eigenvalues;
    if (!three_d) lambda(2) = 0.0;
    const Eigen::Matrix3d m = r * lambda.asDiagonal() * r.transpose();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            mm[i][j] = m(i, j);
}

}  // namespace

// Inside a body and at its surfaces (eigenvalues 1 and 1/2) L is M^-1: in 2D the same bits as the plain
// inverse the solid sums used before the bound.
TEST(BoundedCorrection, WellConditionedIsThePlainInverse) {
    double mm[3][3];
    rotated({1.05, 0.5, 0.8}, 0.4, false, mm);
    const double det = mm[0][0] * mm[1][1] - mm[0][1] * mm[1][0];
    const SymTensor3 l2 = bounded_correction<2>(mm);
    EXPECT_EQ(l2.xx, mm[1][1] / det);
    EXPECT_EQ(l2.yy, mm[0][0] / det);
    EXPECT_EQ(l2.xy, -mm[0][1] / det);
    EXPECT_EQ(l2.zz, 1.0);
    rotated({1.05, 0.5, 0.8}, 0.4, true, mm);
    Eigen::Matrix3d m3;
    m3 << mm[0][0], mm[0][1], mm[0][2], mm[1][0], mm[1][1], mm[1][2], mm[2][0], mm[2][1], mm[2][2];
    const Eigen::Matrix3d inv = m3.inverse();
    const SymTensor3 l3 = bounded_correction<3>(mm);
    // (3D: within 4 ulp; the same Eigen inverse may be contracted differently in another translation unit.)
    EXPECT_DOUBLE_EQ(l3.xx, inv(0, 0));
    EXPECT_DOUBLE_EQ(l3.yz, inv(1, 2));
    EXPECT_DOUBLE_EQ(l3.zx, inv(2, 0));
}

// A fragment: M's eigenvalues 0.9 and 0.01 (3D: 0.9, 0.6, 0.003). L keeps M's eigenvectors, inverts the
// eigenvalues above the bound and amplifies the others by 1 / min_moment_eigenvalue = 10, not 100 or more.
TEST(BoundedCorrection, FewNeighboursAmplifyNoMoreThanTheBound) {
    for (const bool three_d : {false, true}) {
        SCOPED_TRACE(three_d ? "3D" : "2D");
        double mm[3][3];
        const Eigen::Vector3d lambda(0.9, three_d ? 0.6 : 0.01, three_d ? 0.003 : 0.0);
        rotated(lambda, 1.1, three_d, mm);
        const SymTensor3 l = three_d ? bounded_correction<3>(mm) : bounded_correction<2>(mm);
        Eigen::Matrix3d expected_l;
        {
            Eigen::Matrix3d r = Eigen::AngleAxisd(1.1, Eigen::Vector3d::UnitZ()).toRotationMatrix();
            if (three_d) r = Eigen::AngleAxisd(0.77, Eigen::Vector3d::UnitX()).toRotationMatrix() * r;
            Eigen::Vector3d s;
            for (int i = 0; i < 3; ++i)
                s(i) = 1.0 / std::max(lambda(i), min_moment_eigenvalue);
            if (!three_d) s(2) = 1.0;
            expected_l = r * s.asDiagonal() * r.transpose();
        }
        const Eigen::Matrix3d got = full(l);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                EXPECT_NEAR(got(i, j), expected_l(i, j), 1e-12) << i << "," << j;
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(got);
        EXPECT_NEAR(eig.eigenvalues().maxCoeff(), 1.0 / min_moment_eigenvalue, 1e-12);
    }
}

// The bound is continuous: just above and just below it, L differs by the change of M alone.
TEST(BoundedCorrection, ContinuousAcrossTheBound) {
    double above[3][3], below[3][3];
    rotated({0.9, min_moment_eigenvalue * (1.0 + 1e-9), 0.0}, 0.3, false, above);
    rotated({0.9, min_moment_eigenvalue * (1.0 - 1e-9), 0.0}, 0.3, false, below);
    const Eigen::Matrix3d a = full(bounded_correction<2>(above)), b = full(bounded_correction<2>(below));
    EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-7);
    // An isolated particle (M = 0) gets I / min_moment_eigenvalue, finite.
    const double zero[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    const SymTensor3 l = bounded_correction<2>(zero);
    EXPECT_EQ(l.xx, 1.0 / min_moment_eigenvalue);
    EXPECT_EQ(l.yy, 1.0 / min_moment_eigenvalue);
    EXPECT_EQ(l.xy, 0.0);
}

namespace {

/// L of the particle at lattice site (i, j) (3D: (i, j, k)) of a block of n^Dim particles at spacing 1
/// (volume 1 each), from the cubic spline at h = 1.25 (the cases' h / dx), as the solid sums build it.
template <int Dim>
SymTensor3 lattice_correction(int n, const int (&site)[3]) {
    const grit::sph::CubicSpline<Dim> kernel(1.25);
    double mm[3][3] = {};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < (Dim == 3 ? n : 1); ++k) {
                const double xab[3] = {double(site[0] - i), double(site[1] - j), Dim == 3 ? double(site[2] - k) : 0.0};
                const double r = std::sqrt(xab[0] * xab[0] + xab[1] * xab[1] + xab[2] * xab[2]);
                if (r == 0.0) continue;
                const double f = kernel.gradient_factor(r);  // grad_a W_ab = x_ab f, and x_b - x_a = -x_ab
                for (int a = 0; a < Dim; ++a)
                    for (int b = 0; b < Dim; ++b) mm[a][b] -= f * xab[a] * xab[b];
            }
    return bounded_correction<Dim>(mm);
}

}  // namespace

// The surface test that bounds eq. (35)'s triaxiality: on a lattice block, the particles of the outer
// layer (faces, edges, corners) are on the surface, those one spacing in and deeper are not (M's normal
// eigenvalue there is within a few per cent of 1: the kernel reaches 2.5 spacings).
TEST(SolidSurface, OuterLayerOfALatticeBlockOnly) {
    const int n = 9;
    struct Site {
        int ijk[3];
        bool surface;
    };
    for (const Site s : {Site{{4, 4, 4}, false}, Site{{4, 1, 4}, false}, Site{{1, 1, 4}, false}, Site{{4, 0, 4}, true},
                         Site{{0, 0, 4}, true}, Site{{0, 4, 4}, true}, Site{{8, 8, 4}, true}}) {
        SCOPED_TRACE(testing::Message() << s.ijk[0] << "," << s.ijk[1]);
        EXPECT_EQ(at_solid_surface<2>(lattice_correction<2>(n, s.ijk)), s.surface);
        EXPECT_EQ(at_solid_surface<3>(lattice_correction<3>(n, s.ijk)), s.surface);
    }
    const int face[3] = {4, 4, 0}, edge[3] = {0, 4, 0}, inside[3] = {4, 4, 1};
    EXPECT_TRUE(at_solid_surface<3>(lattice_correction<3>(n, face)));
    EXPECT_TRUE(at_solid_surface<3>(lattice_correction<3>(n, edge)));
    EXPECT_FALSE(at_solid_surface<3>(lattice_correction<3>(n, inside)));
    // A flat surface's M: eigenvalues 1 and about 1/2; a fragment's is bounded and on the surface too.
    double mm[3][3];
    rotated({1.0, 0.5, 1.0}, 0.3, false, mm);
    EXPECT_TRUE(at_solid_surface<2>(bounded_correction<2>(mm)));
    rotated({1.0, 0.8, 1.0}, 0.3, false, mm);
    EXPECT_FALSE(at_solid_surface<2>(bounded_correction<2>(mm)));
    rotated({0.9, 0.01, 0.0}, 0.3, false, mm);
    EXPECT_TRUE(at_solid_surface<2>(bounded_correction<2>(mm)));
}
