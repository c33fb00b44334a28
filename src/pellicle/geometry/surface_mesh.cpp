#include "pellicle/geometry/surface_mesh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <numbers>
#include <sstream>

#include "pellicle/core/error.hpp"
#include "pellicle/core/input_file.hpp"

namespace pellicle {

namespace {

//! Two unit vectors completing `axis` to a right-handed orthonormal basis.
std::pair<Vec3, Vec3> basis_around(const Vec3& axis) {
  const Vec3 n = axis.normalized();
  const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 a = (helper - helper.dot(n) * n).normalized();
  return {a, n.cross(a)};
}

//! A grid of (nu + 1) × (nv + 1) vertices from x(i/nu, j/nv), triangulated, optionally
//! closed (periodic) in u and/or v.
SurfaceMesh grid_surface(int nu, int nv, bool wrap_u, bool wrap_v,
                         const std::function<Vec3(double, double)>& x) {
  SurfaceMesh m;
  const int cu = wrap_u ? nu : nu + 1, cv = wrap_v ? nv : nv + 1;
  for (int j = 0; j < cv; ++j)
    for (int i = 0; i < cu; ++i) m.vertices.push_back(x(double(i) / nu, double(j) / nv));
  auto id = [&](int i, int j) { return (j % cv) * cu + (i % cu); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

int divisions(double length, double spacing) {
  return std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
}

}  // namespace

void refine(SurfaceMesh& mesh, double max_edge, const std::function<Vec3(const Vec3&)>& project) {
  while (longest_edge(mesh) > max_edge * (1.0 + 1e-9)) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      Vec3 x = 0.5 * (mesh.vertices[a] + mesh.vertices[b]);
      if (project) x = project(x);
      mesh.vertices.push_back(x);
      const int id = static_cast<int>(mesh.vertices.size()) - 1;
      midpoint[key] = id;
      return id;
    };
    std::vector<std::array<int, 3>> finer;
    finer.reserve(4 * mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({ab, t[1], bc});
      finer.push_back({ca, bc, t[2]});
      finer.push_back({ab, bc, ca});
    }
    mesh.triangles = std::move(finer);
  }
}

double longest_edge(const SurfaceMesh& mesh) {
  double longest = 0.0;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (mesh.vertices[t[k]] - mesh.vertices[t[(k + 1) % 3]]).norm());
  return longest;
}

void drop_unused_vertices(SurfaceMesh& mesh) {
  std::vector<int> renumber(mesh.vertices.size(), -1);
  for (const auto& t : mesh.triangles)
    for (int k : t) renumber[k] = 0;
  std::vector<Vec3> kept;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (renumber[i] == 0) {
      renumber[i] = static_cast<int>(kept.size());
      kept.push_back(mesh.vertices[i]);
    }
  mesh.vertices = std::move(kept);
  for (auto& t : mesh.triangles)
    for (int& k : t) k = renumber[k];
}

std::vector<double> vertex_areas(const SurfaceMesh& mesh) {
  std::vector<double> area(mesh.vertices.size(), 0.0);
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const double third = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm() / 6.0;
    for (int k = 0; k < 3; ++k) area[t[k]] += third;
  }
  return area;
}

SurfaceMesh make_rectangle_patch(const Vec3& corner, const Vec3& u, const Vec3& v, double spacing) {
  return grid_surface(divisions(u.norm(), spacing), divisions(v.norm(), spacing), false, false,
                      [&](double s, double t) { return Vec3(corner + s * u + t * v); });
}

SurfaceMesh make_disk(const Vec3& center, const Vec3& axis, double radius, double spacing) {
  const auto [a, b] = basis_around(axis);
  const int rings = divisions(radius, spacing);
  SurfaceMesh m;
  m.vertices.push_back(center);
  std::vector<int> previous{0};
  for (int r = 1; r <= rings; ++r) {
    const double rho = radius * r / rings;
    const int n =
        std::max(6, static_cast<int>(std::lround(2.0 * std::numbers::pi * rho / spacing)));
    std::vector<int> ring;
    for (int k = 0; k < n; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / n;
      m.vertices.push_back(center + rho * (std::cos(phi) * a + std::sin(phi) * b));
      ring.push_back(static_cast<int>(m.vertices.size()) - 1);
    }
    // Stitch the two rings by advancing along whichever is behind in angle.
    const int np = static_cast<int>(previous.size());
    int i = 0, j = 0;
    while (i < np || j < n) {
      const double next_i = np == 1 ? 2.0 : double(i + 1) / np, next_j = double(j + 1) / n;
      if (j < n && (i >= np || next_j <= next_i)) {
        m.triangles.push_back({previous[i % np], ring[j], ring[(j + 1) % n]});
        ++j;
      } else {
        m.triangles.push_back({previous[i % np], ring[j % n], previous[(i + 1) % np]});
        ++i;
      }
    }
    previous = ring;
  }
  return m;
}

SurfaceMesh make_ellipsoid(const Vec3& center, const Vec3& semi_axes, double spacing) {
  // Icosahedron refined on the unit sphere, then stretched; refined until the stretched
  // edges are short enough.
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  SurfaceMesh m;
  m.vertices = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  for (auto& v : m.vertices) v.normalize();
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  const double stretch = semi_axes.maxCoeff();
  refine(m, spacing / stretch, [](const Vec3& x) { return Vec3(x.normalized()); });
  for (auto& v : m.vertices) v = center + v.cwiseProduct(semi_axes);
  return m;
}

SurfaceMesh make_ellipsoid_part(const Vec3& center, const Vec3& semi_axes, double spacing,
                                const std::array<int, 3>& side) {
  // Each face of the octahedron ±e_x, ±e_y, ±e_z covers one octant, and the midpoints of an
  // edge in a coordinate plane stay in it when projected onto the sphere.
  SurfaceMesh m;
  m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int sx : {1, -1})
    for (int sy : {1, -1})
      for (int sz : {1, -1}) {
        if (sx * side[0] < 0 || sy * side[1] < 0 || sz * side[2] < 0) continue;
        const int a = sx > 0 ? 0 : 1, b = sy > 0 ? 2 : 3, c = sz > 0 ? 4 : 5;
        // (e_x, e_y, e_z) is counter-clockwise seen from outside; each sign flip mirrors it.
        if (sx * sy * sz > 0)
          m.triangles.push_back({a, b, c});
        else
          m.triangles.push_back({a, c, b});
      }
  drop_unused_vertices(m);
  const double stretch = semi_axes.maxCoeff();
  refine(m, spacing / stretch, [](const Vec3& x) { return Vec3(x.normalized()); });
  for (auto& v : m.vertices) v = center + v.cwiseProduct(semi_axes);
  return m;
}

SurfaceMesh make_cylinder(const Vec3& center, const Vec3& axis, double radius, double height,
                          double spacing) {
  const auto [a, b] = basis_around(axis);
  const Vec3 n = axis.normalized();
  const int nu = std::max(6, divisions(2.0 * std::numbers::pi * radius, spacing));
  return grid_surface(nu, divisions(height, spacing), true, false, [&](double s, double t) {
    const double phi = 2.0 * std::numbers::pi * s;
    return Vec3(center + radius * (std::cos(phi) * a + std::sin(phi) * b) + (t - 0.5) * height * n);
  });
}

SurfaceMesh make_torus(const Vec3& center, const Vec3& axis, double major, double minor,
                       double spacing) {
  const auto [a, b] = basis_around(axis);
  const Vec3 n = axis.normalized();
  const int nu = std::max(6, divisions(2.0 * std::numbers::pi * (major + minor), spacing));
  const int nv = std::max(6, divisions(2.0 * std::numbers::pi * minor, spacing));
  return grid_surface(nu, nv, true, true, [&](double s, double t) {
    const double phi = 2.0 * std::numbers::pi * s, psi = 2.0 * std::numbers::pi * t;
    const Vec3 radial = std::cos(phi) * a + std::sin(phi) * b;
    return Vec3(center + (major + minor * std::cos(psi)) * radial + minor * std::sin(psi) * n);
  });
}

namespace {

//! Merges coincident corners (STL repeats them per triangle).
class VertexMerger {
 public:
  explicit VertexMerger(SurfaceMesh& mesh) : mesh_(mesh) {}
  int add(const Vec3& x) {
    const std::array<long long, 3> key{std::llround(x.x() * 1e9), std::llround(x.y() * 1e9),
                                       std::llround(x.z() * 1e9)};
    const auto it = index_.find(key);
    if (it != index_.end()) return it->second;
    mesh_.vertices.push_back(x);
    return index_[key] = static_cast<int>(mesh_.vertices.size()) - 1;
  }

 private:
  SurfaceMesh& mesh_;
  std::map<std::array<long long, 3>, int> index_;
};

constexpr std::uintmax_t kLargestMesh = 1u << 30;  // bytes: 20 million binary triangles

[[noreturn]] void malformed(const std::string& path, int line, const std::string& what) {
  throw InputError(SourceLocation{path, line, line > 0 ? 1 : 0}, "", what);
}

}  // namespace

SurfaceMesh read_stl(const std::string& path) {
  const std::string data = read_input_file(path, "", "STL file", kLargestMesh);
  SurfaceMesh mesh;
  VertexMerger merge(mesh);
  // Binary STL: 80-byte header, uint32 count, 50 bytes per triangle. An ASCII file may also
  // start with "solid", so the size decides.
  if (data.size() >= 84) {
    std::uint32_t count;
    std::memcpy(&count, data.data() + 80, 4);
    if (data.size() == 84 + 50ull * count) {
      for (std::uint32_t t = 0; t < count; ++t) {
        const char* rec = data.data() + 84 + 50ull * t + 12;  // skip the facet normal
        std::array<int, 3> tri;
        for (int k = 0; k < 3; ++k) {
          float xyz[3];
          std::memcpy(xyz, rec + 12 * k, 12);
          tri[k] = merge.add(Vec3(xyz[0], xyz[1], xyz[2]));
        }
        mesh.triangles.push_back(tri);
      }
      if (mesh.triangles.empty()) malformed(path, 0, "the STL file holds no triangle");
      return mesh;
    }
  }
  std::istringstream text(data);
  std::string line, word;
  std::vector<int> corners;
  int number = 0;
  while (std::getline(text, line)) {
    ++number;
    std::istringstream words(line);
    if (!(words >> word)) continue;
    if (word == "vertex") {
      Vec3 x;
      if (!(words >> x.x() >> x.y() >> x.z())) malformed(path, number, "expected `vertex x y z`");
      corners.push_back(merge.add(x));
    } else if (word == "endloop") {
      if (corners.size() != 3) malformed(path, number, "expected 3 vertices per facet");
      mesh.triangles.push_back({corners[0], corners[1], corners[2]});
      corners.clear();
    }
  }
  if (mesh.triangles.empty()) malformed(path, 0, "not an STL file (no facet found)");
  return mesh;
}

SurfaceMesh read_obj(const std::string& path) {
  std::istringstream in(read_input_file(path, "", "OBJ file", kLargestMesh));
  SurfaceMesh mesh;
  std::string line, word;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    std::istringstream words(line);
    if (!(words >> word)) continue;
    if (word == "v") {
      Vec3 x;
      if (!(words >> x.x() >> x.y() >> x.z())) malformed(path, number, "expected `v x y z`");
      mesh.vertices.push_back(x);
    } else if (word == "f") {
      std::vector<int> polygon;
      while (words >> word) {
        const int index = std::atoi(word.c_str());  // "7/3/2" reads as 7
        const int resolved = index < 0 ? static_cast<int>(mesh.vertices.size()) + index : index - 1;
        if (index == 0 || resolved < 0 || resolved >= static_cast<int>(mesh.vertices.size()))
          malformed(path, number, "face refers to vertex " + word + ", which is not defined");
        polygon.push_back(resolved);
      }
      if (polygon.size() < 3) malformed(path, number, "a face needs at least 3 vertices");
      for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
        mesh.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
    }
  }
  if (mesh.triangles.empty()) malformed(path, 0, "the OBJ file holds no face");
  return mesh;
}

}  // namespace pellicle
