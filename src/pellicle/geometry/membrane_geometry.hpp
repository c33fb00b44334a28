#pragma once
//! Membrane bodies from user input: the points of a curve (2D) or surface (3D), the length or
//! area each stands for, and how they connect (for the connectivity frame estimator only).
//!
//! Keys of a membrane table (lengths in the case's unit):
//!   2D  shape = "polyline"  vertices = [[x, y], …], closed = false
//!       shape = "circle"    center, radius, start_angle = 0, end_angle = 360 (degrees)
//!       shape = "ellipse"   center, semi_axes, start_angle, end_angle
//!       shape = "spline"    through = [[x, y], …], closed = false (centripetal Catmull–Rom)
//!       spacing (default: a quarter cell) or points (exact count)
//!   3D  shape = "rectangle" corner, edge_u, edge_v        (normal edge_u × edge_v)
//!       shape = "disk"      center, normal, radius
//!       shape = "sphere"    center, radius, keep = [[1, 0, 0], …] (optional)
//!       shape = "ellipsoid" center, semi_axes, keep (optional): the sides of the coordinate
//!                           planes through the centre to keep (a half, quarter or eighth)
//!       shape = "cylinder"  center, axis, radius, height   (open tube)
//!       shape = "torus"     center, axis, major_radius, minor_radius
//!       shape = "mesh"      file (STL or OBJ, relative to the case file), scale = 1,
//!                           translate = [0, 0, 0]; refined until no edge exceeds spacing
//!       spacing: the longest distance between neighbouring points (default: a quarter cell)

#include <array>
#include <string>
#include <vector>

#include "pellicle/core/parameters.hpp"
#include "pellicle/core/types.hpp"

namespace pellicle {

//! What a body's points know of each other, from how they were generated. Estimators that
//! need no connectivity ignore it.
struct MembraneConnectivity {
  bool closed_curve = false;                  //!< 2D: the points run round a closed curve
  std::vector<std::array<int, 3>> triangles;  //!< 3D: the surface mesh (indices in the body)
};

template <int D>
struct MembraneGeometry {
  std::vector<Vec<D>> points;
  std::vector<double> measure;  //!< length (2D) or area (3D) each point stands for
  MembraneConnectivity connectivity;
  double longest_gap = 0.0;  //!< largest distance between neighbouring points
};

//! Read and sample a membrane shape. `cell` sets the default spacing; `base_directory` is
//! where mesh files are looked for. Problems are recorded in the reader. A shape whose
//! length or area at its spacing (or its `points`) would give more than `most_points` points
//! is refused before it is sampled (the key named, with the estimate).
template <int D>
MembraneGeometry<D> make_membrane_geometry(ParameterReader& in, double cell,
                                           const std::string& base_directory, double most_points);

}  // namespace pellicle
