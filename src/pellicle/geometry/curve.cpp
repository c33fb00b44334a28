#include "pellicle/geometry/curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pellicle {

SampledCurve sample_curve(const std::function<Vec2(double)>& x, bool closed, Sampling sampling) {
  // Tabulate arc length finely, then invert it at equal steps.
  constexpr int kTable = 20000;
  std::vector<double> u(kTable + 1), s(kTable + 1, 0.0);
  Vec2 previous = x(0.0);
  for (int i = 0; i <= kTable; ++i) {
    u[i] = static_cast<double>(i) / kTable;
    const Vec2 here = x(u[i]);
    if (i > 0) s[i] = s[i - 1] + (here - previous).norm();
    previous = here;
  }
  const double length = s.back();
  int n = sampling.count;
  if (n <= 0) {
    const int gaps = std::max(1, static_cast<int>(std::lround(length / sampling.spacing)));
    n = closed ? gaps : gaps + 1;
  }
  n = std::max(n, closed ? 3 : 2);
  const int gaps = closed ? n : n - 1;
  SampledCurve c;
  c.closed = closed;
  c.points.reserve(n);
  c.lengths.assign(n, length / gaps);
  for (int k = 0; k < n; ++k) {
    const double target = length * k / gaps;
    const auto it = std::lower_bound(s.begin(), s.end(), target);
    const std::size_t j = std::clamp<std::size_t>(it - s.begin(), 1, kTable);
    const double f = s[j] > s[j - 1] ? (target - s[j - 1]) / (s[j] - s[j - 1]) : 0.0;
    c.points.push_back(x(u[j - 1] + f * (u[j] - u[j - 1])));
  }
  return c;
}

SampledCurve sample_polyline(const std::vector<Vec2>& vertices, bool closed, Sampling sampling) {
  std::vector<Vec2> v = vertices;
  if (closed) v.push_back(vertices.front());
  std::vector<double> at(v.size(), 0.0);  // cumulative length at each vertex
  for (std::size_t i = 1; i < v.size(); ++i) at[i] = at[i - 1] + (v[i] - v[i - 1]).norm();
  const double total = at.back();
  // Parametrised by arc length, so the tabulation in sample_curve is exact.
  auto x = [&](double u) {
    const double s = u * total;
    const std::size_t i = std::clamp<std::size_t>(
        std::upper_bound(at.begin(), at.end(), s) - at.begin(), 1, v.size() - 1);
    const double span = at[i] - at[i - 1];
    const double f = span > 0.0 ? (s - at[i - 1]) / span : 0.0;
    return Vec2(v[i - 1] + f * (v[i] - v[i - 1]));
  };
  return sample_curve(x, closed, sampling);
}

SampledCurve sample_ellipse_arc(const Vec2& center, const Vec2& semi_axes, double from, double to,
                                Sampling sampling) {
  const bool closed = std::abs(std::abs(to - from) - 2.0 * std::numbers::pi) < 1e-12;
  auto x = [&](double u) {
    const double a = from + u * (to - from);
    return Vec2(center.x() + semi_axes.x() * std::cos(a), center.y() + semi_axes.y() * std::sin(a));
  };
  return sample_curve(x, closed, sampling);
}

SampledCurve sample_spline(const std::vector<Vec2>& through, bool closed, Sampling sampling) {
  const int n = static_cast<int>(through.size());
  const int pieces = closed ? n : n - 1;
  auto point = [&](int i) {
    if (closed) return through[((i % n) + n) % n];
    if (i < 0) return Vec2(2.0 * through[0] - through[1]);  // reflected end tangents
    if (i >= n) return Vec2(2.0 * through[n - 1] - through[n - 2]);
    return through[i];
  };
  // Centripetal Catmull–Rom (knot spacing |Δx|^½): no cusps or self-intersections within a piece.
  auto x = [&](double u) {
    const double t = std::min(u * pieces, pieces - 1e-12);
    const int i = static_cast<int>(t);
    const double f = t - i;
    const Vec2 p0 = point(i - 1), p1 = point(i), p2 = point(i + 1), p3 = point(i + 2);
    const double t0 = 0.0, t1 = t0 + std::sqrt((p1 - p0).norm()),
                 t2 = t1 + std::sqrt((p2 - p1).norm()), t3 = t2 + std::sqrt((p3 - p2).norm());
    const double tt = t1 + f * (t2 - t1);
    auto lerp = [](const Vec2& a, const Vec2& b, double ta, double tb, double tv) {
      return tb > ta ? Vec2((tb - tv) / (tb - ta) * a + (tv - ta) / (tb - ta) * b) : a;
    };
    const Vec2 a1 = lerp(p0, p1, t0, t1, tt), a2 = lerp(p1, p2, t1, t2, tt),
               a3 = lerp(p2, p3, t2, t3, tt);
    const Vec2 b1 = lerp(a1, a2, t0, t2, tt), b2 = lerp(a2, a3, t1, t3, tt);
    return lerp(b1, b2, t1, t2, tt);
  };
  return sample_curve(x, closed, sampling);
}

}  // namespace pellicle
