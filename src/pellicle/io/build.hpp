#pragma once
//! Turn a checked case into a ready-to-run Simulation through the engine's builder
//! (mpm/builder.hpp), reporting what the builder refuses at the case's locations.

#include <memory>

#include "pellicle/io/case.hpp"
#include "pellicle/mpm/builder.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

//! Consumes the case's materials, bodies and contact model. Throws InputError (a body that holds
//! no point, a point index a body does not have, …) with the body's table location. With
//! `select`, only the points it chooses are kept (SimulationBuilder::select_points).
template <int D>
std::unique_ptr<Simulation<D>> build_simulation(Case<D>& c, PointSelection<D> select = {});

}  // namespace pellicle
