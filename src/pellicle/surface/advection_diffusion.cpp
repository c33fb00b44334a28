#include "pellicle/surface/advection_diffusion.hpp"

#include <cstdio>

#include "pellicle/surface/pde_rows.hpp"

namespace pellicle {

namespace {

template <int D>
class AdvectionDiffusion final : public SurfacePde<D> {
 public:
  explicit AdvectionDiffusion(ParameterReader& in)
      : alpha_(in.number_or("diffusion", 0.0, NumberRange::non_negative())),
        reaction_(read_formula_or(in, "reaction", "0")),
        source_(read_formula_or(in, "source", "0")),
        initial_(read_formula(in, "initial")),
        exact_(read_formula_or(in, "exact", "")),
        boundary_(in.choice("boundary", {"zero-flux", "dirichlet"}, "zero-flux") == "dirichlet"
                      ? SurfaceBoundary::dirichlet
                      : SurfaceBoundary::zero_flux),
        boundary_value_(read_formula_or(in, "boundary_value", "")) {
    if (boundary_ == SurfaceBoundary::dirichlet && boundary_value_.empty() && exact_.empty())
      in.fail("boundary_value",
              "expected a formula: boundary = \"dirichlet\" needs boundary_value (or exact)");
  }

  std::string describe() const override {
    char text[256];
    std::snprintf(text, sizeof text, "advection-diffusion (eq 28), α = %g, reaction %s, source %s",
                  alpha_, reaction_.text().c_str(), source_.text().c_str());
    return text;
  }
  int unknown() const override { return phi_; }
  const PointFormula* exact() const override { return exact_.empty() ? nullptr : &exact_; }

  void initialise(SurfaceSimulation<D>& s) override {
    auto& cloud = s.cloud();
    phi_ = cloud.add_field("phi");
    for (std::size_t i = 0; i < cloud.size(); ++i)
      cloud.field(phi_)[i] = initial_(s.values_at(i, s.time()));
  }

  void advance(SurfaceSimulation<D>& s, double dt, const std::vector<double>& divergence) override {
    auto& cloud = s.cloud();
    const auto& nb = s.neighbours();
    const auto& st = s.stencils();
    const long n = static_cast<long>(cloud.size());
    const double t = s.time();
    auto& values = s.system().values;
    values.resize(nb.index.size());
    rhs_.resize(n);
    std::vector<double>& phi = cloud.field(phi_);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      const PointValues v = s.values_at(i, t);  // φ = φⁿ for the explicit source
      if (cloud.boundary[i] && boundary_ == SurfaceBoundary::dirichlet) {
        value_row(nb, i, values);
        rhs_[i] = (boundary_value_.empty() ? exact_ : boundary_value_)(v);
        continue;
      }
      operator_row(nb, st, i, 1.0 / dt + divergence[i] - reaction_(v), alpha_,
                   cloud.boundary[i] != 0, values);
      rhs_[i] = phi[i] / dt + source_(v);
    }
    s.record_solve(s.system().solve(nb, rhs_, phi, s.settings().solver));
  }

 private:
  double alpha_;
  PointFormula reaction_, source_, initial_, exact_;
  SurfaceBoundary boundary_;
  PointFormula boundary_value_;
  int phi_ = -1;
  std::vector<double> rhs_;
};

}  // namespace

template <int D>
std::unique_ptr<SurfacePde<D>> make_advection_diffusion(ParameterReader& in) {
  return std::make_unique<AdvectionDiffusion<D>>(in);
}

template std::unique_ptr<SurfacePde<2>> make_advection_diffusion<2>(ParameterReader&);
template std::unique_ptr<SurfacePde<3>> make_advection_diffusion<3>(ParameterReader&);

}  // namespace pellicle
