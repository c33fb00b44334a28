//! The material registry: adding a model is one new file and one line here.
#include "pellicle/mpm/materials/fluid.hpp"
#include "pellicle/mpm/materials/j2_plasticity.hpp"
#include "pellicle/mpm/materials/linear_elastic.hpp"
#include "pellicle/mpm/materials/material.hpp"
#include "pellicle/mpm/materials/membrane.hpp"
#include "pellicle/mpm/materials/rigid.hpp"

namespace pellicle {

template <int D>
const std::vector<MaterialModel<D>>& material_models() {
  static const std::vector<MaterialModel<D>> models = {
      {"linear-elastic", "isotropic linear elasticity, Jaumann stress rate (IJNME eqs 2, 14)",
       &make_linear_elastic<D>},
      {"j2-plasticity", "von Mises plasticity, linear hardening, radial return (plasticity.md)",
       &make_j2_plasticity<D>},
      {"membrane", "strings and membranes in their local frame (thesis ch. 5, IJNME §3)",
       &make_membrane<D>},
      {"rigid", "rigid body with a prescribed constant velocity; imposes it on its nodes",
       &make_rigid<D>},
      {"gas", "compressible viscous ideal gas with energy equation (thesis ch. 4, eqs 4.1–4.12)",
       &make_gas<D>},
      {"barotropic-liquid", "compressible liquid p = −β tr ε (thesis eq 6.1)",
       &make_barotropic_liquid<D>},
      {"tait-liquid", "compressible liquid p = K0/n [(ρ/ρ0)^n − 1] (Tait)", &make_tait_liquid<D>},
  };
  return models;
}

template const std::vector<MaterialModel<2>>& material_models<2>();
template const std::vector<MaterialModel<3>>& material_models<3>();

}  // namespace pellicle
