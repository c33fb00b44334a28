#include "pellicle/geometry/shape_support.hpp"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdio>

namespace pellicle {

template <int D>
double carrier_measure(const std::vector<Simplex<D>>& carrier) {
  double sum = 0.0;
  for (const auto& s : carrier) {
    if constexpr (D == 2)
      sum += (s[1] - s[0]).norm();
    else
      sum += 0.5 * (s[1] - s[0]).cross(s[2] - s[0]).norm();
  }
  return sum;
}

template double carrier_measure<2>(const std::vector<Simplex<2>>&);
template double carrier_measure<3>(const std::vector<Simplex<3>>&);

std::vector<Simplex<3>> carrier_of(const SurfaceMesh& mesh) {
  std::vector<Simplex<3>> out;
  out.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    out.push_back({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]});
  return out;
}

std::vector<Simplex<2>> closed_polygon(const std::function<Vec2(double)>& x, int n) {
  std::vector<Simplex<2>> out;
  for (int k = 0; k < n; ++k)
    out.push_back({x(static_cast<double>(k) / n), x(static_cast<double>(k + 1) / n)});
  return out;
}

std::vector<Simplex<3>> parametric_grid(int nu, int nv,
                                        const std::function<Vec3(double, double)>& x) {
  std::vector<Vec3> nodes;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i)
      nodes.push_back(x(static_cast<double>(i) / nu, static_cast<double>(j) / nv));
  auto at = [&](int i, int j) { return nodes[j * (nu + 1) + i]; };
  std::vector<Simplex<3>> out;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      out.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      out.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return out;
}

namespace {

//! Where f, linear between a and b, vanishes (f(a) and f(b) of opposite signs).
template <int D>
Vec<D> crossing(const Vec<D>& a, double fa, const Vec<D>& b, double fb) {
  return a + (fa / (fa - fb)) * (b - a);
}

//! The zero level set of f, linear on the simplex with corners x and values v (D + 1 each).
template <int D>
void cut_simplex(const std::array<Vec<D>, D + 1>& x, const std::array<double, D + 1>& v,
                 std::vector<Simplex<D>>& out) {
  std::array<int, D + 1> in{}, outside{};
  int n_in = 0, n_out = 0;
  for (int k = 0; k <= D; ++k) (v[k] >= 0.0 ? in[n_in++] : outside[n_out++]) = k;
  if (n_in == 0 || n_out == 0) return;
  auto cross = [&](int a, int b) { return crossing<D>(x[a], v[a], x[b], v[b]); };
  if constexpr (D == 2) {
    const int lone = n_in == 1 ? in[0] : outside[0];
    const auto& others = n_in == 1 ? outside : in;
    out.push_back({cross(lone, others[0]), cross(lone, others[1])});
  } else if (n_in == 1 || n_out == 1) {
    const int lone = n_in == 1 ? in[0] : outside[0];
    const auto& others = n_in == 1 ? outside : in;
    out.push_back({cross(lone, others[0]), cross(lone, others[1]), cross(lone, others[2])});
  } else {  // two corners on each side: a quadrilateral, in cyclic order
    const Vec3 ac = cross(in[0], outside[0]), ad = cross(in[0], outside[1]),
               bd = cross(in[1], outside[1]), bc = cross(in[1], outside[0]);
    out.push_back({ac, ad, bd});
    out.push_back({ac, bd, bc});
  }
}

}  // namespace

template <int D>
std::vector<Simplex<D>> zero_level_set(const std::function<double(const Vec<D>&)>& f,
                                       const Vec<D>& lower, const Vec<D>& upper, double cell) {
  IVec<D> n;
  for (int d = 0; d < D; ++d)
    n[d] = std::max(1, static_cast<int>(std::ceil((upper[d] - lower[d]) / cell)));
  auto node = [&](const IVec<D>& i) { return Vec<D>(lower + cell * i.template cast<double>()); };
  auto index = [&](const IVec<D>& i) {
    long k = 0;
    for (int d = D - 1; d >= 0; --d) k = k * (n[d] + 1) + i[d];
    return k;
  };
  long nodes = 1, cells = 1;
  for (int d = 0; d < D; ++d) nodes *= n[d] + 1, cells *= n[d];
  std::vector<double> value(nodes);
  for (long k = 0; k < nodes; ++k) {
    IVec<D> i;
    long rest = k;
    for (int d = 0; d < D; ++d) i[d] = static_cast<int>(rest % (n[d] + 1)), rest /= n[d] + 1;
    value[k] = f(node(i));
  }
  // Corners of the unit square or cube by bits (bit d: +1 along axis d); the simplices of
  // the Kuhn split, one per order of the axes, share faces between neighbouring cells.
  std::vector<std::array<int, D + 1>> simplices;
  if constexpr (D == 2) {
    simplices = {{0, 1, 3}, {0, 2, 3}};
  } else {
    const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& o : orders) simplices.push_back({0, 1 << o[0], (1 << o[0]) | (1 << o[1]), 7});
  }
  std::vector<Simplex<D>> out;
  for (long c = 0; c < cells; ++c) {
    IVec<D> base;
    long rest = c;
    for (int d = 0; d < D; ++d) base[d] = static_cast<int>(rest % n[d]), rest /= n[d];
    std::array<Vec<D>, 1 << D> x;
    std::array<double, 1 << D> v;
    bool positive = false, negative = false;
    for (int corner = 0; corner < (1 << D); ++corner) {
      IVec<D> i = base;
      for (int d = 0; d < D; ++d) i[d] += (corner >> d) & 1;
      x[corner] = node(i);
      v[corner] = value[index(i)];
      (v[corner] >= 0.0 ? positive : negative) = true;
    }
    if (!positive || !negative) continue;
    for (const auto& s : simplices) {
      std::array<Vec<D>, D + 1> sx;
      std::array<double, D + 1> sv;
      for (int k = 0; k <= D; ++k) sx[k] = x[s[k]], sv[k] = v[s[k]];
      cut_simplex<D>(sx, sv, out);
    }
  }
  return out;
}

template <int D>
std::string describe_vector(const Vec<D>& x) {
  std::string s = "(";
  for (int d = 0; d < D; ++d) s += (d ? ", " : "") + describe_number(x[d]);
  return s + ")";
}

std::string describe_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

template std::vector<Simplex<2>> zero_level_set<2>(const std::function<double(const Vec2&)>&,
                                                   const Vec2&, const Vec2&, double);
template std::vector<Simplex<3>> zero_level_set<3>(const std::function<double(const Vec3&)>&,
                                                   const Vec3&, const Vec3&, double);
template std::string describe_vector<2>(const Vec2&);
template std::string describe_vector<3>(const Vec3&);

}  // namespace pellicle
