#pragma once
//! A reference solver for strings: a chain of two-node bar elements in 2D with lumped masses,
//! integrated by the explicit central-difference method (the seeds' pendulum reference is
//! "an explicit finite element method using bar elements", IJNME §3.1.2). The first node is
//! pinned; bars carry tension E A (l − l0)/l0 along their current direction, none in
//! compression when `one_way`.

#include <vector>

#include "pellicle/core/types.hpp"

namespace pellicle::validation {

struct BarChainSettings {
  Vec2 pivot, end;  //!< initial straight string from the pinned pivot to the end
  int elements = 200;
  double youngs_modulus = 1.0, area = 1.0, density = 1.0;
  double end_mass = 0.0;  //!< added to the last node
  Vec2 gravity = Vec2::Zero();
  bool one_way = false;
  double end_time = 1.0;
  double courant = 0.5;  //!< Δt = courant × l0 / sqrt(E/ρ)
  double sample_interval = 1e-3;
};

struct BarChainSample {
  double time;
  Vec2 end;  //!< position of the last node
};

//! The end node's path, sampled every `sample_interval`.
std::vector<BarChainSample> solve_bar_chain(const BarChainSettings& settings);

}  // namespace pellicle::validation
