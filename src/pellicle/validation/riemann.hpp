#pragma once
//! The exact solution of the Riemann problem for the 1D Euler equations of an ideal gas: two
//! uniform states at rest or moving, separated at x0 at t = 0. The star-region pressure is
//! the root of f(p) = f_L(p) + f_R(p) + u_R − u_L (Newton iteration), each f_K the shock
//! (Rankine–Hugoniot) or rarefaction (isentropic) relation; the solution is self-similar in
//! x/t and is sampled wave by wave. The reference for Sod's shock tube (docs/theory/gas.md).

namespace pellicle::validation {

struct GasState {
  double density = 0.0, velocity = 0.0, pressure = 0.0;
};

class ExactRiemann {
 public:
  //! Throws std::invalid_argument if the data create a vacuum (no star region).
  ExactRiemann(GasState left, GasState right, double gamma);

  double star_pressure() const { return p_star_; }
  double star_velocity() const { return u_star_; }
  //! Density between the contact and the left (right) wave.
  double star_density_left() const { return rho_star_left_; }
  double star_density_right() const { return rho_star_right_; }
  //! Speed of the right-moving shock (meaningful when the right wave is a shock).
  double right_shock_speed() const;
  //! State at x/t = s.
  GasState sample(double s) const;

 private:
  //! f_K(p) and its derivative for side K (Toro's functions).
  void wave_function(const GasState& k, double sound_speed, double p, double& f, double& df) const;
  double star_density(const GasState& k, double p) const;

  GasState left_, right_;
  double gamma_, c_left_, c_right_;
  double p_star_ = 0.0, u_star_ = 0.0, rho_star_left_ = 0.0, rho_star_right_ = 0.0;
};

}  // namespace pellicle::validation
