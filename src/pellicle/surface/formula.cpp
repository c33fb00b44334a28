#include "pellicle/surface/formula.hpp"

namespace pellicle {

namespace {
enum Variable { kX, kY, kZ, kNx, kNy, kNz, kT, kPhi, kKappa, kKappaMean, kH, kCount };
}

const std::vector<std::string>& PointFormula::variables() {
  static const std::vector<std::string> names = {"x", "y",   "z",     "nx",         "ny", "nz",
                                                 "t", "phi", "kappa", "kappa_mean", "h"};
  return names;
}

PointFormula::PointFormula(const std::string& text) : expression_(text, variables()) {}

double PointFormula::operator()(const PointValues& v) const {
  const double values[kCount] = {v.x.x(), v.x.y(), v.x.z(), v.n.x(),      v.n.y(), v.n.z(),
                                 v.t,     v.phi,   v.kappa, v.kappa_mean, v.h};
  return expression_.evaluate(values);
}

bool PointFormula::reads_phi() const {
  return expression_.uses(kPhi);
}
bool PointFormula::reads_curvature() const {
  return expression_.uses(kKappa) || expression_.uses(kKappaMean);
}
bool PointFormula::reads_mean_curvature() const {
  return expression_.uses(kKappaMean);
}

}  // namespace pellicle
