#include "pellicle/geometry/membrane_geometry.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "pellicle/core/error.hpp"
#include "pellicle/geometry/curve.hpp"
#include "pellicle/geometry/surface_mesh.hpp"

namespace pellicle {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

std::vector<Vec2> read_points(ParameterReader& in, std::string_view key, std::size_t at_least) {
  std::vector<Vec2> out;
  for (const auto& v : in.number_lists(key, 2)) out.emplace_back(v[0], v[1]);
  if (out.size() < at_least) {
    in.fail(key, "expected at least " + std::to_string(at_least) + " points");
    out.assign(at_least, Vec2::Zero());
    for (std::size_t i = 0; i < at_least; ++i) out[i].x() = static_cast<double>(i);
  }
  return out;
}

// Points a shape gets at spacing s, at least: one per s of length along curves (sample_*),
// one per s² of area on meshes refined to edges ≤ s (measured 1.05 on planes, disks and
// cylinders, 1.4 on tori, 2.0 on spheres).
double expected_points(double measure, double spacing, int dimension) {
  return measure / std::pow(spacing, dimension - 1) + 1.0;
}

//! Refuse (record a problem about `key`) a shape that would have more points than fit.
bool too_many_points(ParameterReader& in, std::string_view key, double points, double measure,
                     double spacing, double most_points, int dimension) {
  if (!(points > most_points)) return false;
  std::ostringstream text;
  text.precision(3);
  text << "about " << points << " points";
  if (spacing > 0.0)
    text << " (" << (dimension == 2 ? "length " : "area ") << measure << " at spacing " << spacing
         << ")";
  text << ", more than the " << most_points
       << " points this machine's available memory holds in a run; raise the spacing or give "
          "fewer points";
  in.fail(key, text.str());
  return true;
}

double polyline_length(const std::vector<Vec2>& p, bool closed) {
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) length += (p[i + 1] - p[i]).norm();
  if (closed && p.size() > 2) length += (p.front() - p.back()).norm();
  return length;
}

MembraneGeometry<2> from_curve(const SampledCurve& c) {
  MembraneGeometry<2> g;
  g.points = c.points;
  g.measure = c.lengths;
  g.connectivity.closed_curve = c.closed;
  const std::size_t n = c.points.size();
  for (std::size_t i = 0; i + 1 < n + (c.closed ? 1 : 0); ++i)
    g.longest_gap = std::max(g.longest_gap, (c.points[(i + 1) % n] - c.points[i]).norm());
  return g;
}

MembraneGeometry<3> from_mesh(const SurfaceMesh& m) {
  MembraneGeometry<3> g;
  g.points = m.vertices;
  g.measure = vertex_areas(m);
  g.connectivity.triangles = m.triangles;
  g.longest_gap = longest_edge(m);
  return g;
}

MembraneGeometry<2> curve(ParameterReader& in, double cell, double most_points) {
  const std::string shape = in.choice("shape", {"polyline", "circle", "ellipse", "spline"});
  if (shape.empty()) {
    in.ignore_rest();
    return from_curve(sample_polyline({Vec2(0, 0), Vec2(1, 0)}, false, {1.0, 0}));
  }
  Sampling sampling;
  // 0: not given, the spacing decides; a curve needs at least its two ends.
  sampling.count =
      in.has("points") ? static_cast<int>(in.integer_or("points", 2, 2, 100000000)) : 0;
  if (in.has("points") && in.has("spacing")) in.fail("spacing", "give either points or spacing");
  sampling.spacing = in.number_or("spacing", 0.25 * cell, NumberRange::positive());
  // A curve through points that all coincide has no length to place points along.
  auto has_length = [&](const std::vector<Vec2>& points, const char* key) {
    for (const auto& x : points)
      if ((x - points.front()).norm() > 0.0) return true;
    in.fail(key, "expected points that are not all the same: the curve has no length");
    return false;
  };
  const std::vector<Vec2> segment{Vec2(0, 0), Vec2(1, 0)};  // stands in after a problem
  const SampledCurve stand_in = sample_polyline(segment, false, {1.0, 0});
  // Before sampling: the count given, or the curve's length (at least) over the spacing.
  auto too_long = [&](double length) {
    if (sampling.count > 0)
      return too_many_points(in, "points", sampling.count, length, 0.0, most_points, 2);
    return too_many_points(in, "spacing", expected_points(length, sampling.spacing, 2), length,
                           sampling.spacing, most_points, 2);
  };
  if (shape == "polyline" || shape == "spline") {
    const char* key = shape == "polyline" ? "vertices" : "through";
    auto points = read_points(in, key, 2);
    if (!has_length(points, key)) points = segment;
    const bool closed = in.flag_or("closed", false);
    if (too_long(polyline_length(points, closed))) return from_curve(stand_in);
    return from_curve(shape == "polyline" ? sample_polyline(points, closed, sampling)
                                          : sample_spline(points, closed, sampling));
  }
  const Vec2 center = read_vector<2>(in, "center");
  const Vec2 axes = shape == "circle" ? Vec2::Constant(in.number("radius", NumberRange::positive()))
                                      : read_vector<2>(in, "semi_axes", NumberRange::positive());
  const double from = in.number_or("start_angle", 0.0, NumberRange::any());
  const double to = in.number_or("end_angle", from + 360.0, NumberRange::any());
  if (to <= from || to - from > 360.0)
    in.fail("end_angle", "expected start_angle < end_angle <= start_angle + 360");
  if (too_long(axes.minCoeff() * (std::min(to, from + 360.0) - from) * kDegree))
    return from_curve(stand_in);
  return from_curve(sample_ellipse_arc(center, axes, from * kDegree,
                                       std::min(to, from + 360.0) * kDegree, sampling));
}

//! `keep = [[1, 0, 0], [0, -1, 0], …]`: the sides of the coordinate planes through the centre
//! to keep (n·(x − c) ≥ 0 for each n, as for surface shapes), so a quarter or eighth of a bag
//! has its boundary edges on symmetry faces. Only ± coordinate axes are offered.
std::array<int, 3> kept_sides(ParameterReader& in) {
  std::array<int, 3> side{0, 0, 0};
  for (const auto& n : in.number_lists("keep", 3)) {
    int axis = -1, nonzero = 0;
    for (int d = 0; d < 3; ++d)
      if (n[d] != 0.0) axis = d, ++nonzero;
    if (nonzero != 1) {
      std::ostringstream found;
      found << "[" << n[0] << ", " << n[1] << ", " << n[2] << "]";
      in.fail("keep", "expected coordinate directions such as [1, 0, 0] or [0, -1, 0], found " +
                          found.str());
      continue;
    }
    const int sign = n[axis] > 0 ? 1 : -1;
    if (side[axis] == -sign) {
      const std::string axis_name(1, "xyz"[axis]);
      in.fail("keep", "expected one side of the plane " + axis_name + " = center." + axis_name +
                          ", found both (nothing is kept)");
    }
    side[axis] = sign;
  }
  return side;
}

MembraneGeometry<3> surface(ParameterReader& in, double cell, const std::string& base,
                            double most_points) {
  const std::string shape =
      in.choice("shape", {"rectangle", "disk", "sphere", "ellipsoid", "cylinder", "torus", "mesh"});
  if (shape.empty()) {
    in.ignore_rest();
    return from_mesh(make_rectangle_patch(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), 1.0));
  }
  const double ds = in.number_or("spacing", 0.25 * cell, NumberRange::positive());
  const auto positive = NumberRange::positive();
  const auto stand_in = [] {
    return from_mesh(make_rectangle_patch(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), 1.0));
  };
  // Before meshing: the area (at least) over the spacing squared.
  auto too_large = [&](double area) {
    return too_many_points(in, "spacing", expected_points(area, ds, 3), area, ds, most_points, 3);
  };
  constexpr double pi = std::numbers::pi;
  if (shape == "rectangle") {
    const Vec3 corner = read_vector<3>(in, "corner"), u = read_vector<3>(in, "edge_u"),
               v = read_vector<3>(in, "edge_v");
    if (u.cross(v).norm() == 0.0) in.fail("edge_v", "expected edges that are not parallel");
    if (too_large(u.cross(v).norm())) return stand_in();
    return from_mesh(make_rectangle_patch(corner, u, v, ds));
  }
  if (shape == "disk") {
    const Vec3 c = read_vector<3>(in, "center"), n = read_vector<3>(in, "normal");
    if (n.norm() == 0.0) in.fail("normal", "expected a non-zero vector");
    const double r = in.number("radius", positive);
    if (too_large(pi * r * r)) return stand_in();
    return from_mesh(make_disk(c, n.norm() > 0 ? n : Vec3::UnitZ(), r, ds));
  }
  if (shape == "sphere" || shape == "ellipsoid") {
    const Vec3 c = read_vector<3>(in, "center");
    const Vec3 a = shape == "sphere" ? Vec3::Constant(in.number("radius", positive))
                                     : read_vector<3>(in, "semi_axes", positive);
    const bool part = in.has("keep");
    const auto sides = part ? kept_sides(in) : std::array<int, 3>{0, 0, 0};
    // At least the area of the sphere of the same volume (isoperimetric), times the part kept.
    double share = 1.0;
    for (int side : sides) share *= side != 0 ? 0.5 : 1.0;
    if (too_large(share * 4.0 * pi * std::cbrt(a.prod() * a.prod()))) return stand_in();
    if (!part) return from_mesh(make_ellipsoid(c, a, ds));
    return from_mesh(make_ellipsoid_part(c, a, ds, sides));
  }
  if (shape == "cylinder" || shape == "torus") {
    const Vec3 c = read_vector<3>(in, "center"), axis = read_vector<3>(in, "axis");
    const Vec3 a = axis.norm() > 0 ? axis : Vec3::UnitZ();
    if (axis.norm() == 0.0) in.fail("axis", "expected a non-zero vector");
    if (shape == "cylinder") {
      const double r = in.number("radius", positive), height = in.number("height", positive);
      if (too_large(2.0 * pi * r * height)) return stand_in();
      return from_mesh(make_cylinder(c, a, r, height, ds));
    }
    const double major = in.number("major_radius", positive),
                 minor = in.number("minor_radius", positive);
    if (minor >= major) in.fail("minor_radius", "expected minor_radius < major_radius");
    if (too_large(4.0 * pi * pi * major * minor)) return stand_in();
    return from_mesh(make_torus(c, a, major, minor, ds));
  }
  // A triangulated surface from a file.
  const std::string file = in.text("file");
  const double scale = in.number_or("scale", 1.0, positive);
  const Vec3 shift = read_vector_or<3>(in, "translate", Vec3::Zero());
  const std::filesystem::path path = std::filesystem::path(base) / file;
  SurfaceMesh mesh;
  try {
    const std::string ext = path.extension().string();
    if (ext == ".stl" || ext == ".STL")
      mesh = read_stl(path.string());
    else if (ext == ".obj" || ext == ".OBJ")
      mesh = read_obj(path.string());
    else
      in.fail("file", "expected a .stl or .obj file, found \"" + file + "\"");
  } catch (const InputError& e) {
    in.fail("file", e.what());
  }
  if (mesh.triangles.empty()) return stand_in();
  drop_unused_vertices(mesh);
  for (auto& v : mesh.vertices) v = scale * v + shift;
  double area = 0.0;
  for (const auto& t : mesh.triangles)
    area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                      .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                      .norm();
  if (too_large(area)) return stand_in();
  refine(mesh, ds);
  return from_mesh(mesh);
}

}  // namespace

template <>
MembraneGeometry<2> make_membrane_geometry<2>(ParameterReader& in, double cell, const std::string&,
                                              double most_points) {
  return curve(in, cell, most_points);
}

template <>
MembraneGeometry<3> make_membrane_geometry<3>(ParameterReader& in, double cell,
                                              const std::string& base_directory,
                                              double most_points) {
  return surface(in, cell, base_directory, most_points);
}

}  // namespace pellicle
