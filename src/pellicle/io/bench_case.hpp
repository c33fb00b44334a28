#pragma once
//! The benchmark problems, shared by `pellicle bench` and bench/. The two-disk case
//! (cases/two_disks.toml) refined to about `points` points, 2 × 2 points per cell, with the
//! given kernel and velocity update.

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

//! Gas inside a membrane: the quarter circle of Sulsky & York 2000 §8 (cases/
//! fsi_quarter_circle.toml) refined to about `points` points, 16 gas points per cell, the
//! membrane at a quarter cell, quadratic B-splines with APIC, Δt scaled with the cell.
std::unique_ptr<Simulation<2>> make_bench_gas_membrane(long points);

//! Two elastic spheres of radius 0.2 approaching along the diagonal of the unit cube (the
//! two-disk problem in 3D), 2 × 2 × 2 points per cell, refined to about `points` points
//! (140,640 points on 64³ cells), with the given kernel, velocity update and scheme.
std::unique_ptr<Simulation<3>> make_bench_two_spheres(long points, const std::string& kernel,
                                                      const std::string& velocity_update,
                                                      const std::string& scheme);

}  // namespace pellicle
