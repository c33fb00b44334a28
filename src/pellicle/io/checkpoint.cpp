#include "pellicle/io/checkpoint.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "pellicle/core/error.hpp"

namespace pellicle {
namespace {

constexpr const char* kFormat = "pellicle-checkpoint";
constexpr const char* kPieceFormat = "pellicle-checkpoint-piece";

//! An HDF5 identifier closed when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error(what);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { close_(id_); }
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error(what);
}

Handle group(hid_t parent, const std::string& name, bool create) {
  const hid_t id = create ? H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)
                          : H5Gopen2(parent, name.c_str(), H5P_DEFAULT);
  return Handle(id, H5Gclose, "no group '" + name + "'");
}

void write_text(hid_t object, const char* name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(type, std::max<std::size_t>(value.size(), 1)), "string size");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle attribute(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                   std::string("attribute ") + name);
  check(H5Awrite(attribute, type, value.empty() ? "" : value.data()), name);
}

template <class T>
void write_number(hid_t object, const char* name, T value) {
  const hid_t type = std::is_integral_v<T> ? H5T_NATIVE_LONG : H5T_NATIVE_DOUBLE;
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle attribute(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                   std::string("attribute ") + name);
  check(H5Awrite(attribute, type, &value), name);
}

std::string read_text(hid_t object, const char* name) {
  Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose,
                   std::string("no attribute '") + name + "'");
  Handle type(H5Aget_type(attribute), H5Tclose, name);
  if (H5Tget_class(type) != H5T_STRING)
    throw std::runtime_error(std::string("attribute '") + name + "' is not text");
  std::string value(H5Tget_size(type), '\0');
  check(H5Aread(attribute, type, value.data()), name);
  value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  return value;
}

template <class T>
T read_number(hid_t object, const char* name) {
  Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose,
                   std::string("no attribute '") + name + "'");
  T value{};
  check(H5Aread(attribute, std::is_integral_v<T> ? H5T_NATIVE_LONG : H5T_NATIVE_DOUBLE, &value),
        name);
  return value;
}

//! rows × columns doubles as a 2D dataset (1D when columns is 1).
void write_array(hid_t parent, const std::string& name, const double* data, long rows,
                 int columns) {
  const hsize_t dims[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(columns)};
  Handle space(H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr), H5Sclose, name);
  Handle set(H5Dcreate2(parent, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT,
                        H5P_DEFAULT),
             H5Dclose, "dataset " + name);
  if (rows > 0) check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name);
}

//! Read exactly rows × columns doubles; false when the dataset does not exist.
bool read_array(hid_t parent, const std::string& name, double* data, long rows, int columns) {
  if (H5Lexists(parent, name.c_str(), H5P_DEFAULT) <= 0) return false;
  Handle set(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  Handle space(H5Dget_space(set), H5Sclose, name);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  if (count != static_cast<hssize_t>(rows) * columns)
    throw std::runtime_error("dataset '" + name + "' holds " + std::to_string(count) +
                             " values, expected " + std::to_string(rows * columns));
  if (rows > 0) check(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name);
  return true;
}

//! The values a dataset holds (rows × columns), without reading them.
long dataset_values(hid_t parent, const std::string& name) {
  Handle set(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  Handle space(H5Dget_space(set), H5Sclose, name);
  return static_cast<long>(H5Sget_simple_extent_npoints(space));
}

std::vector<double> read_vector(hid_t parent, const std::string& name) {
  Handle set(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  Handle space(H5Dget_space(set), H5Sclose, name);
  std::vector<double> values(H5Sget_simple_extent_npoints(space));
  if (!values.empty())
    check(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), name);
  return values;
}

std::vector<std::string> members(hid_t group) {
  H5G_info_t info;
  check(H5Gget_info(group, &info), "group info");
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t size =
        H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    std::string name(size, '\0');
    H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), size + 1,
                       H5P_DEFAULT);
    names.push_back(name);
  }
  return names;
}

//! The common and declared columns of points from `begin` on, in one place for both
//! directions (`begin` may be the end: a rank without points of a body).
template <int D, class Particles, class Visit>
void for_each_point_array(Particles& p, long begin, Visit&& visit) {
  auto doubles = [](auto& column) {
    return reinterpret_cast<decltype(&column[0][0])>(column.data());
  };
  visit("position", doubles(p.position) + D * begin, D);
  visit("velocity", doubles(p.velocity) + D * begin, D);
  visit("mass", p.mass.data() + begin, 1);
  visit("volume", p.volume.data() + begin, 1);
  visit("density", p.density.data() + begin, 1);
  visit("stress", doubles(p.stress) + kSymComponents<D> * begin, kSymComponents<D>);
  for (int c = 0; c < p.columns.count(); ++c)
    if (p.columns.spec(c).checkpoint) {
      const int k = p.columns.components(c);
      visit("columns/" + p.columns.spec(c).name, p.columns.data(c) + k * begin, k);
    }
}

//! This process's point of index `index` in the body as built, or −1 when another holds it. A
//! process built in part (column_names::body_index set) keeps its points of a body in the order
//! they were built.
template <int D>
long point_of(const Particles<D>& p, const Column<double>& built, const BodyInfo<D>& body,
              long index) {
  if (!built.valid()) return index < body.count() ? body.begin + index : -1;
  const auto& numbers = p[built];
  const auto first = numbers.begin() + body.begin, last = numbers.begin() + body.end;
  const auto at = std::lower_bound(first, last, static_cast<double>(index));
  return at != last && *at == static_cast<double>(index) ? static_cast<long>(at - numbers.begin())
                                                         : -1;
}

//! The file of rank `rank`'s points of a distributed run's checkpoint `path` (the index):
//! checkpoint.h5 → checkpoint_r0003.h5.
std::string piece_path(const std::string& path, int rank) {
  const std::filesystem::path index(path);
  char suffix[16];
  std::snprintf(suffix, sizeof suffix, "_r%04d", rank);
  return (index.parent_path() / (index.stem().string() + suffix + index.extension().string()))
      .string();
}

//! Write an HDF5 file through `fill(file)` under a temporary name, then rename it into place;
//! a failure removes the temporary and throws std::runtime_error naming `path`.
template <class Fill>
void write_atomically(const std::string& path, Fill&& fill) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions with the path
  const std::string temporary = path + ".partial";
  try {
    {
      Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                  "cannot create");
      fill(file);
      check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush");
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) throw std::runtime_error(ec.message());
  } catch (const std::runtime_error& e) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write checkpoint " + path + ": " + e.what());
  }
}

//! The group of the body named `name` among `bodies`' members, or "" when none is.
std::string body_group(hid_t bodies, const std::string& name) {
  for (const auto& g : members(bodies))
    if (read_text(group(bodies, g, false), "name") == name) return g;
  return "";
}

//! visit(file) for piece `rank` of the distributed run's checkpoint `path` at step `step`,
//! refusing a file that is missing or not a piece of that checkpoint.
template <class Visit>
void with_piece(const std::string& path, int rank, long step, Visit&& visit) {
  const std::string piece = piece_path(path, rank);
  Handle file(H5Fopen(piece.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
              "cannot open its piece " + piece);
  if (H5Aexists(file, "format") <= 0 || read_text(file, "format") != kPieceFormat ||
      read_number<long>(file, "step") != step)
    throw std::runtime_error(piece + " is not a piece of this checkpoint (step " +
                             std::to_string(step) + ")");
  visit(file);
}

//! The saved parts of the body whose group is `name` that `read` accepts: in a checkpoint of
//! one file its group, whose rows are the body's points in the order they were built
//! (visit(group, nullptr)); in a distributed run's, the group in each rank's piece with the
//! index in the body of each of its rows (visit(group, &indices); a piece may hold none).
//! read(piece, lower, upper) decides for piece k whose points lie within [lower, upper]
//! (k = −1: the one file); an empty filter reads every part.
template <int D, class Visit>
void for_each_part(hid_t index, const std::string& path, const std::string& name,
                   const PartFilter<D>& read, Visit&& visit) {
  const double far = std::numeric_limits<double>::infinity();
  const Vec<D> everywhere_lower = Vec<D>::Constant(-far), everywhere_upper = Vec<D>::Constant(far);
  Handle bodies = group(index, "bodies", false);
  if (H5Aexists(index, "pieces") <= 0) {
    if (!read || read(-1, everywhere_lower, everywhere_upper))
      visit(group(bodies, name, false), nullptr);
    return;
  }
  const long pieces = read_number<long>(index, "pieces"), step = read_number<long>(index, "step");
  // The box around each piece's points of the body (rows: lower, upper corner), from the
  // index, so that a piece the filter refuses is not opened. Checkpoints written before the
  // index held them are read whole.
  std::vector<double> boxes;
  {
    Handle g = group(bodies, name, false);
    if (H5Lexists(g, "boxes", H5P_DEFAULT) > 0) boxes = read_vector(g, "boxes");
  }
  if (!boxes.empty() && static_cast<long>(boxes.size()) != 2 * D * pieces)
    throw std::runtime_error("body group '" + name + "' has " + std::to_string(boxes.size()) +
                             " box corners' coordinates for " + std::to_string(pieces) + " pieces");
  for (int rank = 0; rank < pieces; ++rank) {
    const double* box = boxes.empty() ? nullptr : boxes.data() + 2 * D * rank;
    if (read && !(box ? read(rank, Vec<D>(box), Vec<D>(box + D))
                      : read(rank, everywhere_lower, everywhere_upper)))
      continue;
    with_piece(path, rank, step, [&](hid_t file) {
      Handle piece_bodies = group(file, "bodies", false);
      Handle g = group(piece_bodies, name, false);
      const std::vector<double> index_in_body = read_vector(g, "body_index");
      visit(g, &index_in_body);
    });
  }
}

//! The number of points the checkpoint holds of the body whose group is `name`.
long saved_points(hid_t index, const std::string& name) {
  Handle bodies = group(index, "bodies", false);
  Handle g = group(bodies, name, false);
  if (H5Aexists(index, "pieces") > 0) return read_number<long>(g, "points");
  return dataset_values(g, "mass");
}

//! visit(file, group name) for the checkpoint's body named `body`; false when it has none.
//! Read failures become InputError naming the file.
template <class Visit>
bool with_saved_body(const std::string& path, const std::string& body, Visit&& visit) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  try {
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open");
    Handle bodies = group(file, "bodies", false);
    const std::string found = body_group(bodies, body);
    if (found.empty()) return false;
    visit(file, found);
    return true;
  } catch (const std::runtime_error& e) {
    throw InputError(SourceLocation{path, 0, 0}, "--restart", e.what());
  }
}

}  // namespace

template <int D>
void write_checkpoint(const std::string& path, const Simulation<D>& s,
                      const CheckpointHeader& header, const NodeCarrier* to_whole_grid) {
  // A distributed run: each rank writes its points to a piece of its own, then rank 0 the
  // index (header, node states of the whole grid, the bodies' point counts), so that any
  // number of ranks can continue.
  const Collective* ranks = s.collective();
  const auto& p = s.points();
  std::vector<HookState> hook_states;
  for (const auto& hook : s.hooks()) hook_states.push_back(hook->save_state());
  const double max_speed = ranks ? ranks->max(s.max_point_speed()) : s.max_point_speed();
  std::vector<double> piece_boxes;
  if (ranks) {
    if (!to_whole_grid)
      throw std::logic_error("a distributed run's checkpoint needs the carrier to the whole grid");
    for (auto& state : hook_states)
      for (auto& array : state)
        if (array.per_node) to_whole_grid->carry(array.values);
    const Column<double> built = p.columns.template find<double>(column_names::body_index);
    if (!built.valid())
      throw std::logic_error("a distributed run's points carry their index in their body");
    std::string failure;
    try {
      write_atomically(piece_path(path, ranks->rank()), [&](hid_t file) {
        write_text(file, "format", kPieceFormat);
        write_number<long>(file, "step", s.step_count());
        write_number<long>(file, "rank", ranks->rank());
        Handle bodies = group(file, "bodies", true);
        for (std::size_t b = 0; b < p.bodies.size(); ++b) {
          const auto& body = p.bodies[b];
          Handle g = group(bodies, "body_" + std::to_string(b), true);
          write_text(g, "name", body.name);
          Handle columns = group(g, "columns", true);
          write_array(g, "body_index", p[built].data() + body.begin, body.count(), 1);
          for_each_point_array<D>(p, body.begin,
                                  [&](const std::string& name, const double* data, int k) {
                                    write_array(g, name, data, body.count(), k);
                                  });
        }
      });
    } catch (const std::runtime_error& e) {
      failure = e.what();
    }
    if (ranks->max(failure.empty() ? 0.0 : 1.0) > 0.0)
      throw std::runtime_error(failure.empty() ? "cannot write checkpoint " + path +
                                                     ": another rank could not write its piece"
                                               : failure);
    // The box around each piece's points of each body, for the index: a continued run's
    // ranks open only the pieces whose boxes meet their patches.
    std::vector<double> corners;
    for (const auto& body : p.bodies) {
      Vec<D> lower = Vec<D>::Constant(std::numeric_limits<double>::infinity());
      Vec<D> upper = -lower;
      for (long q = body.begin; q < body.end; ++q)
        lower = lower.cwiseMin(p.position[q]), upper = upper.cwiseMax(p.position[q]);
      corners.insert(corners.end(), lower.data(), lower.data() + D);
      corners.insert(corners.end(), upper.data(), upper.data() + D);
    }
    piece_boxes = ranks->all_gather(corners);  // rank by rank, body by body
    if (ranks->rank() != 0) return;
  }
  write_atomically(path, [&](hid_t file) {
    write_text(file, "format", kFormat);
    write_text(file, "version", PELLICLE_VERSION);
    write_number<long>(file, "dimension", D);
    write_text(file, "case_file", header.case_file);
    write_text(file, "case_hash", header.case_hash);
    write_text(file, "case_text", header.case_text);
    write_text(file, "case_toml", header.case_toml);
    write_number<double>(file, "time", s.time());
    write_number<long>(file, "step", s.step_count());
    write_number<double>(file, "last_dt", s.last_dt());
    write_number<double>(file, "max_speed", max_speed);
    write_text(file, "rng",
               "isosurface frames: one generator per cell, seeded from " +
                   std::to_string(FrameSetup<D>{}.seed));
    if (ranks) write_number<long>(file, "pieces", ranks->size());
    Handle bodies = group(file, "bodies", true);
    for (std::size_t b = 0; b < p.bodies.size(); ++b) {
      const auto& body = p.bodies[b];
      Handle g = group(bodies, "body_" + std::to_string(b), true);
      write_text(g, "name", body.name);
      write_number<long>(g, "material", body.material);
      write_number<long>(g, "points", body.built);
      if (ranks) {  // piece by piece: lower, upper corner
        std::vector<double> boxes;
        const std::size_t per_piece = 2 * D * p.bodies.size();
        for (std::size_t at = 2 * D * b; at < piece_boxes.size(); at += per_piece)
          boxes.insert(boxes.end(), piece_boxes.begin() + at, piece_boxes.begin() + at + 2 * D);
        write_array(g, "boxes", boxes.data(), 2 * ranks->size(), D);
      }
      Handle columns = group(g, "columns", true);
      if (!ranks)
        for_each_point_array<D>(p, body.begin,
                                [&](const std::string& name, const double* data, int k) {
                                  write_array(g, name, data, body.count(), k);
                                });
    }
    Handle hooks = group(file, "hooks", true);
    for (std::size_t h = 0; h < s.hooks().size(); ++h) {
      const std::string name = s.hooks()[h]->state_name();
      if (name.empty()) continue;
      Handle g = group(hooks, name, true);
      for (const auto& array : hook_states[h])
        write_array(g, array.name, array.values.data(), static_cast<long>(array.values.size()), 1);
    }
  });
}

CheckpointHeader read_checkpoint_header(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const SourceLocation where{path, 0, 0};
  if (!std::filesystem::is_regular_file(path) || H5Fis_hdf5(path.c_str()) <= 0)
    throw InputError(where, "--restart", "not an HDF5 file (expected a Pellicle checkpoint)");
  try {
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open");
    const std::string format = H5Aexists(file, "format") > 0 ? read_text(file, "format") : "";
    if (format == kPieceFormat) {  // name_r0003.h5: the index is name.h5
      const std::filesystem::path piece(path);
      const std::string stem = piece.stem().string();
      const std::string index = stem.substr(0, stem.size() - std::min<std::size_t>(6, stem.size()));
      throw std::runtime_error(
          "one rank's piece of a distributed run's checkpoint: continue from " +
          (piece.parent_path() / (index + ".h5")).string());
    }
    if (format != kFormat) throw std::runtime_error("an HDF5 file, but not a Pellicle checkpoint");
    CheckpointHeader h;
    h.version = read_text(file, "version");
    h.dimension = static_cast<int>(read_number<long>(file, "dimension"));
    h.case_file = read_text(file, "case_file");
    h.case_hash = read_text(file, "case_hash");
    h.case_text = read_text(file, "case_text");
    h.case_toml = read_text(file, "case_toml");
    h.time = read_number<double>(file, "time");
    h.step = read_number<long>(file, "step");
    return h;
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(where, "--restart", e.what());
  }
}

void check_checkpoint_pieces(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  try {
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open");
    if (H5Aexists(file, "pieces") <= 0) return;
    const long pieces = read_number<long>(file, "pieces"), step = read_number<long>(file, "step");
    for (int rank = 0; rank < pieces; ++rank) with_piece(path, rank, step, [](hid_t) {});
  } catch (const std::runtime_error& e) {
    throw InputError(SourceLocation{path, 0, 0}, "--restart", e.what());
  }
}

template <int D>
std::vector<std::string> restore_checkpoint(const std::string& path, Simulation<D>& s,
                                            const PartFilter<D>& read) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const SourceLocation where{path, 0, 0};
  std::vector<std::string> added;
  try {
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open");
    auto& p = s.points();
    // Built in part (a distributed run's rank): each point's row is its index in its body.
    const Column<double> built = p.columns.template find<double>(column_names::body_index);
    Handle bodies = group(file, "bodies", false);
    for (const auto& body : p.bodies) {
      const std::string found = body_group(bodies, body.name);
      if (found.empty()) {
        added.push_back(body.name);
        continue;
      }
      const long rows_saved = saved_points(file, found);
      if (rows_saved != body.built)
        throw InputError(where, "--restart",
                         "body '" + body.name + "': the checkpoint holds " +
                             std::to_string(rows_saved) + " points, the case builds " +
                             std::to_string(body.built));
      long restored = 0;  // this process's points found in the parts read
      for_each_part<D>(file, path, found, read, [&](hid_t g, const std::vector<double>* index) {
        const long rows = index ? static_cast<long>(index->size()) : body.built;
        std::vector<long> target(rows);  // this process's point of each row, or −1
        for (long r = 0; r < rows; ++r) {
          target[r] = point_of(p, built, body, index ? static_cast<long>((*index)[r]) : r);
          restored += target[r] >= 0;
        }
        std::vector<double> values;
        for_each_point_array<D>(p, body.begin, [&](const std::string& name, double* data, int k) {
          values.resize(rows * k);
          if (!read_array(g, name, values.data(), rows, k))
            throw InputError(where, "--restart",
                             "body '" + body.name + "': the checkpoint has no '" + name +
                                 "' (the run now needs it: a model or velocity update changed)");
          for (long r = 0; r < rows; ++r)
            if (target[r] >= 0)
              std::copy_n(values.data() + r * k, k, data + (target[r] - body.begin) * k);
        });
      });
      if (restored != body.count())
        throw std::logic_error("body '" + body.name + "': " + std::to_string(restored) + " of " +
                               std::to_string(body.count()) +
                               " points of this process found in the checkpoint's parts read");
    }
    for (auto& hook : s.hooks()) {
      const std::string name = hook->state_name();
      if (name.empty()) continue;
      const std::string at = "hooks/" + name;
      if (H5Lexists(file, "hooks", H5P_DEFAULT) <= 0 ||
          H5Lexists(file, at.c_str(), H5P_DEFAULT) <= 0)
        continue;  // a hook the saved run did not have starts fresh
      Handle g = group(file, at, false);
      HookState state;
      for (const auto& array : members(g)) state.push_back({array, read_vector(g, array)});
      hook->load_state(state);
    }
    s.restore_clock(read_number<double>(file, "time"), read_number<long>(file, "step"),
                    read_number<double>(file, "last_dt"), read_number<double>(file, "max_speed"));
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(where, "--restart", e.what());
  }
  return added;
}

std::optional<long> checkpoint_points(const std::string& path, const std::string& body) {
  long points = 0;
  if (!with_saved_body(path, body, [&](hid_t file, const std::string& found) {
        points = saved_points(file, found);
      }))
    return std::nullopt;
  return points;
}

template <int D>
void for_each_saved_position(const std::string& path, const std::string& body,
                             const PartFilter<D>& read,
                             const std::function<void(long, const Vec<D>&)>& visit) {
  with_saved_body(path, body, [&](hid_t file, const std::string& found) {
    for_each_part<D>(file, path, found, read, [&](hid_t g, const std::vector<double>* index) {
      const std::vector<double> values = read_vector(g, "position");
      const long rows = static_cast<long>(values.size()) / D;
      for (long r = 0; r < rows; ++r)
        visit(index ? static_cast<long>((*index)[r]) : r, Vec<D>(values.data() + D * r));
    });
  });
}

template void write_checkpoint<2>(const std::string&, const Simulation<2>&, const CheckpointHeader&,
                                  const NodeCarrier*);
template void write_checkpoint<3>(const std::string&, const Simulation<3>&, const CheckpointHeader&,
                                  const NodeCarrier*);
template std::vector<std::string> restore_checkpoint<2>(const std::string&, Simulation<2>&,
                                                        const PartFilter<2>&);
template std::vector<std::string> restore_checkpoint<3>(const std::string&, Simulation<3>&,
                                                        const PartFilter<3>&);
template void for_each_saved_position<2>(const std::string&, const std::string&,
                                         const PartFilter<2>&,
                                         const std::function<void(long, const Vec<2>&)>&);
template void for_each_saved_position<3>(const std::string&, const std::string&,
                                         const PartFilter<3>&,
                                         const std::function<void(long, const Vec<3>&)>&);

}  // namespace pellicle
