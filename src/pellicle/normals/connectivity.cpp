#include "pellicle/normals/connectivity.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>

#include "pellicle/pointcloud/local_frame.hpp"

namespace pellicle {

namespace {

//! The sign that turns normals away from the enclosed points, by majority over the points
//! (+1 when the rule is not away_from_inside or nothing is near).
template <int D>
int enclosed_sign(const FrameOrientation<D>& orientation, const std::vector<Vec<D>>& x, long begin,
                  long end, const std::vector<Vec<D>>& normal, double cell) {
  if (orientation.rule != NormalOrientation::away_from_inside) return 1;
  long vote = 0;
  for (int side : sides_from_inside<D>(x, begin, end, normal, orientation.inside, cell))
    vote += side;
  return vote < 0 ? -1 : 1;
}

//! Index of the mirror plane x lies on (within a hundredth of a cell), or −1.
template <int D>
int plane_at(const Vec<D>& x, const std::vector<MirrorPlane>& planes, double cell) {
  for (std::size_t k = 0; k < planes.size(); ++k)
    if (std::abs(x[planes[k].axis] - planes[k].position) <= 0.01 * cell) return static_cast<int>(k);
  return -1;
}

class CurveConnectivity final : public FrameEstimator<2> {
 public:
  explicit CurveConnectivity(const FrameSetup<2>& setup) : setup_(setup) {}
  void estimate(const std::vector<Vec2>& x, long begin, long end, std::vector<Vec2>& normal,
                std::vector<Vec2>& tangent) override {
    const long n = end - begin;
    const bool closed = setup_.connectivity.closed_curve;
    for (long i = 0; i < n; ++i) {
      Vec2 before = x[begin + (closed ? (i - 1 + n) % n : std::max(i - 1, 0L))];
      Vec2 after = x[begin + (closed ? (i + 1) % n : std::min(i + 1, n - 1))];
      // An open end on a symmetry plane or wall continues into its mirror image there, so its
      // neighbour beyond the end is the mirrored next point.
      if (!closed && n > 1 && (i == 0 || i == n - 1)) {
        const int k = plane_at<2>(x[begin + i], setup_.mirrors, setup_.cell);
        if (k >= 0) {
          const MirrorPlane& m = setup_.mirrors[k];
          Vec2& beyond = i == 0 ? before : after;
          beyond = x[begin + (i == 0 ? 1 : n - 2)];
          beyond[m.axis] = 2.0 * m.position - beyond[m.axis];
        }
      }
      const Vec2 t = (after - before).normalized();  // thesis eq 7.1
      tangent[begin + i] = t;
      normal[begin + i] = Vec2(-t.y(), t.x());
    }
    if (sign_ == 0)
      sign_ = enclosed_sign<2>(setup_.orientation, x, begin, end, normal, setup_.cell);
    if (sign_ < 0)
      for (long p = begin; p < end; ++p) normal[p] = -normal[p], tangent[p] = -tangent[p];
  }

 private:
  FrameSetup<2> setup_;
  int sign_ = 0;  //!< ±1 once settled at the first call
};

class MeshConnectivity final : public FrameEstimator<3> {
 public:
  explicit MeshConnectivity(const FrameSetup<3>& setup) : setup_(setup) {
    std::map<std::pair<int, int>, int> uses;
    for (const auto& t : setup_.connectivity.triangles)
      for (int e = 0; e < 3; ++e)
        ++uses[{std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3])}];
    for (const auto& [edge, count] : uses)
      if (count == 1) boundary_.push_back(edge.first), boundary_.push_back(edge.second);
    std::sort(boundary_.begin(), boundary_.end());
    boundary_.erase(std::unique(boundary_.begin(), boundary_.end()), boundary_.end());
  }
  void estimate(const std::vector<Vec3>& x, long begin, long end, std::vector<Vec3>& normal,
                std::vector<Vec3>& tangent) override {
    for (long p = begin; p < end; ++p) normal[p].setZero();
    for (const auto& t : setup_.connectivity.triangles) {
      const Vec3& a = x[begin + t[0]];
      const Vec3 area_normal = (x[begin + t[1]] - a).cross(x[begin + t[2]] - a);
      for (int k : t) normal[begin + k] += area_normal;
    }
    // A boundary point on a symmetry plane or wall: its mirrored triangles would cancel the
    // normal's component across the plane.
    for (int i : boundary_) {
      const int k = plane_at<3>(x[begin + i], setup_.mirrors, setup_.cell);
      if (k >= 0) normal[begin + i][setup_.mirrors[k].axis] = 0.0;
    }
    for (long p = begin; p < end; ++p) normal[p].normalize();
    if (sign_ == 0)
      sign_ = enclosed_sign<3>(setup_.orientation, x, begin, end, normal, setup_.cell);
    for (long p = begin; p < end; ++p) {
      if (sign_ < 0) normal[p] = -normal[p];
      tangent[p] = continue_tangent(tangent[p], normal[p]);
    }
  }

 private:
  FrameSetup<3> setup_;
  std::vector<int> boundary_;  //!< points on an edge used by one triangle only
  int sign_ = 0;
};

}  // namespace

template <>
std::unique_ptr<FrameEstimator<2>> make_connectivity_estimator<2>(const FrameSetup<2>& s) {
  return std::make_unique<CurveConnectivity>(s);
}

template <>
std::unique_ptr<FrameEstimator<3>> make_connectivity_estimator<3>(const FrameSetup<3>& s) {
  return std::make_unique<MeshConnectivity>(s);
}

}  // namespace pellicle
