// Eigenvalues of the Laplace–Beltrami operator on point clouds (beyond the paper; its GFDM
// operators of §4.1): on the unit sphere −Δ_M has the eigenvalues l(l + 1) with
// multiplicity 2l + 1; the first nonzero ones, 2, 6 and 12, are checked within 1 % at
// h = 0.1 (fast: h = 0.2). On the torus (c − √(x² + y²))² + z² = a², c = 3, a = 1, the
// operator separates in the toroidal angle φ and the poloidal angle θ: u = e^{imφ} Θ(θ) with
//   −(1/(a² ρ)) (ρ Θ′)′ + (m²/ρ²) Θ = λ Θ,   ρ = c + a cos θ,
// a periodic Sturm–Liouville problem solved here by second-order finite differences on 400
// and 800 points and Richardson extrapolation (the two differ by less than 1e-4 relative):
// the reference for the cloud's first eigenvalues, checked within 1 %.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "pellicle/geometry/surface_shapes.hpp"
#include "pellicle/surface/frames.hpp"
#include "pellicle/surface/spectrum.hpp"
#include "pellicle/validation/problem.hpp"

namespace pellicle::validation {

namespace {

//! The first `count` eigenvalues of −Δ_M of a cloud sampled on `shape` (the paper's spacing).
SpectrumReport cloud_spectrum(const SurfaceShape<3>& shape, double h, int count,
                              std::size_t& points) {
  const PointSample<3> sample = shape.sample({kPaperSpacingFactor * h, 1});
  PointCloud<3> cloud;
  for (std::size_t i = 0; i < sample.size(); ++i) cloud.add_point(sample.points[i], h, false);
  points = cloud.size();
  NeighbourSearch<3> search;
  NeighbourLists nb;
  SurfaceStencils<3> st;
  search.find(cloud, nb);
  estimate_frames(cloud, nb, FrameOptions{}, false);
  orient_consistently(cloud, nb, &sample.normals);
  build_stencils(cloud, nb, GfdmOptions{}, st);
  refine_normals(cloud, nb, st);
  build_stencils(cloud, nb, GfdmOptions{}, st);
  return laplace_beltrami_spectrum<3>(nb, st, count);
}

//! Eigenvalues of the separated torus problem for one m, on n points in θ.
std::vector<double> torus_mode_eigenvalues(double c, double a, int m, int n) {
  const double d = 2.0 * std::numbers::pi / n;
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(n, n), mass = Eigen::MatrixXd::Zero(n, n);
  const auto rho = [&](double theta) { return c + a * std::cos(theta); };
  for (int k = 0; k < n; ++k) {
    const double theta = k * d, left = rho(theta - 0.5 * d), right = rho(theta + 0.5 * d);
    // −(ρΘ′)′/a² + m²/ρ Θ = λ ρ Θ, symmetric in the weight ρ.
    stiffness(k, k) += (left + right) / (a * a * d * d) + m * m / rho(theta);
    stiffness(k, (k + 1) % n) -= right / (a * a * d * d);
    stiffness(k, (k + n - 1) % n) -= left / (a * a * d * d);
    mass(k, k) = rho(theta);
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(stiffness, mass);
  const Eigen::VectorXd values = solver.eigenvalues();
  return {values.data(), values.data() + values.size()};
}

//! The smallest `count` eigenvalues of −Δ_M on the torus, each m > 0 counted twice (±m).
std::vector<double> torus_reference(double c, double a, int count) {
  std::vector<double> all;
  for (int m = 0; m <= 8; ++m) {
    const auto coarse = torus_mode_eigenvalues(c, a, m, 400);
    const auto fine = torus_mode_eigenvalues(c, a, m, 800);
    for (int k = 0; k < 12; ++k) {
      const double value = (4.0 * fine[k] - coarse[k]) / 3.0;  // Richardson, O(d²)
      for (int copy = 0; copy < (m == 0 ? 1 : 2); ++copy) all.push_back(value);
    }
  }
  std::sort(all.begin(), all.end());
  all.resize(count);
  return all;
}

}  // namespace

Outcome laplace_spectrum(Resolution resolution) {
  const bool full = resolution == Resolution::full;
  Outcome out;
  char line[256];
  // Sphere.
  const double h = full ? 0.1 : 0.2;
  std::size_t points = 0;
  const auto sphere = make_cut_sphere<3>(Vec3::Zero(), 1.0, {});
  const SpectrumReport s = cloud_spectrum(*sphere, h, 16, points);
  std::snprintf(line, sizeof line,
                "\nUnit sphere, h = %g, %zu points (largest imaginary part %.2g)\n\n"
                "| k | λ_k | exact |\n|---|---|---|\n",
                h, points, s.largest_imaginary);
  out.table += line;
  const int degree[16] = {0, 1, 1, 1, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3};
  for (int k = 0; k < 16; ++k) {
    const double exact = degree[k] * (degree[k] + 1.0);
    std::snprintf(line, sizeof line, "| %d | %.5f | %g |\n", k, s.eigenvalues[k], exact);
    out.table += line;
  }
  for (int l : {1, 2, 3}) {
    // The mean over the 2l + 1 copies of l(l + 1).
    const int first = l * l, copies = 2 * l + 1;
    double mean = 0.0;
    for (int k = first; k < first + copies; ++k) mean += s.eigenvalues[k] / copies;
    std::snprintf(line, sizeof line, "sphere, eigenvalue l(l+1) = %d (mean of %d), h = %g",
                  l * (l + 1), copies, h);
    const double exact = l * (l + 1.0);
    out.checks.push_back({line, mean, exact, 0.99 * exact, 1.01 * exact, ""});
  }
  // Torus.
  const double ht = full ? 0.1 : 0.2;
  const auto torus = make_torus_shape(Vec3::Zero(), 3.0, 1.0);
  const SpectrumReport t = cloud_spectrum(*torus, ht, 12, points);
  const std::vector<double> reference = torus_reference(3.0, 1.0, 12);
  std::snprintf(line, sizeof line,
                "\nTorus c = 3, a = 1, h = %g, %zu points (largest imaginary part %.2g)\n\n"
                "| k | λ_k | reference | relative difference |\n|---|---|---|---|\n",
                ht, points, t.largest_imaginary);
  out.table += line;
  for (int k = 1; k < 12; ++k) {
    std::snprintf(line, sizeof line, "| %d | %.5f | %.5f | %.2e |\n", k, t.eigenvalues[k],
                  reference[k], t.eigenvalues[k] / reference[k] - 1.0);
    out.table += line;
    std::snprintf(line, sizeof line, "torus, eigenvalue %d, h = %g", k, ht);
    out.checks.push_back(
        {line, t.eigenvalues[k], reference[k], 0.99 * reference[k], 1.01 * reference[k], ""});
  }
  return out;
}

}  // namespace pellicle::validation
