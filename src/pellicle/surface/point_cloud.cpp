#include "pellicle/surface/point_cloud.hpp"

#include <algorithm>

namespace pellicle {

namespace {
template <class T>
void compact(std::vector<T>& values, const std::vector<std::uint8_t>& remove) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!remove[i]) values[kept++] = values[i];
  values.resize(kept);
}
}  // namespace

template <int D>
std::size_t PointCloud<D>::add_point(const Vec<D>& x, double h, bool on_boundary) {
  position.push_back(x);
  smoothing_length.push_back(h);
  frame.push_back(Mat<D>::Identity());
  boundary.push_back(on_boundary ? 1 : 0);
  boundary_normal.push_back(Vec<D>::Zero());
  corner.push_back(0);
  velocity.push_back(Vec<D>::Zero());
  previous_velocity.push_back(Vec<D>::Zero());
  has_previous_velocity.push_back(0);
  chamber.push_back(0);
  surface.push_back(0);
  contact_side.push_back(0);
  for (auto& values : field_values_) values.push_back(0.0);
  ++generation_;
  return position.size() - 1;
}

template <int D>
void PointCloud<D>::remove_points(const std::vector<std::uint8_t>& remove) {
  if (std::none_of(remove.begin(), remove.end(), [](std::uint8_t r) { return r != 0; })) return;
  compact(position, remove);
  compact(smoothing_length, remove);
  compact(frame, remove);
  compact(boundary, remove);
  compact(boundary_normal, remove);
  compact(corner, remove);
  compact(velocity, remove);
  compact(previous_velocity, remove);
  compact(has_previous_velocity, remove);
  compact(chamber, remove);
  compact(surface, remove);
  compact(contact_side, remove);
  for (auto& values : field_values_) compact(values, remove);
  ++generation_;
}

template <int D>
int PointCloud<D>::chamber_count() const {
  std::vector<int> ids(chamber);
  std::sort(ids.begin(), ids.end());
  return static_cast<int>(std::unique(ids.begin(), ids.end()) - ids.begin());
}

template <int D>
void PointCloud<D>::keep_apart(int s, int t) {
  const int size = std::max({apart_size_, s + 1, t + 1});
  if (size > apart_size_) {
    std::vector<std::uint8_t> grown(static_cast<std::size_t>(size) * size, 0);
    for (int a = 0; a < apart_size_; ++a)
      for (int b = 0; b < apart_size_; ++b) grown[a * size + b] = apart_[a * apart_size_ + b];
    apart_.swap(grown);
    apart_size_ = size;
  }
  apart_[s * apart_size_ + t] = apart_[t * apart_size_ + s] = 1;
}

template <int D>
bool PointCloud<D>::has_parts() const {
  const auto differs = [](const std::vector<int>& ids) {
    return std::any_of(ids.begin(), ids.end(), [&](int c) { return c != ids[0]; });
  };
  return facing_limit >= -1.0 || differs(chamber) || (apart_size_ > 0 && differs(surface));
}

template <int D>
int PointCloud<D>::add_field(const std::string& name, double initial) {
  const int existing = field_index(name);
  if (existing >= 0) return existing;
  field_names_.push_back(name);
  field_values_.emplace_back(size(), initial);
  return static_cast<int>(field_names_.size()) - 1;
}

template <int D>
int PointCloud<D>::field_index(const std::string& name) const {
  const auto it = std::find(field_names_.begin(), field_names_.end(), name);
  return it == field_names_.end() ? -1 : static_cast<int>(it - field_names_.begin());
}

template class PointCloud<2>;
template class PointCloud<3>;

}  // namespace pellicle
