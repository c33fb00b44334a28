#pragma once
//! Small signal tools for validation measurements.

#include <vector>

namespace pellicle::validation {

//! Times at which a sampled signal changes sign (linear interpolation between samples).
std::vector<double> sign_changes(const std::vector<double>& t, const std::vector<double>& f);
//! Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y);
//! Least-squares slope of y against its index 0, 1, 2, …
double slope_per_index(const std::vector<double>& y);

}  // namespace pellicle::validation
