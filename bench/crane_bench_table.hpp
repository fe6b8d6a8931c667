// The results of bench_crane as rows (one per model × integrator): written to and read from CSV so
// that runs of two builds (before / after a change, bench/before_after.sh) can be merged, best of
// their repetitions, into one side-by-side Markdown table with the cost exponent in N and the real-time-factor
// targets. Header-only so the same file builds in an old source tree.
#pragma once

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace ffrf::bench {

struct CraneRow {
  std::string key;         // "nodal N=16 | cvode" (stable across builds)
  std::string model;       // "nodal N=16"
  std::string integrator;  // "cvode"
  int elements = 0;        // N of a nodal boom (0 otherwise): the cost exponent's abscissa
  double duration = 0.0;   // simulated [s]
  double wall_ms = 0.0;    // best of the repetitions [ms]
  long steps = 0, rhs = 0, jacobians = 0, newton = 0;
  double per_step_us() const { return steps > 0 ? 1e3 * wall_ms / static_cast<double>(steps) : 0.0; }
  double real_time_factor() const { return wall_ms > 0.0 ? duration / (1e-3 * wall_ms) : 0.0; }
};

inline void write_rows(const std::string& path, const std::vector<CraneRow>& rows) {
  std::ofstream out(path);
  out << "key,model,integrator,elements,duration_s,wall_ms,steps,rhs,jacobians,newton\n";
  for (const CraneRow& r : rows) {
    out << r.key << ',' << r.model << ',' << r.integrator << ',' << r.elements << ',' << r.duration << ','
        << fmt::format("{:.6g}", r.wall_ms) << ',' << r.steps << ',' << r.rhs << ',' << r.jacobians << ',' << r.newton << '\n';
  }
}

// Rows of several CSV files merged by key: the best (smallest) wall time, the statistics of that run.
inline std::vector<CraneRow> read_best_rows(const std::vector<std::string>& paths) {
  std::vector<CraneRow> rows;
  std::map<std::string, std::size_t> index;
  for (const std::string& path : paths) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("bench_crane: cannot read " + path);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::stringstream fields(line);
      for (std::string item; std::getline(fields, item, ',');) f.push_back(item);
      if (f.size() != 10) continue;
      CraneRow r{f[0], f[1], f[2], std::stoi(f[3]), std::stod(f[4]), std::stod(f[5]), std::stol(f[6]),
                 std::stol(f[7]), std::stol(f[8]), std::stol(f[9])};
      const auto it = index.find(r.key);
      if (it == index.end()) {
        index[r.key] = rows.size();
        rows.push_back(r);
      } else if (r.wall_ms < rows[it->second].wall_ms) {
        rows[it->second] = r;
      }
    }
  }
  return rows;
}

// Least-squares slope of log(µs per step) against log N over the nodal rows of one integrator with N ≥ 16.
inline double cost_exponent(const std::vector<CraneRow>& rows, const std::string& integrator) {
  std::vector<double> x, y;
  for (const CraneRow& r : rows) {
    if (r.integrator == integrator && r.elements >= 16 && r.model.rfind("nodal", 0) == 0 && r.steps > 0) {
      x.push_back(std::log(static_cast<double>(r.elements)));
      y.push_back(std::log(r.per_step_us()));
    }
  }
  if (x.size() < 2) return std::nan("");
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Local exponent of µs per step from the previous nodal row of the same integrator (— if none).
inline std::string local_exponent(const std::vector<CraneRow>& rows, const CraneRow& r) {
  if (r.elements == 0 || r.model.rfind("nodal", 0) != 0) return "—";
  const CraneRow* previous = nullptr;
  for (const CraneRow& other : rows) {
    if (other.integrator == r.integrator && other.model.rfind("nodal", 0) == 0 && other.elements > 0 &&
        other.elements < r.elements && other.steps > 0 && (!previous || other.elements > previous->elements) &&
        other.model.find("stiffened") == std::string::npos) {
      previous = &other;
    }
  }
  if (!previous || previous->elements < 4 || r.model.find("stiffened") != std::string::npos) return "—";
  return fmt::format("{:.2f}", std::log(r.per_step_us() / previous->per_step_us()) /
                                   std::log(static_cast<double>(r.elements) / previous->elements));
}

inline const CraneRow* find_row(const std::vector<CraneRow>& rows, const std::string& key) {
  for (const CraneRow& r : rows) {
    if (r.key == key) return &r;
  }
  return nullptr;
}

// One table: before and after side by side (before may be empty: after only).
inline void print_table(const std::vector<CraneRow>& before, const std::vector<CraneRow>& after) {
  const bool pair = !before.empty();
  if (pair) {
    fmt::print("| model | integrator | wall before [ms] | wall after [ms] | speed-up | steps b / a | RHS evals b / a | "
               "Jacobians b / a | µs/step b / a | × real time b / a | N-exponent b / a |\n");
    fmt::print("|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  } else {
    fmt::print("| model | integrator | wall [ms] | steps | RHS evals | Jacobians | µs/step | × real time | N-exponent |\n");
    fmt::print("|---|---|--:|--:|--:|--:|--:|--:|--:|\n");
  }
  for (const CraneRow& a : after) {
    const CraneRow* b = pair ? find_row(before, a.key) : nullptr;
    if (!pair) {
      fmt::print("| {} | {} | {:.1f} | {} | {} | {} | {:.1f} | {:.0f} | {} |\n", a.model, a.integrator, a.wall_ms, a.steps,
                 a.rhs, a.jacobians, a.per_step_us(), a.real_time_factor(), local_exponent(after, a));
      continue;
    }
    if (!b) {
      fmt::print("| {} | {} | — | {:.1f} | — | — / {} | — / {} | — / {} | — / {:.1f} | — / {:.0f} | — / {} |\n", a.model,
                 a.integrator, a.wall_ms, a.steps, a.rhs, a.jacobians, a.per_step_us(), a.real_time_factor(),
                 local_exponent(after, a));
      continue;
    }
    fmt::print("| {} | {} | {:.1f} | {:.1f} | {:.1f}× | {} / {} | {} / {} | {} / {} | {:.1f} / {:.1f} | {:.0f} / {:.0f} | {} / {} |\n",
               a.model, a.integrator, b->wall_ms, a.wall_ms, b->wall_ms / a.wall_ms, b->steps, a.steps, b->rhs, a.rhs,
               b->jacobians, a.jacobians, b->per_step_us(), a.per_step_us(), b->real_time_factor(), a.real_time_factor(),
               local_exponent(before, *b), local_exponent(after, a));
  }
  const auto exponent = [](const std::vector<CraneRow>& rows, const std::string& integrator) {
    const double e = cost_exponent(rows, integrator);
    return std::isnan(e) ? std::string("—") : fmt::format("{:.2f}", e);
  };
  for (const std::string integrator : {"cvode", "ida", "generalized-alpha"}) {
    if (std::none_of(after.begin(), after.end(), [&](const CraneRow& r) { return r.integrator == integrator && r.elements >= 16; })) continue;
    fmt::print("\ncost exponent in N ({}, µs per step against N = 16 … 128, least squares): {}{}\n", integrator,
               pair ? "before " + exponent(before, integrator) + ", after " : "", exponent(after, integrator));
  }
}

struct Target {
  const char* key;
  double real_time_factor;
};
// Real-time-factor targets of the per-step cost work (structured Newton solves, closed-form hull
// pressure) on the 2-core reference machine (CVODE, reference scene, 120 s); docs/performance.md.
inline const std::vector<Target>& targets() {
  static const std::vector<Target> list = {{"rigid | cvode", 1e4},
                                           {"modal k=2+static (N=16) | cvode", 3e3},
                                           {"nodal N=16 | cvode", 1e3},
                                           {"nodal N=64 | cvode", 300.0},
                                           {"nodal N=128 | cvode", 150.0}};
  return list;
}

}  // namespace ffrf::bench
