#include "pellicle/app/validation/signals.hpp"

namespace pellicle::validation {

std::vector<double> sign_changes(const std::vector<double>& t, const std::vector<double>& f) {
  std::vector<double> out;
  for (std::size_t i = 1; i < f.size(); ++i)
    if ((f[i - 1] < 0.0) != (f[i] < 0.0))
      out.push_back(t[i - 1] + (t[i] - t[i - 1]) * f[i - 1] / (f[i - 1] - f[i]));
  return out;
}

double slope_per_index(const std::vector<double>& y) {
  const double n = static_cast<double>(y.size());
  double sk = 0, sy = 0, skk = 0, sky = 0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    sk += k;
    sy += y[k];
    skk += double(k) * k;
    sky += k * y[k];
  }
  return (n * sky - sk * sy) / (n * skk - sk * sk);
}

}  // namespace pellicle::validation
