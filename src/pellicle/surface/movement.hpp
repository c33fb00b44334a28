#pragma once
//! Lagrangian movement of a point cloud with its velocity (Suchde & Kuhnert §3.1): first
//! order, x⁽ⁿ⁺¹⁾ = x⁽ⁿ⁾ + v⁽ⁿ⁾ Δt (eq 2), or second order,
//! x⁽ⁿ⁺¹⁾ = x⁽ⁿ⁾ + v⁽ⁿ⁾ Δt + ½ (v⁽ⁿ⁾ − v⁽ⁿ⁻¹⁾) Δt (eq 3), which falls back to eq 2 at points
//! without a previous velocity (the first step, new points without one).

#include "pellicle/surface/point_cloud.hpp"

namespace pellicle {

enum class MovementOrder { first, second };

//! Move every point with `cloud.velocity`, then keep that velocity as the previous one.
template <int D>
void move_points(PointCloud<D>& cloud, double dt, MovementOrder order) {
  const long n = static_cast<long>(cloud.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const Vec<D>& v = cloud.velocity[i];
    Vec<D> step = v * dt;
    if (order == MovementOrder::second && cloud.has_previous_velocity[i])
      step += 0.5 * (v - cloud.previous_velocity[i]) * dt;
    cloud.position[i] += step;
    cloud.previous_velocity[i] = v;
    cloud.has_previous_velocity[i] = 1;
  }
}

}  // namespace pellicle
