#pragma once
//! Formulas over surface points: case-file expressions (core/expression.hpp) evaluated at a
//! point of the cloud with the variables every surface formula may use:
//!   x y z       position (z = 0 on curves)
//!   nx ny nz    unit normal (nz = 0 on curves)
//!   t           time
//!   phi         the PDE's unknown at the point (0 without one)
//!   kappa       mean curvature κ (eq 37), smoothed by eq 40 when the velocity reads it
//!   kappa_mean  its average over the cloud (κ̄ of eq 38)
//!   h           smoothing length

#include <string>
#include <vector>

#include "pellicle/core/expression.hpp"
#include "pellicle/core/types.hpp"

namespace pellicle {

//! The values a surface formula reads at one point.
struct PointValues {
  Vec3 x = Vec3::Zero(), n = Vec3::Zero();
  double t = 0.0, phi = 0.0, kappa = 0.0, kappa_mean = 0.0, h = 0.0;
};

class PointFormula {
 public:
  PointFormula() = default;
  //! Throws ExpressionError (the case reader adds file, line and key).
  explicit PointFormula(const std::string& text);
  double operator()(const PointValues& v) const;
  bool reads_phi() const;
  bool reads_curvature() const;
  bool reads_mean_curvature() const;  //!< kappa_mean
  bool empty() const { return expression_.empty(); }
  const std::string& text() const { return expression_.text(); }
  static const std::vector<std::string>& variables();

 private:
  Expression expression_;
};

//! Embed a D-vector in 3D (curves: z = 0).
template <int D>
Vec3 to_vec3(const Vec<D>& v) {
  Vec3 out = Vec3::Zero();
  out.template head<D>() = v;
  return out;
}

}  // namespace pellicle
