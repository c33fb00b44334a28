#include "pellicle/io/probes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pellicle {

template <int D>
Probe<D>::Probe(const ProbeSpec<D>& spec, const Simulation<D>& simulation) : spec_(spec) {
  const auto& bodies = simulation.points().bodies;
  const BodyInfo<D>* body = nullptr;
  for (const auto& b : bodies)
    if (b.name == spec.body) body = &b;
  if (!body) throw InputError(spec.where, "probe.body", "no body named \"" + spec.body + "\"");
  for (long index : {spec.a, spec.b})
    if (index < 0 || index >= body->count())
      throw InputError(spec.where, "probe.point",
                       "probe '" + spec.name + "': body '" + spec.body + "' has no point " +
                           std::to_string(index) + " (it has " + std::to_string(body->count()) +
                           ")");
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
std::vector<double> Probe<D>::values(const Simulation<D>& s) const {
  const auto& p = s.points();
  if (spec_.quantity == ProbeQuantity::angle) {
    const Vec<D> d = p.position[b_] - p.position[a_];
    const Vec<D>& r = spec_.reference;
    double angle;
    if constexpr (D == 2) {
      angle = std::atan2(r.x() * d.y() - r.y() * d.x(), r.dot(d));  // signed, counter-clockwise
    } else {
      angle = std::acos(std::clamp(r.dot(d) / (r.norm() * d.norm()), -1.0, 1.0));
    }
    return {angle * 180.0 / std::numbers::pi};
  }
  if (spec_.quantity == ProbeQuantity::radius) return {(p.position[a_] - spec_.reference).norm()};
  const Vec<D>& v = spec_.quantity == ProbeQuantity::position ? p.position[a_] : p.velocity[a_];
  return std::vector<double>(v.data(), v.data() + D);
}

template class Probe<2>;
template class Probe<3>;

}  // namespace pellicle
