#pragma once
//! Pieces the surface shapes share: carriers (segments or triangles close to a shape, from
//! which poisson_sampling.hpp draws candidates) and the text of describe().

#include <functional>
#include <string>
#include <vector>

#include "pellicle/geometry/poisson_sampling.hpp"
#include "pellicle/geometry/surface_mesh.hpp"

namespace pellicle {

//! Total length (D = 2) or area (D = 3) of carrier pieces.
template <int D>
double carrier_measure(const std::vector<Simplex<D>>& carrier);

//! The triangles of a mesh as carrier pieces.
std::vector<Simplex<3>> carrier_of(const SurfaceMesh& mesh);

//! The closed polygon through x(k/n), k = 0 … n − 1, as carrier segments.
std::vector<Simplex<2>> closed_polygon(const std::function<Vec2(double)>& x, int n);

//! The grid x(i/nu, j/nv), i ≤ nu, j ≤ nv, each quad split into two triangles.
std::vector<Simplex<3>> parametric_grid(int nu, int nv,
                                        const std::function<Vec3(double, double)>& x);

//! Where f changes sign in the box [lower, upper], by marching simplices on a grid of cell
//! `cell` (squares split into 2 triangles, cubes into 6 tetrahedra; f linear on each): the
//! segments (D = 2) or triangles (D = 3) of the piecewise-linear zero level set.
template <int D>
std::vector<Simplex<D>> zero_level_set(const std::function<double(const Vec<D>&)>& f,
                                       const Vec<D>& lower, const Vec<D>& upper, double cell);

//! "(0, 0.5, 1)".
template <int D>
std::string describe_vector(const Vec<D>& x);
//! A number as %g prints it.
std::string describe_number(double x);

}  // namespace pellicle
