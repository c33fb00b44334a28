#include "pellicle/io/output.hpp"

#include <omp.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "pellicle/io/atomic_file.hpp"
#include "pellicle/io/json_text.hpp"
#include "pellicle/io/output_directory.hpp"

namespace pellicle {

namespace {
const char* axis_names = "xyz";

//! Per body: its mass, Σ m x and Σ m v, then its material's history sums; over every rank of a
//! distributed run.
template <int D>
struct BodySums {
  std::vector<double> values;
  std::vector<std::size_t> first;  //!< where each body's values start
  std::vector<long> points;        //!< each body's points

  explicit BodySums(const Simulation<D>& s) {
    const auto& p = s.points();
    for (const auto& body : p.bodies) {
      first.push_back(values.size());
      points.push_back(body.count());
      double mass = 0.0;
      Vec<D> mx = Vec<D>::Zero(), mv = Vec<D>::Zero();
      for (long i = body.begin; i < body.end; ++i) {
        mx += p.mass[i] * p.position[i];
        mv += p.mass[i] * p.velocity[i];
        mass += p.mass[i];
      }
      values.push_back(mass);
      values.insert(values.end(), mx.data(), mx.data() + D);
      values.insert(values.end(), mv.data(), mv.data() + D);
      s.material(body.material).history_sums(p, body.begin, body.end, values);
    }
    if (const Collective* ranks = s.collective()) {
      ranks->sum_in_rank_order(values);
      ranks->sum(points);
    }
  }
  double mass(int b) const { return values[first[b]]; }
  Vec<D> com(int b) const { return Vec<D>(values.data() + first[b] + 1) / mass(b); }
  Vec<D> velocity(int b) const { return Vec<D>(values.data() + first[b] + 1 + D) / mass(b); }
  const double* material_sums(int b) const { return values.data() + first[b] + 1 + 2 * D; }
  long total_points() const {
    long n = 0;
    for (long k : points) n += k;
    return n;
  }
};

}  // namespace

std::string hash_text(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64 offset basis
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(h));
  return buffer;
}

template <int D>
OutputWriter<D>::OutputWriter(const OutputSettings& settings, const Simulation<D>& simulation,
                              std::vector<Probe<D>> probes)
    : settings_(settings),
      probes_(std::move(probes)),
      points_series_(settings.directory + "/points.pvd"),
      grid_series_(settings.directory + "/grid.pvd"),
      rank_(simulation.collective() ? simulation.collective()->rank() : 0),
      ranks_(simulation.collective() ? simulation.collective()->size() : 1) {
  std::error_code ec;
  std::filesystem::create_directories(settings_.directory, ec);
  if (ec) throw std::runtime_error("cannot create " + settings_.directory + ": " + ec.message());
  // Rank 0 writes the history (a null stream elsewhere: every rank takes part in the sums).
  if (rank_ == 0) {
    history_.open(settings_.directory + "/history.csv", std::ios::trunc);
    if (!history_) throw std::runtime_error("cannot write " + settings_.directory + "/history.csv");
  } else {
    history_.setstate(std::ios::badbit);
  }
  history_ << "time,step,dt,kinetic,strain,internal,gravitational,total";
  for (int d = 0; d < D; ++d) history_ << ",momentum_" << axis_names[d];
  for (const auto& b : simulation.points().bodies) {
    for (int d = 0; d < D; ++d) history_ << ',' << b.name << ".com_" << axis_names[d];
    for (int d = 0; d < D; ++d) history_ << ',' << b.name << ".vel_" << axis_names[d];
  }
  for (const auto& b : simulation.points().bodies)
    for (const auto& name : simulation.material(b.material).history_names())
      history_ << ',' << b.name << '.' << name;
  if (simulation.contact_forces())
    for (const auto& b : simulation.points().bodies)
      for (int d = 0; d < D; ++d) history_ << ',' << b.name << ".contact_" << axis_names[d];
  for (const auto& pair : simulation.enclosed()) {
    const auto& bodies = simulation.points().bodies;
    const std::string& m = bodies[pair.membrane].name;
    history_ << ',' << m << ".enclosed_volume," << m << ".tension," << bodies[pair.filler].name
             << ".escaped";
  }
  escaped_.assign(simulation.enclosed().size(), 0);
  for (const auto& probe : probes_)
    for (const auto& column : probe.columns()) history_ << ',' << column;
  history_ << '\n' << std::setprecision(12);
  write_history_row(simulation);
  write_snapshot(simulation);
}

template <int D>
void OutputWriter<D>::write_history_row(const Simulation<D>& simulation) {
  const SystemState<D> s = simulation.state();
  history_ << simulation.time() << ',' << simulation.step_count() << ',' << simulation.last_dt()
           << ',' << s.kinetic << ',' << s.strain << ',' << s.internal << ',' << s.gravitational
           << ',' << s.total();
  for (int d = 0; d < D; ++d) history_ << ',' << s.momentum[d];
  const auto& p = simulation.points();
  const BodySums<D> sums(simulation);
  const int bodies = static_cast<int>(p.bodies.size());
  for (int b = 0; b < bodies; ++b) {
    const Vec<D> com = sums.com(b), vel = sums.velocity(b);
    for (int d = 0; d < D; ++d) history_ << ',' << com[d];
    for (int d = 0; d < D; ++d) history_ << ',' << vel[d];
  }
  std::vector<double> values;
  for (int b = 0; b < bodies; ++b) {
    values.clear();
    simulation.material(p.bodies[b].material).history_from_sums(sums.material_sums(b), values);
    for (double v : values) history_ << ',' << v;
  }
  if (const auto* forces = simulation.contact_forces()) {
    // Each rank's share is over the nodes it owns.
    std::vector<double> total;
    for (const auto& f : *forces) total.insert(total.end(), f.data(), f.data() + D);
    if (const Collective* ranks = simulation.collective()) ranks->sum_in_rank_order(total);
    for (double f : total) history_ << ',' << f;
  }
  for (std::size_t k = 0; k < simulation.enclosed().size(); ++k) {
    const auto& pair = simulation.enclosed()[k];
    const Collective* ranks = simulation.collective();
    const long escaped = escaped_points(p, pair, ranks);
    escaped_[k] = std::max(escaped_[k], escaped);
    history_ << ',' << enclosed_volume(p, pair, simulation.settings().kinematics, ranks) << ','
             << mean_tension(p, pair, ranks) << ',' << escaped;
  }
  for (const auto& probe : probes_)
    for (double v : probe.values(simulation)) history_ << ',' << v;
  history_ << '\n';
  history_.flush();
  if (rank_ == 0 && !history_)
    throw std::runtime_error("cannot write " + settings_.directory + "/history.csv");
  last_history_step_ = simulation.step_count();
  next_history_ = simulation.time() + settings_.history_interval;
}

template <int D>
void OutputWriter<D>::write_snapshot(const Simulation<D>& simulation) {
  char name[48];
  if (ranks_ == 1) {
    std::snprintf(name, sizeof name, "points_%06d.vtu", snapshots_);
    write_points_vtu<D>(settings_.directory + "/" + name, simulation);
  } else {  // a piece per rank, and the file that joins them
    std::snprintf(name, sizeof name, "points_%06d_r%04d.vtu", snapshots_, rank_);
    write_points_vtu<D>(settings_.directory + "/" + name, simulation);
    std::vector<std::string> pieces;
    for (int r = 0; r < ranks_; ++r) {
      std::snprintf(name, sizeof name, "points_%06d_r%04d.vtu", snapshots_, r);
      pieces.push_back(name);
    }
    std::snprintf(name, sizeof name, "points_%06d.pvtu", snapshots_);
    if (rank_ == 0) write_points_pvtu<D>(settings_.directory + "/" + name, simulation, pieces);
  }
  if (rank_ == 0) points_series_.add(simulation.time(), name);
  if (settings_.grid_snapshots) {
    const Grid<D>& grid = simulation.grid();
    const NodeStresses<D>& stresses = projection_.project(simulation);
    if (ranks_ == 1) {
      std::snprintf(name, sizeof name, "grid_%06d.vti", snapshots_);
      write_grid_vti<D>(settings_.directory + "/" + name, grid, stresses);
    } else {
      write_grid_pieces(simulation, stresses, name, sizeof name);
    }
    if (rank_ == 0) grid_series_.add(simulation.time(), name);
  }
  ++snapshots_;
  last_snapshot_step_ = simulation.step_count();
  next_snapshot_ = settings_.snapshot_interval > 0.0
                       ? simulation.time() + settings_.snapshot_interval
                       : std::numeric_limits<double>::infinity();
}

template <int D>
void OutputWriter<D>::write_grid_pieces(const Simulation<D>& simulation,
                                        const NodeStresses<D>& stresses, char* name,
                                        std::size_t size) {
  // Each rank writes the nodes it owns and, across a cut, the layer of nodes its upper
  // neighbour owns, so that the pieces meet without gaps (VTK pieces share their faces).
  const Grid<D>& grid = simulation.grid();
  const IVec<D> stored_last = grid.first() + grid.nodes() - IVec<D>::Ones();
  const IVec<D> first = grid.owned_first();
  const IVec<D> last = (grid.owned_last() + IVec<D>::Ones()).cwiseMin(stored_last);
  std::snprintf(name, size, "grid_%06d_r%04d.vti", snapshots_, rank_);
  write_grid_vti<D>(settings_.directory + "/" + name, grid, stresses, first, last);
  std::vector<double> mine;
  for (int d = 0; d < D; ++d) mine.push_back(first[d]);
  for (int d = 0; d < D; ++d) mine.push_back(last[d]);
  const std::vector<double> boxes = simulation.collective()->all_gather(mine);
  std::vector<std::string> pieces;
  std::vector<IVec<D>> firsts, lasts;
  for (int r = 0; r < ranks_; ++r) {
    std::snprintf(name, size, "grid_%06d_r%04d.vti", snapshots_, r);
    pieces.push_back(name);
    IVec<D> f, l;
    for (int d = 0; d < D; ++d) {
      f[d] = static_cast<int>(boxes[2 * D * r + d]);
      l[d] = static_cast<int>(boxes[2 * D * r + D + d]);
    }
    firsts.push_back(f);
    lasts.push_back(l);
  }
  std::snprintf(name, size, "grid_%06d.pvti", snapshots_);
  if (rank_ == 0) write_grid_pvti<D>(settings_.directory + "/" + name, grid, pieces, firsts, lasts);
}

template <int D>
void OutputWriter<D>::after_step(const Simulation<D>& simulation) {
  // A small tolerance keeps rows on the intended times despite round-off in Σ Δt.
  const double t = simulation.time() + 1e-9 * simulation.last_dt();
  if (t >= next_history_) write_history_row(simulation);
  if (t >= next_snapshot_) write_snapshot(simulation);
}

template <int D>
void OutputWriter<D>::finish(const Simulation<D>& simulation, const std::string& status,
                             const std::string& case_hash, double wall_seconds) {
  // A distributed run's failure is one rank's: the others wait in the step, so nothing that
  // needs them is written (the history up to the failure is on disk).
  if (ranks_ > 1 && status != "completed" && status != "interrupted") return;
  if (last_history_step_ != simulation.step_count()) write_history_row(simulation);
  if (last_snapshot_step_ != simulation.step_count()) write_snapshot(simulation);
  const SystemState<D> s = simulation.state();
  const auto& p = simulation.points();
  const BodySums<D> sums(simulation);
  std::vector<std::pair<std::string, double>> figures;
  for (const auto& hook : simulation.hooks()) hook->summary_figures(figures);
  if (rank_ != 0) return;
  const long points = sums.total_points();
  const double point_steps = static_cast<double>(points) * simulation.step_count();
  std::ostringstream j;
  j << "{\n";
  j << "  \"version\": " << json_string(PELLICLE_VERSION) << ",\n";
  j << "  \"status\": " << json_string(status) << ",\n";
  j << "  \"case_hash\": " << json_string(case_hash) << ",\n";
  j << "  \"time\": " << json_number(simulation.time()) << ",\n";
  j << "  \"steps\": " << simulation.step_count() << ",\n";
  j << "  \"points\": " << points << ",\n";
  j << "  \"ranks\": " << ranks_ << ",\n";
  j << "  \"threads\": " << omp_get_max_threads() << ",\n";
  j << "  \"wall_seconds\": " << json_number(wall_seconds) << ",\n";
  j << "  \"particle_steps_per_second\": "
    << json_number(wall_seconds > 0.0 ? point_steps / wall_seconds : 0.0) << ",\n";
  j << "  \"energy\": {\"kinetic\": " << json_number(s.kinetic)
    << ", \"strain\": " << json_number(s.strain) << ", \"internal\": " << json_number(s.internal)
    << ", \"gravitational\": " << json_number(s.gravitational)
    << ", \"total\": " << json_number(s.total()) << "},\n";
  j << "  \"momentum\": [";
  for (int d = 0; d < D; ++d) j << (d ? ", " : "") << json_number(s.momentum[d]);
  j << "],\n  \"bodies\": {";
  for (int b = 0; b < static_cast<int>(p.bodies.size()); ++b) {
    const Vec<D> com = sums.com(b), vel = sums.velocity(b);
    j << (b ? ",\n" : "\n") << "    " << json_string(p.bodies[b].name)
      << ": {\"points\": " << sums.points[b] << ", \"mass\": " << json_number(sums.mass(b))
      << ", \"com\": [";
    for (int d = 0; d < D; ++d) j << (d ? ", " : "") << json_number(com[d]);
    j << "], \"velocity\": [";
    for (int d = 0; d < D; ++d) j << (d ? ", " : "") << json_number(vel[d]);
    j << "]}";
  }
  j << "\n  }";
  if (!simulation.enclosed().empty()) {
    // The most points of each filling body ever seen outside its membrane (history rows).
    j << ",\n  \"escaped_points\": {";
    for (std::size_t k = 0; k < escaped_.size(); ++k)
      j << (k ? ", " : "") << json_string(p.bodies[simulation.enclosed()[k].filler].name) << ": "
        << escaped_[k];
    j << "}";
  }
  if (!figures.empty()) {
    j << ",\n  \"figures\": {";
    for (std::size_t k = 0; k < figures.size(); ++k)
      j << (k ? ", " : "") << json_string(figures[k].first) << ": "
        << json_number(figures[k].second);
    j << "}";
  }
  j << "\n}\n";
  write_file_atomically(settings_.directory + "/summary.json", j.str());
  mark_output_directory(settings_.directory, status);
}

template class OutputWriter<2>;
template class OutputWriter<3>;

}  // namespace pellicle
