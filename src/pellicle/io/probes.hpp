#pragma once
//! Probes: named quantities of chosen points written as extra history.csv columns.
//!
//! Case keys ([[probe]], optional, any number):
//!   name      string, required: column prefix
//!   body      string, required: the body the points belong to
//!   quantity  "position" | "velocity" (of `point`; columns <name>.x, <name>.y[, <name>.z])
//!             | "angle" (of the line from points[0] to points[1]; column <name>, degrees)
//!             | "radius" (distance of `point` from `center`; column <name>)
//!   point     index within the body (position, velocity)
//!   points    [a, b], indices within the body (angle)
//!   reference direction the angle is measured from; default [0, −1] (2D: "hanging down",
//!             positive counter-clockwise) or [0, 0, −1] (3D: unsigned)
//!   center    the point radii are measured from; default the origin

#include <string>
#include <vector>

#include "pellicle/core/error.hpp"
#include "pellicle/core/types.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

enum class ProbeQuantity { position, velocity, angle, radius };

template <int D>
struct ProbeSpec {
  std::string name, body;
  ProbeQuantity quantity = ProbeQuantity::position;
  long a = 0, b = 0;                  //!< indices within the body (b only for angles)
  Vec<D> reference = Vec<D>::Zero();  //!< angle: the direction; radius: the centre
  SourceLocation where;
};

//! A probe bound to a simulation's points.
template <int D>
class Probe {
 public:
  //! Throws InputError when the body or point does not exist.
  Probe(const ProbeSpec<D>& spec, const Simulation<D>& simulation);
  //! Column names this probe adds.
  std::vector<std::string> columns() const;
  //! Current values, in column order. Collective in a distributed run: the rank that holds a
  //! probed point (found by its index in the body as built) gives it to the others.
  std::vector<double> values(const Simulation<D>& simulation) const;

 private:
  //! Position and velocity of point `a`, position of point `b`.
  struct Probed {
    Vec<D> position_a, velocity_a, position_b;
  };
  Probed probed(const Simulation<D>& simulation) const;

  ProbeSpec<D> spec_;
  int body_ = 0;
  long a_ = 0, b_ = 0;  //!< point indices of a whole simulation
};

extern template class Probe<2>;
extern template class Probe<3>;

}  // namespace pellicle
