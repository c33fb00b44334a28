// The files of a surface run (io/surface_output.hpp), written for a small cloud and read
// back: N = 64 points equally spaced on the unit circle, h = 0.3, carrying φ = 1 + x by a
// static advection-diffusion with the exact solution 1 + x and a monitor x² + y². By hand:
//   area       each point stands for half of its two chords (quadrature.hpp), so Σ A_i is
//              the inscribed polygon's perimeter 2N sin(π/N)
//   total_phi  Σ A_i (1 + x_i) = the perimeter, since Σ_k cos(2πk/N) = 0 and all A_i are equal
//   errors     0 at t = 0 (φ is the exact solution), and φ stays put on a static cloud
//   mean_r2    1 at every point
// The snapshot holds the cloud's arrays (positions (cos, sin, 0), radial normals, h, no
// boundary, φ, exact, error); the series and summary list what was written; no temporary
// file is left behind. A file that cannot be written is an output error (not a problem of
// the input) naming its path, and leaves no temporary file.
#include <gtest/gtest.h>

#include <toml++/toml.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "pellicle/core/error.hpp"
#include "pellicle/io/surface_output.hpp"
#include "pellicle/io/toml_parameters.hpp"
#include "pellicle/surface/pde.hpp"
#include "pellicle/surface/simulation.hpp"
#include "support/vtk_files.hpp"

namespace pellicle {
namespace {

namespace fs = std::filesystem;
using test::decoded_array;
using test::read_all;

constexpr int kPoints = 64;
constexpr double kH = 0.3;

std::unique_ptr<SurfacePde<2>> make_pde(const std::string& name, const std::string& table) {
  const toml::table parsed = toml::parse(std::string_view(table), std::string_view("case.toml"));
  ProblemList problems{"case.toml", {}};
  std::unique_ptr<SurfacePde<2>> pde;
  {
    TomlParameters in(parsed, "pde", problems);
    for (const auto& model : surface_pde_models<2>())
      if (model.name == name) pde = model.make(in);
  }
  problems.throw_if_any();
  return pde;
}

//! The unit circle, static, with φ = 1 + x and its exact solution.
std::unique_ptr<SurfaceSimulation<2>> circle() {
  PointCloud<2> cloud;
  std::vector<Vec2> outward;
  for (int k = 0; k < kPoints; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kPoints;
    cloud.add_point(Vec2(std::cos(a), std::sin(a)), kH, false);
    outward.push_back(Vec2(std::cos(a), std::sin(a)));
  }
  SurfaceSettings settings;
  settings.dt = 0.01;
  settings.end_time = 0.02;
  settings.manage = false;
  return std::make_unique<SurfaceSimulation<2>>(
      std::move(cloud), settings, std::array<PointFormula, 2>{PointFormula("0"), PointFormula("0")},
      make_pde("advection-diffusion", "initial = \"1 + x\"\nexact = \"1 + x\"\n"), &outward);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}

void expect_no_temporary_files(const fs::path& dir) {
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    EXPECT_NE(entry.path().extension(), ".part") << entry.path();
}

class SurfaceOutput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("pellicle_surface_output_" +
           std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

TEST_F(SurfaceOutput, HistorySeriesAndSummaryOfAShortRun) {
  const auto s = circle();
  OutputSettings settings;
  settings.directory = (dir / "run").string();  // created by the writer
  SurfaceOutputWriter<2> writer(settings, *s, {{"r2", PointFormula("x*x + y*y")}});
  s->add_observer(&writer);
  s->run();
  writer.finish(*s, "completed", "0123abcd", 0.5);
  const fs::path run = dir / "run";

  std::istringstream history(read_all(run / "history.csv"));
  std::string header;
  std::getline(history, header);
  EXPECT_EQ(header,
            "time,step,points,added,merged,removed,solver_iterations,solver_residual,area,"
            "enclosed_volume,parts,chambers,contact_points,contact_removed,total_phi,error_l2,"
            "error_max,mean_r2");
  std::vector<std::vector<std::string>> rows;
  for (std::string row; std::getline(history, row);) rows.push_back(split(row));
  ASSERT_EQ(rows.size(), 3u);  // t = 0 and each of the two steps (history_interval 0)
  const double perimeter = 2.0 * kPoints * std::sin(std::numbers::pi / kPoints);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    SCOPED_TRACE("row " + std::to_string(r));
    const auto& f = rows[r];
    ASSERT_EQ(f.size(), split(header).size());
    EXPECT_NEAR(std::stod(f[0]), 0.01 * static_cast<double>(r), 1e-12);  // time
    EXPECT_EQ(f[1], std::to_string(r));                                  // step
    EXPECT_EQ(f[2], std::to_string(kPoints));                            // points
    EXPECT_EQ(f[3] + f[4] + f[5], "000");            // nothing added, merged or removed
    EXPECT_NEAR(std::stod(f[8]), perimeter, 1e-10);  // area
    // enclosed: ½ Σ A_i x_i · n_i, with x · n = 1 on the unit circle
    EXPECT_NEAR(std::stod(f[9]), 0.5 * perimeter, 1e-10);
    EXPECT_EQ(f[10], "1");                            // parts: one closed curve
    EXPECT_EQ(f[11] + f[12] + f[13], "100");          // one chamber, no contact
    EXPECT_NEAR(std::stod(f[14]), perimeter, 1e-10);  // total_phi
    EXPECT_LT(std::abs(std::stod(f[15])), 1e-8);      // error_l2
    EXPECT_LT(std::abs(std::stod(f[16])), 1e-8);      // error_max
    EXPECT_NEAR(std::stod(f[17]), 1.0, 1e-12);        // mean_r2
  }
  EXPECT_EQ(rows[0][6] + rows[0][7], "00");  // no solve before the first step

  // With snapshot_interval 0 the first and the last state are written.
  const std::string pvd = read_all(run / "surface.pvd");
  EXPECT_NE(pvd.find("<DataSet timestep=\"0\" file=\"surface_000000.vtp\"/>"), std::string::npos)
      << pvd;
  EXPECT_NE(pvd.find("file=\"surface_000001.vtp\"/>"), std::string::npos) << pvd;
  EXPECT_EQ(pvd.find("surface_000002"), std::string::npos) << pvd;
  EXPECT_TRUE(fs::exists(run / "surface_000000.vtp"));
  EXPECT_TRUE(fs::exists(run / "surface_000001.vtp"));

  const std::string summary = read_all(run / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"completed\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"case_hash\": \"0123abcd\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"steps\": 2,"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"points\": 64,"), std::string::npos) << summary;
  EXPECT_EQ(read_all(run / "status"), "completed\n");
  expect_no_temporary_files(dir);
}

TEST_F(SurfaceOutput, SnapshotHoldsTheCloudsArrays) {
  const auto s = circle();
  const fs::path file = dir / "one.vtp";
  write_surface_vtp<2>(file.string(), *s);
  const std::string vtp = read_all(file);
  EXPECT_EQ(vtp.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\"", 0), 0u);
  EXPECT_NE(vtp.find("<Piece NumberOfPoints=\"64\" NumberOfVerts=\"64\">"), std::string::npos);
  int k = 0;
  const auto position = decoded_array<double>(vtp, "position", k);
  EXPECT_EQ(k, 3);
  const auto normal = decoded_array<double>(vtp, "normal", k);
  EXPECT_EQ(k, 3);
  const auto h = decoded_array<double>(vtp, "smoothing_length", k);
  EXPECT_EQ(k, 1);
  const auto boundary = decoded_array<std::uint8_t>(vtp, "boundary", k);
  const auto curvature = decoded_array<double>(vtp, "curvature", k);
  const auto phi = decoded_array<double>(vtp, "phi", k);
  const auto exact = decoded_array<double>(vtp, "exact", k);
  const auto error = decoded_array<double>(vtp, "error", k);
  const auto connectivity = decoded_array<std::int32_t>(vtp, "connectivity", k);
  ASSERT_EQ(position.size(), 3u * kPoints);
  ASSERT_EQ(normal.size(), 3u * kPoints);
  ASSERT_EQ(h.size(), std::size_t(kPoints));
  ASSERT_EQ(boundary.size(), std::size_t(kPoints));
  ASSERT_EQ(curvature.size(), std::size_t(kPoints));
  ASSERT_EQ(phi.size(), std::size_t(kPoints));
  ASSERT_EQ(exact.size(), std::size_t(kPoints));
  ASSERT_EQ(error.size(), std::size_t(kPoints));
  ASSERT_EQ(connectivity.size(), std::size_t(kPoints));
  for (int i = 0; i < kPoints; ++i) {
    SCOPED_TRACE("point " + std::to_string(i));
    const double a = 2.0 * std::numbers::pi * i / kPoints;
    EXPECT_EQ(position[3 * i], std::cos(a));
    EXPECT_EQ(position[3 * i + 1], std::sin(a));
    EXPECT_EQ(position[3 * i + 2], 0.0);
    // Every point sees the same symmetric neighbourhood: its normal is radial, outward.
    EXPECT_NEAR(normal[3 * i], std::cos(a), 1e-9);
    EXPECT_NEAR(normal[3 * i + 1], std::sin(a), 1e-9);
    EXPECT_EQ(normal[3 * i + 2], 0.0);
    EXPECT_EQ(h[i], kH);
    EXPECT_EQ(boundary[i], 0);
    EXPECT_EQ(curvature[i], s->curvature()[i]);
    EXPECT_EQ(phi[i], 1.0 + std::cos(a));
    EXPECT_EQ(exact[i], 1.0 + std::cos(a));
    EXPECT_EQ(error[i], 0.0);
    EXPECT_EQ(connectivity[i], i);
  }
  expect_no_temporary_files(dir);
}

TEST_F(SurfaceOutput, AFileThatCannotBeWrittenIsAnOutputErrorNamingIt) {
  const auto s = circle();
  std::ofstream(dir / "a-file") << "not a directory\n";
  // No directory can be made under a file (this holds for root too).
  const std::string unreachable = (dir / "a-file" / "one.vtp").string();
  try {
    write_surface_vtp<2>(unreachable, *s);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    ADD_FAILURE() << "reported as a problem of the input: " << e.what();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(unreachable), std::string::npos) << e.what();
  }
  OutputSettings settings;
  settings.directory = (dir / "a-file" / "run").string();
  try {
    SurfaceOutputWriter<2> writer(settings, *s, {});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    ADD_FAILURE() << "reported as a problem of the input: " << e.what();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(settings.directory), std::string::npos) << e.what();
  }
  // The temporary file is written, but cannot take the target's name (a directory holds
  // it): the error names the target, and the temporary file goes.
  fs::create_directories(dir / "taken.vtp" / "inside");
  const std::string taken = (dir / "taken.vtp").string();
  try {
    write_surface_vtp<2>(taken, *s);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    ADD_FAILURE() << "reported as a problem of the input: " << e.what();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(taken), std::string::npos) << e.what();
  }
  expect_no_temporary_files(dir);
}

}  // namespace
}  // namespace pellicle
