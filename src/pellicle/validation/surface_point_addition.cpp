// Curvature-corrected addition of points (Suchde & Kuhnert §3.4.1 and §3.7.4, Table 1,
// Figure 11): a cloud spaced for h0 on the unit sphere and on the torus c = 3, a = 1 (eq 14)
// has its smoothing length halved, and the hole filling refines it to about four times the
// points; the error of the added points is the mean of |‖x‖² − 1| (eq 13) or of eq 15. Three
// placements: the circumcentre (no correction), the paper's eqs 6–9 as printed, and the
// midway rule (surface/management.hpp). The paper: the corrected error about half the
// uncorrected one, both converging faster than O(h²). Measured: eqs 8–9 put the point as far
// outside the surface as the circumcentre lies inside (their error equals the uncorrected
// one, order 2), so the paper's finding is not reproduced with them; the midway rule is
// exact to leading order. Checked: the uncorrected error converges at order 2 (± 0.3); the
// midway error is below half the uncorrected one and converges faster than h² (order > 2.5;
// leading-order exactness makes it 4); the eqs 6–9 column is reported.
#include <cmath>
#include <cstdio>

#include "pellicle/geometry/surface_shapes.hpp"
#include "pellicle/surface/frames.hpp"
#include "pellicle/surface/gfdm.hpp"
#include "pellicle/surface/management.hpp"
#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/surface_support.hpp"

namespace pellicle::validation {

namespace {

//! The density the filling itself leaves, about 3.4 points per h²: spacing 0.52 h.
constexpr double kManagedSpacing = 0.52;

struct Addition {
  std::size_t before = 0, after = 0;
  double error[3] = {0, 0, 0};  //!< circumcentre, eqs 6–9, midway
};

Addition refine(const SurfaceShape<3>& shape, double h0) {
  Addition out;
  for (int rule = 0; rule < 3; ++rule) {
    const PointSample<3> sample = shape.sample({kManagedSpacing * h0, 1});
    PointCloud<3> cloud;
    for (const auto& x : sample.points) cloud.add_point(x, h0, false);
    NeighbourSearch<3> search;
    NeighbourLists nb;
    SurfaceStencils<3> st;
    search.find(cloud, nb, 1.0, 10);
    estimate_frames(cloud, nb, FrameOptions{}, false);
    orient_consistently(cloud, nb, &sample.normals);
    build_stencils(cloud, nb, GfdmOptions{}, st);
    refine_normals(cloud, nb, st);
    out.before = cloud.size();
    for (double& h : cloud.smoothing_length) h = 0.5 * h0;
    ManagementOptions options;
    options.curvature_correction = rule > 0;
    options.curvature_rule = rule == 2 ? CurvatureRule::midway : CurvatureRule::tangent_planes;
    const ManagementReport report = manage_points(cloud, search, options, FrameOptions{});
    double sum = 0.0;
    for (std::size_t i = cloud.size() - report.added; i < cloud.size(); ++i)
      sum += shape.surface_error(cloud.position[i]);
    out.error[rule] = report.added ? sum / report.added : 0.0;
    out.after = cloud.size();
  }
  return out;
}

void table(Outcome& out, const char* name, const SurfaceShape<3>& shape,
           const std::vector<double>& h0s) {
  std::vector<Addition> rows;
  for (double h0 : h0s) rows.push_back(refine(shape, h0));
  char line[256];
  std::snprintf(line, sizeof line,
                "\n%s: error of the added points (orders)\n\n| h0 | points before → after | "
                "circumcentre | eqs 6–9 | midway |\n|---|---|---|---|---|\n",
                name);
  out.table += line;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto& r = rows[k];
    std::string orders[3];
    for (int rule = 0; rule < 3; ++rule)
      if (k > 0) {
        char text[32];
        std::snprintf(text, sizeof text, " (%.2f)",
                      std::log2(rows[k - 1].error[rule] / r.error[rule]));
        orders[rule] = text;
      }
    std::snprintf(line, sizeof line, "| %g | %zu → %zu | %.3g%s | %.3g%s | %.3g%s |\n", h0s[k],
                  r.before, r.after, r.error[0], orders[0].c_str(), r.error[1], orders[1].c_str(),
                  r.error[2], orders[2].c_str());
    out.table += line;
    char check[160];
    std::snprintf(check, sizeof check, "%s, h0 = %g: midway / uncorrected error", name, h0s[k]);
    out.checks.push_back({check, r.error[2] / r.error[0], 0.5, 0.0, 0.5, ""});
    if (k == 0) continue;
    std::snprintf(check, sizeof check, "%s, h0 = %g: order of the uncorrected error", name, h0s[k]);
    out.checks.push_back({check, std::log2(rows[k - 1].error[0] / r.error[0]), 2.0, 1.7, 2.3, ""});
    std::snprintf(check, sizeof check, "%s, h0 = %g: order of the midway error", name, h0s[k]);
    out.checks.push_back({check, std::log2(rows[k - 1].error[2] / r.error[2]), 4.0, 2.5, 6.0, ""});
  }
}

}  // namespace

Outcome surface_point_addition(Resolution resolution) {
  const bool full = resolution == Resolution::full;
  Outcome out;
  const auto sphere = make_cut_sphere<3>(Vec3::Zero(), 1.0, {});
  const auto torus = make_torus_shape(Vec3::Zero(), 3.0, 1.0);
  table(out, "unit sphere", *sphere,
        full ? std::vector<double>{0.4, 0.2, 0.1, 0.05} : std::vector<double>{0.4, 0.2});
  table(out, "torus c = 3, a = 1", *torus,
        full ? std::vector<double>{0.8, 0.4, 0.2} : std::vector<double>{0.8, 0.4});
  return out;
}

}  // namespace pellicle::validation
