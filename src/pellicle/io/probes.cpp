#include "pellicle/io/probes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pellicle {

template <int D>
Probe<D>::Probe(const ProbeSpec<D>& spec, const Simulation<D>& simulation) : spec_(spec) {
  const auto& bodies = simulation.points().bodies;
  const BodyInfo<D>* body = nullptr;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].name == spec.body) body = &bodies[b], body_ = static_cast<int>(b);
  if (!body) throw InputError(spec.where, "probe.body", "no body named \"" + spec.body + "\"");
  for (long index : {spec.a, spec.b})  // of the whole body, as built (a rank holds a part)
    if (index < 0 || index >= body->built)
      throw InputError(spec.where, "probe.point",
                       "probe '" + spec.name + "': body '" + spec.body + "' has no point " +
                           std::to_string(index) + " (it has " + std::to_string(body->built) + ")");
  a_ = body->begin + spec.a;
  b_ = body->begin + spec.b;
}

template <int D>
std::vector<std::string> Probe<D>::columns() const {
  if (spec_.quantity == ProbeQuantity::angle || spec_.quantity == ProbeQuantity::radius)
    return {spec_.name};
  std::vector<std::string> out;
  for (int d = 0; d < D; ++d) out.push_back(spec_.name + "." + "xyz"[d]);
  return out;
}

template <int D>
typename Probe<D>::Probed Probe<D>::probed(const Simulation<D>& s) const {
  const auto& p = s.points();
  const Collective* ranks = s.collective();
  if (!ranks) return {p.position[a_], p.velocity[a_], p.position[b_]};
  // This rank's points of the body give what they hold; one rank holds each point, so the
  // sum over the ranks is exact.
  std::vector<double> sums(3 * D, 0.0);
  const auto& index = p.template named<double>(column_names::body_index);
  const BodyInfo<D>& body = p.bodies[body_];
  for (long i = body.begin; i < body.end; ++i) {
    if (index[i] == spec_.a) {
      std::copy_n(p.position[i].data(), D, sums.data());
      std::copy_n(p.velocity[i].data(), D, sums.data() + D);
    }
    if (index[i] == spec_.b) std::copy_n(p.position[i].data(), D, sums.data() + 2 * D);
  }
  ranks->sum_in_rank_order(sums);
  return {Vec<D>(sums.data()), Vec<D>(sums.data() + D), Vec<D>(sums.data() + 2 * D)};
}

template <int D>
std::vector<double> Probe<D>::values(const Simulation<D>& s) const {
  const Probed probe = probed(s);
  if (spec_.quantity == ProbeQuantity::angle) {
    const Vec<D> d = probe.position_b - probe.position_a;
    const Vec<D>& r = spec_.reference;
    double angle;
    if constexpr (D == 2) {
      angle = std::atan2(r.x() * d.y() - r.y() * d.x(), r.dot(d));  // signed, counter-clockwise
    } else {
      angle = std::acos(std::clamp(r.dot(d) / (r.norm() * d.norm()), -1.0, 1.0));
    }
    return {angle * 180.0 / std::numbers::pi};
  }
  if (spec_.quantity == ProbeQuantity::radius) return {(probe.position_a - spec_.reference).norm()};
  const Vec<D>& v = spec_.quantity == ProbeQuantity::position ? probe.position_a : probe.velocity_a;
  return std::vector<double>(v.data(), v.data() + D);
}

template class Probe<2>;
template class Probe<3>;

}  // namespace pellicle
