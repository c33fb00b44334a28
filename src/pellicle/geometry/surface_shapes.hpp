#pragma once
//! The shapes make_surface_shape reads, for code that builds them directly. Each lives in
//! its own file (sphere_shape.cpp, ellipsoid_shape.cpp, …) and is registered by name in
//! surface_shape_factory.cpp.

#include <string>
#include <vector>

#include "pellicle/geometry/surface_mesh.hpp"
#include "pellicle/geometry/surface_shape.hpp"

namespace pellicle {

//! Sphere (D = 3) or circle (D = 2) of radius r about c, cut to the part where
//! n·(x − c) ≥ 0 for every n in `keep` (none: the whole shape). The cut curves (D = 3: great
//! circles; D = 2: points) are the part's boundary. Error measure: eq 13, |‖x − c‖² − r²|/r².
template <int D>
SurfaceShapePtr<D> make_cut_sphere(const Vec<D>& center, double radius, std::vector<Vec<D>> keep);

//! Ellipsoid (D = 3) or ellipse (D = 2) Σ ((x − c)_d / a_d)² = 1; exact closest points.
template <int D>
SurfaceShapePtr<D> make_ellipsoid_shape(const Vec<D>& center, const Vec<D>& semi_axes);

//! Torus about the z axis through `center`: (c − √(x² + y²))² + z² = a² (eq 14), c the
//! major and a the minor radius; error measure eq 15.
SurfaceShapePtr<3> make_torus_shape(const Vec3& center, double major, double minor);

//! Which lengthwise half of the tube a half pipe keeps: the one facing the arc's centre, the
//! one facing away from it, or the y ≥ 0 one.
enum class HalfPipeSide { inner, outer, upper };

//! The half pipe of §4.2.2: a tube of radius `pipe_radius` about the arc x = R cos θ,
//! z = R sin θ (R = `arc_radius`, |θ| ≤ `arc_angle`/2, radians), one half of it.
SurfaceShapePtr<3> make_half_pipe_shape(double pipe_radius, double arc_radius, double arc_angle,
                                        HalfPipeSide side = HalfPipeSide::inner);

//! The level set Σ_k exp(−|x − c_k|²/r_k²) = level, 0 < level < 1 (each centre inside).
template <int D>
SurfaceShapePtr<D> make_implicit_blobs(std::vector<Vec<D>> centers, std::vector<double> radii,
                                       double level);

//! An open tube: the cylinder of radius `radius` about the z axis through `center`,
//! |z − center_z| ≤ length/2; its boundary is the two end circles.
SurfaceShapePtr<3> make_tube_shape(const Vec3& center, double radius, double length);

//! The dumbbell of Suchde & Kuhnert §4.2.3: balls of radius `ball_radius` with centres
//! `separation` apart along x about `center`, joined by a rod of radius `rod_radius` along x
//! (rod_radius < ball_radius < separation / 2); the boundary of their union.
template <int D>
SurfaceShapePtr<D> make_dumbbell_shape(const Vec<D>& center, double ball_radius, double separation,
                                       double rod_radius);

//! A triangulated surface (at least one triangle); `name` is used by describe().
SurfaceShapePtr<3> make_mesh_shape(SurfaceMesh mesh, std::string name);

}  // namespace pellicle
