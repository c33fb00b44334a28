// The transfers conserve what they move: for every kernel, the scatter to the grid keeps the
// points' total mass and momentum (the APIC affine term adds none: Σ_i N_i (x_i − x_p) = 0),
// and the gather back (PIC, APIC) returns the grid's momentum to the points, to round-off.
// APIC's scatter also keeps the angular momentum, counting each point's affine part
// (Jiang et al. 2015): L = Σ_p m_p (x_p × v_p + ε : (C_p D_p)), D_p = Σ_i N_i (x_i − x_p)².
// What APIC's transfers remove from the kinetic energy is kept as heat, exactly.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>

#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/particles.hpp"
#include "pellicle/mpm/transfer.hpp"

namespace pellicle {
namespace {

template <int D>
FaceConditions<D> free_faces() {
  FaceConditions<D> faces;
  faces.fill(FaceCondition::free);
  return faces;
}

template <int D>
struct Cloud {
  Grid<D> grid{Vec<D>::Zero(), Vec<D>::Constant(1.0), 0.1, free_faces<D>()};  // nothing folds
  Particles<D> points;
  std::unique_ptr<Transfer<D>> transfer;

  //! `thermal`: a model with an internal energy is present, so APIC keeps the transfer heat.
  Cloud(const KernelChoice<D>& kernel, VelocityUpdate update, bool thermal = false) {
    TransferOptions options;
    options.update = update;
    options.kinematics = D == 2 ? Kinematics::plane_strain : Kinematics::solid;
    transfer = kernel.make(options, 2.0);
    if (thermal) points.template declare<double>({column_names::internal_energy, "J/kg"});
    transfer->declare_columns(points);
    points.bodies.push_back({"cloud", 0, Vec<D>::Zero(), 0, 0, nullptr});
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 400; ++k) {
      Vec<D> x, v;
      for (int d = 0; d < D; ++d) x[d] = 0.2 + 0.6 * u(rng), v[d] = 2.0 * u(rng) - 1.0;
      points.add(x, v, 0.5 + u(rng), 1.0);
    }
    if (update == VelocityUpdate::apic)
      for (auto& c : points.template named<Mat<D>>("affine"))
        for (int i = 0; i < D * D; ++i) c.data()[i] = 4.0 * u(rng) - 2.0;
    transfer->compute_stencils(points, grid, {});
    transfer->to_grid(points, Vec<D>::Zero(), grid, false);
  }

  double point_mass() const {
    double m = 0.0;
    for (double x : points.mass) m += x;
    return m;
  }
  Vec<D> point_momentum() const {
    Vec<D> sum = Vec<D>::Zero();
    for (long p = 0; p < points.size(); ++p) sum += points.mass[p] * points.velocity[p];
    return sum;
  }
  double grid_mass() const {
    double m = 0.0;
    for (double x : grid.mass) m += x;
    return m;
  }
  //! Angular momentum about the origin (2D: its z component in [0]).
  Vec3 grid_angular_momentum() const {
    Vec3 sum = Vec3::Zero();
    for (long i = 0; i < grid.node_count(); ++i)
      sum += embed(grid.node_position(i)).cross(embed(grid.momentum[i]));
    return sum;
  }
  Vec3 point_angular_momentum() const {
    const auto& affine = points.template named<Mat<D>>("affine");
    const int k = transfer->stencil_size();
    std::vector<long> nodes(k);
    std::vector<double> weights(k);
    Vec3 sum = Vec3::Zero();
    for (long p = 0; p < points.size(); ++p) {
      transfer->node_weights(points, grid, p, p + 1, nodes.data(), weights.data());
      Mat<D> inertia = Mat<D>::Zero();  // D_p
      for (int j = 0; j < k; ++j) {
        const Vec<D> r = grid.node_position(nodes[j]) - points.position[p];
        inertia += weights[j] * r * r.transpose();
      }
      const Mat<D> b = affine[p] * inertia;  // C_p D_p
      Vec3 spin = Vec3::Zero();              // ε_kab (C D)_ba
      if constexpr (D == 2) {
        spin.z() = b(1, 0) - b(0, 1);
      } else {
        spin = Vec3(b(2, 1) - b(1, 2), b(0, 2) - b(2, 0), b(1, 0) - b(0, 1));
      }
      sum += points.mass[p] * (embed(points.position[p]).cross(embed(points.velocity[p])) + spin);
    }
    return sum;
  }
  static Vec3 embed(const Vec<D>& v) {
    Vec3 out = Vec3::Zero();
    out.template head<D>() = v;
    return out;
  }

  double point_kinetic_energy() const {
    double e = transfer->affine_kinetic_energy(points, grid);
    for (long p = 0; p < points.size(); ++p)
      e += 0.5 * points.mass[p] * points.velocity[p].squaredNorm();
    return e;
  }

  Vec<D> grid_momentum() const {
    Vec<D> sum = Vec<D>::Zero();
    for (const auto& q : grid.momentum) sum += q;
    return sum;
  }
};

template <int D>
void expect_conserved() {
  for (const auto& kernel : kernel_choices<D>()) {
    std::vector<VelocityUpdate> updates = {VelocityUpdate::pic};
    if (kernel.offers_apic) updates.push_back(VelocityUpdate::apic);
    for (const VelocityUpdate update : updates) {
      Cloud<D> c(kernel, update);
      const std::string what = kernel.name + (update == VelocityUpdate::apic ? " APIC" : " PIC") +
                               " " + std::to_string(D) + "D";
      EXPECT_NEAR(c.grid_mass(), c.point_mass(), 1e-12 * c.point_mass()) << what;
      const Vec<D> before = c.point_momentum();
      EXPECT_LT((c.grid_momentum() - before).norm(), 1e-12 * c.point_mass()) << what;
      if (update == VelocityUpdate::apic) {
        EXPECT_LT((c.grid_angular_momentum() - c.point_angular_momentum()).norm(),
                  1e-12 * c.point_mass())
            << what;
      }
      // Back to the points with no force and no time: the grid's momentum, exactly.
      c.grid.velocities_from_momentum();
      for (auto& dv : c.grid.velocity_change) dv.setZero();
      PointFailure failure;
      c.transfer->to_points(c.grid, 0.0, c.points, failure);
      EXPECT_LT(failure.point, 0) << what;
      EXPECT_LT((c.point_momentum() - c.grid_momentum()).norm(), 1e-12 * c.point_mass()) << what;
    }
  }
}

// The internal and external forces on the grid, f_i = Σ_p N_i m_p g − V_p σ_p ∇N_i (IJNME eq 16),
// have the total Σ_p m_p g (Σ_i ∇N_i = 0) and, since every kernel reproduces linear functions
// (Σ_i N_i x_i = x_p, Σ_i x_i ∇N_iᵀ = I), the first moment Σ_i x_i f_iᵀ = Σ_p (m_p x_p gᵀ − V_p
// σ_p): every term of the force scatter, each stress component with its gradient direction.
template <int D>
void expect_force_moments() {
  for (const auto& kernel : kernel_choices<D>()) {
    const bool apic = kernel.offers_apic;
    Cloud<D> c(kernel, apic ? VelocityUpdate::apic : VelocityUpdate::pic);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Vec<D> gravity;
    for (int d = 0; d < D; ++d) gravity[d] = u(rng);
    Mat<D> expected_moment = Mat<D>::Zero();
    Vec<D> expected_total = Vec<D>::Zero();
    double scale = 0.0;
    for (long p = 0; p < c.points.size(); ++p) {
      for (int k = 0; k < c.points.stress[p].size(); ++k) c.points.stress[p][k] = u(rng);
      c.points.volume[p] = 0.5 + 0.5 * u(rng);
      const Mat<D> sigma = to_mat3<D>(c.points.stress[p]).template topLeftCorner<D, D>();
      const double m = c.points.mass[p];
      expected_moment +=
          m * c.points.position[p] * gravity.transpose() - c.points.volume[p] * sigma;
      expected_total += m * gravity;
      scale += m * gravity.norm() + c.points.volume[p] * sigma.norm();
    }
    c.transfer->to_grid(c.points, gravity, c.grid, true);
    Mat<D> moment = Mat<D>::Zero();
    Vec<D> total = Vec<D>::Zero();
    for (long i = 0; i < c.grid.node_count(); ++i) {
      moment += c.grid.node_position(i) * c.grid.force[i].transpose();
      total += c.grid.force[i];
    }
    const std::string what = kernel.name + (apic ? " APIC " : " PIC ") + std::to_string(D) + "D";
    EXPECT_LT((total - expected_total).norm(), 1e-12 * scale) << what;
    EXPECT_LT((moment - expected_moment).norm(), 1e-12 * scale) << what;
  }
}

TEST(TransferConservation, ForcesHaveTheTotalAndFirstMomentOfTheStress2D) {
  expect_force_moments<2>();
}

TEST(TransferConservation, ForcesHaveTheTotalAndFirstMomentOfTheStress3D) {
  expect_force_moments<3>();
}

TEST(TransferConservation, MassAndMomentumThroughTheGrid2D) {
  expect_conserved<2>();
}

TEST(TransferConservation, MassAndMomentumThroughTheGrid3D) {
  expect_conserved<3>();
}

// APIC's transfers dissipate kinetic energy; with a thermal model present the transfer keeps,
// per point, what it removed (½ m (r_in + r_out), transfer_impl.hpp), so that
//   KE_points(before) + ΔKE_grid(forces) = KE_points(after) + Σ_p m_p heat_p
// holds to round-off, whatever the grid update did (here random velocity changes Δv_i, with
// ΔKE_grid = Σ_i ½ m_i (|ṽ_i + Δv_i|² − |ṽ_i|²)); with the B-splines' least-squares affine
// fit every point's heat is ≥ 0 (the gradient form of UGIMP can give energy back).
template <int D>
void expect_heat_balances_kinetic_energy() {
  for (const auto& kernel : kernel_choices<D>()) {
    if (!kernel.offers_apic) continue;
    Cloud<D> c(kernel, VelocityUpdate::apic, true);
    const std::string what = kernel.name + " " + std::to_string(D) + "D";
    const double before = c.point_kinetic_energy();
    c.grid.velocities_from_momentum();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    double grid_work = 0.0;
    for (long i = 0; i < c.grid.node_count(); ++i) {
      auto& dv = c.grid.velocity_change[i];
      for (int d = 0; d < D; ++d) dv[d] = c.grid.mass[i] > 0.0 ? u(rng) : 0.0;
      const Vec<D> mapped = c.grid.velocity[i];
      c.grid.velocity[i] += dv;
      grid_work += 0.5 * c.grid.mass[i] * (c.grid.velocity[i].squaredNorm() - mapped.squaredNorm());
    }
    PointFailure failure;
    c.transfer->to_points(c.grid, 0.0, c.points, failure);  // Δt = 0: D_p stays put
    ASSERT_LT(failure.point, 0) << what;
    const auto& heat = c.points.template named<double>(column_names::transfer_heat);
    double dissipated = 0.0;
    const bool least_squares = kernel.name.find("bspline") != std::string::npos;
    for (long p = 0; p < c.points.size(); ++p) {
      if (least_squares) {
        EXPECT_GE(heat[p], -1e-14) << what << ", point " << p;
      }
      dissipated += c.points.mass[p] * heat[p];
    }
    EXPECT_GT(dissipated, 1e-3 * before) << what;  // random velocities are far from affine
    EXPECT_NEAR(before + grid_work, c.point_kinetic_energy() + dissipated, 1e-12 * before) << what;
  }
}

TEST(TransferConservation, ApicHeatBalancesKineticEnergy2D) {
  expect_heat_balances_kinetic_energy<2>();
}

TEST(TransferConservation, ApicHeatBalancesKineticEnergy3D) {
  expect_heat_balances_kinetic_energy<3>();
}

}  // namespace
}  // namespace pellicle
