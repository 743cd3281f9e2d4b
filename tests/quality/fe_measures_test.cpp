// The FE measures (core/quality/fe_measures.h) against dense computations done here with
// Eigen's dense solvers on matrices assembled independently (barycentric gradients from the
// inverse of the [1 x y z] matrix, not the cross products of p1_system.cpp).
#include "core/quality/fe_measures.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <nlohmann/json.hpp>
#include <random>
#include <vector>

#include "core/quality/element_time_step.h"
#include "core/quality/explicit_time_step.h"
#include "core/quality/p1_system.h"
#include "core/quality/poisson_cg.h"
#include "core/quality/quality_table.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

struct Dense {
  Eigen::MatrixXd K;
  Eigen::VectorXd m;
  std::vector<char> boundary;
};

// Dense K and lumped mass of a simplex mesh of dimension D (elems: (D+1) ids per element).
template <int D>
Dense dense_system(int nv, const std::vector<double>& x, const std::vector<int>& elems) {
  Dense d;
  d.K = Eigen::MatrixXd::Zero(nv, nv);
  d.m = Eigen::VectorXd::Zero(nv);
  d.boundary.assign(nv, 0);
  std::map<std::vector<int>, int> faces;
  for (std::size_t e = 0; e < elems.size() / (D + 1); ++e) {
    Eigen::Matrix<double, D + 1, D + 1> A;
    for (int i = 0; i <= D; ++i) {
      A(i, 0) = 1;
      for (int k = 0; k < D; ++k) A(i, k + 1) = x[D * elems[(D + 1) * e + i] + k];
    }
    // phi_i = c_i . (1, x): the columns of A^-1; gradients = rows 1..D of A^-1.
    const Eigen::Matrix<double, D + 1, D + 1> C = A.inverse();
    double fact = 1;
    for (int k = 2; k <= D; ++k) fact *= k;
    const double vol = std::fabs(A.determinant()) / fact;
    for (int i = 0; i <= D; ++i) {
      const int vi = elems[(D + 1) * e + i];
      d.m(vi) += vol / (D + 1);
      for (int j = 0; j <= D; ++j) {
        const int vj = elems[(D + 1) * e + j];
        d.K(vi, vj) += vol * C.col(i).tail(D).dot(C.col(j).tail(D));
      }
      std::vector<int> f;
      for (int j = 0; j <= D; ++j)
        if (j != i) f.push_back(elems[(D + 1) * e + j]);
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  }
  for (const auto& [f, n] : faces)
    if (n == 1)
      for (int v : f) d.boundary[v] = 1;
  return d;
}

double dense_lambda_max(const Dense& d) {
  const Eigen::VectorXd w = d.m.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd A = w.asDiagonal() * d.K * w.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(A, Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}

TetMesh jittered_cube(int n, double jitter) {
  return testing::delaunay_of_points(testing::cube_lattice(n, jitter));
}

TriMesh2 jittered_square(int n, double jitter) {
  TriMesh2 m;
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool inner = i > 0 && j > 0 && i < n && j < n;
      m.xy.push_back(i + (inner ? u(gen) : 0));
      m.xy.push_back(j + (inner ? u(gen) : 0));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      m.tris.insert(m.tris.end(), {a, b, c, a, c, d});
    }
  m.tri_region.assign(m.tris.size() / 3, 1);
  m.vclass.assign(m.xy.size() / 2, VertexClass{2, 1});
  return m;
}

TEST(FeMeasures, SingleTetGlobalStepIsTheElementStep) {
  TetMesh m = testing::make_tet_mesh({{0, 0, 0}, {1, 0.1, 0}, {0.2, 0.9, 0.1}, {0.3, 0.2, 0.7}},
                                     {{0, 1, 2, 3}});
  const ExplicitTimeStep ts = explicit_time_step(p1_system(m));
  const int* v = &m.tets[0];
  const double dt_e = tet_time_step(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
  EXPECT_GT(dt_e, 0);
  // One element: M_L^-1 K is the element matrix, Irons' bound is an equality.
  EXPECT_NEAR(ts.time_step, dt_e, 1e-9 * dt_e);
  // The dense eigenvalue of the element matrix.
  const Dense d = dense_system<3>(4, m.xyz, m.tets);
  EXPECT_NEAR(dt_e, 2 / std::sqrt(dense_lambda_max(d)), 1e-9 * dt_e);
}

TEST(FeMeasures, TimeStepMatchesTheDenseEigenvalue3D) {
  const TetMesh m = jittered_cube(5, 0.3);
  ASSERT_GT(m.nb_tets(), 300);
  const Dense d = dense_system<3>(m.nb_vertices(), m.xyz, m.tets);
  const double dt_dense = 2 / std::sqrt(dense_lambda_max(d));
  const FeMeasures fe = fe_measures(m);
  ASSERT_TRUE(fe.measured);
  EXPECT_TRUE(fe.converged);
  EXPECT_NEAR(fe.time_step, dt_dense, 1e-3 * dt_dense);
  // Irons: the element bound is a lower bound of the global step.
  EXPECT_LE(fe.element_time_step, fe.time_step * (1 + 1e-12));
  EXPECT_GT(fe.element_time_step, 0);
  // Wave speed c: both steps scale as 1/c.
  FeOptions o;
  o.wave_speed = 2;
  const FeMeasures fe2 = fe_measures(m, o);
  EXPECT_NEAR(fe2.time_step, fe.time_step / 2, 1e-12 * fe.time_step);
  EXPECT_NEAR(fe2.element_time_step, fe.element_time_step / 2, 1e-12 * fe.time_step);
}

TEST(FeMeasures, ElementBoundIsBelowTheGlobalStepOnAGradedMesh) {
  const MeshData d = testing::cube_sphere(0.3, 0.15);
  ASSERT_GT(d.tet.nb_tets(), 100);
  const FeMeasures fe = fe_measures(d.tet);
  ASSERT_TRUE(fe.measured);
  EXPECT_LE(fe.element_time_step, fe.time_step);
  const Dense dn = dense_system<3>(d.tet.nb_vertices(), d.tet.xyz, d.tet.tets);
  const double dt_dense = 2 / std::sqrt(dense_lambda_max(dn));
  EXPECT_NEAR(fe.time_step, dt_dense, 1e-3 * dt_dense);
}

TEST(FeMeasures, CgMatchesADenseSolveAndADensePcg) {
  const TetMesh m = jittered_cube(5, 0.3);
  const P1System s = p1_system(m);
  const Dense d = dense_system<3>(m.nb_vertices(), m.xyz, m.tets);
  ASSERT_EQ(std::vector<char>(s.boundary), d.boundary);
  std::vector<int> free;
  for (int i = 0; i < m.nb_vertices(); ++i)
    if (!d.boundary[i]) free.push_back(i);
  const int nf = static_cast<int>(free.size());
  ASSERT_GT(nf, 20);
  Eigen::MatrixXd Kf(nf, nf);
  Eigen::VectorXd b(nf);
  for (int i = 0; i < nf; ++i) {
    b(i) = d.m(free[i]);
    for (int j = 0; j < nf; ++j) Kf(i, j) = d.K(free[i], free[j]);
  }
  const Eigen::VectorXd xs = Kf.ldlt().solve(b);
  const PoissonCg cg = poisson_cg(s, 1e-8);
  ASSERT_TRUE(cg.converged);
  Eigen::VectorXd x(nf);
  for (int i = 0; i < nf; ++i) x(i) = cg.x[free[i]];
  // The residual of our solution with the dense matrix is what CG reports, below the tolerance.
  const double res = (b - Kf * x).norm() / b.norm();
  EXPECT_LE(res, 1e-8);
  EXPECT_NEAR(res, cg.residual, 1e-3 * res + 1e-14);
  EXPECT_LE((x - xs).norm(), 1e-6 * xs.norm());
  for (int i = 0; i < m.nb_vertices(); ++i)
    if (d.boundary[i]) EXPECT_EQ(cg.x[i], 0.0);
  // A dense Jacobi-PCG to the same tolerance needs the same number of iterations (+-1 for
  // rounding at the threshold), and one iteration fewer leaves a residual above it.
  const Eigen::VectorXd dinv = Kf.diagonal().cwiseInverse();
  Eigen::VectorXd xd = Eigen::VectorXd::Zero(nf), r = b, z = dinv.cwiseProduct(r), p = z;
  int it = 0;
  double rz = r.dot(z);
  while (r.norm() > 1e-8 * b.norm() && it < 10000) {
    const Eigen::VectorXd q = Kf * p;
    const double alpha = rz / p.dot(q);
    xd += alpha * p;
    r -= alpha * q;
    z = dinv.cwiseProduct(r);
    const double rz2 = r.dot(z);
    p = z + rz2 / rz * p;
    rz = rz2;
    ++it;
  }
  EXPECT_NEAR(cg.iterations, it, 1);
  EXPECT_GT(poisson_cg(s, 1e-8, cg.iterations - 1).residual, 1e-8);
  // The condition estimate: cond(D^-1 K) from the dense eigenvalues of D^-1/2 K D^-1/2.
  const Eigen::VectorXd w = dinv.cwiseSqrt();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(w.asDiagonal() * Kf * w.asDiagonal(),
                                                    Eigen::EigenvaluesOnly);
  const double kappa = es.eigenvalues().maxCoeff() / es.eigenvalues().minCoeff();
  EXPECT_NEAR(cg.condition, kappa, 0.05 * kappa);
}

TEST(FeMeasures, TrianglesMatchTheDenseEigenvalue2D) {
  const TriMesh2 m = jittered_square(14, 0.3);
  const Dense d = dense_system<2>(m.nb_vertices(), m.xy, m.tris);
  const double dt_dense = 2 / std::sqrt(dense_lambda_max(d));
  const FeMeasures fe = fe_measures(m);
  ASSERT_TRUE(fe.measured);
  EXPECT_NEAR(fe.time_step, dt_dense, 1e-3 * dt_dense);
  EXPECT_LE(fe.element_time_step, fe.time_step);
  EXPECT_GT(fe.cg_iterations, 5);
  // One triangle: the element step is the global one.
  TriMesh2 one;
  one.xy = {0, 0, 1, 0.2, 0.3, 0.8};
  one.tris = {0, 1, 2};
  const ExplicitTimeStep ts = explicit_time_step(p1_system(one));
  const double dt_e = tri_time_step(&one.xy[0], &one.xy[2], &one.xy[4]);
  EXPECT_NEAR(ts.time_step, dt_e, 1e-9 * dt_e);
  EXPECT_LT(tri_time_step(&one.xy[0], &one.xy[4], &one.xy[2]), 0);
}

TEST(FeMeasures, TimeStepScalesWithTheMesh) {
  TetMesh m = jittered_cube(4, 0.25);
  const FeMeasures a = fe_measures(m);
  for (double& x : m.xyz) x *= 0.01;
  const FeMeasures b = fe_measures(m);
  EXPECT_NEAR(b.time_step, 0.01 * a.time_step, 1e-3 * b.time_step);
  EXPECT_NEAR(b.element_time_step, 0.01 * a.element_time_step, 1e-9 * b.element_time_step);
  // CG on -Lap u = 1 is scale-invariant up to the scaling of b: the same count.
  EXPECT_NEAR(b.cg_iterations, a.cg_iterations, 1);
}

TEST(FeMeasures, TableRowsAndJsonKeys) {
  const TetMesh m = jittered_cube(3, 0.2);
  QualityTable t;
  t.columns.push_back(quality_stats(m, "a"));
  set_fe_measures(t.columns.back(), fe_measures(m));
  t.columns.push_back(quality_stats(m, "b"));  // not measured
  FeOptions off;
  off.mode = "off";
  EXPECT_FALSE(fe_measures(m, off).measured);
  const auto j = nlohmann::json::parse(t.to_json());
  for (const char* k : {"time_step", "element_time_step", "cg_iterations", "stiffness_condition"}) {
    ASSERT_TRUE(j[0].contains(k)) << k;
    EXPECT_TRUE(j[0][k].is_number()) << k;
    EXPECT_TRUE(j[1][k].is_null()) << k;
  }
  EXPECT_GT(j[0]["time_step"].get<double>(), 0);
  const std::string text = t.to_text();
  EXPECT_NE(text.find("time step"), std::string::npos);
  EXPECT_NE(text.find("CG iterations"), std::string::npos);
  FeOptions bad;
  bad.mode = "sometimes";
  EXPECT_THROW(fe_measures(m, bad), std::invalid_argument);
}

}  // namespace
}  // namespace cvtmesh
