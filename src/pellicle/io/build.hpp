#pragma once
//! Turn a checked case into a ready-to-run Simulation: fill the bodies with points, give them
//! mass, velocity and initial stress, and choose the kernel's transfers.

#include <memory>

#include "pellicle/io/case.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

//! Consumes the case's materials. Throws InputError when a body holds no point.
template <int D>
std::unique_ptr<Simulation<D>> build_simulation(Case<D>& c);

//! Volume a point stands for: its sub-cell (per unit depth in 2D; × 2πr in axisymmetry).
template <int D>
double point_volume(double cell, int points_per_cell, Kinematics kinematics, const Vec<D>& x);

}  // namespace pellicle
