// Two disks and a wire (IJNME §4.3–4.4, cases/disks_wire.toml; the geometry of the lost
// Figure 21 is reconstructed in the case file).
// disks-wire: with contact-release the disks pinch the wire (both feel a contact force in
// the same steps), never cross it, and by t = 5 are both more than a cell away; with the single
// field they stay on it; at t = 5 disk I moves to the left and disk II to the right (the
// paper's last frames; signs checked).
// offset-disks: the disks, offset vertically and moving at the same speed, rotate clockwise
// while they pinch the wire (both feel it) and counter-clockwise after release (neither
// feels it any more); the signs of the mean angular velocities are checked.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

constexpr int kDiskI = 0, kDiskII = 1, kWire = 2;

//! Smallest distance from a point of `body` to a point of the wire.
double distance_to_wire(const Simulation<2>& s, int body) {
  const auto& p = s.points();
  double nearest = 1e300;
  for (long i = p.bodies[body].begin; i < p.bodies[body].end; ++i)
    for (long w = p.bodies[kWire].begin; w < p.bodies[kWire].end; ++w)
      nearest = std::min(nearest, (p.position[i] - p.position[w]).squaredNorm());
  return std::sqrt(nearest);
}

//! Signed horizontal distance of `body`'s points past the wire, x − x_wire(y) with the wire
//! interpolated between its points (ordered along it): the largest for disk I (must stay
//! < 0), the smallest for disk II (must stay > 0).
double beyond_wire(const Simulation<2>& s, int body) {
  const auto& p = s.points();
  const auto& w = p.bodies[kWire];
  const bool left = body == kDiskI;
  double extreme = left ? -1e300 : 1e300;
  for (long i = p.bodies[body].begin; i < p.bodies[body].end; ++i) {
    const Vec2& x = p.position[i];
    for (long k = w.begin; k + 1 < w.end; ++k) {
      const Vec2 &a = p.position[k], &b = p.position[k + 1];
      if ((a.y() - x.y()) * (b.y() - x.y()) > 0.0 || a.y() == b.y()) continue;
      const double wire_x = a.x() + (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y());
      extreme = left ? std::max(extreme, x.x() - wire_x) : std::min(extreme, x.x() - wire_x);
    }
  }
  return extreme;
}

//! Angular velocity of a body about its centre of mass (counter-clockwise positive).
double angular_velocity(const Simulation<2>& s, int body) {
  const auto& p = s.points();
  const auto& b = p.bodies[body];
  double mass = 0.0;
  Vec2 centre = Vec2::Zero(), velocity = Vec2::Zero();
  for (long i = b.begin; i < b.end; ++i) {
    mass += p.mass[i];
    centre += p.mass[i] * p.position[i];
    velocity += p.mass[i] * p.velocity[i];
  }
  centre /= mass;
  velocity /= mass;
  double momentum = 0.0, inertia = 0.0;
  for (long i = b.begin; i < b.end; ++i) {
    const Vec2 r = p.position[i] - centre, v = p.velocity[i] - velocity;
    momentum += p.mass[i] * (r.x() * v.y() - r.y() * v.x());
    inertia += p.mass[i] * r.squaredNorm();
  }
  return momentum / inertia;
}

}  // namespace

Outcome disks_wire(Resolution) {
  Outcome out;
  const double h = 0.25;
  auto s = builtin_simulation<2>("disks_wire.toml", {});
  const double e0 = s->state().total();
  double worst_I = -1e300, worst_II = 1e300;
  long pinching_steps = 0;
  Series series{"disks_wire_velocity",
                "Disks and wire: disk velocities (compare IJNME Fig. 22)",
                {"time", "disk I", "disk II"},
                {{0.0, 1.0, -1.1}}};
  long step = 0;
  while (!s->finished()) {
    s->step();
    const auto& force = *s->contact_forces();
    if (force[kDiskI].norm() > 0.0 && force[kDiskII].norm() > 0.0) ++pinching_steps;
    if (++step % 10 != 0 && !s->finished()) continue;
    worst_I = std::max(worst_I, beyond_wire(*s, kDiskI));
    worst_II = std::min(worst_II, beyond_wire(*s, kDiskII));
    series.rows.push_back(
        {s->time(), body_velocity(*s, kDiskI).x(), body_velocity(*s, kDiskII).x()});
  }
  out.checks.push_back({"pinch: steps with both disks in contact with the wire",
                        static_cast<double>(pinching_steps), 1.0, 1.0, 1e9, ""});
  out.checks.push_back({"disk I, largest distance past the wire", worst_I, 0.0, -1e9, 0.0, ""});
  out.checks.push_back({"disk II, smallest distance past the wire", worst_II, 0.0, 0.0, 1e9, ""});
  out.checks.push_back(
      {"disk I to the wire at t = 5", distance_to_wire(*s, kDiskI), h, h, 1e9, ""});
  out.checks.push_back(
      {"disk II to the wire at t = 5", distance_to_wire(*s, kDiskII), h, h, 1e9, ""});
  // The paper's last frames: disk I moves off to the left, disk II to the right.
  out.checks.push_back({"disk I velocity at t = 5 (to the left)", body_velocity(*s, kDiskI).x(),
                        0.0, -1e9, 0.0, ""});
  out.checks.push_back({"disk II velocity at t = 5 (to the right)", body_velocity(*s, kDiskII).x(),
                        0.0, 0.0, 1e9, ""});
  char row[256];
  std::snprintf(row, sizeof row, "| contact-release | %.3f | %.3f | %.3f | %.3f |\n",
                body_velocity(*s, kDiskI).x(), body_velocity(*s, kDiskII).x(),
                s->state().total() / e0,
                std::min(distance_to_wire(*s, kDiskI), distance_to_wire(*s, kDiskII)));
  out.table =
      "| contact | disk I at t = 5 | disk II at t = 5 | energy end / start | nearest disk "
      "to the wire |\n|---|---|---|---|---|\n" +
      std::string(row);

  auto stuck = builtin_simulation<2>("disks_wire.toml", {"contact={model=\"single-field\"}"});
  stuck->run();
  const double near = std::min(distance_to_wire(*stuck, kDiskI), distance_to_wire(*stuck, kDiskII));
  out.checks.push_back(
      {"single field: nearest disk to the wire at t = 5 (they stick)", near, 0.0, 0.0, h, ""});
  std::snprintf(row, sizeof row, "| single field | %.3f | %.3f | %.3f | %.3f |\n",
                body_velocity(*stuck, kDiskI).x(), body_velocity(*stuck, kDiskII).x(),
                stuck->state().total() / e0, near);
  out.table += row;
  out.series.push_back(std::move(series));
  return out;
}

Outcome offset_disks(Resolution) {
  Outcome out;
  auto s = builtin_simulation<2>("disks_wire.toml",
                                 {"body[0].region={shape=\"disk\", center=[3.5, 5.6], radius=1.0}",
                                  "body[1].region={shape=\"disk\", center=[6.5, 4.4], radius=1.0}",
                                  "body[1].velocity=[-1.0, 0.0]"});
  const double e0 = s->state().total();
  Series series{"offset_disks_spin",
                "Offset disks: angular velocities (counter-clockwise > 0)",
                {"time", "disk I", "disk II"},
                {{0.0, 0.0, 0.0}}};
  // Pinching: steps in which both disks feel a contact force from the wire; after release:
  // the steps after the last one in which either disk feels it.
  std::vector<std::array<double, 3>> spin;  // time, disk I, disk II
  std::vector<bool> pinched, touched;
  while (!s->finished()) {
    s->step();
    const auto& force = *s->contact_forces();
    pinched.push_back(force[kDiskI].norm() > 0.0 && force[kDiskII].norm() > 0.0);
    touched.push_back(force[kDiskI].norm() > 0.0 || force[kDiskII].norm() > 0.0);
    spin.push_back({s->time(), angular_velocity(*s, kDiskI), angular_velocity(*s, kDiskII)});
    if (spin.size() % 10 == 0)
      series.rows.push_back({spin.back()[0], spin.back()[1], spin.back()[2]});
  }
  std::size_t last_touch = 0;
  for (std::size_t i = 0; i < touched.size(); ++i)
    if (touched[i]) last_touch = i;
  double pinching_I = 0.0, pinching_II = 0.0, after_I = 0.0, after_II = 0.0;
  int pinching = 0, after = 0;
  for (std::size_t i = 0; i < spin.size(); ++i) {
    if (pinched[i]) pinching_I += spin[i][1], pinching_II += spin[i][2], ++pinching;
    if (i > last_touch) after_I += spin[i][1], after_II += spin[i][2], ++after;
  }
  out.checks.push_back({"steps pinching (both disks feel the wire)", static_cast<double>(pinching),
                        1.0, 1.0, 1e9, ""});
  out.checks.push_back({"steps after release (neither disk feels the wire)",
                        static_cast<double>(after), 1.0, 1.0, 1e9, ""});
  out.checks.push_back({"disk I, mean angular velocity while pinching (clockwise < 0)",
                        pinching_I / std::max(pinching, 1), 0.0, -1e9, 0.0, "rad/s"});
  out.checks.push_back({"disk II, mean angular velocity while pinching (clockwise < 0)",
                        pinching_II / std::max(pinching, 1), 0.0, -1e9, 0.0, "rad/s"});
  out.checks.push_back({"disk I, mean angular velocity after release (counter-clockwise > 0)",
                        after_I / std::max(after, 1), 0.0, 0.0, 1e9, "rad/s"});
  out.checks.push_back({"disk II, mean angular velocity after release (counter-clockwise > 0)",
                        after_II / std::max(after, 1), 0.0, 0.0, 1e9, "rad/s"});
  char row[320];
  std::snprintf(row, sizeof row,
                "| while pinching (paper: clockwise, < 0) | %.4f | %.4f |\n"
                "| after release, from t = %.2f (paper: counter-clockwise, > 0) | %.4f | %.4f |\n\n"
                "Energy at t = 5 / start: %.3f.\n",
                pinching_I / std::max(pinching, 1), pinching_II / std::max(pinching, 1),
                spin[std::min(last_touch + 1, spin.size() - 1)][0], after_I / std::max(after, 1),
                after_II / std::max(after, 1), s->state().total() / e0);
  out.table = "| mean angular velocity | disk I | disk II |\n|---|---|---|\n" + std::string(row);
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
