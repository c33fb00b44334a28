#include "pellicle/mpm/grid.hpp"

#include <cmath>
#include <stdexcept>

namespace pellicle {

template <int D>
Grid<D>::Grid(const Vec<D>& lower, const Vec<D>& upper, double cell, const FaceConditions<D>& faces,
              Shape)
    : lower_(lower), upper_(upper), h_(cell), inv_h_(1.0 / cell), faces_(faces) {
  for (int d = 0; d < D; ++d)
    cells_[d] = static_cast<int>(std::lround((upper[d] - lower[d]) / cell));
  origin_ = lower_ - Vec<D>::Constant(kGhost * h_);
}

template <int D>
Grid<D>::Grid(const Vec<D>& lower, const Vec<D>& upper, double cell, const FaceConditions<D>& faces)
    : Grid(lower, upper, cell, faces, Shape{}) {
  allocate(IVec<D>::Zero(), cells_ + IVec<D>::Constant(1 + 2 * kGhost));
}

template <int D>
Grid<D> Grid<D>::without_storage(const Vec<D>& lower, const Vec<D>& upper, double cell,
                                 const FaceConditions<D>& faces) {
  Grid<D> g(lower, upper, cell, faces, Shape{});
  g.set_extent(IVec<D>::Zero(), g.cells_ + IVec<D>::Constant(1 + 2 * kGhost));
  return g;
}

template <int D>
Grid<D> Grid<D>::window(const IVec<D>& first, const IVec<D>& last, const IVec<D>& owned_first,
                        const IVec<D>& owned_last) const {
  for (int d = 0; d < D; ++d)
    if (first[d] < 0 || last[d] > cells_[d] + 2 * kGhost || last[d] < first[d] ||
        owned_first[d] < first[d] || owned_last[d] > last[d])
      throw std::invalid_argument(
          "a grid window must lie within the grid, its owned nodes within it");
  Grid<D> w(lower_, upper_, h_, faces_, Shape{});  // not a copy: the storage is the window's
  w.allocate(first, last - first + IVec<D>::Ones());
  w.owned_first_ = owned_first;
  w.owned_last_ = owned_last;
  return w;
}

template <int D>
void Grid<D>::set_extent(const IVec<D>& first, const IVec<D>& count) {
  first_ = owned_first_ = first;
  nodes_ = count;
  owned_last_ = first + count - IVec<D>::Ones();
  node_count_ = 1;
  for (int d = 0; d < D; ++d) {
    strides_[d] = node_count_;
    node_count_ *= nodes_[d];
  }
}

template <int D>
void Grid<D>::allocate(const IVec<D>& first, const IVec<D>& count) {
  set_extent(first, count);
  mass.assign(node_count_, 0.0);
  momentum.assign(node_count_, Vec<D>::Zero());
  force.assign(node_count_, Vec<D>::Zero());
  velocity.assign(node_count_, Vec<D>::Zero());
  velocity_change.assign(node_count_, Vec<D>::Zero());
  constraints_.clear();
  mirrors_.clear();
  group_ends_.clear();
  prescribed_.clear();
  live_.assign(row_count(), NodeSpan{0, nodes_[0] - 1});
  live_parts_.clear();

  // Nodes on a constrained face take the face's condition; corners collect the conditions of
  // every face they touch.
  for (long n = 0; n < node_count_; ++n) {
    const IVec<D> idx = unflatten(n);
    unsigned mask = 0;
    for (int d = 0; d < D; ++d) {
      const bool low = idx[d] == kGhost;
      const bool high = idx[d] == kGhost + cells_[d];
      for (int side = 0; side < 2; ++side) {
        if (!(side == 0 ? low : high)) continue;
        switch (faces_[2 * d + side]) {
          case FaceCondition::free:
            break;
          case FaceCondition::slip:
            mask |= 1u << d;
            break;
          case FaceCondition::fixed:
            mask |= (1u << D) - 1u;
            break;
        }
      }
    }
    if (mask) constraints_.push_back({n, mask});
  }

  // Ghost nodes beyond a constrained face are slaved to their mirror images inside:
  // v_ghost = R v_mirror, R = −I at a fixed face (odd extension: zero velocity on the face)
  // and the reflection of the normal component at a slip face (even extension). Axis by
  // axis, so corner ghosts reach the interior through two reflections. A window keeps the
  // pairs it holds both nodes of (a patch is wider than the ghost layers, so a ghost it
  // holds has its image too).
  const auto stored = [&](const IVec<D>& idx) {
    return ((idx - first_).array() >= 0).all() && ((idx - first_).array() < nodes_.array()).all();
  };
  for (int d = 0; d < D; ++d) {
    for (int side = 0; side < 2; ++side) {
      const FaceCondition condition = faces_[2 * d + side];
      if (condition == FaceCondition::free) continue;
      const int face = side == 0 ? kGhost : kGhost + cells_[d];
      const unsigned flips = condition == FaceCondition::fixed ? (1u << D) - 1u : 1u << d;
      for (long n = 0; n < node_count_; ++n) {
        IVec<D> idx = unflatten(n);
        const int k = side == 0 ? face - idx[d] : idx[d] - face;  // layers beyond the face
        if (k < 1) continue;
        idx[d] = side == 0 ? face + k : face - k;
        if (stored(idx)) mirrors_.push_back({n, flatten(idx), flips});
      }
      group_ends_.push_back(static_cast<long>(mirrors_.size()));
    }
  }
  select_live_boundary();
}

template <int D>
template <bool Backwards, class F>
void Grid<D>::for_each_mirror_group(F&& f) const {
  const int groups = static_cast<int>(live_group_ends_.size());
  for (int i = 0; i < groups; ++i) {
    const int g = Backwards ? groups - 1 - i : i;
    f(g == 0 ? 0L : live_group_ends_[g - 1], live_group_ends_[g]);
  }
}

template <int D>
void Grid<D>::select_live_boundary() {
  // Constraining a node that is not live, or folding or mirroring a pair whose ghost is not
  // live (its image is not either: close_live), changes nothing: they hold zero.
  live_constraints_.clear();
  for (const Constraint& c : constraints_)
    if (is_live(c.node)) live_constraints_.push_back(c);
  live_mirrors_.clear();
  live_group_ends_.clear();
  long begin = 0;
  for (const long end : group_ends_) {
    for (long i = begin; i < end; ++i)
      if (is_live(mirrors_[i].ghost)) live_mirrors_.push_back(mirrors_[i]);
    live_group_ends_.push_back(static_cast<long>(live_mirrors_.size()));
    begin = end;
  }
}

namespace {
//! Below this many pairs a face's loop stays on one thread: a parallel region costs a few
//! microseconds, about what a thread spends on a thousand pairs.
constexpr long kParallelMirrors = 4096;
}  // namespace

template <int D>
void Grid<D>::fold(std::vector<double>& field) const {
  for_each_mirror_group([&](long begin, long end) {
#pragma omp parallel for schedule(static) if (end - begin > kParallelMirrors)
    for (long i = begin; i < end; ++i) {
      const Mirror& m = live_mirrors_[i];
      field[m.image] += field[m.ghost];
      field[m.ghost] = 0.0;
    }
  });
}

template <int D>
void Grid<D>::fold(std::vector<Vec<D>>& field) const {
  for_each_mirror_group([&](long begin, long end) {
#pragma omp parallel for schedule(static) if (end - begin > kParallelMirrors)
    for (long i = begin; i < end; ++i) {
      const Mirror& m = live_mirrors_[i];
      field[m.image] += reflect(field[m.ghost], m.flips);
      field[m.ghost].setZero();
    }
  });
}

template <int D>
void Grid<D>::mirror(std::vector<Vec<D>>& field) const {
  for_each_mirror_group<true>([&](long begin, long end) {
#pragma omp parallel for schedule(static) if (end - begin > kParallelMirrors)
    for (long i = begin; i < end; ++i) {
      const Mirror& m = live_mirrors_[i];
      field[m.ghost] = reflect(field[m.image], m.flips);
    }
  });
}

template <int D>
void Grid<D>::restart_live(const std::vector<NodeSpan>& next) {
  const bool given = next.size() == live_.size();
  const NodeSpan whole{0, nodes_[0] - 1};
  const long width = nodes_[0];
  const auto zero_velocities = [&](long begin, long end) {
    for (long n = begin; n <= end; ++n) {
      velocity[n].setZero();
      velocity_change[n].setZero();
    }
  };
  const long rows = row_count();
  // The rows shared by the old live set's counts: a body's own field may live in a few rows.
#pragma omp parallel
  {
    const auto [r0, r1] = live_rows_of_thread();
    for (long r = r0; r < r1; ++r) {
      const NodeSpan now = live_[r];
      if (now.empty()) continue;
      const long base = r * width;
      for (long n = base + now.first; n <= base + now.last; ++n) {
        mass[n] = 0.0;
        momentum[n].setZero();
        force[n].setZero();
      }
      // The velocities stay wherever the next live set holds them: the update rewrites them.
      const NodeSpan kept = given ? next[r] : whole;
      if (kept.empty()) {
        zero_velocities(base + now.first, base + now.last);
      } else {
        zero_velocities(base + now.first, base + std::min(now.last, kept.first - 1));
        zero_velocities(base + std::max(now.first, kept.last + 1), base + now.last);
      }
    }
  }
  if (given)
    live_ = next;
  else
    live_.assign(rows, whole);
  close_live();
}

template <int D>
void Grid<D>::mark_live(const long* first, const long* last) {
  if (first == last) return;
  for (const long* n = first; n != last; ++n) add_live(*n);
  close_live();
}

template <int D>
void Grid<D>::prescribe(const std::pair<long, Vec<D>>* first, const std::pair<long, Vec<D>>* last) {
  if (first == last) return;
  for (const auto* p = first; p != last; ++p) add_live(p->first);
  close_live();
  prescribed_.insert(prescribed_.end(), first, last);
}

template <int D>
void Grid<D>::close_live() {
  // A mirror pair is a ghost f − k and its image f + k (k = 1..kGhost) across a constrained
  // face f, along one axis. Along axis 0 both lie in one row: a span reaching into the face's
  // band takes the band part's reflection. Along a higher axis the pair's rows take the
  // smallest span holding both. Repeated until nothing grows (corner ghosts: two axes).
  const int width = nodes_[0];
  const long rows = row_count();
  bool grew = true;
  while (grew) {
    grew = false;
    for (int d = 0; d < D; ++d) {
      for (int side = 0; side < 2; ++side) {
        if (faces_[2 * d + side] == FaceCondition::free) continue;
        const int f = (side == 0 ? kGhost : kGhost + cells_[d]) - first_[d];
        if (d == 0) {
          for (NodeSpan& s : live_) {
            const int a = std::max(s.first, f - kGhost), b = std::min(s.last, f + kGhost);
            if (s.empty() || a > b) continue;
            const int ra = std::max(2 * f - b, 0), rb = std::min(2 * f - a, width - 1);
            if (ra < s.first || rb > s.last) s.add(ra, rb), grew = true;
          }
          continue;
        }
        // Rows with index j along axis d: r = (outer · nodes_[d] + j) · step + inner.
        const long step = strides_[d] / width, outers = rows / (step * nodes_[d]);
        for (int j = std::max(f - kGhost, 0); j < f; ++j) {
          const int image = 2 * f - j;
          if (j >= nodes_[d] || image >= nodes_[d]) continue;
          for (long outer = 0; outer < outers; ++outer)
            for (long inner = 0; inner < step; ++inner) {
              NodeSpan& ghost = live_[(outer * nodes_[d] + j) * step + inner];
              NodeSpan& inside = live_[(outer * nodes_[d] + image) * step + inner];
              NodeSpan both = ghost;
              both.add(inside.first, inside.last);
              if (!(both == ghost) || !(both == inside)) ghost = inside = both, grew = true;
            }
        }
      }
    }
  }
  select_live_boundary();
  // Rows shared among the threads by live node counts, for for_each_live().
  const int threads = omp_get_max_threads();
  long total = 0;
  for (const NodeSpan& s : live_) total += s.size();
  live_parts_.assign(threads + 1, rows);
  live_parts_[0] = 0;
  long seen = 0;
  int t = 1;
  for (long r = 0; r < rows && t < threads; ++r) {
    seen += live_[r].size();
    while (t < threads && seen * threads >= total * t) live_parts_[t++] = r + 1;
  }
}

template <int D>
void Grid<D>::integrate(double dt) {
  constrain(momentum);
  constrain(force);
  for_each_live([&](long n) {
    if (mass[n] > 0.0) {
      const double inv_m = 1.0 / mass[n];
      velocity_change[n] = (dt * inv_m) * force[n];
      velocity[n] = inv_m * momentum[n] + velocity_change[n];
    } else {
      velocity_change[n].setZero();
      velocity[n].setZero();
    }
  });
  for (const auto& [n, v] : prescribed_) {
    velocity_change[n] = v - (mass[n] > 0.0 ? Vec<D>(momentum[n] / mass[n]) : v);
    velocity[n] = v;
  }
  mirror(velocity);
  mirror(velocity_change);
}

template <int D>
bool Grid<D>::return_to_face(Vec<D>& x) const {
  const double tolerance = 1e-6 * h_;
  for (int d = 0; d < D; ++d) {
    const bool walled_low = faces_[2 * d] != FaceCondition::free;
    const bool walled_high = faces_[2 * d + 1] != FaceCondition::free;
    if (walled_low && x[d] < lower_[d] && x[d] > lower_[d] - tolerance) x[d] = lower_[d];
    if (walled_high && x[d] > upper_[d] && x[d] < upper_[d] + tolerance) x[d] = upper_[d];
  }
  return contains(x);
}

template <int D>
void Grid<D>::velocities_from_momentum() {
  constrain(momentum);
  for_each_live([&](long n) {
    velocity[n] = mass[n] > 0.0 ? Vec<D>(momentum[n] / mass[n]) : Vec<D>::Zero();
  });
  for (const auto& [n, v] : prescribed_) velocity[n] = v;
  mirror(velocity);
}

template class Grid<2>;
template class Grid<3>;

}  // namespace pellicle
