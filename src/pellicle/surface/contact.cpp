#include "pellicle/surface/contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "pellicle/pointcloud/union_find.hpp"
#include "pellicle/surface/signed_distance.hpp"

namespace pellicle {

const std::vector<std::string>& contact_response_names() {
  static const std::vector<std::string> names{"none", "non-penetration", "delete", "merge"};
  return names;
}

ContactResponse contact_response_from_name(const std::string& name) {
  const auto& names = contact_response_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw std::invalid_argument("unknown contact response '" + name + "'");
  return static_cast<ContactResponse>(it - names.begin());
}

ContactResponse ContactOptions::response(int a, int b) const {
  for (const ContactRule& r : rules)
    if ((r.first == a && r.second == b) || (r.first == b && r.second == a)) return r.response;
  return a == b ? self : between;
}

bool ContactOptions::active() const {
  return between != ContactResponse::none || self != ContactResponse::none ||
         std::any_of(rules.begin(), rules.end(),
                     [](const ContactRule& r) { return r.response != ContactResponse::none; });
}

bool ContactOptions::self_contact() const {
  if (self != ContactResponse::none) return true;
  return std::any_of(rules.begin(), rules.end(), [](const ContactRule& r) {
    return r.first == r.second && r.response != ContactResponse::none;
  });
}

namespace {

//! Fewest points of the other part for a signed distance: the quadratic's terms along the
//! surface (signed_distance.hpp).
template <int D>
constexpr int kQuadraticPatch = D == 3 ? 6 : 3;

//! What detection found at one point.
template <int D>
struct Detected {
  int nearest = -1;       //!< the nearest point of the other part (−1: no contact)
  double distance = 0.0;  //!< to it
  SignedDistance<D> dc;   //!< eq 10, where the patch carries the quadratic
  Vec<D> patch_velocity = Vec<D>::Zero();
};

//! The other part nearest to i: the points of S_i^ext in the chamber and surface of the
//! nearest one whose normals agree with its normal (the same side of the same part).
template <int D>
int nearest_patch(const PointCloud<D>& cloud, const NeighbourLists& external, std::size_t i,
                  std::vector<int>& patch) {
  patch.clear();
  int nearest = -1;
  double best = std::numeric_limits<double>::infinity();
  for (long k = external.begin(i); k < external.end(i); ++k) {
    const int j = external.index[k];
    const double r = (cloud.position[j] - cloud.position[i]).squaredNorm();
    if (r < best) {
      best = r;
      nearest = j;
    }
  }
  if (nearest < 0) return -1;
  patch.push_back(nearest);
  const Vec<D> n = cloud.normal(nearest);
  for (long k = external.begin(i); k < external.end(i); ++k) {
    const int j = external.index[k];
    if (j != nearest && cloud.chamber[j] == cloud.chamber[nearest] &&
        cloud.surface[j] == cloud.surface[nearest] && cloud.normal(j).dot(n) > 0.0)
      patch.push_back(j);
  }
  return nearest;
}

}  // namespace

template <int D>
ContactReport resolve_contacts(PointCloud<D>& cloud, const NeighbourLists& own,
                               const NeighbourLists& external, const ContactOptions& options,
                               double r_min) {
  ContactReport report;
  const long n = static_cast<long>(cloud.size());
  // ξ: a third of the smallest distance between neighbouring points in contact.
  double spacing = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(min : spacing)
  for (long i = 0; i < n; ++i) {
    if (external.count(i) == 0) continue;
    for (long k = own.begin(i); k < own.end(i); ++k)
      if (own.index[k] != i)
        spacing = std::min(spacing, (cloud.position[own.index[k]] - cloud.position[i]).norm());
  }
  if (!std::isfinite(spacing)) {  // nothing in contact anywhere
    std::fill(cloud.contact_side.begin(), cloud.contact_side.end(), 0);
    return report;
  }
  const double xi = spacing / 3.0;

  // Detection: DC_i of eq 10 for every point with S_i^ext.
  std::vector<Detected<D>> found(n);
#pragma omp parallel
  {
    std::vector<int> patch;
    std::vector<Vec<D>> x, normals;
#pragma omp for schedule(dynamic, 64)
    for (long i = 0; i < n; ++i) {
      if (external.count(i) == 0) continue;
      Detected<D>& d = found[i];
      d.nearest = nearest_patch(cloud, external, i, patch);
      d.distance = (cloud.position[d.nearest] - cloud.position[i]).norm();
      // A patch too small for the quadratic of eq 10 is the other part's edge seen from
      // nearly h away, or a part too thin to be resolved: its plane can tilt through x_i and
      // fake a change of sign. Only the distance to the nearest point counts there.
      if (static_cast<int>(patch.size()) < kQuadraticPatch<D>) continue;
      x.clear();
      normals.clear();
      Vec<D> v = Vec<D>::Zero();
      for (int j : patch) {
        x.push_back(cloud.position[j]);
        normals.push_back(cloud.normal(j));
        v += cloud.velocity[j];
      }
      d.dc = signed_distance<D>(cloud.position[i], x.data(), normals.data(),
                                static_cast<int>(patch.size()), xi);
      d.patch_velocity = v / static_cast<double>(patch.size());
    }
  }

  // Responses, in point order.
  // Chamber ids joined by responses, each set relabelled to its smallest id.
  UnionFind joins(cloud.chamber.empty()
                      ? 0
                      : *std::max_element(cloud.chamber.begin(), cloud.chamber.end()) + 1);
  std::vector<std::uint8_t> remove(n, 0), merged(n, 0);
  for (long i = 0; i < n; ++i) {
    const Detected<D>& d = found[i];
    if (d.nearest < 0) {
      cloud.contact_side[i] = 0;
      continue;
    }
    ++report.in_contact;
    // Without DC_i the side stays as it was.
    const std::int8_t side = d.dc.valid ? (d.dc.distance >= 0.0 ? 1 : -1) : cloud.contact_side[i];
    const bool penetrated = cloud.contact_side[i] != 0 && side != cloud.contact_side[i];
    // Near: within the deletion distance of a point of the other part (§3.6, delete contact).
    const bool near = !penetrated && d.distance < r_min * cloud.smoothing_length[i];
    report.penetrated += penetrated;
    report.near += near;
    const int j = d.nearest;
    switch (options.response(cloud.surface[i], cloud.surface[j])) {
      case ContactResponse::none:
        cloud.contact_side[i] = side;
        break;
      case ContactResponse::non_penetration:
        if (penetrated) {  // back to its side, ξ off the other surface; v averaged
          cloud.position[i] -= (d.dc.distance - cloud.contact_side[i] * xi) * d.dc.direction;
          cloud.velocity[i] = 0.5 * (cloud.velocity[i] + d.patch_velocity);
          ++report.projected;
        } else {
          cloud.contact_side[i] = side;
        }
        break;
      case ContactResponse::remove:
        if (penetrated || near) {
          remove[i] = 1;
          ++report.removed;
          report.joined += joins.join(cloud.chamber[i], cloud.chamber[j]);
        } else {
          cloud.contact_side[i] = side;
        }
        break;
      case ContactResponse::merge:
        if (penetrated || near) {
          report.joined += joins.join(cloud.chamber[i], cloud.chamber[j]);
          if (!merged[i] && !merged[j] && !remove[j]) {  // i into j, halfway
            merged[i] = merged[j] = 1;
            remove[i] = 1;
            ++report.removed;
            cloud.position[j] = 0.5 * (cloud.position[i] + cloud.position[j]);
            cloud.velocity[j] = 0.5 * (cloud.velocity[i] + cloud.velocity[j]);
          }
        } else {
          cloud.contact_side[i] = side;
        }
        break;
    }
  }
  if (report.joined > 0)
    for (int& c : cloud.chamber) c = joins.root(c);
  cloud.remove_points(remove);
  return report;
}

template ContactReport resolve_contacts<2>(PointCloud<2>&, const NeighbourLists&,
                                           const NeighbourLists&, const ContactOptions&, double);
template ContactReport resolve_contacts<3>(PointCloud<3>&, const NeighbourLists&,
                                           const NeighbourLists&, const ContactOptions&, double);

}  // namespace pellicle
