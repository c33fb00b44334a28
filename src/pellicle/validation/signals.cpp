#include "pellicle/validation/signals.hpp"

namespace pellicle::validation {

std::vector<double> sign_changes(const std::vector<double>& t, const std::vector<double>& f) {
  std::vector<double> out;
  for (std::size_t i = 1; i < f.size(); ++i)
    if ((f[i - 1] < 0.0) != (f[i] < 0.0))
      out.push_back(t[i - 1] + (t[i] - t[i - 1]) * f[i - 1] / (f[i - 1] - f[i]));
  return out;
}

double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(y.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    sx += x[k];
    sy += y[k];
    sxx += x[k] * x[k];
    sxy += x[k] * y[k];
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

double slope_per_index(const std::vector<double>& y) {
  std::vector<double> index(y.size());
  for (std::size_t k = 0; k < y.size(); ++k) index[k] = static_cast<double>(k);
  return slope(index, y);
}

}  // namespace pellicle::validation
