#include "pellicle/geometry/region_factory.hpp"

namespace pellicle {
namespace {

template <int D>
RegionPtr<D> read_box(ParameterReader& in) {
  const Vec<D> lo = read_vector<D>(in, "lower"), hi = read_vector<D>(in, "upper");
  if ((hi.array() <= lo.array()).any()) in.fail("upper", "expected every component above lower");
  return make_box<D>(lo, hi);
}
template <int D>
RegionPtr<D> read_ball(ParameterReader& in) {
  const Vec<D> c = read_vector<D>(in, "center");
  return make_ball<D>(c, in.number("radius", NumberRange::positive()));
}
template <int D>
RegionPtr<D> read_ellipsoid(ParameterReader& in) {
  const Vec<D> c = read_vector<D>(in, "center");
  return make_ellipsoid<D>(c, read_vector<D>(in, "semi_axes", NumberRange::positive()));
}
template <int D>
RegionPtr<D> read_half_space(ParameterReader& in) {
  const Vec<D> p = read_vector<D>(in, "point"), n = read_vector<D>(in, "normal");
  if (n.norm() == 0.0) in.fail("normal", "expected a non-zero vector");
  return make_half_space<D>(p, n);
}
template <int D>
RegionPtr<D> read_polygon(ParameterReader& in) {
  if constexpr (D == 2) {
    std::vector<Vec2> vertices;
    for (const auto& v : in.number_lists("vertices", 2)) vertices.emplace_back(v[0], v[1]);
    if (vertices.size() < 3) {
      in.fail("vertices", "expected at least 3 vertices");
      vertices = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
    }
    return make_polygon(std::move(vertices));
  } else {
    return nullptr;  // not registered in 3D
  }
}
template <int D>
RegionPtr<D> read_cylinder(ParameterReader& in) {
  if constexpr (D == 3) {
    const Vec3 c = read_vector<3>(in, "center"), axis = read_vector<3>(in, "axis");
    if (axis.norm() == 0.0) in.fail("axis", "expected a non-zero vector");
    const double r = in.number("radius", NumberRange::positive());
    const double h = in.number("height", NumberRange::positive());
    return make_cylinder_region(c, axis.norm() > 0 ? axis : Vec3::UnitZ(), r, h);
  } else {
    return nullptr;  // not registered in 2D
  }
}
template <int D>
std::vector<RegionPtr<D>> read_parts(ParameterReader& in, std::size_t at_least) {
  std::vector<RegionPtr<D>> parts;
  for (auto& t : in.tables("parts")) parts.push_back(make_region<D>(*t));
  if (parts.size() < at_least) {
    in.fail("parts", "expected at least " + std::to_string(at_least) + " regions");
    while (parts.size() < at_least) parts.push_back(make_box<D>(Vec<D>::Zero(), Vec<D>::Ones()));
  }
  return parts;
}
template <int D>
RegionPtr<D> read_union(ParameterReader& in) {
  return make_union<D>(read_parts<D>(in, 1));
}
template <int D>
RegionPtr<D> read_intersection(ParameterReader& in) {
  return make_intersection<D>(read_parts<D>(in, 1));
}
template <int D>
RegionPtr<D> read_difference(ParameterReader& in) {
  return make_difference<D>(read_parts<D>(in, 2));
}

template <int D>
struct Shape {
  const char* name;
  int dimension;  //!< 0: any
  RegionPtr<D> (*read)(ParameterReader&);
};

template <int D>
const std::vector<Shape<D>>& shapes() {
  static const std::vector<Shape<D>> table = {
      {"box", 0, &read_box<D>},
      {"disk", 2, &read_ball<D>},
      {"sphere", 3, &read_ball<D>},
      {"ellipse", 2, &read_ellipsoid<D>},
      {"ellipsoid", 3, &read_ellipsoid<D>},
      {"cylinder", 3, &read_cylinder<D>},
      {"half-space", 0, &read_half_space<D>},
      {"polygon", 2, &read_polygon<D>},
      {"union", 0, &read_union<D>},
      {"intersection", 0, &read_intersection<D>},
      {"difference", 0, &read_difference<D>},
  };
  return table;
}

}  // namespace

template <int D>
std::vector<std::string> region_shapes() {
  std::vector<std::string> names;
  for (const auto& s : shapes<D>())
    if (s.dimension == 0 || s.dimension == D) names.emplace_back(s.name);
  return names;
}

template <int D>
RegionPtr<D> make_region(ParameterReader& in) {
  const std::string name = in.choice("shape", region_shapes<D>());
  if (name.empty()) in.ignore_rest();
  for (const auto& s : shapes<D>())
    if (name == s.name && (s.dimension == 0 || s.dimension == D)) return s.read(in);
  return make_box<D>(Vec<D>::Zero(), Vec<D>::Ones());  // stands in after a reported problem
}

template RegionPtr<2> make_region<2>(ParameterReader&);
template RegionPtr<3> make_region<3>(ParameterReader&);
template std::vector<std::string> region_shapes<2>();
template std::vector<std::string> region_shapes<3>();

}  // namespace pellicle
