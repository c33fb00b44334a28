#include "pellicle/mpm/enclosed_body.hpp"

#include "pellicle/mpm/body_as_built.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace pellicle {

namespace {

//! The membrane's positions in the order its points were built: its range on one process; in
//! a distributed run every rank's points, placed by their index in the body as built.
template <int D>
std::vector<Vec<D>> membrane_as_built(const Particles<D>& points, int membrane,
                                      const Collective* ranks) {
  const auto& body = points.bodies[membrane];
  const std::vector<double> x = body_as_built(
      points, body.begin, body.end, D,
      [&](long p, std::vector<double>& out) {
        out.insert(out.end(), points.position[p].data(), points.position[p].data() + D);
      },
      ranks);
  std::vector<Vec<D>> out(x.size() / D);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec<D>(x.data() + i * D);
  return out;
}

}  // namespace

template <int D>
double enclosed_volume(const Particles<D>& points, const EnclosedBody<D>& pair,
                       Kinematics kinematics, const Collective* ranks) {
  const std::vector<Vec<D>> x = membrane_as_built(points, pair.membrane, ranks);
  Vec<D> c = Vec<D>::Zero();  // on every mirror plane (one per axis is all a closed shape uses)
  for (const auto& m : pair.mirrors) c[m.axis] = m.position;
  double sum = 0.0;
  if constexpr (D == 2) {
    const long n = static_cast<long>(x.size());
    const long segments = pair.connectivity.closed_curve ? n : n - 1;
    for (long i = 0; i < segments; ++i) {
      const Vec2 a = x[i], b = x[(i + 1) % n];
      if (kinematics == Kinematics::axisymmetric)  // ∫ r² dz along the segment, r linear
        sum += std::numbers::pi * (a.x() * a.x() + a.x() * b.x() + b.x() * b.x()) / 3.0 *
               (b.y() - a.y());
      else  // ½ (x − c) × (b − a): the segment's share of ½ ∮ (x − c)·n ds, exact
        sum += 0.5 * ((0.5 * (a + b) - c).x() * (b.y() - a.y()) -
                      (0.5 * (a + b) - c).y() * (b.x() - a.x()));
    }
  } else {
    for (const auto& t : pair.connectivity.triangles) {
      const Vec3 a = x[t[0]] - c, b = x[t[1]] - c, cc = x[t[2]] - c;
      sum += a.dot(b.cross(cc)) / 6.0;  // the tetrahedron (c, a, b, cc)
    }
  }
  return std::abs(sum);
}

template <int D>
double mean_tension(const Particles<D>& points, const EnclosedBody<D>& pair,
                    const Collective* ranks) {
  const auto& body = points.bodies[pair.membrane];
  const auto& tangent = points.template named<Vec<D>>(column_names::tangent);
  const auto& normal = points.template named<Vec<D>>(column_names::normal);
  double weighted = 0.0, mass = 0.0;
  for (long p = body.begin; p < body.end; ++p) {
    const Mat3 s = to_mat3<D>(points.stress[p]);
    Vec3 t = Vec3::Zero(), n = Vec3::Zero();
    t.template head<D>() = tangent[p];
    n.template head<D>() = normal[p];
    const double in_surface = D == 2 ? t.dot(s * t) : 0.5 * (s.trace() - n.dot(s * n));
    weighted += points.mass[p] * in_surface;
    mass += points.mass[p];
  }
  std::vector<double> sums = {weighted, mass};
  if (ranks) ranks->sum_in_rank_order(sums);
  return sums[1] > 0.0 ? pair.thickness * sums[0] / sums[1] : 0.0;
}

template <int D>
long escaped_points(const Particles<D>& points, const EnclosedBody<D>& pair,
                    const Collective* ranks) {
  const std::vector<Vec<D>> membrane = membrane_as_built(points, pair.membrane, ranks);
  const auto& filler = points.bodies[pair.filler];
  const Enclosure<D> enclosure(membrane, 0, static_cast<long>(membrane.size()), pair.connectivity,
                               pair.mirrors, pair.tolerance);
  long outside = 0;
#pragma omp parallel for reduction(+ : outside) schedule(static)
  for (long p = filler.begin; p < filler.end; ++p)
    if (!enclosure.inside(points.position[p])) ++outside;
  std::vector<long> total = {outside};
  if (ranks) ranks->sum(total);
  return total[0];
}

template double enclosed_volume<2>(const Particles<2>&, const EnclosedBody<2>&, Kinematics,
                                   const Collective*);
template double enclosed_volume<3>(const Particles<3>&, const EnclosedBody<3>&, Kinematics,
                                   const Collective*);
template double mean_tension<2>(const Particles<2>&, const EnclosedBody<2>&, const Collective*);
template double mean_tension<3>(const Particles<3>&, const EnclosedBody<3>&, const Collective*);
template long escaped_points<2>(const Particles<2>&, const EnclosedBody<2>&, const Collective*);
template long escaped_points<3>(const Particles<3>&, const EnclosedBody<3>&, const Collective*);

}  // namespace pellicle
