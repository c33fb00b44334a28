//! `pellicle normals`: normals of a point set read from CSV, by any frame estimator, with
//! angle errors against exact normals when the file gives them. The estimators are the ones
//! membrane bodies use in runs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "pellicle/app/commands.hpp"
#include "pellicle/core/error.hpp"
#include "pellicle/core/input_file.hpp"
#include "pellicle/io/atomic_file.hpp"
#include "pellicle/normals/frame_estimator.hpp"
#include "pellicle/normals/isosurface.hpp"

namespace pellicle {

namespace {

struct PointTable {
  int dimension = 0;
  bool has_exact = false;
  std::vector<std::vector<double>> rows;  //!< x, y[, z][, nx, ny[, nz]]
  std::vector<int> lines;                 //!< each row's line in the file
};

std::string shown(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

const char* column_name(int column, int count) {
  static const char* const names2[] = {"x", "y", "nx", "ny"};
  static const char* const names3[] = {"x", "y", "z", "nx", "ny", "nz"};
  return count == 2 || count == 4 ? names2[column] : names3[column];
}

//! Rows of 2, 3, 4 or 6 numbers: x y, x y z, x y nx ny, x y z nx ny nz. A first line that is
//! not numeric is a header and may name the columns instead (x, y, z, nx, ny, nz).
PointTable read_points(const std::string& path) {
  std::istringstream in(read_input_file(path, "--points", "point table", 1u << 30));
  PointTable t;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    std::vector<double> values;
    std::string field;
    bool numeric = true;
    while (fields >> field) {
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      if (*end != '\0') numeric = false;
      values.push_back(v);
    }
    if (!numeric) {
      if (t.rows.empty() && t.dimension == 0) continue;  // header
      throw InputError(SourceLocation{path, number, 1}, "--points",
                       "expected numbers, found \"" + line + "\"");
    }
    const int n = static_cast<int>(values.size());
    if (n != 2 && n != 3 && n != 4 && n != 6)
      throw InputError(
          SourceLocation{path, number, 1}, "--points",
          "expected 2 (x y), 3 (x y z), 4 (x y nx ny) or 6 (x y z nx ny nz) columns, found " +
              std::to_string(n));
    const int dimension = n == 2 || n == 4 ? 2 : 3;
    if (t.dimension != 0 && (dimension != t.dimension || (n > 3) != t.has_exact))
      throw InputError(SourceLocation{path, number, 1}, "--points",
                       "row has " + std::to_string(n) + " columns, unlike the rows before it");
    for (int k = 0; k < n; ++k)
      if (!std::isfinite(values[k]))
        throw InputError(SourceLocation{path, number, 1}, "--points",
                         "column " + std::to_string(k + 1) + " (" + column_name(k, n) +
                             "): expected a finite number, found " + shown(values[k]));
    t.dimension = dimension;
    t.has_exact = n == 4 || n == 6;
    t.rows.push_back(values);
    t.lines.push_back(number);
  }
  if (t.rows.empty())
    throw InputError(SourceLocation{path, 0, 0}, "--points", "no points in the file");
  return t;
}

template <int D>
int normals(const NormalsOptions& o, const PointTable& table) {
  const FrameEstimatorChoice<D>* choice = nullptr;
  std::string known;
  for (const auto& e : frame_estimators<D>()) {
    known += " " + e.name;
    if (e.name == o.method) choice = &e;
  }
  if (!choice || o.method == "connectivity")
    throw InputError(
        SourceLocation{"command line", 0, 0}, "--method",
        "expected a connectivity-free estimator, one of:" + known + " (not connectivity)");
  FrameSetup<D> setup;
  setup.cell = o.cell;
  for (int d = 0; d < D; ++d)
    setup.grid_origin[d] = d < static_cast<int>(o.origin.size()) ? o.origin[d] : 0.0;
  if (!o.origin.empty() && static_cast<int>(o.origin.size()) != D)
    throw InputError(
        SourceLocation{"command line", 0, 0}, "--origin",
        "expected " + std::to_string(D) + " numbers for these " + std::to_string(D) + "D points");
  for (int d = 0; d < D; ++d)
    if (!std::isfinite(setup.grid_origin[d]))
      throw InputError(SourceLocation{"command line", 0, 0}, "--origin",
                       "expected finite numbers, found " + shown(setup.grid_origin[d]));
  if (!std::isfinite(o.cell))
    throw InputError(SourceLocation{"command line", 0, 0}, "--cell",
                     "expected a finite cell size, found " + shown(o.cell));
  const long n = static_cast<long>(table.rows.size());
  std::vector<Vec<D>> x(n), normal(n, Vec<D>::Zero()), tangent(n, Vec<D>::Zero()), exact(n);
  // Cells are numbered by int: a point must lie within 2^30 cells of the origin.
  constexpr double kFarthestCell = 1073741824.0;
  for (long i = 0; i < n; ++i)
    for (int d = 0; d < D; ++d) {
      x[i][d] = table.rows[i][d];
      if (table.has_exact) exact[i][d] = table.rows[i][D + d];
      const double cells = std::abs(x[i][d] - setup.grid_origin[d]) / o.cell;
      if (!(cells < kFarthestCell))
        throw InputError(SourceLocation{o.points, table.lines[i], 1}, "--points",
                         "column " + std::to_string(d + 1) + " (" +
                             column_name(d, static_cast<int>(table.rows[i].size())) + " = " +
                             shown(x[i][d]) + ") lies " + shown(cells) +
                             " cells from the origin; the grid numbers at most 2^30 each way");
    }
  setup.orientation.rule =
      o.orient == "outward" ? NormalOrientation::outward : NormalOrientation::propagate;
  if (!o.inside.empty() && static_cast<int>(o.inside.size()) != D)
    throw InputError(
        SourceLocation{"command line", 0, 0}, "--inside",
        "expected " + std::to_string(D) + " numbers for these " + std::to_string(D) + "D points");
  auto estimator = choice->make(setup);
  estimator->estimate(x, 0, n, normal, tangent);
  if (!o.inside.empty()) {  // away from the given point, whatever the estimator chose
    Vec<D> centre;
    for (int d = 0; d < D; ++d) centre[d] = o.inside[d];
    for (long i = 0; i < n; ++i)
      if (normal[i].dot(x[i] - centre) < 0.0) normal[i] = -normal[i];
  }

  std::string csv = D == 2 ? "x,y,nx,ny" : "x,y,z,nx,ny,nz";
  csv += table.has_exact ? ",error_deg,side\n" : "\n";
  double worst = 0.0, sum = 0.0;
  long wrong_side = 0;
  char buffer[160];
  for (long i = 0; i < n; ++i) {
    for (int d = 0; d < D; ++d) {
      std::snprintf(buffer, sizeof buffer, "%s%.10g", d ? "," : "", x[i][d]);
      csv += buffer;
    }
    for (int d = 0; d < D; ++d) {
      std::snprintf(buffer, sizeof buffer, ",%.10g", normal[i][d]);
      csv += buffer;
    }
    if (table.has_exact) {  // the error: the angle between the lines; the side separately
      const Vec<D> e = exact[i].normalized();
      const double along = std::abs(normal[i].dot(e)),
                   across = (normal[i] - normal[i].dot(e) * e).norm();
      const double angle = std::atan2(across, along);
      worst = std::max(worst, angle);
      sum += angle * angle;
      // The side: +1 where the normal faces the exact normal's way, −1 where it is reversed.
      const bool reversed = normal[i].dot(e) < 0.0;
      wrong_side += reversed;
      std::snprintf(buffer, sizeof buffer, ",%.6g,%d", angle * 180.0 / std::numbers::pi,
                    reversed ? -1 : 1);
      csv += buffer;
    }
    csv += '\n';
  }
  write_file_atomically(o.out, csv);
  std::printf("method    %s, %ld points, %dD, cell %g\n", o.method.c_str(), n, D, o.cell);
  if (table.has_exact) {
    const double rms = std::sqrt(sum / n);
    std::printf("error     max %.6g rad (%.4g deg), rms %.6g rad (%.4g deg), the line's angle\n",
                worst, worst * 180 / std::numbers::pi, rms, rms * 180 / std::numbers::pi);
    std::printf("side      %ld of %ld normals (%.3g %%) face opposite to the exact normal (%s)\n",
                wrong_side, n, 100.0 * wrong_side / n,
                o.inside.empty() ? ("--orient " + o.orient).c_str() : "--inside");
  }
  if (const auto* iso = dynamic_cast<const IsosurfaceEstimator<D>*>(estimator.get())) {
    auto c = iso->statistics().condition;
    if (!c.empty()) {
      std::sort(c.begin(), c.end());
      std::printf(
          "condition %zu systems; condition of the normal equations min %.3g median %.3g max "
          "%.3g\n",
          c.size(), c.front(), c[c.size() / 2], c.back());
    }
    if (iso->statistics().fallbacks > 0)
      std::printf("fallback  %ld points had ∇χ = 0 and took principal-component normals\n",
                  iso->statistics().fallbacks);
  }
  std::printf("written   %s\n", o.out.c_str());
  return kExitOk;
}

}  // namespace

int command_normals(const NormalsOptions& o) {
  try {
    const PointTable table = read_points(o.points);
    return table.dimension == 2 ? normals<2>(o, table) : normals<3>(o, table);
  } catch (const InputError& e) {
    return report_input_error(e);
  }
}

}  // namespace pellicle
