#include "pellicle/geometry/poisson_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace pellicle {

template <int D>
SpacedPoints<D>::SpacedPoints(double spacing)
    : spacing_(spacing), inverse_(0.5 / spacing), slots_(1024, Slot{0, -1}) {}

template <int D>
std::uint64_t SpacedPoints<D>::key_of(const Cell& c) {
  // Pack the cell indices (21 bits each in 3D, 32 in 2D), then mix the bits (the SplitMix64
  // finaliser) so neighbouring cells land in unrelated slots.
  constexpr int bits = D == 2 ? 32 : 21;
  constexpr std::uint64_t mask = (1ull << bits) - 1;
  std::uint64_t k = 0;
  for (int d = 0; d < D; ++d) k = (k << bits) | (static_cast<std::uint64_t>(c[d]) & mask);
  k = (k ^ (k >> 30)) * 0xbf58476d1ce4e5b9ull;
  k = (k ^ (k >> 27)) * 0x94d049bb133111ebull;
  return k ^ (k >> 31);
}

template <int D>
int SpacedPoints<D>::head(std::uint64_t key) const {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = key & mask;; i = (i + 1) & mask) {
    if (slots_[i].head < 0) return -1;
    if (slots_[i].key == key) return slots_[i].head;
  }
}

template <int D>
void SpacedPoints<D>::link(std::uint64_t key, int point) {
  if (2 * (used_ + 1) > slots_.size()) grow();
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = key & mask;; i = (i + 1) & mask) {
    if (slots_[i].head < 0) {
      slots_[i] = {key, point};
      next_[point] = -1;
      ++used_;
      return;
    }
    if (slots_[i].key == key) {
      next_[point] = slots_[i].head;
      slots_[i].head = point;
      return;
    }
  }
}

template <int D>
void SpacedPoints<D>::grow() {
  std::vector<Slot> old(2 * slots_.size(), Slot{0, -1});
  old.swap(slots_);
  const std::size_t mask = slots_.size() - 1;
  for (const Slot& s : old) {
    if (s.head < 0) continue;
    std::size_t i = s.key & mask;
    while (slots_[i].head >= 0) i = (i + 1) & mask;
    slots_[i] = s;
  }
}

template <int D>
bool SpacedPoints<D>::try_add(const Vec<D>& x) {
  // Cells are twice the spacing wide, so the points closer than the spacing lie in the 2^D
  // cells nearest to x: along each axis its own cell and the neighbour on its nearer side.
  Cell c, side;
  for (int d = 0; d < D; ++d) {
    const double u = x[d] * inverse_;
    c[d] = static_cast<long long>(std::floor(u));
    side[d] = u - static_cast<double>(c[d]) < 0.5 ? -1 : 1;
  }
  const double s2 = spacing_ * spacing_;
  for (int k = 0; k < (1 << D); ++k) {
    Cell n = c;
    for (int d = 0; d < D; ++d)
      if ((k >> d) & 1) n[d] += side[d];
    for (int p = head(key_of(n)); p >= 0; p = next_[p])
      if ((points_[p] - x).squaredNorm() < s2) return false;
  }
  points_.push_back(x);
  next_.push_back(-1);
  link(key_of(c), static_cast<int>(points_.size()) - 1);
  return true;
}

namespace {

//! A point uniformly distributed in the triangle (or on the segment) o + u e1 (+ v e2).
template <int D>
Vec<D> random_in(const Vec<D>& o, const Vec<D>& e1, const Vec<D>& e2, SampleRandom& random) {
  double u = random.uniform();
  if constexpr (D == 2) {
    return o + u * e1;
  } else {
    double v = random.uniform();
    if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
    return o + u * e1 + v * e2;
  }
}

}  // namespace

template <int D>
std::vector<Vec<D>> carrier_candidates(const std::vector<Simplex<D>>& carrier,
                                       const Projection<D>& project, double cell,
                                       SampleRandom& random) {
  std::vector<Vec<D>> out;
  const auto map = [&](const Vec<D>& x) { return project ? project(x) : x; };
  for (const Simplex<D>& s : carrier) {
    // The mapped corners tell how long the piece is on the shape; the margin covers the
    // uneven stretching of a curved piece between its corners.
    double longest = 0.0;
    std::array<Vec<D>, D> mapped;
    for (int k = 0; k < D; ++k) mapped[k] = map(s[k]);
    for (int k = 0; k < D; ++k)
      for (int l = k + 1; l < D; ++l) longest = std::max(longest, (mapped[k] - mapped[l]).norm());
    const int m = std::max(1, static_cast<int>(std::ceil(1.1 * longest / cell)));
    const Vec<D> e1 = (s[1] - s[0]) / m;
    if constexpr (D == 2) {
      for (int i = 0; i < m; ++i) out.push_back(map(random_in<2>(s[0] + i * e1, e1, e1, random)));
    } else {
      const Vec3 e2 = (s[2] - s[0]) / m;
      for (int j = 0; j < m; ++j)
        for (int i = 0; i + j < m; ++i) {
          const Vec3 corner = s[0] + i * e1 + j * e2;
          out.push_back(map(random_in<3>(corner, e1, e2, random)));
          if (i + j + 1 < m)  // the downward triangle beside it
            out.push_back(map(random_in<3>(Vec3(corner + e1 + e2), Vec3(-e1), Vec3(-e2), random)));
        }
    }
  }
  return out;
}

template <int D>
std::vector<Vec<D>> boundary_points(const BoundaryCurve<D>& curve, double spacing,
                                    SampleRandom& random) {
  // Arc length by a dense polyline through x(u), with the joints of a piecewise curve among
  // its vertices; points are then placed at parameters interpolated in it, on the exact curve.
  const int per_piece = 64;
  auto table = [&](int per) {
    const int n = curve.pieces * per;
    std::vector<double> u(n + 1), s(n + 1, 0.0);
    for (int i = 0; i <= n; ++i) u[i] = static_cast<double>(i) / n;
    Vec<D> previous = curve.at(0.0);
    for (int i = 1; i <= n; ++i) {
      const Vec<D> x = curve.at(u[i]);
      s[i] = s[i - 1] + (x - previous).norm();
      previous = x;
    }
    return std::pair{u, s};
  };
  std::vector<double> u, s;
  std::tie(u, s) = table(per_piece);
  const int wanted = static_cast<int>(std::ceil(16.0 * s.back() / spacing / curve.pieces));
  if (wanted > per_piece) std::tie(u, s) = table(wanted);
  const double length = s.back();
  auto at_length = [&](double l) {
    const auto it = std::upper_bound(s.begin(), s.end(), l);
    const std::size_t i = std::clamp<std::size_t>(it - s.begin(), 1, s.size() - 1);
    const double w = s[i] > s[i - 1] ? (l - s[i - 1]) / (s[i] - s[i - 1]) : 0.0;
    return curve.at(std::clamp(u[i - 1] + w * (u[i] - u[i - 1]), 0.0, 1.0));
  };
  const double phase = curve.closed ? random.uniform() : 0.0;
  // As many equal steps as the length holds, fewer while some chord falls short.
  for (int steps = static_cast<int>(std::floor(length / spacing)); steps >= 1; --steps) {
    std::vector<Vec<D>> points;
    const int count = curve.closed ? steps : steps + 1;
    for (int k = 0; k < count; ++k) {
      const double l = (k + phase) * length / steps;
      points.push_back(curve.closed ? at_length(std::fmod(l, length)) : at_length(l));
    }
    if (!curve.closed) points.back() = curve.at(1.0);
    bool spaced = true;
    for (std::size_t k = 1; k < points.size() + (curve.closed ? 1 : 0) && spaced; ++k)
      spaced = (points[k % points.size()] - points[k - 1]).norm() >= spacing;
    if (spaced || (curve.closed && steps <= 3)) return points;
  }
  if (curve.closed) return {curve.at(phase)};
  return {curve.at(0.0), curve.at(1.0)};  // shorter than the spacing: the ends only
}

template <int D>
PointSample<D> select_spaced(const SurfaceShape<D>& shape, const std::vector<Vec<D>>& boundary,
                             std::vector<Vec<D>> candidates, double spacing, SampleRandom& random) {
  SpacedPoints<D> kept(spacing);
  for (const Vec<D>& x : boundary) kept.try_add(x);
  const std::size_t on_boundary = kept.points().size();
  // An advancing front: candidates are offered in order of their distance from a randomly
  // chosen one, so each is kept as soon as the front has moved a spacing past the kept
  // points. A counting sort on distances rounded to a fiftieth of the spacing is as good as
  // an exact sort and costs one pass.
  if (!candidates.empty()) {
    const Vec<D> origin = candidates[random.below(candidates.size())];
    const double width = kFrontResolution * spacing;
    std::vector<std::size_t> bucket(candidates.size());
    std::size_t last = 0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      bucket[i] = static_cast<std::size_t>((candidates[i] - origin).norm() / width);
      last = std::max(last, bucket[i]);
    }
    std::vector<std::size_t> start(last + 2, 0);
    for (std::size_t b : bucket) ++start[b + 1];
    for (std::size_t b = 0; b <= last; ++b) start[b + 1] += start[b];
    std::vector<Vec<D>> ordered(candidates.size());
    for (std::size_t i = 0; i < candidates.size(); ++i) ordered[start[bucket[i]]++] = candidates[i];
    candidates.swap(ordered);
  }
  for (const Vec<D>& x : candidates) kept.try_add(x);
  PointSample<D> out;
  out.points = kept.points();
  out.normals.reserve(out.points.size());
  for (const Vec<D>& x : out.points) out.normals.push_back(shape.normal(x));
  out.boundary.assign(out.points.size(), 0);
  std::fill(out.boundary.begin(), out.boundary.begin() + on_boundary, 1);
  return out;
}

template class SpacedPoints<2>;
template class SpacedPoints<3>;
template std::vector<Vec2> carrier_candidates<2>(const std::vector<Simplex<2>>&,
                                                 const Projection<2>&, double, SampleRandom&);
template std::vector<Vec3> carrier_candidates<3>(const std::vector<Simplex<3>>&,
                                                 const Projection<3>&, double, SampleRandom&);
template std::vector<Vec2> boundary_points<2>(const BoundaryCurve<2>&, double, SampleRandom&);
template std::vector<Vec3> boundary_points<3>(const BoundaryCurve<3>&, double, SampleRandom&);
template PointSample<2> select_spaced<2>(const SurfaceShape<2>&, const std::vector<Vec2>&,
                                         std::vector<Vec2>, double, SampleRandom&);
template PointSample<3> select_spaced<3>(const SurfaceShape<3>&, const std::vector<Vec3>&,
                                         std::vector<Vec3>, double, SampleRandom&);

}  // namespace pellicle
