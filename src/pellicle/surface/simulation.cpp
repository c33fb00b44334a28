#include "pellicle/surface/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pellicle/core/error.hpp"
#include "pellicle/surface/chambers.hpp"
#include "pellicle/surface/quadrature.hpp"

namespace pellicle {

template <int D>
SurfaceSimulation<D>::SurfaceSimulation(PointCloud<D> cloud, SurfaceSettings settings,
                                        std::array<PointFormula, D> velocity,
                                        std::unique_ptr<SurfacePde<D>> pde,
                                        const std::vector<Vec<D>>* reference)
    : cloud_(std::move(cloud)),
      settings_(settings),
      velocity_(std::move(velocity)),
      pde_(std::move(pde)),
      search_(settings.rebuild_fraction) {
  if (settings_.minimum_neighbours == 0) settings_.minimum_neighbours = D == 3 ? 10 : 5;
  const ContactOptions& contact = settings_.contact;
  cloud_.facing_limit = contact.self_contact() ? contact.facing_limit : -2.0;
  // Delete contact joins chambers and goes on between their surfaces.
  const int surfaces =
      cloud_.size() ? *std::max_element(cloud_.surface.begin(), cloud_.surface.end()) + 1 : 0;
  for (int s = 0; s < surfaces; ++s)
    for (int t = s + 1; t < surfaces; ++t)
      if (contact.response(s, t) == ContactResponse::remove) cloud_.keep_apart(s, t);
  find_neighbours();
  estimate_frames(cloud_, neighbours_, settings_.frames, false);
  orient_consistently(cloud_, neighbours_, reference);  // the sweep of §3.2, once
  update_geometry(true);
  if (pde_) pde_->initialise(*this);
}

template <int D>
void SurfaceSimulation<D>::find_neighbours() {
  const int minimum = settings_.minimum_neighbours;
  // Repair where contact has cut a surface (or a pinching neck threw points off or
  // collapsed into a thread): stray pieces too small for a normal, and points whose part
  // has too few points within 2 h for a stencil, go; the pieces become chambers. A few
  // rounds, as each removal can leave others short.
  for (int round = 0;; ++round) {
    search_.find(cloud_, neighbours_, 1.0, minimum);
    if (!cloud_.has_parts()) {
      external_.offset.assign(cloud_.size() + 1, 0);
      external_.index.clear();
      return;
    }
    split_by_part(cloud_, neighbours_, &external_);  // S_i and S_i^ext of §3.6
    if (!settings_.contact.active()) {
      top_up_parts(cloud_, search_, neighbours_, minimum, short_of_);
      return;
    }
    const ChamberReport r = split_chambers(cloud_, neighbours_, external_, minimum + 1);
    debris_ += r.debris;
    if (r.debris > 0) continue;
    if (top_up_parts(cloud_, search_, neighbours_, minimum, short_of_) == 0 || round >= 16) return;
    debris_ += std::count(short_of_.begin(), short_of_.end(), 1);
    cloud_.remove_points(short_of_);
  }
}

template <int D>
void SurfaceSimulation<D>::update_geometry(bool keep_side) {
  find_neighbours();
  estimate_frames(cloud_, neighbours_, settings_.frames, keep_side);
  build_stencils(cloud_, neighbours_, settings_.gfdm, stencils_);
  if (settings_.refine_normals) {
    refine_normals(cloud_, neighbours_, stencils_);
    build_stencils(cloud_, neighbours_, settings_.gfdm, stencils_);
  }
  mean_curvature(cloud_, neighbours_, stencils_, curvature_);
  if (settings_.smooth_curvature) {
    // eq 40–41: a wide Gaussian average over the support, applied twice. Cut off at h, the
    // Gaussian's symbol changes sign at wavelengths near h, so one pass turns the curvature's
    // restoring term around for those modes and they grow (a sphere under mean-curvature
    // flow at h = 0.07: radius errors of 1e-6 at t = 0.1, 4e-4 at 0.2, then the cloud
    // breaks up); two passes have the squared symbol, which cannot turn negative (docs/theory/
    // surface-pdes.md).
    const long n = static_cast<long>(cloud_.size());
    smoothing_weights_.resize(neighbours_.index.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {  // W̃_ij / Σ_j W̃_ij, computed once for both passes
      double total = 0.0;
      for (long k = neighbours_.begin(i); k < neighbours_.end(i); ++k) {
        const int j = neighbours_.index[k];
        smoothing_weights_[k] =
            gaussian_weight((cloud_.position[j] - cloud_.position[i]).squaredNorm(),
                            cloud_.smoothing_length[i], 1.0);
        total += smoothing_weights_[k];
      }
      for (long k = neighbours_.begin(i); k < neighbours_.end(i); ++k)
        smoothing_weights_[k] /= total;
    }
    std::vector<double>& smooth = smoothed_;
    smooth.resize(curvature_.size());
    for (int pass = 0; pass < 2; ++pass) {
#pragma omp parallel for schedule(static)
      for (long i = 0; i < n; ++i) {
        double sum = 0.0;
        for (long k = neighbours_.begin(i); k < neighbours_.end(i); ++k)
          sum += smoothing_weights_[k] * curvature_[neighbours_.index[k]];
        smooth[i] = sum;
      }
      curvature_.swap(smooth);
    }
  }
  average_curvature();
}

template <int D>
void SurfaceSimulation<D>::average_curvature() {
  // κ̄ of eq 38, each chamber's average ∮ κ dA / ∮ dA over the points' one-ring areas, when
  // the velocity reads it (elsewhere the mean over points). The plain mean over points leans
  // toward where points crowd: an ellipsoid under the averaged flow gained 6.6 % of its volume
  // by t = 1 with it.
  const bool by_area = std::any_of(velocity_.begin(), velocity_.end(),
                                   [](const auto& f) { return f.reads_mean_curvature(); });
  if (by_area) point_areas(cloud_, neighbours_, areas_);
  const int chambers =
      cloud_.size() ? *std::max_element(cloud_.chamber.begin(), cloud_.chamber.end()) + 1 : 0;
  std::vector<double> total(chambers, 0.0);
  kappa_mean_.assign(chambers, 0.0);
  for (std::size_t i = 0; i < curvature_.size(); ++i) {
    const double a = by_area ? areas_[i] : 1.0;
    kappa_mean_[cloud_.chamber[i]] += a * curvature_[i];
    total[cloud_.chamber[i]] += a;
  }
  for (int c = 0; c < chambers; ++c)
    kappa_mean_[c] = total[c] > 0.0 ? kappa_mean_[c] / total[c] : 0.0;
}

template <int D>
PointValues SurfaceSimulation<D>::values_at(std::size_t i, double t) const {
  PointValues v;
  v.x = to_vec3<D>(cloud_.position[i]);
  v.n = to_vec3<D>(cloud_.normal(i));
  v.t = t;
  const int phi = pde_ ? pde_->unknown() : -1;
  v.phi = phi >= 0 ? cloud_.field(phi)[i] : 0.0;
  v.kappa = curvature_.empty() ? 0.0 : curvature_[i];
  v.kappa_mean = mean_curvature_value(i);
  v.h = cloud_.smoothing_length[i];
  return v;
}

template <int D>
void SurfaceSimulation<D>::evaluate_velocity(double t, std::vector<Vec<D>>& v) const {
  const long n = static_cast<long>(cloud_.size());
  v.resize(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const PointValues values = values_at(i, t);
    for (int d = 0; d < D; ++d) v[i][d] = velocity_[d](values);
  }
}

template <int D>
void SurfaceSimulation<D>::step() {
  try {
    advance_one_step();
  } catch (const NumericalError& e) {  // the stages know the point, not the time
    // A failure inside point management leaves the curvature of the old points: unknown now
    // (the snapshot written at the failure shows NaN rather than a misaligned array).
    if (curvature_.size() != cloud_.size())
      curvature_.assign(cloud_.size(), std::numeric_limits<double>::quiet_NaN());
    throw NumericalError({time_, steps_, "surface", e.context().point}, e.reason());
  }
  for (auto* o : observers_) o->after_step(*this);
}

template <int D>
void SurfaceSimulation<D>::advance_one_step() {
  const double dt = settings_.dt;
  if (pde_) pde_->before_move(*this);
  evaluate_velocity(time_, cloud_.velocity);    // 1. v⁽ⁿ⁾
  move_points(cloud_, dt, settings_.movement);  // 2. eq 3 (eq 2 first)
  time_ += dt;
  update_geometry(true);  // 3. frames keep their side (eq 5)
  resolve_contact();      // 3b. §3.6
  bool changed = last_contact_.changed();
  if (settings_.manage && management_due()) changed = manage() || changed;  // 4. §3.4–3.5
  if (changed) update_geometry(true);
  if (pde_) {         // 5. implicit step
    surface_rates();  // v⁽ⁿ⁺¹⁾ and ∇_M · v⁽ⁿ⁺¹⁾
    if (settings_.contact.active()) remove_unresolved();  // §3.6 repair
    pde_->advance(*this, dt, divergence_);
  }
  ++steps_;
  if (cloud_.has_parts() && split_chambers(cloud_, neighbours_, external_).split > 0)  // 6.
    average_curvature();  // κ̄ of each new chamber
  check_state();
}

template <int D>
void SurfaceSimulation<D>::resolve_contact() {
  last_contact_ = ContactReport{};
  if (!settings_.contact.active() || external_.index.empty()) {
    std::fill(cloud_.contact_side.begin(), cloud_.contact_side.end(), 0);
    return;
  }
  last_contact_ = resolve_contacts(cloud_, neighbours_, external_, settings_.contact,
                                   settings_.management.r_min);
  contact_total_.penetrated += last_contact_.penetrated;
  contact_total_.near += last_contact_.near;
  contact_total_.projected += last_contact_.projected;
  contact_total_.removed += last_contact_.removed;
  contact_total_.joined += last_contact_.joined;
}

template <int D>
bool SurfaceSimulation<D>::manage() {
  const ManagementReport r = manage_points(cloud_, search_, settings_.management, settings_.frames);
  managed_at_ = cloud_.position;
  managed_generation_ = cloud_.generation();
  management_total_.added += r.added;
  management_total_.merged += r.merged;
  management_total_.removed += r.removed;
  return r.changed();
}

template <int D>
void SurfaceSimulation<D>::surface_rates() {
  evaluate_velocity(time_, next_velocity_);
  const long n = static_cast<long>(cloud_.size());
  divergence_.resize(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
    divergence_[i] = surface_divergence(neighbours_, stencils_, i, next_velocity_);
}

template <int D>
void SurfaceSimulation<D>::remove_unresolved() {
  // Points where the PDE's implicit row would amplify instead of damp: a Laplacian whose
  // centre coefficient is not negative even under the broadest weight and, at the rim of a
  // part, with zero flux across it (gfdm.cpp) — a fold or thread narrower than the cloud;
  // and a point whose area would vanish within the step, Δt ∇_M · v ≤ −1 — a band the
  // velocity crushes (docs/theory/surface-contact.md, "Folds"). They go like the repair's
  // thread points; point management then fills the gap from the sheets around it. A few
  // rounds, as a removal can expose others.
  const double dt = settings_.dt;
  for (int round = 0; round < 8; ++round) {
    short_of_.assign(cloud_.size(), 0);
    long count = 0;
    for (std::size_t i = 0; i < cloud_.size(); ++i) {
      const bool unresolved =
          !cloud_.boundary[i] && !(stencils_.laplacian[neighbours_.begin(i)] < 0.0);
      const bool crushed = !(dt * divergence_[i] > -1.0);
      if (unresolved || crushed) {
        short_of_[i] = 1;
        ++count;
      }
    }
    if (count == 0) return;
    debris_ += count;
    cloud_.remove_points(short_of_);
    if (settings_.manage) {
      update_geometry(true);
      manage();
    }
    update_geometry(true);
    surface_rates();
  }
}

template <int D>
bool SurfaceSimulation<D>::management_due() const {
  if (managed_generation_ != cloud_.generation() || managed_at_.size() != cloud_.size())
    return true;
  for (std::size_t i = 0; i < cloud_.size(); ++i)
    if ((cloud_.position[i] - managed_at_[i]).norm() >
        settings_.management_interval * cloud_.smoothing_length[i])
      return true;
  return false;
}

template <int D>
void SurfaceSimulation<D>::check_state() const {
  const int phi = pde_ ? pde_->unknown() : -1;
  for (std::size_t i = 0; i < cloud_.size(); ++i) {
    const bool bad_position = !cloud_.position[i].allFinite();
    if (bad_position || (phi >= 0 && !std::isfinite(cloud_.field(phi)[i])))
      throw NumericalError({time_, steps_, "surface", static_cast<long>(i)},
                           bad_position ? "a point's position is not finite"
                                        : "the solution is not finite at a point");
  }
}

template <int D>
void SurfaceSimulation<D>::run() {
  while (!finished()) step();
}

template <int D>
void SurfaceSimulation<D>::remove_observer(SurfaceObserver<D>* o) {
  observers_.erase(std::remove(observers_.begin(), observers_.end(), o), observers_.end());
}

template class SurfaceSimulation<2>;
template class SurfaceSimulation<3>;

}  // namespace pellicle
