#pragma once
//! A Riemann problem in a tube, run on cases/sod_shock_tube.toml's set-up (one cell across,
//! slip walls, a diaphragm at x = 0.5) with any left and right gas states: the tube's points
//! at the end, the shock front's history, and L1 errors and profiles against the exact
//! solution (riemann.hpp). Shared by Sod's tube and the held-out Riemann problems.

#include <string>
#include <vector>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/riemann.hpp"

namespace pellicle::validation {

struct ShockTube {
  GasState left, right;
  double gamma = 1.4;
  double end_time = 0.0;
  //! Time step at 100 cells; scaled with the cell.
  double dt_100 = 1e-4;
};

//! One point of the tube at the end: position, density, velocity, pressure, energy, volume.
struct TubeSample {
  double x, rho, u, p, e, volume;
};

struct TubeRun {
  std::vector<TubeSample> tube;  //!< sorted by x
  std::vector<double> t, front;  //!< shock-front history (after 0.2 of the end time)
  double energy_change = 0.0;    //!< total energy at the end / at the start − 1
};

//! Runs the tube at `cells` cells with extra `--set` overrides; the front is the rightmost
//! point whose pressure exceeds the mean of `p_star` and the right pressure.
TubeRun run_tube(const ShockTube& setup, int cells, const std::vector<std::string>& extra,
                 double p_star);

//! Rightmost point whose pressure is above the mean of p_star and p_right: the shock front.
double shock_position(const std::vector<TubeSample>& tube, double p_star, double p_right);

struct TubeErrors {
  double density = 0.0, velocity = 0.0, pressure = 0.0;
};

//! L1 norms ∫|f − f_exact| dx over the tube at time t, each point standing for its length
//! V/height.
TubeErrors l1_errors(const std::vector<TubeSample>& tube, const ExactRiemann& exact, double t,
                     double height);

//! Total variation of the exact density, velocity and pressure over the tube at time t. A
//! profile displaced by a distance s from the exact one has L1 error at most s × its total
//! variation: with s the kernel's support (each wave placed within it), the accepted L1
//! error of a run (first order in the cell).
TubeErrors total_variation(const ExactRiemann& exact, double t);

//! Mean of a column over the points with x in (a, b).
double plateau_mean(const std::vector<TubeSample>& tube, double a, double b,
                    double TubeSample::*column);

//! Profiles against the exact solution at time t, one row per distinct x.
Series tube_profile(const std::string& name, const std::string& title,
                    const std::vector<TubeSample>& tube, const ExactRiemann& exact, double t,
                    double gamma);

}  // namespace pellicle::validation
