#pragma once
//! The benchmark problems. The built-in two-disk case refined to about `points` points,
//! 2 × 2 points per cell, with the given kernel and velocity update. Shared by
//! `pellicle bench` and bench/.

#include <memory>
#include <string>
#include <vector>

#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

std::unique_ptr<Simulation<2>> make_bench_two_disks(long points, const std::string& kernel,
                                                    const std::string& velocity_update,
                                                    const std::vector<std::string>& extra = {});

//! A closed box of compressing gas (ideal gas, viscosity, artificial viscosity) with about
//! `points` points: the fluid constitutive update and energy equation under load.
std::unique_ptr<Simulation<2>> make_bench_gas_box(long points, const std::string& kernel,
                                                  const std::string& velocity_update);

}  // namespace pellicle
