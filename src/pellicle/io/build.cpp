#include "pellicle/io/build.hpp"

#include "pellicle/io/problem_size.hpp"

namespace pellicle {

template <int D>
std::unique_ptr<Simulation<D>> build_simulation(Case<D>& c, PointSelection<D> select) {
  refuse_oversized_problem(c);  // before anything is allocated
  SimulationBuilder<D> builder(c.lower, c.upper, c.cell, c.faces);
  builder.settings(c.settings).kernel(c.kernel, c.transfer).gravity(c.gravity);
  for (auto& material : c.materials) builder.material(std::move(material));
  // Copied, not moved: `check` describes the bodies after building.
  for (const auto& body : c.bodies) builder.body(static_cast<const BodySetup<D>&>(body));
  builder.contact(std::move(c.contact));
  for (auto& boundary : c.boundaries) builder.hook(std::move(boundary));
  if (select) builder.select_points(std::move(select));
  try {
    return builder.build();
  } catch (const BuildError& e) {  // the same problems, at the tables they come from
    std::vector<InputProblem> problems;
    for (const auto& p : e.problems()) {
      if (p.body >= 0)
        problems.push_back({c.bodies[p.body].where, "body." + p.key, p.message});
      else
        problems.push_back({SourceLocation{c.file, 0, 0}, "solver." + p.key, p.message});
    }
    throw InputError(problems);
  } catch (const SetupError& e) {
    throw InputError(SourceLocation{c.file, 0, 0}, "", e.what());
  }
}

template std::unique_ptr<Simulation<2>> build_simulation<2>(Case<2>&, PointSelection<2>);
template std::unique_ptr<Simulation<3>> build_simulation<3>(Case<3>&, PointSelection<3>);

}  // namespace pellicle
