#pragma once
//! The benchmark problem: the built-in two-disk case refined to about `points` points,
//! 2 × 2 points per cell, with the given kernel and velocity update. Shared by
//! `pellicle bench` and bench/.

#include <memory>
#include <string>

#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

std::unique_ptr<Simulation<2>> make_bench_two_disks(long points, const std::string& kernel,
                                                    const std::string& velocity_update);

}  // namespace pellicle
