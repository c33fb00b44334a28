//! The surface PDE registry: adding a PDE is one new file and one line here.
#include "pellicle/core/expression.hpp"
#include "pellicle/surface/advection_diffusion.hpp"
#include "pellicle/surface/wave.hpp"

namespace pellicle {

template <int D>
const std::vector<SurfacePdeModel<D>>& surface_pde_models() {
  static const std::vector<SurfacePdeModel<D>> models = {
      {"advection-diffusion",
       "Dφ/Dt + φ ∇_M·v = α Δ_M φ + kφ + s, implicit (Suchde & Kuhnert eqs 28–29)",
       &make_advection_diffusion<D>},
      {"wave", "D²φ/Dt² + Dφ/Dt ∇_M·v = c² Δ_M φ + f, implicit (eqs 42–45)", &make_wave<D>},
  };
  return models;
}

PointFormula read_formula_or(ParameterReader& in, std::string_view key, std::string_view fallback) {
  const std::string text = in.has(key) ? in.text(key) : std::string(fallback);
  if (text.empty()) return {};
  try {
    return PointFormula(text);
  } catch (const ExpressionError& e) {
    in.fail(key, "column " + std::to_string(e.column()) + " of the formula: " + e.what());
    return {};
  }
}

PointFormula read_formula(ParameterReader& in, std::string_view key) {
  if (!in.has(key)) {
    in.text(key);  // records the missing key
    return {};
  }
  return read_formula_or(in, key, "");
}

template const std::vector<SurfacePdeModel<2>>& surface_pde_models<2>();
template const std::vector<SurfacePdeModel<3>>& surface_pde_models<3>();

}  // namespace pellicle
