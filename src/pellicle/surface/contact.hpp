#pragma once
//! Contact between point-cloud surfaces and between facing parts of one surface (Suchde &
//! Kuhnert §3.6). For every point with other-part points within h (S_i^ext), the signed
//! distance DC_i to the nearest other part (eq 10, signed_distance.hpp; only where that part
//! has points enough within h for the quadratic, 6 in 3D and 3 in 2D) is compared with its
//! sign at the previous step: a change of sign is a penetration; a point of the other part
//! within the deletion distance r_min h without one is a near contact. The response is
//! chosen by the pair of surfaces the two points come from:
//!   non-penetration  penetrated points are projected back to the side they came from, ξ off
//!                    the other surface, their velocity averaged with the other surface's;
//!   delete           penetrated and near points are deleted, and the two chambers become
//!                    one (two droplets that meet are one droplet);
//!   merge            each penetrated or near point is merged with the nearest point of the
//!                    other part, halfway between them, and the two chambers become one.
//! Choices the paper leaves open are written down in docs/theory/surface-contact.md.

#include <string>
#include <vector>

#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/surface/point_cloud.hpp"

namespace pellicle {

enum class ContactResponse { none, non_penetration, remove, merge };

//! "none", "non-penetration", "delete", "merge" (as case files write them).
const std::vector<std::string>& contact_response_names();
ContactResponse contact_response_from_name(const std::string& name);

struct ContactRule {
  int first = 0, second = 0;  //!< surfaces (the same one twice: its self-contact)
  ContactResponse response = ContactResponse::none;
};

struct ContactOptions {
  //! Between two different surfaces, unless a rule names the pair.
  ContactResponse between = ContactResponse::none;
  //! Between facing parts of one surface (a neck that pinches, a hole that closes), unless
  //! a rule names the surface twice.
  ContactResponse self = ContactResponse::none;
  std::vector<ContactRule> rules;
  //! Points of one chamber whose normals have n_i·n_j below this are facing parts
  //! (PointCloud::facing_limit), when some self-contact response is not none.
  double facing_limit = 0.0;

  ContactResponse response(int surface_a, int surface_b) const;
  bool self_contact() const;  //!< some surface's self-contact response is not none
  bool active() const;        //!< some response is not none
};

struct ContactReport {
  long in_contact = 0;  //!< points with other-part points within h
  long penetrated = 0;  //!< sign of DC_i changed since the previous step
  long near = 0;        //!< the other part within r_min h, without a change of sign
  long projected = 0;   //!< moved back by non-penetration
  long removed = 0;     //!< deleted by delete contact, or merged into another point
  int joined = 0;       //!< chambers joined into others
  bool changed() const { return projected + removed > 0; }
};

//! Detect and respond for every point (`own`: S_i; `external`: S_i^ext, both of the current
//! positions; the normals current). Changes positions, velocities, chambers and the points
//! themselves; the caller rebuilds the geometry when the report says the cloud changed. ξ
//! of eq 10 is a third of the smallest distance between neighbouring points in contact.
template <int D>
ContactReport resolve_contacts(PointCloud<D>& cloud, const NeighbourLists& own,
                               const NeighbourLists& external, const ContactOptions& options,
                               double r_min);

}  // namespace pellicle
