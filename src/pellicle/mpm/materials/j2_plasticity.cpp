#include "pellicle/mpm/materials/j2_plasticity.hpp"

#include <cmath>

#include "pellicle/core/ordered_sum.hpp"
#include "pellicle/mpm/materials/kinematics.hpp"

namespace pellicle {

template <int D>
J2Plasticity<D>::J2Plasticity(Kinematics kinematics, double density, const J2Constants& constants)
    : Material<D>(kinematics),
      density_(density),
      constants_(constants),
      elastic_(kinematics, density, constants.young, constants.poisson) {}

template <int D>
void J2Plasticity<D>::declare_columns(Particles<D>& points) {
  Material<D>::declare_columns(points);  // strain
  plastic_strain_ = points.template declare<double>({plastic_strain_column, "1", true, true});
}

template <int D>
void J2Plasticity<D>::update(const MaterialStep<D>& step) const {
  auto& pts = step.points;
  auto& strain = pts[this->strain_];
  auto& plastic_strain = pts[plastic_strain_];
  const Kinematics kinematics = this->kinematics();
  const bool axisymmetric = kinematics == Kinematics::axisymmetric;
  for (long p = step.begin; p < step.end; ++p) {
    const Mat<D>& L = step.velocity_gradient[p];
    // Δε = Δt sym(L), hoop increment in axisymmetry (P3); the plane-stress return sets Δε_zz.
    Sym<D> de = strain_increment<D>(L, axisymmetric ? step.hoop_rate[p] : 0.0, step.dt);
    // Rotate first (P2): ε̄p is a scalar and is not rotated.
    const J2State<D> rotated{jaumann_rotate<D>(pts.stress[p], L, step.dt), plastic_strain[p]};
    // Elastic predictor and return mapping (P3)–(P15).
    const J2State<D> next = j2_update<D>(rotated, de, constants_, kinematics);
    pts.stress[p] = next.stress;
    plastic_strain[p] = next.plastic_strain;
    strain[p] += de;
  }
}

template <int D>
double J2Plasticity<D>::max_signal_speed(const Particles<D>& points, long begin, long end,
                                         double /*cell*/) const {
  return std::sqrt(wave_modulus() / smallest_density(points, begin, end, density_));
}

template <int D>
double J2Plasticity<D>::strain_energy(const Particles<D>& points, long begin, long end) const {
  // (P16): from the stress alone, σ_zz included, so valid for every kinematics and after
  // yield (the elastic strain is not the total strain then).
  return ordered_sum(begin, end, [&](long p) {
    return points.volume[p] * j2_elastic_energy_density<D>(points.stress[p], constants_);
  });
}

template <int D>
Sym<D> J2Plasticity<D>::stress_from_strain(const Sym<D>& strain) const {
  return elastic_.stress_from_strain(strain);  // (P1); σ_zz = 0 in plane stress (P11)
}

template <int D>
std::unique_ptr<Material<D>> make_j2_plasticity(ParameterReader& in, Kinematics kinematics) {
  if (!j2_supports<D>(kinematics))
    in.fail("model",
            "j2-plasticity needs grid.kinematics = \"plane-strain\", \"plane-stress\" or "
            "\"axisymmetric\" in 2D, \"solid\" in 3D");
  J2Constants c{};
  const double rho = in.number("density", NumberRange::positive());
  c.young = in.number("youngs_modulus", NumberRange::positive());
  c.poisson = in.number_or("poisson_ratio", 0.0, {-1.0, 0.5, true, true});
  c.yield_stress = in.number("yield_stress", NumberRange::positive());
  c.hardening = in.number_or("hardening_modulus", 0.0, NumberRange::non_negative());
  return std::make_unique<J2Plasticity<D>>(kinematics, rho, c);
}

template class J2Plasticity<2>;
template class J2Plasticity<3>;
template std::unique_ptr<Material<2>> make_j2_plasticity<2>(ParameterReader&, Kinematics);
template std::unique_ptr<Material<3>> make_j2_plasticity<3>(ParameterReader&, Kinematics);

}  // namespace pellicle
