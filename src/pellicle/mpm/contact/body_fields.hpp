#pragma once
//! Per-body grid fields for contact models (IJNME §4.1, thesis A.1.3): each body's mass,
//! momentum and force on its own copy of the grid (eqs 23–25 / 9.4–9.6), the centre-of-mass
//! field as their sum (eqs 20–22 / 9.1–9.3), each body's colour function on cell centres
//! (eq 27 / 9.10) whose gradient gives its outward normal at a node (eq 28 / 9.11), and the
//! sweep over the nodes that two or more bodies share, where a contact model decides which
//! velocity each body moves with.

#include <omp.h>

#include <algorithm>
#include <vector>

#include "pellicle/mpm/cell_field.hpp"
#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/particles.hpp"
#include "pellicle/mpm/transfer.hpp"

namespace pellicle {

//! The bodies that share one node, as a contact rule sees them.
template <int D>
struct SharedNode {
  static constexpr int kMaxBodies = 8;  //!< more bodies at one node: the extra ones are left alone
  long index = 0;                       //!< the grid node
  int count = 0;
  int body[kMaxBodies];
  double mass[kMaxBodies];
  Vec<D> velocity[kMaxBodies];  //!< each body's own new velocity; the rule overwrites it
  //! Each body's velocity from its points' momentum, before the grid forces act (IJNME
  //! eq 25): the criteria compare these, free of the large accelerations of nodes that
  //! hold only a sliver of a body's mass.
  Vec<D> mapped[kMaxBodies];
  Vec<D> normal[kMaxBodies];  //!< outward unit normal of each body (zero where undefined)
  bool membrane[kMaxBodies];  //!< membranes have outward normals on both sides
  //! Set by a rule for bodies that move with the centre-of-mass velocity here (IJNME
  //! eqs 20–22) instead of their own.
  bool in_contact[kMaxBodies];
  Vec<D> centre_of_mass;         //!< centre-of-mass new velocity
  Vec<D> centre_of_mass_mapped;  //!< centre-of-mass velocity from momentum (IJNME eq 22)
};

//! Which grid velocities a contact rule corrects: the Lagrangian ones after the grid solve
//! (they move the points; their corrections are the contact forces), or the convected ones
//! of the MUSL remap (they give the strain rates, so bodies in contact deform together).
enum class ContactPass { lagrangian, convected };

//! For two bodies at a node: one normal, opposite for each, so that corrections balance
//! (Bardenhagen et al. 2000). It is the normal of a solid rather than a membrane (whose
//! two-sided colour gives a normal pointing away from it on either side, not toward the
//! other body), and of the body holding more mass at the node: where one body has only a
//! corner there, the other's surface is the better defined (a block's corner on a plate).
template <int D>
void use_common_normal(SharedNode<D>& node) {
  if (node.count != 2) return;
  int major = node.mass[0] >= node.mass[1] ? 0 : 1;
  if (node.membrane[0] != node.membrane[1]) major = node.membrane[0] ? 1 : 0;
  node.normal[1 - major] = -node.normal[major];
}

template <int D>
class BodyFields {
 public:
  BodyFields(const Grid<D>& grid, int bodies)
      : grids_(bodies, grid), colour_(bodies), contact_force_(bodies, Vec<D>::Zero()) {}

  int body_count() const { return static_cast<int>(grids_.size()); }
  Grid<D>& body_grid(int b) { return grids_[b]; }
  const Grid<D>& body_grid(int b) const { return grids_[b]; }
  //! Total contact force on each body in the last step (Σ over nodes of m ΔV/Δt).
  const std::vector<Vec<D>>& contact_force() const { return contact_force_; }

  //! Stage `to_grid`: every body onto its own grid; the centre-of-mass grid is their sum.
  void to_grid(Transfer<D>& transfer, const Particles<D>& points, const Vec<D>& gravity,
               Grid<D>& centre_of_mass);
  //! Stage `grid`: each body's Lagrangian velocity from its own mass, momentum and force.
  void integrate(double dt);
  //! Stage `to_points`, body by body in its own field. Returns the largest point speed.
  double to_points(Transfer<D>& transfer, double dt, Particles<D>& points, PointFailure& failure);
  //! Stage `remap` (MUSL), body by body; the centre-of-mass grid gets their sum.
  void remap(Transfer<D>& transfer, const Particles<D>& points, Grid<D>& centre_of_mass);
  //! Velocity gradients and continuity, each body from its own field. Returns the first bad
  //! point or −1.
  long point_kinematics(Transfer<D>& transfer, double dt, Particles<D>& points,
                        std::vector<Mat<D>>& gradient, std::vector<double>& hoop_rate);

  //! Apply `rule(SharedNode&)` at every node shared by two or more bodies: it sets the
  //! velocity each body moves with there. The bodies' fields follow, and in the Lagrangian
  //! pass their FLIP increments and the contact forces.
  template <class Rule>
  void sweep_shared_nodes(const Grid<D>& centre_of_mass, const Particles<D>& points, double dt,
                          ContactPass pass, Rule&& rule);

 private:
  void colour_functions(const Particles<D>& points);
  Vec<D> outward_normal(int body, long node) const;

  std::vector<Grid<D>> grids_;
  std::vector<std::vector<double>> colour_;  //!< per body, on cell centres
  std::vector<Vec<D>> contact_force_;
};

template <int D>
template <class Rule>
void BodyFields<D>::sweep_shared_nodes(const Grid<D>& centre_of_mass, const Particles<D>& points,
                                       double dt, ContactPass pass, Rule&& rule) {
  const bool lagrangian = pass == ContactPass::lagrangian;
  // Normals from the colour at the start of the step serve both passes.
  if (lagrangian) colour_functions(points);
  const int bodies = body_count();
  // Before the forces act: v^k = v − Δv (the convected pass has no forces).
  auto mapped = [lagrangian](const Grid<D>& g, long n) -> Vec<D> {
    return lagrangian ? Vec<D>(g.velocity[n] - g.velocity_change[n]) : g.velocity[n];
  };
  if (lagrangian) contact_force_.assign(bodies, Vec<D>::Zero());
  const long nodes = centre_of_mass.node_count();
#pragma omp parallel
  {
    std::vector<Vec<D>> force(bodies, Vec<D>::Zero());
#pragma omp for schedule(static)
    for (long n = 0; n < nodes; ++n) {
      SharedNode<D> node;
      for (int b = 0; b < bodies && node.count < SharedNode<D>::kMaxBodies; ++b) {
        if (!(grids_[b].mass[n] > 0.0)) continue;
        node.body[node.count] = b;
        node.mass[node.count] = grids_[b].mass[n];
        node.velocity[node.count] = grids_[b].velocity[n];
        node.mapped[node.count] = mapped(grids_[b], n);
        node.in_contact[node.count] = false;
        node.membrane[node.count] = points.bodies[b].frames != nullptr;
        ++node.count;
      }
      if (node.count < 2) continue;
      node.index = n;
      node.centre_of_mass = centre_of_mass.velocity[n];
      node.centre_of_mass_mapped = mapped(centre_of_mass, n);
      for (int k = 0; k < node.count; ++k) node.normal[k] = outward_normal(node.body[k], n);
      rule(node);
      for (int k = 0; k < node.count; ++k) {
        Grid<D>& g = grids_[node.body[k]];
        if (node.in_contact[k]) node.velocity[k] = node.centre_of_mass;
        if (lagrangian) {
          const Vec<D> change = node.velocity[k] - g.velocity[n];
          force[node.body[k]] += node.mass[k] / dt * change;
          // FLIP increment: in contact the centre-of-mass field's own, as standard MPM moves
          // the points there (eqs 20–22); otherwise from the body's own velocity before
          // the step, with the rule's correction.
          if (node.in_contact[k])
            g.velocity_change[n] = centre_of_mass.velocity_change[n];
          else
            g.velocity_change[n] += change;
        }
        g.velocity[n] = node.velocity[k];
      }
    }
#pragma omp critical
    for (int b = 0; b < bodies; ++b) contact_force_[b] += force[b];
  }
  for (auto& g : grids_) {
    g.constrain(g.velocity);
    g.mirror(g.velocity);
    if (!lagrangian) continue;
    g.constrain(g.velocity_change);
    g.mirror(g.velocity_change);
  }
}

extern template class BodyFields<2>;
extern template class BodyFields<3>;

}  // namespace pellicle
