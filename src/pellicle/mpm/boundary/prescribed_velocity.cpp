#include "pellicle/mpm/boundary/prescribed_velocity.hpp"

#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

template <int D>
void PrescribedVelocity<D>::after_to_grid(Simulation<D>& simulation) {
  if (simulation.time() >= until_) return;
  auto& fields = simulation.fields();
  const Grid<D>& grid = fields.centre_of_mass();
  if (nodes_.empty()) {
    const double slack = 1e-9 * grid.cell();
    for (long n = 0; n < grid.node_count(); ++n) {
      const Vec<D> x = grid.node_position(n);
      if ((x.array() >= lower_.array() - slack).all() &&
          (x.array() <= upper_.array() + slack).all())
        nodes_.emplace_back(n, velocity_);
    }
  }
  fields.for_each_grid([&](Grid<D>& g) { g.prescribe(nodes_); });
}

template <int D>
std::unique_ptr<StepHook<D>> make_prescribed_velocity(ParameterReader& in) {
  auto vector = [&](const char* key) {
    const auto v = in.numbers(key, D, NumberRange::any());
    Vec<D> out = Vec<D>::Zero();
    for (int d = 0; d < D && d < static_cast<int>(v.size()); ++d) out[d] = v[d];
    return out;
  };
  const Vec<D> lower = vector("lower"), upper = vector("upper"), velocity = vector("velocity");
  if (!((upper.array() >= lower.array()).all()))
    in.fail("upper", "expected every component at or above lower");
  const double until =
      in.number_or("until", std::numeric_limits<double>::infinity(), NumberRange::positive());
  return std::make_unique<PrescribedVelocity<D>>(lower, upper, velocity, until);
}

template class PrescribedVelocity<2>;
template class PrescribedVelocity<3>;
template std::unique_ptr<StepHook<2>> make_prescribed_velocity<2>(ParameterReader&);
template std::unique_ptr<StepHook<3>> make_prescribed_velocity<3>(ParameterReader&);

}  // namespace pellicle
