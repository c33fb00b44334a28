#include "pellicle/mpm/contact/body_fields.hpp"

namespace pellicle {

template <int D>
void BodyFields<D>::to_grid(Transfer<D>& transfer, const Particles<D>& points,
                            const Vec<D>& gravity, Grid<D>& centre_of_mass) {
  const long nodes = centre_of_mass.node_count();
  for (int b = 0; b < body_count(); ++b) {
    const auto& body = points.bodies[b];
    transfer.to_grid(points, gravity, grids_[b], true, {body.begin, body.end});
  }
#pragma omp parallel for schedule(static)
  for (long n = 0; n < nodes; ++n) {
    double mass = 0.0;
    Vec<D> momentum = Vec<D>::Zero(), force = Vec<D>::Zero();
    for (const auto& g : grids_) {
      mass += g.mass[n];
      momentum += g.momentum[n];
      force += g.force[n];
    }
    centre_of_mass.mass[n] = mass;
    centre_of_mass.momentum[n] = momentum;
    centre_of_mass.force[n] = force;
  }
}

template <int D>
void BodyFields<D>::integrate(double dt) {
  for (auto& g : grids_) g.integrate(dt);
}

template <int D>
double BodyFields<D>::to_points(Transfer<D>& transfer, double dt, Particles<D>& points,
                                PointFailure& failure) {
  double fastest = 0.0;
  for (int b = 0; b < body_count() && failure.point < 0; ++b) {
    const auto& body = points.bodies[b];
    fastest = std::max(fastest,
                       transfer.to_points(grids_[b], dt, points, failure, {body.begin, body.end}));
  }
  return fastest;
}

template <int D>
void BodyFields<D>::remap(Transfer<D>& transfer, const Particles<D>& points,
                          Grid<D>& centre_of_mass) {
  for (int b = 0; b < body_count(); ++b)
    transfer.remap(points, grids_[b], {points.bodies[b].begin, points.bodies[b].end});
  const long nodes = centre_of_mass.node_count();
#pragma omp parallel for schedule(static)
  for (long n = 0; n < nodes; ++n) {
    Vec<D> momentum = Vec<D>::Zero();
    for (const auto& g : grids_) momentum += g.momentum[n];
    centre_of_mass.momentum[n] = momentum;
  }
  centre_of_mass.velocities_from_momentum();
}

template <int D>
long BodyFields<D>::point_kinematics(Transfer<D>& transfer, double dt, Particles<D>& points,
                                     std::vector<Mat<D>>& gradient,
                                     std::vector<double>& hoop_rate) {
  for (int b = 0; b < body_count(); ++b) {
    const auto& body = points.bodies[b];
    const long bad = transfer.point_kinematics(grids_[b], dt, points, gradient, hoop_rate,
                                               {body.begin, body.end});
    if (bad >= 0) return bad;
  }
  return -1;
}

template <int D>
void BodyFields<D>::colour_functions(const Particles<D>& points) {
  // Eq 27 / 9.10 with each point's colour its volume: the colour function is a smoothed
  // volume of its body per cell (its scale does not matter, only its gradient's direction).
  for (int b = 0; b < body_count(); ++b) {
    const auto& body = points.bodies[b];
    colour_[b].assign(cell_count(grids_[b]), 0.0);
    spread_to_cells(grids_[b], points.position, points.volume, body.begin, body.end, colour_[b]);
  }
}

template <int D>
Vec<D> BodyFields<D>::outward_normal(int body, long node) const {
  // Eq 28 / 9.11: the colour falls off outward, so the outward normal is −∇χ / |∇χ|.
  const Vec<D> gradient = cell_gradient_at_node(grids_[body], colour_[body], node);
  const double length = gradient.norm();
  return length > 0.0 ? Vec<D>(-gradient / length) : Vec<D>::Zero();
}

template class BodyFields<2>;
template class BodyFields<3>;

}  // namespace pellicle
