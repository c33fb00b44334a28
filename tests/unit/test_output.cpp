// Output files: history columns, complete VTK snapshots (decoded back), the ParaView series,
// summary.json, and no temporary files left behind.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pellicle/io/output.hpp"
#include "pellicle/io/run.hpp"
#include "support/case_text.hpp"

namespace pellicle {
namespace {

namespace fs = std::filesystem;

const std::string kCase = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.25
[solver]
end_time = 0.01
dt = 0.001
gravity = [0.0, -9.81]
[output]
history_interval = 0.005
snapshot_interval = 0.005
grid_snapshots = true
[[material]]
name = "m"
model = "linear-elastic"
density = 10.0
youngs_modulus = 1000.0
[[body]]
name = "block-A"
material = "m"
points_per_cell = 1
velocity = [0.5, 0.0]
region = { shape = "box", lower = [0.25, 0.25], upper = [0.75, 0.5] }
)";

std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<unsigned char> base64_decode(const std::string& text) {
  std::vector<unsigned char> out;
  unsigned buffer = 0;
  int bits = 0;
  for (char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z')
      v = c - 'A';
    else if (c >= 'a' && c <= 'z')
      v = c - 'a' + 26;
    else if (c >= '0' && c <= '9')
      v = c - '0' + 52;
    else if (c == '+')
      v = 62;
    else if (c == '/')
      v = 63;
    else
      continue;
    buffer = (buffer << 6) | v;
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buffer >> bits) & 0xff));
    }
  }
  return out;
}

TEST(Output, RunWritesCompleteFiles) {
  const fs::path dir = fs::temp_directory_path() / "pellicle_test_output";
  fs::remove_all(dir);
  const auto source = case_source_from_text(kCase, "<test>");
  Case<2> c = read_case<2>(*source);
  c.output.directory = dir.string();
  auto simulation = build_simulation<2>(c);
  OutputWriter<2> output(c.output, *simulation);
  RunControl control;
  control.case_hash = "abc";
  run_simulation(*simulation, output, nullptr, control);

  // history.csv: header with per-body columns, rows at t = 0, 0.005, 0.01.
  std::istringstream history(read_all(dir / "history.csv"));
  std::string header, row;
  std::getline(history, header);
  EXPECT_EQ(header,
            "time,step,dt,kinetic,strain,internal,gravitational,total,momentum_x,momentum_y,"
            "block-A.com_x,block-A.com_y,block-A.vel_x,block-A.vel_y");
  int rows = 0;
  while (std::getline(history, row)) ++rows;
  EXPECT_EQ(rows, 3);

  // Snapshots and series.
  EXPECT_TRUE(fs::exists(dir / "points_000002.vtu"));
  EXPECT_TRUE(fs::exists(dir / "grid_000002.vti"));
  const std::string pvd = read_all(dir / "points.pvd");
  EXPECT_NE(pvd.find("<DataSet timestep=\"0.01"), std::string::npos) << pvd;
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_NE(entry.path().extension(), ".part") << entry.path();

  // The positions array decodes to the points' coordinates.
  const std::string vtu = read_all(dir / "points_000002.vtu");
  const auto begin = vtu.find('>', vtu.find("Name=\"position\"")) + 1;
  const auto end = vtu.find("</DataArray>", begin);
  const auto bytes = base64_decode(vtu.substr(begin, end - begin));
  std::uint64_t count;
  std::memcpy(&count, bytes.data(), 8);
  const auto& p = simulation->points();
  ASSERT_EQ(count, 3 * 8 * static_cast<std::uint64_t>(p.size()));
  for (long i = 0; i < p.size(); ++i) {
    double xyz[3];
    std::memcpy(xyz, bytes.data() + 8 + 24 * i, 24);
    EXPECT_EQ(xyz[0], p.position[i].x());
    EXPECT_EQ(xyz[1], p.position[i].y());
    EXPECT_EQ(xyz[2], 0.0);
  }

  const std::string summary = read_all(dir / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"completed\""), std::string::npos);
  EXPECT_NE(summary.find("\"steps\": 10"), std::string::npos) << summary;
  fs::remove_all(dir);
}

TEST(Output, CaseHashIsStable) {
  EXPECT_EQ(hash_text(""), "cbf29ce484222325");  // FNV-1a offset basis
  EXPECT_NE(hash_text("a"), hash_text("b"));
}

}  // namespace
}  // namespace pellicle
