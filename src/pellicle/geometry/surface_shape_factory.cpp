// Surface shapes by name from user input (`kind = "sphere"` …). Adding a shape is its file
// (surface_shapes.hpp) and one line in the table below. docs/user-guide.md, "Surface
// shapes", lists the keys.
#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "pellicle/core/error.hpp"
#include "pellicle/geometry/shape_support.hpp"
#include "pellicle/geometry/surface_shapes.hpp"

namespace pellicle {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
//! Largest ratio of a torus's major to minor radius, and of a half pipe's arc to pipe
//! radius: the carrier the cloud is drawn from has pieces about a third of the tube's radius
//! wide, so its size grows with the ratio (10³: about 10⁶ triangles, 70 MB).
constexpr double kSlenderest = 1e3;

//! Whether some direction d has n·d > 0 for every cut n: the cuts leave a part with area.
template <int D>
bool cuts_leave_a_part(const std::vector<Vec<D>>& keep) {
  if (keep.empty()) return true;
  // Fibonacci points on the sphere (evenly spread angles on the circle) and the mean normal.
  std::vector<Vec<D>> directions;
  Vec<D> mean = Vec<D>::Zero();
  for (const auto& n : keep) mean += n;
  if (mean.norm() > 0) directions.push_back(mean.normalized());
  const int count = D == 3 ? 20000 : 3600;
  for (int k = 0; k < count; ++k) {
    if constexpr (D == 2) {
      const double t = 2 * std::numbers::pi * (k + 0.5) / count;
      directions.emplace_back(std::cos(t), std::sin(t));
    } else {
      const double z = 1.0 - 2.0 * (k + 0.5) / count, r = std::sqrt(1.0 - z * z);
      const double t = k * std::numbers::pi * (3.0 - std::sqrt(5.0));
      directions.emplace_back(r * std::cos(t), r * std::sin(t), z);
    }
  }
  for (const auto& d : directions) {
    bool inside = true;
    for (const auto& n : keep) inside = inside && n.dot(d) > 1e-9;
    if (inside) return true;
  }
  return false;
}

template <int D>
SurfaceShapePtr<D> read_sphere(ParameterReader& in, const std::string&) {
  const Vec<D> c = read_vector<D>(in, "center");
  const double r = in.number("radius", NumberRange::positive());
  std::vector<Vec<D>> keep;
  if (in.has("keep")) {
    for (const auto& v : in.number_lists("keep", D)) {
      Vec<D> n;
      for (int d = 0; d < D; ++d) n[d] = v[d];
      if (n.norm() == 0.0) {
        in.fail("keep", "expected non-zero normals, found a zero vector");
        continue;
      }
      keep.push_back(n.normalized());
    }
    if (!cuts_leave_a_part<D>(keep)) {
      in.fail("keep", "expected cuts that leave part of the shape, found none left");
      keep.clear();
    }
  }
  return make_cut_sphere<D>(c, r, std::move(keep));
}

template <int D>
SurfaceShapePtr<D> read_ellipsoid(ParameterReader& in, const std::string&) {
  const Vec<D> c = read_vector<D>(in, "center");
  return make_ellipsoid_shape<D>(c, read_vector<D>(in, "semi_axes", NumberRange::positive()));
}

template <int D>
SurfaceShapePtr<D> read_torus(ParameterReader& in, const std::string&) {
  if constexpr (D == 3) {
    const Vec3 c = read_vector<3>(in, "center");
    const double major = in.number("major_radius", NumberRange::positive());
    double minor = in.number("minor_radius", NumberRange::positive());
    if (minor >= major) {
      in.fail("minor_radius", "expected minor_radius < major_radius");
      minor = 0.5 * major;
    } else if (major > kSlenderest * minor) {
      in.fail("minor_radius", "expected minor_radius at least major_radius / " +
                                  describe_number(kSlenderest) +
                                  " (a thinner tube is not sampled)");
      minor = major / kSlenderest;
    }
    return make_torus_shape(c, major, minor);
  } else {
    return nullptr;  // not registered in 2D
  }
}

template <int D>
SurfaceShapePtr<D> read_half_pipe(ParameterReader& in, const std::string&) {
  if constexpr (D == 3) {
    double pipe = in.number_or("pipe_radius", 0.25, NumberRange::positive());
    const double arc = in.number_or("arc_radius", 0.75, NumberRange::positive());
    const double angle = in.number_or("arc_angle", 180.0, {0.0, 360.0, true, true});
    if (pipe >= arc) {
      in.fail("pipe_radius", "expected pipe_radius < arc_radius");
      pipe = 0.5 * arc;
    } else if (arc > kSlenderest * pipe) {
      in.fail("pipe_radius", "expected pipe_radius at least arc_radius / " +
                                 describe_number(kSlenderest) + " (a thinner pipe is not sampled)");
      pipe = arc / kSlenderest;
    }
    const std::string side = in.choice("side", {"inner", "outer", "upper"}, "inner");
    return make_half_pipe_shape(pipe, arc, angle * kDegree,
                                side == "outer"   ? HalfPipeSide::outer
                                : side == "upper" ? HalfPipeSide::upper
                                                  : HalfPipeSide::inner);
  } else {
    return nullptr;  // not registered in 2D
  }
}

template <int D>
SurfaceShapePtr<D> read_blobs(ParameterReader& in, const std::string&) {
  std::vector<Vec<D>> centers;
  for (const auto& v : in.number_lists("centers", D)) {
    Vec<D> c;
    for (int d = 0; d < D; ++d) c[d] = v[d];
    centers.push_back(c);
  }
  std::vector<double> radii = in.numbers("radii", -1, NumberRange::positive());
  const double level = in.number("level", {0.0, 1.0, true, true});
  if (!centers.empty() && !radii.empty() && radii.size() != centers.size())
    in.fail("radii", "expected one radius per centre (" + std::to_string(centers.size()) +
                         "), found " + std::to_string(radii.size()));
  if (centers.empty()) centers.push_back(Vec<D>::Zero());
  radii.resize(centers.size(), radii.empty() ? 1.0 : radii.back());
  for (double& r : radii) r = r > 0.0 ? r : 1.0;
  return make_implicit_blobs<D>(std::move(centers), std::move(radii), level);
}

template <int D>
SurfaceShapePtr<D> read_tube(ParameterReader& in, const std::string&) {
  if constexpr (D == 3) {
    const Vec3 c = in.has("center") ? read_vector<3>(in, "center") : Vec3(Vec3::Zero());
    const double radius = in.number("radius", NumberRange::positive());
    double length = in.number("length", NumberRange::positive());
    if (radius > 0.0 && length > kSlenderest * radius) {
      in.fail("length", "expected length at most " + describe_number(kSlenderest) +
                            " radius (a longer tube is not sampled)");
      length = radius;
    }
    return make_tube_shape(c, radius > 0.0 ? radius : 1.0, length > 0.0 ? length : 1.0);
  } else {
    return nullptr;  // not registered in 2D
  }
}

template <int D>
SurfaceShapePtr<D> read_dumbbell(ParameterReader& in, const std::string&) {
  const Vec<D> c = in.has("center") ? read_vector<D>(in, "center") : Vec<D>(Vec<D>::Zero());
  const double ball = in.number_or("ball_radius", 1.0, NumberRange::positive());
  double separation = in.number_or("separation", 4.0, NumberRange::positive());
  double rod = in.number_or("rod_radius", 0.2, NumberRange::positive());
  if (!(separation > 2.0 * ball)) {
    in.fail("separation", "expected separation > 2 ball_radius (the balls apart)");
    separation = 4.0 * ball;
  }
  if (!(rod < ball)) {
    in.fail("rod_radius", "expected rod_radius < ball_radius");
    rod = 0.2 * ball;
  } else if (ball > kSlenderest * rod) {
    in.fail("rod_radius", "expected rod_radius at least ball_radius / " +
                              describe_number(kSlenderest) + " (a thinner rod is not sampled)");
    rod = ball / kSlenderest;
  }
  return make_dumbbell_shape<D>(c, ball, separation, rod);
}

template <int D>
SurfaceShapePtr<D> read_mesh(ParameterReader& in, const std::string& base) {
  if constexpr (D == 3) {
    const std::string file = in.text("file");
    if (file.empty()) return nullptr;
    const std::filesystem::path path = std::filesystem::path(base) / file;
    const std::string ext = path.extension().string();
    SurfaceMesh mesh;
    try {
      if (ext == ".stl" || ext == ".STL") {
        mesh = read_stl(path.string());
      } else if (ext == ".obj" || ext == ".OBJ") {
        mesh = read_obj(path.string());
      } else {
        in.fail("file", "expected a .stl or .obj file, found \"" + file + "\"");
        return nullptr;
      }
    } catch (const InputError& e) {
      in.fail("file", e.what());
      return nullptr;
    }
    drop_unused_vertices(mesh);
    bool has_area = false;
    for (const auto& t : mesh.triangles) {
      const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
      has_area = has_area || (b - a).cross(c - a).norm() > 0.0;
    }
    if (!has_area) {
      in.fail("file", "expected a mesh with at least one triangle of non-zero area");
      return nullptr;
    }
    return make_mesh_shape(std::move(mesh), file);
  } else {
    return nullptr;  // not registered in 2D
  }
}

template <int D>
struct Kind {
  const char* name;
  int dimension;  //!< 0: any
  SurfaceShapePtr<D> (*read)(ParameterReader&, const std::string&);
};

template <int D>
const std::vector<Kind<D>>& kinds() {
  static const std::vector<Kind<D>> table = {
      {"sphere", 3, &read_sphere<D>},        {"circle", 2, &read_sphere<D>},
      {"ellipsoid", 3, &read_ellipsoid<D>},  {"ellipse", 2, &read_ellipsoid<D>},
      {"torus", 3, &read_torus<D>},          {"half-pipe", 3, &read_half_pipe<D>},
      {"implicit-blobs", 0, &read_blobs<D>}, {"mesh", 3, &read_mesh<D>},
      {"dumbbell", 0, &read_dumbbell<D>},    {"tube", 3, &read_tube<D>},
  };
  return table;
}

}  // namespace

template <int D>
std::vector<std::string> surface_shape_kinds() {
  std::vector<std::string> names;
  for (const auto& k : kinds<D>())
    if (k.dimension == 0 || k.dimension == D) names.emplace_back(k.name);
  return names;
}

template <int D>
SurfaceShapePtr<D> make_surface_shape(ParameterReader& in, const std::string& base_directory) {
  const std::string name = in.choice("kind", surface_shape_kinds<D>());
  if (name.empty()) {
    in.ignore_rest();
    return nullptr;
  }
  for (const auto& k : kinds<D>())
    if (name == k.name && (k.dimension == 0 || k.dimension == D)) return k.read(in, base_directory);
  return nullptr;
}

template <int D>
SurfaceShapePtr<D> make_surface_shape(ParameterReader& in) {
  return make_surface_shape<D>(in, ".");
}

template SurfaceShapePtr<2> make_surface_shape<2>(ParameterReader&);
template SurfaceShapePtr<3> make_surface_shape<3>(ParameterReader&);
template SurfaceShapePtr<2> make_surface_shape<2>(ParameterReader&, const std::string&);
template SurfaceShapePtr<3> make_surface_shape<3>(ParameterReader&, const std::string&);
template std::vector<std::string> surface_shape_kinds<2>();
template std::vector<std::string> surface_shape_kinds<3>();

}  // namespace pellicle
