#include "pellicle/mpm/materials/membrane.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "pellicle/core/ordered_sum.hpp"
#include "pellicle/mpm/materials/kinematics.hpp"

namespace pellicle {

template <int D>
Membrane<D>::Membrane(Kinematics kinematics, double density, double youngs_modulus,
                      double poisson_ratio, MembraneLaw law, bool one_way, bool surface_volume)
    : Material<D>(kinematics),
      density_(density),
      young_(youngs_modulus),
      poisson_(poisson_ratio),
      uniaxial_(law == MembraneLaw::uniaxial || kinematics == Kinematics::plane_stress),
      one_way_(one_way),
      surface_volume_(surface_volume) {}

template <int D>
double Membrane<D>::wave_modulus() const {
  return uniaxial_ ? young_ : young_ / (1.0 - poisson_ * poisson_);
}

template <int D>
void Membrane<D>::local_stress(double e11, double& e22, double e12, double& s11, double& s22,
                               double& s12) const {
  const double E = young_, nu = poisson_;
  if (uniaxial_) {  // thesis eqs 5.5–5.9; one-way: no compressive stress (§5.2)
    e22 = -nu * e11;
    s11 = one_way_ && e11 < 0.0 ? 0.0 : E * e11;
    s22 = s12 = 0.0;
    return;
  }
  const double C = E / (1.0 - nu * nu);  // plane stress, thesis eqs 5.12–5.15
  auto plane_stress = [&] {
    s11 = C * (e11 + nu * e22);
    s22 = C * (e22 + nu * e11);
    s12 = C * (1.0 - nu) * e12;
  };
  if (!one_way_) return plane_stress();
  // Tension field: principal in-plane strains e1 ≥ e2.
  const double mean = 0.5 * (e11 + e22), half_diff = 0.5 * (e11 - e22);
  const double radius = std::sqrt(half_diff * half_diff + e12 * e12);
  const double e1 = mean + radius, e2 = mean - radius;
  if (C * (e2 + nu * e1) >= 0.0) return plane_stress();  // taut
  if (e1 <= 0.0) {                                       // slack
    s11 = s22 = s12 = 0.0;
    return;
  }
  // Wrinkled: uniaxial tension E e1 along the first principal direction d1 (radius > 0 here).
  const double cos2 = half_diff / radius, sin2 = e12 / radius;
  s11 = E * e1 * 0.5 * (1.0 + cos2);
  s22 = E * e1 * 0.5 * (1.0 - cos2);
  s12 = E * e1 * 0.5 * sin2;
}

Mat3 membrane_axes(const Vec2& t, const Vec2& n) {
  Mat3 Q;
  Q << t.x(), t.y(), 0.0, 0.0, 0.0, 1.0, n.x(), n.y(), 0.0;
  return Q;
}

Mat3 membrane_axes(const Vec3& t, const Vec3& n) {
  Mat3 Q;
  Q.row(0) = t.transpose();
  Q.row(1) = n.cross(t).transpose();
  Q.row(2) = n.transpose();
  return Q;
}

Mat3 normal_transport(const Vec2& from, const Vec2& to) {
  const double sign = from.dot(to) < 0.0 ? -1.0 : 1.0;  // n and −n are the same surface
  const double c = sign * from.dot(to), s = sign * (from.x() * to.y() - from.y() * to.x());
  Mat3 R = Mat3::Identity();
  R(0, 0) = R(1, 1) = c;
  R(0, 1) = -s;
  R(1, 0) = s;
  return R;
}

Mat3 normal_transport(const Vec3& from, const Vec3& to) {
  const Vec3 b = from.dot(to) < 0.0 ? Vec3(-to) : to;
  const Vec3 v = from.cross(b);
  const double c = from.dot(b);  // ≥ 0: the rotation is at most 90°, 1 + c ≥ 1
  Mat3 K;
  K << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return Mat3::Identity() + K + K * K / (1.0 + c);  // Rodrigues' formula
}

template <int D>
void Membrane<D>::declare_columns(Particles<D>& points) {
  Material<D>::declare_columns(points);
  normal_ = points.template declare<Vec<D>>({column_names::normal, "1", true, true});
  tangent_ = points.template declare<Vec<D>>({column_names::tangent, "1", true, true});
  strain_normal_ = points.template declare<Vec<D>>({"strain_normal", "1", false, true});
}

template <int D>
void Membrane<D>::snapshot_values(int field, const Particles<D>& points, long begin, long end,
                                  double* out) const {
  // Strain (field 0) or stress (field 1) in the local axes: 11 tangent, 22 second
  // in-surface direction, 12 in-surface shear.
  const auto& tensor = field == 0 ? points[this->strain_] : points.stress;
  for (long p = begin; p < end; ++p, out += 3) {
    const Mat3 Q = membrane_axes(points[tangent_][p], points[normal_][p]);
    const Mat3 local = Q * to_mat3<D>(tensor[p]) * Q.transpose();
    out[0] = local(0, 0);
    out[1] = local(1, 1);
    out[2] = local(0, 1);
  }
}

template <int D>
void Membrane<D>::update(const MaterialStep<D>& step) const {
  auto& pts = step.points;
  auto& strain = pts[this->strain_];
  const auto& normal = pts[normal_];
  const auto& tangent = pts[tangent_];
  auto& strain_normal = pts[strain_normal_];
  const bool axisymmetric = this->kinematics() == Kinematics::axisymmetric;
  const double nu = poisson_;
  for (long p = step.begin; p < step.end; ++p) {
    const Sym<D> de = strain_increment<D>(step.velocity_gradient[p],
                                          axisymmetric ? step.hoop_rate[p] : 0.0, step.dt);
    const Mat3 Q = membrane_axes(tangent[p], normal[p]);
    // The stored strain was resolved about last step's normal: carry it with the surface to
    // the new one, so a rotated or re-estimated frame reads the same membrane strain and never
    // the thickness strain as in-surface strain (docs/theory/fluid-membrane.md).
    Mat3 carried = to_mat3<D>(strain[p]);
    if (strain_normal[p].squaredNorm() > 0.0) {
      const Mat3 R = normal_transport(strain_normal[p], normal[p]);
      carried = R * carried * R.transpose();
    }
    strain_normal[p] = normal[p];
    const Mat3 local = Q * (carried + to_mat3<D>(de)) * Q.transpose();  // thesis eq 5.3
    // The point stands for Δs t (2D) or ΔA t (3D) of membrane at a fixed thickness: its volume
    // follows the stretch in the surface, not the grid's velocity gradient across it (the
    // gas on one side and nothing on the other). The transfer divided the density by
    // 1 + Δt tr L; take that back and divide by 1 + the in-surface dilatation instead
    // (docs/theory/fluid-membrane.md).
    if (surface_volume_) {
      const Mat3 local_rate = Q * to_mat3<D>(de) * Q.transpose();
      const double full =
          step.velocity_gradient[p].trace() + (axisymmetric ? step.hoop_rate[p] : 0.0);
      pts.density[p] *= (1.0 + step.dt * full) / (1.0 + local_rate(0, 0) + local_rate(1, 1));
      pts.volume[p] = pts.mass[p] / pts.density[p];
    }
    const double e11 = local(0, 0), e12 = local(0, 1);
    double e22 = local(1, 1), s11, s22, s12;
    local_stress(e11, e22, e12, s11, s22, s12);
    const double e33 = uniaxial_ ? -nu * e11 : -nu / (1.0 - nu) * (e11 + e22);
    Mat3 stress_local = Mat3::Zero(), strain_local = Mat3::Zero();
    stress_local(0, 0) = s11;
    stress_local(1, 1) = s22;
    stress_local(0, 1) = stress_local(1, 0) = s12;
    strain_local(0, 0) = e11;
    strain_local(1, 1) = e22;
    strain_local(0, 1) = strain_local(1, 0) = e12;
    strain_local(2, 2) = e33;
    pts.stress[p] = from_mat3<D>(Q.transpose() * stress_local * Q);
    strain[p] = from_mat3<D>(Q.transpose() * strain_local * Q);
  }
}

template <int D>
double Membrane<D>::max_signal_speed(const Particles<D>& points, long begin, long end,
                                     double /*cell*/) const {
  return std::sqrt(wave_modulus() / smallest_density(points, begin, end, density_));
}

template <int D>
double Membrane<D>::strain_energy(const Particles<D>& points, long begin, long end) const {
  // ½ σ : ε V with the adjusted strain: the local law's energy (zero when slack).
  const auto& strain = points[this->strain_];
  return ordered_sum(begin, end, [&](long p) {
    return 0.5 * points.volume[p] * contract<D>(points.stress[p], strain[p]);
  });
}

template <int D>
Sym<D> Membrane<D>::stress_from_strain(const Sym<D>&) const {
  return Sym<D>::Zero();
}

template <int D>
std::unique_ptr<Material<D>> make_membrane(ParameterReader& in, Kinematics kinematics) {
  const double rho = in.number("density", NumberRange::positive());
  const double E = in.number("youngs_modulus", NumberRange::positive());
  const double nu = in.number_or("poisson_ratio", 0.0, {-1.0, 0.5, true, true});
  const std::string law =
      in.choice("law", {"uniaxial", "plane-stress"}, D == 2 ? "uniaxial" : "plane-stress");
  if (D == 3 && law == "uniaxial")
    in.fail("law", "expected \"plane-stress\": 3D membranes are surfaces");
  const bool one_way = in.flag_or("one_way", false);
  const bool surface = in.choice("volume", {"surface", "continuity"}, "surface") == "surface";
  return std::make_unique<Membrane<D>>(
      kinematics, rho, E, nu, law == "uniaxial" ? MembraneLaw::uniaxial : MembraneLaw::plane_stress,
      one_way, surface);
}

template class Membrane<2>;
template class Membrane<3>;
template std::unique_ptr<Material<2>> make_membrane<2>(ParameterReader&, Kinematics);
template std::unique_ptr<Material<3>> make_membrane<3>(ParameterReader&, Kinematics);

}  // namespace pellicle
