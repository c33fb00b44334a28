#include "pellicle/normals/connectivity.hpp"

#include <Eigen/Geometry>

namespace pellicle {

Vec3 continue_tangent(const Vec3& previous, const Vec3& n) {
  Vec3 t = previous - previous.dot(n) * n;
  if (t.squaredNorm() < 1e-12) {
    const Vec3 axis = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    t = axis - axis.dot(n) * n;
  }
  return t.normalized();
}

namespace {

class CurveConnectivity final : public FrameEstimator<2> {
 public:
  explicit CurveConnectivity(bool closed) : closed_(closed) {}
  void estimate(const std::vector<Vec2>& x, long begin, long end, std::vector<Vec2>& normal,
                std::vector<Vec2>& tangent) override {
    const long n = end - begin;
    for (long i = 0; i < n; ++i) {
      long prev = i - 1, next = i + 1;
      if (closed_) {
        prev = (prev + n) % n;
        next = next % n;
      } else {
        prev = std::max(prev, 0L);
        next = std::min(next, n - 1);
      }
      const Vec2 t = (x[begin + next] - x[begin + prev]).normalized();  // thesis eq 7.1
      tangent[begin + i] = t;
      normal[begin + i] = Vec2(-t.y(), t.x());
    }
  }

 private:
  bool closed_;
};

class MeshConnectivity final : public FrameEstimator<3> {
 public:
  explicit MeshConnectivity(std::vector<std::array<int, 3>> triangles)
      : triangles_(std::move(triangles)) {}
  void estimate(const std::vector<Vec3>& x, long begin, long end, std::vector<Vec3>& normal,
                std::vector<Vec3>& tangent) override {
    for (long p = begin; p < end; ++p) normal[p].setZero();
    for (const auto& t : triangles_) {
      const Vec3& a = x[begin + t[0]];
      const Vec3 area_normal = (x[begin + t[1]] - a).cross(x[begin + t[2]] - a);
      for (int k : t) normal[begin + k] += area_normal;
    }
    for (long p = begin; p < end; ++p) {
      normal[p].normalize();
      tangent[p] = continue_tangent(tangent[p], normal[p]);
    }
  }

 private:
  std::vector<std::array<int, 3>> triangles_;
};

}  // namespace

template <>
std::unique_ptr<FrameEstimator<2>> make_connectivity_estimator<2>(const FrameSetup<2>& s) {
  return std::make_unique<CurveConnectivity>(s.connectivity.closed_curve);
}

template <>
std::unique_ptr<FrameEstimator<3>> make_connectivity_estimator<3>(const FrameSetup<3>& s) {
  return std::make_unique<MeshConnectivity>(s.connectivity.triangles);
}

}  // namespace pellicle
