#include "pellicle/surface/wave.hpp"

#include <cstdio>

#include "pellicle/surface/pde_rows.hpp"

namespace pellicle {

namespace {

template <int D>
class Wave final : public SurfacePde<D> {
 public:
  explicit Wave(ParameterReader& in)
      : speed_(in.number("speed", NumberRange::positive())),
        source_(read_formula_or(in, "source", "0")),
        initial_(read_formula(in, "initial")),
        initial_rate_(read_formula_or(in, "initial_rate", "0")),
        exact_(read_formula_or(in, "exact", "")) {}

  std::string describe() const override {
    char text[256];
    std::snprintf(text, sizeof text, "wave (eq 42), c = %g, source %s", speed_,
                  source_.text().c_str());
    return text;
  }
  int unknown() const override { return phi_; }
  const PointFormula* exact() const override { return exact_.empty() ? nullptr : &exact_; }

  void initialise(SurfaceSimulation<D>& s) override {
    auto& cloud = s.cloud();
    phi_ = cloud.add_field("phi");
    previous_ = cloud.add_field("phi_previous");
    forcing_ = cloud.add_field("forcing");
    const double dt = s.settings().dt;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const PointValues v = s.values_at(i, s.time());
      cloud.field(phi_)[i] = initial_(v);
      cloud.field(previous_)[i] = initial_(v) - dt * initial_rate_(v);  // eq 44
    }
  }

  void before_move(SurfaceSimulation<D>& s) override {
    auto& cloud = s.cloud();
    std::vector<double>& f = cloud.field(forcing_);
    const long n = static_cast<long>(cloud.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) f[i] = source_(s.values_at(i, s.time()));  // fⁿ at xⁿ
  }

  void advance(SurfaceSimulation<D>& s, double dt, const std::vector<double>& divergence) override {
    auto& cloud = s.cloud();
    const auto& nb = s.neighbours();
    const auto& st = s.stencils();
    const long n = static_cast<long>(cloud.size());
    auto& values = s.system().values;
    values.resize(nb.index.size());
    rhs_.resize(n);
    std::vector<double>& phi = cloud.field(phi_);
    std::vector<double>& previous = cloud.field(previous_);
    const std::vector<double>& f = cloud.field(forcing_);
    const double c2 = speed_ * speed_;
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      operator_row(nb, st, i, 1.0 / (dt * dt) + divergence[i] / dt, c2, cloud.boundary[i] != 0,
                   values);
      rhs_[i] = (2.0 * phi[i] - previous[i]) / (dt * dt) + divergence[i] * phi[i] / dt + f[i];
    }
    next_ = phi;
    s.record_solve(s.system().solve(nb, rhs_, next_, s.settings().solver));
    previous.swap(phi);  // φⁿ⁻¹ ← φⁿ
    phi.swap(next_);     // φⁿ ← φⁿ⁺¹
  }

 private:
  double speed_;
  PointFormula source_, initial_, initial_rate_, exact_;
  int phi_ = -1, previous_ = -1, forcing_ = -1;
  std::vector<double> rhs_, next_;
};

}  // namespace

template <int D>
std::unique_ptr<SurfacePde<D>> make_wave(ParameterReader& in) {
  return std::make_unique<Wave<D>>(in);
}

template std::unique_ptr<SurfacePde<2>> make_wave<2>(ParameterReader&);
template std::unique_ptr<SurfacePde<3>> make_wave<3>(ParameterReader&);

}  // namespace pellicle
