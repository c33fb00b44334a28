#include "pellicle/io/checkpoint.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "pellicle/core/error.hpp"
#include "pellicle/mpm/body_as_built.hpp"

namespace pellicle {
namespace {

constexpr const char* kFormat = "pellicle-checkpoint";

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

//! One body's point array in the order the points were built.
struct WholeArray {
  std::string name;
  int components;
  std::vector<double> values;
};

//! A body's point arrays in a distributed run, gathered on rank 0 in the order the points were
//! built (empty elsewhere). Collective.
template <int D>
std::vector<WholeArray> gather_body(const Particles<D>& p, const BodyInfo<D>& body,
                                    const Collective& ranks) {
  std::vector<WholeArray> arrays;
  std::vector<const double*> sources;  // each array's values of the body's first point
  int width = 0;
  for_each_point_array<D>(p, body.begin, [&](const std::string& name, const double* data, int k) {
    arrays.push_back({name, k, {}});
    sources.push_back(data);
    width += k;
  });
  auto append = [&](long point, std::vector<double>& out) {
    const long i = point - body.begin;
    for (std::size_t a = 0; a < arrays.size(); ++a) {
      const int k = arrays[a].components;
      out.insert(out.end(), sources[a] + i * k, sources[a] + (i + 1) * k);
    }
  };
  const std::vector<double> rows =
      body_as_built(p, body.begin, body.end, width, append, &ranks, false);
  const long count = static_cast<long>(rows.size()) / width;
  for (auto& a : arrays) a.values.resize(count * a.components);
  const double* v = rows.data();
  for (long i = 0; i < count; ++i)
    for (auto& a : arrays) {
      std::copy_n(v, a.components, a.values.data() + i * a.components);
      v += a.components;
    }
  return arrays;
}

}  // namespace

template <int D>
void write_checkpoint(const std::string& path, const Simulation<D>& s,
                      const CheckpointHeader& header, const NodeCarrier* to_whole_grid) {
  // A distributed run: rank 0 writes what one process would (points in the order they were
  // built, node states of the whole grid), so that any number of ranks can continue.
  const Collective* ranks = s.collective();
  const auto& p = s.points();
  std::vector<std::vector<WholeArray>> whole_bodies;
  std::vector<HookState> hook_states;
  for (const auto& hook : s.hooks()) hook_states.push_back(hook->save_state());
  const double max_speed = ranks ? ranks->max(s.max_point_speed()) : s.max_point_speed();
  if (ranks) {
    if (!to_whole_grid)
      throw std::logic_error("a distributed run's checkpoint needs the carrier to the whole grid");
    for (const auto& body : p.bodies) whole_bodies.push_back(gather_body(p, body, *ranks));
    for (auto& state : hook_states)
      for (auto& array : state)
        if (array.per_node) to_whole_grid->carry(array.values);
    if (ranks->rank() != 0) return;
  }
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions with the path
  const std::string temporary = path + ".partial";
  try {
    {
      Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                  "cannot create");
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
      Handle bodies = group(file, "bodies", true);
      for (std::size_t b = 0; b < p.bodies.size(); ++b) {
        const auto& body = p.bodies[b];
        Handle g = group(bodies, "body_" + std::to_string(b), true);
        write_text(g, "name", body.name);
        write_number<long>(g, "material", body.material);
        Handle columns = group(g, "columns", true);
        if (ranks)
          for (const auto& a : whole_bodies[b])
            write_array(g, a.name, a.values.data(),
                        static_cast<long>(a.values.size()) / a.components, a.components);
        else
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
          write_array(g, array.name, array.values.data(), static_cast<long>(array.values.size()),
                      1);
      }
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

CheckpointHeader read_checkpoint_header(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const SourceLocation where{path, 0, 0};
  if (!std::filesystem::is_regular_file(path) || H5Fis_hdf5(path.c_str()) <= 0)
    throw InputError(where, "--restart", "not an HDF5 file (expected a Pellicle checkpoint)");
  try {
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open");
    if (H5Aexists(file, "format") <= 0 || read_text(file, "format") != kFormat)
      throw std::runtime_error("an HDF5 file, but not a Pellicle checkpoint");
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

template <int D>
std::vector<std::string> restore_checkpoint(const std::string& path, Simulation<D>& s) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const SourceLocation where{path, 0, 0};
  std::vector<std::string> added;
  try {
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open");
    auto& p = s.points();
    // Built in part (a distributed run's rank): each point's row is its index in its body.
    const Column<double> built = p.columns.template find<double>(column_names::body_index);
    Handle bodies = group(file, "bodies", false);
    const auto saved = members(bodies);
    for (const auto& body : p.bodies) {
      std::string found;
      for (const auto& g : saved)
        if (read_text(group(bodies, g, false), "name") == body.name) found = g;
      if (found.empty()) {
        added.push_back(body.name);
        continue;
      }
      Handle g = group(bodies, found, false);
      std::vector<double> whole;  // a body built in part: its whole array, then this part's rows
      for_each_point_array<D>(p, body.begin, [&](const std::string& name, double* data, int k) {
        if (built.valid()) whole.resize(body.built * k);
        if (!read_array(g, name, built.valid() ? whole.data() : data, body.built, k))
          throw InputError(where, "--restart",
                           "body '" + body.name + "': the checkpoint has no '" + name +
                               "' (the run now needs it: a model or velocity update changed)");
        if (built.valid())
          for (long i = body.begin; i < body.end; ++i)
            std::copy_n(whole.data() + static_cast<long>(p[built][i]) * k, k,
                        data + (i - body.begin) * k);
      });
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

template <int D>
std::optional<std::vector<Vec<D>>> checkpoint_positions(const std::string& path,
                                                        const std::string& body) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  try {
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open");
    Handle bodies = group(file, "bodies", false);
    for (const auto& g : members(bodies)) {
      Handle saved = group(bodies, g, false);
      if (read_text(saved, "name") != body) continue;
      const std::vector<double> values = read_vector(saved, "position");
      std::vector<Vec<D>> positions(values.size() / D);
      for (std::size_t i = 0; i < positions.size(); ++i)
        positions[i] = Vec<D>(values.data() + D * i);
      return positions;
    }
  } catch (const std::runtime_error& e) {
    throw InputError(SourceLocation{path, 0, 0}, "--restart", e.what());
  }
  return std::nullopt;
}

template void write_checkpoint<2>(const std::string&, const Simulation<2>&, const CheckpointHeader&,
                                  const NodeCarrier*);
template void write_checkpoint<3>(const std::string&, const Simulation<3>&, const CheckpointHeader&,
                                  const NodeCarrier*);
template std::vector<std::string> restore_checkpoint<2>(const std::string&, Simulation<2>&);
template std::vector<std::string> restore_checkpoint<3>(const std::string&, Simulation<3>&);
template std::optional<std::vector<Vec<2>>> checkpoint_positions<2>(const std::string&,
                                                                    const std::string&);
template std::optional<std::vector<Vec<3>>> checkpoint_positions<3>(const std::string&,
                                                                    const std::string&);

}  // namespace pellicle
