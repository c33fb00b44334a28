#pragma once
//! How big a case is before anything is allocated: points, grid nodes and bytes, estimated
//! from the case alone, against the machine's available memory. MPM cases from their grid and
//! bodies; surface cases from their shape's length or area and the cloud's spacing.

#include <string>
#include <vector>

#include "pellicle/geometry/surface_shape.hpp"
#include "pellicle/io/case.hpp"

namespace pellicle {

struct ProblemSize {
  double points = 0.0;  //!< upper bound: regions filled over their bounding boxes
  double nodes = 0.0;   //!< grid nodes with ghost layers, times the fields contact keeps
  double bytes = 0.0;
  int largest_body = -1;  //!< the body with the most points
  double largest_body_points = 0.0;
};

template <int D>
ProblemSize estimate_problem_size(const Case<D>& c);

//! Memory the system could give this process now (MemAvailable), in bytes; 0 if unknown.
double available_memory_bytes();

//! How many MPM points fit in the available memory (infinity if unknown): the budget a
//! membrane shape is checked against before it is sampled.
double most_points_in_memory();

//! Refuse (InputError, exit 2) a case whose estimate exceeds the available memory, naming the
//! estimate, the memory and the key that drives it (grid.cell, or the largest body's table).
template <int D>
void refuse_oversized_problem(const Case<D>& c);

//! The initial cloud of a surface case, from its shape before it is sampled.
struct SurfaceSize {
  double measure = 0.0;  //!< the shape's length (2D) or area (3D)
  double points = 0.0;   //!< +inf when the count does not fit a double
  double bytes = 0.0;    //!< the larger of sampling the cloud and running it
};

//! Points of a cloud at `spacing` on `shape`, and the memory a run of it takes.
template <int D>
SurfaceSize estimate_surface_size(const SurfaceShape<D>& shape, double spacing);
//! The same for the cloud of several shapes (their measures added).
template <int D>
SurfaceSize estimate_surface_size(const std::vector<const SurfaceShape<D>*>& shapes,
                                  double spacing);
//! Bytes a surface run takes per point (sampling, the cloud, neighbours, stencils, solver).
template <int D>
double surface_bytes_per_point();

//! Refuse (InputError, exit 2) a surface case whose initial cloud would hold more than 2³¹
//! points (more than its indices count) or need more than the available memory, naming the
//! estimate, the memory and the key that sets the spacing (`key`, given at `where`).
template <int D>
void refuse_oversized_surface(const std::vector<const SurfaceShape<D>*>& shapes, double spacing,
                              const SourceLocation& where, const std::string& key);

}  // namespace pellicle
