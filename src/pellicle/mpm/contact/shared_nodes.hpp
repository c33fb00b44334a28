#pragma once
//! The nodes that two or more bodies share, as contact models see them (IJNME §4.1, thesis
//! A.1.3): each body's own field at the node (GridFields with one field per body), each
//! body's colour function on cell centres (eq 27 / 9.10) whose gradient gives its outward
//! normal at a node (eq 28 / 9.11), and the sweep over the shared nodes where a contact rule
//! decides which velocity each body moves with.

#include <omp.h>

#include <algorithm>
#include <vector>

#include "pellicle/mpm/cell_field.hpp"
#include "pellicle/mpm/grid_fields.hpp"
#include "pellicle/mpm/particles.hpp"
#include "pellicle/mpm/step_hook.hpp"

namespace pellicle {

//! The bodies that share one node, as a contact rule sees them. Sized once per sweep and
//! thread for every body of the run, so any number of bodies may meet at a node.
template <int D>
struct SharedNode {
  explicit SharedNode(int bodies)
      : body(bodies),
        mass(bodies),
        velocity(bodies),
        mapped(bodies),
        normal(bodies),
        membrane(bodies),
        in_contact(bodies) {}
  long index = 0;  //!< the grid node
  int count = 0;
  std::vector<int> body;
  std::vector<double> mass;
  std::vector<Vec<D>> velocity;  //!< each body's own new velocity; the rule overwrites it
  //! Each body's velocity from its points' momentum, before the grid forces act (IJNME
  //! eq 25): the criteria compare these, free of the large accelerations of nodes that
  //! hold only a sliver of a body's mass.
  std::vector<Vec<D>> mapped;
  std::vector<Vec<D>> normal;  //!< outward unit normal of each body (zero where undefined)
  std::vector<char> membrane;  //!< membranes have outward normals on both sides
  //! Set by a rule for bodies that move with the centre-of-mass velocity here (IJNME
  //! eqs 20–22) instead of their own.
  std::vector<char> in_contact;
  Vec<D> centre_of_mass;         //!< centre-of-mass new velocity
  Vec<D> centre_of_mass_mapped;  //!< centre-of-mass velocity from momentum (IJNME eq 22)
};

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
class SharedNodes {
 public:
  //! Total contact force on each body in the last step (Σ over nodes of m ΔV/Δt).
  const std::vector<Vec<D>>& contact_force() const { return contact_force_; }

  //! Each body's colour function from its points (eq 27 / 9.10), completed by the hooks'
  //! after_cell_spread: at the start of a step, for both passes' normals. It holds the full
  //! sums on the cells around the shared nodes, which are all the sweeps read.
  void colour_functions(Simulation<D>& simulation);

  //! Apply `rule(SharedNode&)` at every node shared by two or more bodies: it sets the
  //! velocity each body moves with there. The bodies' fields follow, and in the Lagrangian
  //! pass their FLIP increments and the contact forces (summed over the nodes the grid
  //! owns, Grid::owns).
  template <class Rule>
  void sweep(GridFields<D>& fields, const Particles<D>& points, double dt, GridPass pass,
             Rule&& rule);

 private:
  Vec<D> outward_normal(const Grid<D>& grid, int body, long node) const;
  //! grids_ at the bodies' fields.
  void point_at_fields(GridFields<D>& fields) {
    grids_.resize(fields.count());
    for (int b = 0; b < fields.count(); ++b) grids_[b] = &fields.field(b);
  }
  //! Two or more bodies hold mass at node n (after point_at_fields).
  bool shared(long n) const {
    int present = 0;  // most nodes hold one body or none: stop at two
    for (std::size_t b = 0; b < grids_.size() && present < 2; ++b)
      present += grids_[b]->mass[n] > 0.0;
    return present >= 2;
  }

  std::vector<std::vector<double>> colour_;  //!< per body, on cell centres
  //! The cells the sweeps read (marked > 0), and the first cells of the points that reach
  //! them (cells_spread_from): per step, before the colour functions.
  std::vector<double> reads_;
  std::vector<char> spread_from_;
  CellSpreadCopies spread_copies_;
  std::vector<Vec<D>> contact_force_;
  // Work storage, sized once for the run's bodies and threads (no allocation per step).
  std::vector<Grid<D>*> grids_;
  std::vector<SharedNode<D>> nodes_;               //!< one per thread
  std::vector<std::vector<Vec<D>>> thread_force_;  //!< one per thread
};

template <int D>
template <class Rule>
void SharedNodes<D>::sweep(GridFields<D>& fields, const Particles<D>& points, double dt,
                           GridPass pass, Rule&& rule) {
  const bool lagrangian = pass == GridPass::lagrangian;
  const Grid<D>& centre_of_mass = fields.centre_of_mass();
  const int bodies = fields.count();
  point_at_fields(fields);
  const auto& grids = grids_;
  const int threads = omp_get_max_threads();
  if (static_cast<int>(nodes_.size()) != threads || nodes_.front().body.size() != grids.size()) {
    nodes_.assign(threads, SharedNode<D>(bodies));
    thread_force_.assign(threads, std::vector<Vec<D>>(bodies));
  }
  // Before the forces act: v^k = v − Δv (the convected pass has no forces).
  auto mapped = [lagrangian](const Grid<D>& g, long n) -> Vec<D> {
    return lagrangian ? Vec<D>(g.velocity[n] - g.velocity_change[n]) : g.velocity[n];
  };
  if (lagrangian) contact_force_.assign(bodies, Vec<D>::Zero());
  for (auto& force : thread_force_) std::fill(force.begin(), force.end(), Vec<D>::Zero());
#pragma omp parallel
  {
    std::vector<Vec<D>>& force = thread_force_[omp_get_thread_num()];
    SharedNode<D>& node = nodes_[omp_get_thread_num()];
    // Nodes with mass are live in the centre-of-mass field (the sum of the bodies').
    centre_of_mass.for_each_live_of_thread([&](long n) {
      if (!shared(n)) return;  // look before filling the node
      node.count = 0;
      for (int b = 0; b < bodies; ++b) {
        const Grid<D>& g = *grids[b];
        if (!(g.mass[n] > 0.0)) continue;
        node.body[node.count] = b;
        node.mass[node.count] = g.mass[n];
        node.velocity[node.count] = g.velocity[n];
        node.mapped[node.count] = mapped(g, n);
        node.in_contact[node.count] = false;
        node.membrane[node.count] = points.bodies[b].frames != nullptr;
        ++node.count;
      }
      node.index = n;
      node.centre_of_mass = centre_of_mass.velocity[n];
      node.centre_of_mass_mapped = mapped(centre_of_mass, n);
      for (int k = 0; k < node.count; ++k)
        node.normal[k] = outward_normal(*grids[node.body[k]], node.body[k], n);
      rule(node);
      const bool owned = centre_of_mass.owns(n);
      for (int k = 0; k < node.count; ++k) {
        Grid<D>& g = *grids[node.body[k]];
        if (node.in_contact[k]) node.velocity[k] = node.centre_of_mass;
        if (lagrangian) {
          const Vec<D> change = node.velocity[k] - g.velocity[n];
          if (owned) force[node.body[k]] += node.mass[k] / dt * change;
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
    });
  }
  // In thread order, so that the diagnostic's last bits do not change from run to run.
  for (const auto& force : thread_force_)
    for (int b = 0; b < bodies; ++b) contact_force_[b] += force[b];
  for (Grid<D>* grid : grids) {
    Grid<D>& g = *grid;
    g.constrain(g.velocity);
    g.mirror(g.velocity);
    if (!lagrangian) continue;
    g.constrain(g.velocity_change);
    g.mirror(g.velocity_change);
  }
}

extern template class SharedNodes<2>;
extern template class SharedNodes<3>;

}  // namespace pellicle
