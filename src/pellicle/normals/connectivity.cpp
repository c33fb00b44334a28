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

//! Where each point of a body sits in a part, by its index in the body (−1: not in the
//! part): a table as long as the body, which the connectivity estimators hold anyway in
//! their mesh, filled for one part and emptied again after it.
class PartSlots {
 public:
  //! Slots of `part`'s points in `table` (grown to the body) while this lives.
  PartSlots(std::vector<long>& table, const BodyPart& part) : table_(table), part_(part) {
    table_.resize(part.count, -1);
    for (std::size_t j = 0; j < part.index.size(); ++j) table_[part.index[j]] = j;
  }
  ~PartSlots() {
    for (long i : part_.index) table_[i] = -1;
  }
  PartSlots(const PartSlots&) = delete;
  PartSlots& operator=(const PartSlots&) = delete;
  long operator[](long i) const { return table_[i]; }

 private:
  std::vector<long>& table_;
  const BodyPart& part_;
};

class CurveConnectivity final : public FrameEstimator<2> {
 public:
  explicit CurveConnectivity(const FrameSetup<2>& setup) : setup_(setup) {}
  void estimate(const std::vector<Vec2>& x, long begin, long end, std::vector<Vec2>& normal,
                std::vector<Vec2>& tangent) override {
    const long n = end - begin;
    for (long i = 0; i < n; ++i)
      frame(
          i, n, [&](long k) { return &x[begin + k]; }, normal[begin + i], tangent[begin + i]);
    if (sign_ == 0)
      sign_ = enclosed_sign<2>(setup_.orientation, x, begin, end, normal, setup_.cell);
    if (sign_ < 0)
      for (long p = begin; p < end; ++p) normal[p] = -normal[p], tangent[p] = -tangent[p];
  }

  int reach() const override { return 1; }

  bool estimate_part(const BodyPart& part, const std::vector<Vec2>& x, std::vector<Vec2>& normal,
                     std::vector<Vec2>& tangent) override {
    if (sign_ == 0) return false;
    const PartSlots slot(slots_, part);
    bool complete = true;
    auto at = [&](long i) -> const Vec2* {
      const long j = slot[i];
      complete = complete && j >= 0;
      return j >= 0 ? &x[j] : &x[0];
    };
    for (std::size_t j = 0; j < part.index.size() && complete; ++j) {
      if (!part.wanted[j]) continue;
      frame(part.index[j], part.count, at, normal[j], tangent[j]);
      if (sign_ < 0) normal[j] = -normal[j], tangent[j] = -tangent[j];
    }
    return complete;
  }

 private:
  FrameSetup<2> setup_;
  int sign_ = 0;             //!< ±1 once settled at the first call
  std::vector<long> slots_;  //!< PartSlots' table

  //! The frame of point i of a body of n points, whose points `at(k)` gives (thesis eq 7.1).
  template <class At>
  void frame(long i, long n, At&& at, Vec2& normal, Vec2& tangent) const {
    const bool closed = setup_.connectivity.closed_curve;
    Vec2 before = *at(closed ? (i - 1 + n) % n : std::max(i - 1, 0L));
    Vec2 after = *at(closed ? (i + 1) % n : std::min(i + 1, n - 1));
    // An open end on a symmetry plane or wall continues into its mirror image there, so its
    // neighbour beyond the end is the mirrored next point.
    if (!closed && n > 1 && (i == 0 || i == n - 1)) {
      const int k = plane_at<2>(*at(i), setup_.mirrors, setup_.cell);
      if (k >= 0) {
        const MirrorPlane& m = setup_.mirrors[k];
        Vec2& beyond = i == 0 ? before : after;
        beyond = *at(i == 0 ? 1 : n - 2);
        beyond[m.axis] = 2.0 * m.position - beyond[m.axis];
      }
    }
    const Vec2 t = (after - before).normalized();  // thesis eq 7.1
    tangent = t;
    normal = Vec2(-t.y(), t.x());
  }
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
    for (int i : boundary_) off_plane(x[begin + i], normal[begin + i]);
    for (long p = begin; p < end; ++p) normal[p].normalize();
    if (sign_ == 0)
      sign_ = enclosed_sign<3>(setup_.orientation, x, begin, end, normal, setup_.cell);
    for (long p = begin; p < end; ++p) {
      if (sign_ < 0) normal[p] = -normal[p];
      tangent[p] = continue_tangent(tangent[p], normal[p]);
    }
  }

  int reach() const override { return 1; }

  bool estimate_part(const BodyPart& part, const std::vector<Vec3>& x, std::vector<Vec3>& normal,
                     std::vector<Vec3>& tangent) override {
    if (sign_ == 0) return false;
    if (triangles_at_.empty()) index_triangles(part.count);
    const PartSlots slot(slots_, part);
    for (std::size_t j = 0; j < part.index.size(); ++j) {
      if (!part.wanted[j]) continue;
      const long i = part.index[j];
      // The sum estimate forms, triangle by triangle in the mesh's order.
      Vec3 n = Vec3::Zero();
      for (int f = triangles_at_[i]; f < triangles_at_[i + 1]; ++f) {
        const auto& t = setup_.connectivity.triangles[triangle_[f]];
        long at[3];
        for (int c = 0; c < 3; ++c)
          if ((at[c] = slot[t[c]]) < 0) return false;
        n += (x[at[1]] - x[at[0]]).cross(x[at[2]] - x[at[0]]);
      }
      if (std::binary_search(boundary_.begin(), boundary_.end(), static_cast<int>(i)))
        off_plane(x[j], n);
      normal[j] = n.normalized();
      if (sign_ < 0) normal[j] = -normal[j];
      tangent[j] = continue_tangent(tangent[j], normal[j]);
    }
    return true;
  }

 private:
  FrameSetup<3> setup_;
  std::vector<int> boundary_;  //!< points on an edge used by one triangle only
  int sign_ = 0;
  //! The triangles at each point, in the mesh's order: triangle_[triangles_at_[i] …
  //! triangles_at_[i + 1]) (built at the first estimate_part).
  std::vector<int> triangles_at_, triangle_;
  std::vector<long> slots_;  //!< PartSlots' table

  void off_plane(const Vec3& x, Vec3& normal) const {
    const int k = plane_at<3>(x, setup_.mirrors, setup_.cell);
    if (k >= 0) normal[setup_.mirrors[k].axis] = 0.0;
  }
  void index_triangles(long points) {
    const auto& triangles = setup_.connectivity.triangles;
    triangles_at_.assign(points + 1, 0);
    for (const auto& t : triangles)
      for (int k : t) ++triangles_at_[k + 1];
    for (long i = 0; i < points; ++i) triangles_at_[i + 1] += triangles_at_[i];
    triangle_.resize(triangles_at_[points]);
    std::vector<int> next(triangles_at_.begin(), triangles_at_.end() - 1);
    for (std::size_t f = 0; f < triangles.size(); ++f)
      for (int k : triangles[f]) triangle_[next[k]++] = static_cast<int>(f);
  }
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
