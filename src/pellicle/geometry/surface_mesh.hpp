#pragma once
//! Surfaces in 3D as triangle meshes whose vertices become membrane points. The triangles
//! give each point its area (a third of the adjacent triangles) and, to the connectivity
//! frame estimator, its neighbours; the physics never needs them.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "pellicle/core/types.hpp"

namespace pellicle {

struct SurfaceMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  //!< counter-clockwise seen from the normal side
};

//! Split every triangle into four until no edge is longer than `max_edge`; new vertices are
//! passed through `project` (onto the exact surface) when given.
void refine(SurfaceMesh& mesh, double max_edge,
            const std::function<Vec3(const Vec3&)>& project = nullptr);
//! Area each vertex stands for: a third of each adjacent triangle.
std::vector<double> vertex_areas(const SurfaceMesh& mesh);
double longest_edge(const SurfaceMesh& mesh);
//! Remove vertices no triangle uses (files may carry them), renumbering the triangles.
void drop_unused_vertices(SurfaceMesh& mesh);

//! Parallelogram corner + s u + t v, s, t ∈ [0, 1]; normal u × v.
SurfaceMesh make_rectangle_patch(const Vec3& corner, const Vec3& u, const Vec3& v, double spacing);
//! Flat disk; normal along `axis`.
SurfaceMesh make_disk(const Vec3& center, const Vec3& axis, double radius, double spacing);
//! Outward normals.
SurfaceMesh make_ellipsoid(const Vec3& center, const Vec3& semi_axes, double spacing);
//! The part of an ellipsoid on chosen sides of the coordinate planes through its centre:
//! `side[d]` = +1 keeps x_d ≥ center_d, −1 keeps x_d ≤ center_d, 0 both (an eighth for three
//! non-zero sides). An octahedron refined on the unit sphere, then stretched, so the boundary
//! edges lie exactly in the cutting planes. Outward normals.
SurfaceMesh make_ellipsoid_part(const Vec3& center, const Vec3& semi_axes, double spacing,
                                const std::array<int, 3>& side);
//! Open tube of the given height centred on `center`, along `axis`; outward normals.
SurfaceMesh make_cylinder(const Vec3& center, const Vec3& axis, double radius, double height,
                          double spacing);
//! Torus about `axis`: tube radius `minor` at distance `major` from the centre.
SurfaceMesh make_torus(const Vec3& center, const Vec3& axis, double major, double minor,
                       double spacing);

//! ASCII or binary STL; coincident corners are merged. Throws InputError naming the file
//! (and line, for ASCII) on a malformed file.
SurfaceMesh read_stl(const std::string& path);
//! Wavefront OBJ: `v x y z` and `f a b c …` lines (polygons are split into fans).
SurfaceMesh read_obj(const std::string& path);

}  // namespace pellicle
