// Every shape function, 2D and 3D: partition of unity Σ N_i = 1 and Σ ∇N_i = 0 at arbitrary
// positions, and linear completeness Σ N_i x_i = x (what makes uniform strain exact).
#include <gtest/gtest.h>

#include <random>

#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/shape/kernels.hpp"
#include "pellicle/mpm/shape/stencil.hpp"

namespace pellicle {
namespace {

template <int D, class Kernel>
void check_kernel(const Kernel& kernel) {
  FaceConditions<D> free;
  free.fill(FaceCondition::free);
  const Grid<D> grid(Vec<D>::Zero(), Vec<D>::Constant(1.0), 0.1, free);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    Vec<D> x;
    for (int d = 0; d < D; ++d) x[d] = u(rng);
    if (trial < D) x[trial] = 0.3;  // exactly on a node line
    Stencil<D, Kernel> s;
    compute_stencil(kernel, grid, x, s);
    double sum = 0.0;
    Vec<D> grad_sum = Vec<D>::Zero(), first_moment = Vec<D>::Zero();
    Mat<D> grad_moment = Mat<D>::Zero();
    for_each_node(s, grid.strides(), [&](long node, double N, const Vec<D>& g, const IVec<D>&) {
      sum += N;
      grad_sum += g;
      first_moment += N * grid.node_position(node);
      grad_moment += grid.node_position(node) * g.transpose();
      EXPECT_GE(N, -1e-15);
    });
    EXPECT_NEAR(sum, 1.0, 1e-12) << Kernel::name << " at " << x.transpose();
    EXPECT_LT(grad_sum.norm(), 1e-12 / grid.cell()) << Kernel::name;
    EXPECT_LT((first_moment - x).norm(), 1e-12) << Kernel::name;
    EXPECT_LT((grad_moment - Mat<D>::Identity()).norm(), 1e-10) << Kernel::name;
  }
}

TEST(Kernels, LinearPartitionOfUnity2D) {
  check_kernel<2>(shape::Linear{});
}
TEST(Kernels, LinearPartitionOfUnity3D) {
  check_kernel<3>(shape::Linear{});
}
TEST(Kernels, UGimpPartitionOfUnity2D) {
  check_kernel<2>(shape::UGimp{0.25});
}
TEST(Kernels, UGimpPartitionOfUnity3D) {
  check_kernel<3>(shape::UGimp{1.0 / 6.0});
}
TEST(Kernels, QuadraticBSplinePartitionOfUnity2D) {
  check_kernel<2>(shape::QuadraticBSpline{});
}
TEST(Kernels, QuadraticBSplinePartitionOfUnity3D) {
  check_kernel<3>(shape::QuadraticBSpline{});
}
TEST(Kernels, CubicBSplinePartitionOfUnity2D) {
  check_kernel<2>(shape::CubicBSpline{});
}
TEST(Kernels, CubicBSplinePartitionOfUnity3D) {
  check_kernel<3>(shape::CubicBSpline{});
}

// The derivative each kernel returns is the derivative of its weight (central differences).
template <class Kernel>
void check_derivative(const Kernel& kernel) {
  constexpr int W = Kernel::width;
  for (double xi = 3.013; xi < 5.0; xi += 0.0917) {
    double w[W], dw[W], wp[W], dwp[W], wm[W], dwm[W];
    const double eps = 1e-6;
    const int base = kernel.fill(xi, w, dw);
    ASSERT_EQ(kernel.fill(xi + eps, wp, dwp), base);
    ASSERT_EQ(kernel.fill(xi - eps, wm, dwm), base);
    for (int a = 0; a < W; ++a)
      EXPECT_NEAR(dw[a], (wp[a] - wm[a]) / (2 * eps), 1e-7) << Kernel::name;
  }
}

TEST(Kernels, DerivativesMatchWeights) {
  check_derivative(shape::Linear{});
  check_derivative(shape::UGimp{0.25});
  check_derivative(shape::QuadraticBSpline{});
  check_derivative(shape::CubicBSpline{});
}

}  // namespace
}  // namespace pellicle
