#include "pellicle/mpm/materials/linear_elastic.hpp"

#include <algorithm>
#include <cmath>

#include "pellicle/core/ordered_sum.hpp"
#include "pellicle/mpm/materials/kinematics.hpp"

namespace pellicle {

template <int D>
LinearElastic<D>::LinearElastic(Kinematics kinematics, double density, double youngs_modulus,
                                double poisson_ratio)
    : Material<D>(kinematics),
      density_(density),
      young_(youngs_modulus),
      poisson_(poisson_ratio),
      lambda_(youngs_modulus * poisson_ratio /
              ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio))),
      shear_(youngs_modulus / (2.0 * (1.0 + poisson_ratio))) {}

template <int D>
double LinearElastic<D>::wave_modulus() const {
  if (this->kinematics() == Kinematics::plane_stress) return young_ / (1.0 - poisson_ * poisson_);
  return lambda_ + 2.0 * shear_;
}

template <int D>
typename LinearElastic<D>::Law LinearElastic<D>::law() const {
  return {this->kinematics() == Kinematics::plane_stress, young_, poisson_, lambda_, shear_};
}

template <int D>
inline Sym<D> LinearElastic<D>::Law::increment(Sym<D>& de) const {
  if constexpr (D == 2) {
    if (plane_stress) {
      // σ_zz = 0: in-plane plane-stress law, and the thickness strain that goes with it.
      const double c = young / (1.0 - poisson * poisson);
      de[2] = -poisson / (1.0 - poisson) * (de[0] + de[1]);
      return Sym<2>(c * (de[0] + poisson * de[1]), c * (poisson * de[0] + de[1]), 0.0,
                    2.0 * shear * de[3]);  // from values (kinematics.hpp: store forwarding)
    }
  }
  // T : Δε of eq 14 for the isotropic law, 2μ Δε + λ tr(Δε) I (3D is always solid).
  return add_to_normal<D>(2.0 * shear * de, lambda * trace<D>(de));
}

template <int D>
Sym<D> LinearElastic<D>::stress_increment(Sym<D>& de) const {
  return law().increment(de);
}

template <int D>
void LinearElastic<D>::update(const MaterialStep<D>& step) const {
  Sym<D>* stress = step.points.stress.data();
  Sym<D>* strain = step.points[this->strain_].data();
  if (this->kinematics() == Kinematics::axisymmetric)
    update_points<true>(law(), step, stress, strain);
  else
    update_points<false>(law(), step, stress, strain);
}

template <int D>
template <bool Axisymmetric>
void LinearElastic<D>::update_points(const Law law, const MaterialStep<D>& step, Sym<D>* stress,
                                     Sym<D>* strain) {
  // Copies, so the stores below cannot be taken to change them.
  const BlockValues<Mat<D>> gradient = step.velocity_gradient;
  const BlockValues<double> hoop_rate = step.hoop_rate;
  const double dt = step.dt;
  const long end = step.end;
  for (long p = step.begin; p < end; ++p) {
    const Mat<D>& L = gradient[p];
    Sym<D> de = strain_increment<D>(L, Axisymmetric ? hoop_rate[p] : 0.0, dt);
    const Sym<D> ds = law.increment(de);
    stress[p] = jaumann_rotate<D>(stress[p], L, dt) + ds;
    strain[p] += de;
  }
}

template <int D>
double LinearElastic<D>::max_signal_speed(const Particles<D>& points, long begin, long end,
                                          double /*cell*/) const {
  return std::sqrt(wave_modulus() / smallest_density(points, begin, end, density_));
}

template <int D>
double LinearElastic<D>::strain_energy(const Particles<D>& points, long begin, long end) const {
  // W = ½ σ : C⁻¹ : σ = [(1+ν) σ:σ − ν (tr σ)²] / (2E), valid for every kinematics since the
  // stored stress includes σ_zz (zero in plane stress).
  return ordered_sum(begin, end, [&](long p) {
    const Sym<D>& s = points.stress[p];
    const double tr = trace<D>(s);
    return points.volume[p] * ((1.0 + poisson_) * contract<D>(s, s) - poisson_ * tr * tr) /
           (2.0 * young_);
  });
}

template <int D>
Sym<D> LinearElastic<D>::stress_from_strain(const Sym<D>& strain) const {
  Sym<D> e = strain;
  return law().increment(e);
}

template <int D>
std::unique_ptr<Material<D>> make_linear_elastic(ParameterReader& in, Kinematics kinematics) {
  const double rho = in.number("density", NumberRange::positive());
  const double E = in.number("youngs_modulus", NumberRange::positive());
  const double nu = in.number_or("poisson_ratio", 0.0, {-1.0, 0.5, true, true});
  return std::make_unique<LinearElastic<D>>(kinematics, rho, E, nu);
}

template class LinearElastic<2>;
template class LinearElastic<3>;
template std::unique_ptr<Material<2>> make_linear_elastic<2>(ParameterReader&, Kinematics);
template std::unique_ptr<Material<3>> make_linear_elastic<3>(ParameterReader&, Kinematics);

}  // namespace pellicle
