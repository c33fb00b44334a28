//! `pellicle validate`: run the validation problems, print every check, and write the
//! series (CSV), their plots (PNG, via tools/plot_validation.py) and report.md.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "pellicle/app/commands.hpp"
#include "pellicle/core/error.hpp"
#include "pellicle/io/atomic_file.hpp"
#include "pellicle/validation/problem.hpp"

namespace pellicle {

namespace {

namespace fs = std::filesystem;
using validation::Outcome;
using validation::Problem;

void write_series(const fs::path& dir, const Problem& problem, const validation::Series& s) {
  std::string csv = "# " + s.title + "\n";
  for (std::size_t c = 0; c < s.columns.size(); ++c) {
    std::string name = s.columns[c];
    std::replace(name.begin(), name.end(), ',', ';');  // keep the header one field per column
    csv += (c ? "," : "") + name;
  }
  csv += '\n';
  char number[32];
  for (const auto& row : s.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      std::snprintf(number, sizeof number, "%s%.10g", c ? "," : "", row[c]);
      csv += number;
    }
    csv += '\n';
  }
  write_file_atomically((dir / (problem.name + "_" + s.name + ".csv")).string(), csv);
}

std::string report_row(const validation::Check& c) {
  char row[640];
  std::snprintf(row, sizeof row, "| %s | %.6g | %.6g | [%.6g, %.6g] %s | %s |\n",
                c.quantity.c_str(), c.measured, c.reference, c.lower, c.upper, c.unit.c_str(),
                c.passed() ? "ok" : "**failed**");
  return row;
}

}  // namespace

int command_validate(const ValidateOptions& o) {
  std::vector<const Problem*> selected;
  for (const auto& name : o.only) {
    const Problem* p = validation::find_problem(name);
    if (!p) {
      std::string known;
      for (const auto& q : validation::problems()) known += " " + q.name;
      std::fprintf(stderr, "pellicle: error: --only %s: no such problem; known:%s\n", name.c_str(),
                   known.c_str());
      return kExitBadInput;
    }
    selected.push_back(p);
  }
  if (selected.empty())
    for (const auto& p : validation::problems()) selected.push_back(&p);

  const fs::path dir = !o.out_dir.empty() ? fs::path(o.out_dir)
                       : o.update_docs    ? fs::path(PELLICLE_SOURCE_DIR) / "docs" / "validation"
                                          : fs::path("results/validation");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    std::fprintf(stderr, "pellicle: error: cannot create %s: %s\n", dir.c_str(),
                 ec.message().c_str());
    return kExitBadInput;
  }
  const auto resolution = o.full ? validation::Resolution::full : validation::Resolution::fast;
  std::string report = std::string("# Validation report (") + (o.full ? "full" : "fast") +
                       " resolution, Pellicle " + PELLICLE_VERSION + ")\n\n" +
                       "Written by `pellicle validate" + (o.full ? " --full" : "") +
                       "`; plots beside this file.\n";
  int failed = 0;
  for (const Problem* p : selected) {
    std::printf("== %s: %s (%s)\n", p->name.c_str(), p->title.c_str(), p->source.c_str());
    std::fflush(stdout);
    const auto start = std::chrono::steady_clock::now();
    Outcome outcome;
    try {
      outcome = p->run(resolution);
    } catch (const NumericalError& e) {
      std::printf("   FAILED: %s\n", e.what());
      report += "\n## " + p->title + "\n\nFailed: " + e.what() + "\n";
      ++failed;
      continue;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report += "\n## " + p->title + "\n\nSource: " + p->source + ". Run time " +
              std::to_string(static_cast<int>(seconds + 0.5)) +
              " s.\n\n| quantity | measured | reference | accepted | |\n|---|---|---|---|---|\n";
    for (const auto& c : outcome.checks) {
      std::printf("   %s\n", c.describe().c_str());
      report += report_row(c);
      if (!c.passed()) ++failed;
    }
    if (!outcome.table.empty()) report += "\n" + outcome.table;
    for (const auto& s : outcome.series) {
      write_series(dir, *p, s);
      report += "\n![" + s.title + "](" + p->name + "_" + s.name + ".png)\n";
    }
  }
  write_file_atomically((dir / "report.md").string(), report);

  const std::string plotter = std::string(PELLICLE_SOURCE_DIR) + "/tools/plot_validation.py";
  if (fs::exists(plotter) && fs::exists("/usr/bin/python3")) {
    const std::string command =
        "/usr/bin/python3 '" + plotter + "' '" + dir.string() + "' > /dev/null";
    if (std::system(command.c_str()) != 0)
      std::fprintf(stderr, "pellicle: warning: plotting failed (%s)\n", command.c_str());
  } else {
    std::fprintf(stderr, "pellicle: note: %s or /usr/bin/python3 not found; no plots\n",
                 plotter.c_str());
  }
  std::printf("%s: %d check(s) failed; report in %s\n", failed ? "FAILED" : "passed", failed,
              (dir / "report.md").c_str());
  return failed ? kExitCheckFailed : kExitOk;
}

}  // namespace pellicle
