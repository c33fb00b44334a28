#pragma once
//! Assemble a surface simulation in C++ from a sampled shape: the case reader (io/) calls
//! this, and so can any program that embeds Pellicle, with no case file.

#include <array>
#include <memory>
#include <vector>

#include "pellicle/geometry/surface_shape.hpp"
#include "pellicle/surface/simulation.hpp"

namespace pellicle {

//! A moving cloud on the points of `sample` (its normals orient the first frames), every
//! point with smoothing length h, moved by `velocity` (D formulas) and carrying `pde`
//! (null: the cloud only moves). `surface_of_point` (when given, one entry per point) says
//! which surface of the case each point lies on; each surface starts as its own chamber.
template <int D>
std::unique_ptr<SurfaceSimulation<D>> build_surface_simulation(
    const PointSample<D>& sample, double smoothing_length, const SurfaceSettings& settings,
    std::array<PointFormula, D> velocity, std::unique_ptr<SurfacePde<D>> pde,
    const std::vector<int>* surface_of_point = nullptr);

}  // namespace pellicle
