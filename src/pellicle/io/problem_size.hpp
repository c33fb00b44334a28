#pragma once
//! How big a case is before anything is allocated: points, grid nodes and bytes, estimated
//! from the case alone, against the machine's available memory.

#include <string>

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

//! Refuse (InputError, exit 2) a case whose estimate exceeds the available memory, naming the
//! estimate, the memory and the key that drives it (grid.cell, or the largest body's table).
template <int D>
void refuse_oversized_problem(const Case<D>& c);

}  // namespace pellicle
