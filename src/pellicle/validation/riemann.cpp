#include "pellicle/validation/riemann.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pellicle::validation {

ExactRiemann::ExactRiemann(GasState left, GasState right, double gamma)
    : left_(left),
      right_(right),
      gamma_(gamma),
      c_left_(std::sqrt(gamma * left.pressure / left.density)),
      c_right_(std::sqrt(gamma * right.pressure / right.density)) {
  const double du = right_.velocity - left_.velocity;
  if (2.0 / (gamma_ - 1.0) * (c_left_ + c_right_) <= du)
    throw std::invalid_argument("Riemann data generate vacuum");
  // Newton on f(p) = f_L + f_R + Δu from the two-rarefaction guess, which is exact when
  // both waves are rarefactions and a close start otherwise.
  const double z = (gamma_ - 1.0) / (2.0 * gamma_);
  double p = std::pow(
      (c_left_ + c_right_ - 0.5 * (gamma_ - 1.0) * du) /
          (c_left_ / std::pow(left_.pressure, z) + c_right_ / std::pow(right_.pressure, z)),
      1.0 / z);
  for (int iteration = 0; iteration < 100; ++iteration) {
    double fl, dfl, fr, dfr;
    wave_function(left_, c_left_, p, fl, dfl);
    wave_function(right_, c_right_, p, fr, dfr);
    const double next = std::max(1e-14 * p, p - (fl + fr + du) / (dfl + dfr));
    const double change = 2.0 * std::abs(next - p) / (next + p);
    p = next;
    if (change < 1e-14) break;
  }
  double fl, dfl, fr, dfr;
  wave_function(left_, c_left_, p, fl, dfl);
  wave_function(right_, c_right_, p, fr, dfr);
  p_star_ = p;
  u_star_ = 0.5 * (left_.velocity + right_.velocity) + 0.5 * (fr - fl);
  rho_star_left_ = star_density(left_, p);
  rho_star_right_ = star_density(right_, p);
}

void ExactRiemann::wave_function(const GasState& k, double c, double p, double& f,
                                 double& df) const {
  if (p > k.pressure) {  // shock: Rankine–Hugoniot
    const double a = 2.0 / ((gamma_ + 1.0) * k.density);
    const double b = (gamma_ - 1.0) / (gamma_ + 1.0) * k.pressure;
    const double root = std::sqrt(a / (p + b));
    f = (p - k.pressure) * root;
    df = root * (1.0 - 0.5 * (p - k.pressure) / (p + b));
  } else {  // rarefaction: isentropic
    const double ratio = p / k.pressure;
    f = 2.0 * c / (gamma_ - 1.0) * (std::pow(ratio, (gamma_ - 1.0) / (2.0 * gamma_)) - 1.0);
    df = std::pow(ratio, -(gamma_ + 1.0) / (2.0 * gamma_)) / (k.density * c);
  }
}

double ExactRiemann::star_density(const GasState& k, double p) const {
  const double ratio = p / k.pressure;
  if (p > k.pressure) {
    const double g = (gamma_ - 1.0) / (gamma_ + 1.0);
    return k.density * (ratio + g) / (g * ratio + 1.0);
  }
  return k.density * std::pow(ratio, 1.0 / gamma_);
}

double ExactRiemann::right_shock_speed() const {
  return right_.velocity +
         c_right_ * std::sqrt((gamma_ + 1.0) / (2.0 * gamma_) * p_star_ / right_.pressure +
                              (gamma_ - 1.0) / (2.0 * gamma_));
}

GasState ExactRiemann::sample(double s) const {
  const double g = gamma_;
  // Mirror the right side onto the left so one branch serves both: the sign flips velocity.
  const bool left_side = s <= u_star_;
  const GasState& k = left_side ? left_ : right_;
  const double sign = left_side ? 1.0 : -1.0;
  const double c = left_side ? c_left_ : c_right_;
  const double u = sign * k.velocity, x = sign * s, u_star = sign * u_star_;
  const double rho_star = left_side ? rho_star_left_ : rho_star_right_;
  if (p_star_ > k.pressure) {  // shock
    const double speed =
        u - c * std::sqrt((g + 1.0) / (2.0 * g) * p_star_ / k.pressure + (g - 1.0) / (2.0 * g));
    return x <= speed ? k : GasState{rho_star, u_star_, p_star_};
  }
  const double c_star = c * std::pow(p_star_ / k.pressure, (g - 1.0) / (2.0 * g));
  const double head = u - c, tail = u_star - c_star;
  if (x <= head) return k;
  if (x >= tail) return {rho_star, u_star_, p_star_};
  // Inside the fan.
  GasState out;
  const double factor = 2.0 / (g + 1.0) + (g - 1.0) / ((g + 1.0) * c) * (u - x);
  out.density = k.density * std::pow(factor, 2.0 / (g - 1.0));
  out.velocity = sign * 2.0 / (g + 1.0) * (c + 0.5 * (g - 1.0) * u + x);
  out.pressure = k.pressure * std::pow(factor, 2.0 * g / (g - 1.0));
  return out;
}

}  // namespace pellicle::validation
