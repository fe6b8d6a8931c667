// The sweep's CSV read back, Pareto front, charts and report (see sweep_report.hpp).
#include "app/sweep_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "app/gnuplot.hpp"
#include "app/sweep_run.hpp"

namespace ffrf::app {
namespace {

std::optional<double> optional_number(const std::string& field) {
  if (field.empty()) return std::nullopt;
  return std::stod(field);
}

std::string sci(const std::optional<double>& v) { return v ? fmt::format("{:.2e}", *v) : "-"; }

const std::vector<std::string> families{"rigid", "nodal", "modal", "modal+static"};

// The best (smallest worst-channel error) ok row of each model, in first-appearance order.
std::vector<const SweepRow*> best_per_model(const std::vector<SweepRow>& rows) {
  std::vector<const SweepRow*> best;
  std::map<std::string, std::size_t> index;
  for (const SweepRow& row : rows) {
    if (!row.ok()) continue;
    const auto [it, added] = index.emplace(row.model, best.size());
    if (added) best.push_back(&row);
    else if (*row.worst < *best[it->second]->worst) best[it->second] = &row;
  }
  return best;
}

std::string script_header(const std::string& name, const std::string& terminal, const std::string& size) {
  return fmt::format(
      "# Drawn by `ffrf sweep --out`; restyle and rerun with `gnuplot {0}.gp` in this directory.\n"
      "set terminal {1} size {2} font ',11'\nset output '{0}.png'\nset grid\nset logscale xy\n"
      "set format y '10^{{%L}}'\n",
      name, terminal, size);
}

}  // namespace

std::string SweepRow::settings() const {
  if (integrator == "arkode" && step && !rtol) return fmt::format("arkode h {:.3g} s", *step);
  if (step) return fmt::format("{} h {:g} s", integrator, *step);
  return fmt::format("{} rtol {:g}", integrator, rtol.value_or(0.0));
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

std::vector<SweepRow> read_sweep_csv(const std::string& text, const std::string& name) {
  const std::string header = sweep_csv_header();
  if (text.compare(0, header.size(), header) != 0) {
    throw std::runtime_error(name + ": not a sweep CSV of this ffrf version (its header differs)");
  }
  const std::vector<std::string> columns = split_csv_line(header.substr(0, header.size() - 1));
  auto column = [&](std::string_view column_name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), column_name) - columns.begin());
  };
  std::vector<SweepRow> rows;
  std::size_t start = header.size();
  for (int line_number = 2; start < text.size(); ++line_number) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) throw std::runtime_error(fmt::format("{}:{}: unterminated last line", name, line_number));
    SweepRow row;
    row.line = text.substr(start, end - start + 1);
    start = end + 1;
    const std::vector<std::string> f = split_csv_line(row.line.substr(0, row.line.size() - 1));
    if (f.size() != columns.size()) {
      throw std::runtime_error(fmt::format("{}:{}: {} fields, expected {}", name, line_number, f.size(), columns.size()));
    }
    try {
      row.id = std::stoi(f[column("id")]);
      row.model = f[column("model")];
      row.family = f[column("family")];
      row.elements = f[column("elements")].empty() ? 0 : std::stoi(f[column("elements")]);
      row.modes = f[column("modes")].empty() ? 0 : std::stoi(f[column("modes")]);
      row.static_modes = f[column("static_modes")] == "1";
      row.integrator = f[column("integrator")];
      row.rtol = optional_number(f[column("rtol")]);
      row.step = optional_number(f[column("step")]);
      row.cargo_heave = optional_number(f[column("cargo_heave_nrms")]);
      row.daf_error = optional_number(f[column("daf_error")]);
      row.worst = optional_number(f[column("worst_nrms")]);
      row.steps = f[column("steps")].empty() ? 0 : std::stol(f[column("steps")]);
      row.status = f[column("status")];
      row.reason = f[column("reason")];
      row.wall = optional_number(f[column("wall_s")]);
    } catch (const std::logic_error&) {
      throw std::runtime_error(fmt::format("{}:{}: a malformed number", name, line_number));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string sweep_csv(std::vector<SweepRow>& rows) {
  std::sort(rows.begin(), rows.end(), [](const SweepRow& a, const SweepRow& b) { return a.id < b.id; });
  std::string csv = sweep_csv_header();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i > 0 && rows[i].id == rows[i - 1].id) {
      throw std::runtime_error(fmt::format("configuration {} appears twice (overlapping shards?)", rows[i].id));
    }
    csv += rows[i].line;
  }
  return csv;
}

std::vector<std::size_t> pareto_front(const std::vector<SweepRow>& rows) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].ok() && *rows[i].worst > 0.0) order.push_back(i);
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return *rows[a].wall != *rows[b].wall ? *rows[a].wall < *rows[b].wall : *rows[a].worst < *rows[b].worst;
  });
  std::vector<std::size_t> front;
  for (std::size_t i : order) {
    if (front.empty() || *rows[i].worst < *rows[front.back()].worst) front.push_back(i);
  }
  return front;
}

void draw_sweep_charts(const StagedDirectory& out, const std::vector<SweepRow>& rows, const std::string& subtitle) {
  const std::string terminal = png_terminal();
  // accuracy_speed.dat: one gnuplot data set (index) per model family; pareto.dat: the front.
  std::string points = "# wall_s worst_nrms id (one index per family: rigid, nodal, modal, modal+static)\n";
  for (const std::string& family : families) {
    points += fmt::format("# {}\n", family);
    bool any = false;
    for (const SweepRow& row : rows) {
      if (row.family != family || !row.ok() || *row.worst <= 0.0) continue;
      points += fmt::format("{} {} {}\n", *row.wall, *row.worst, row.id);
      any = true;
    }
    if (!any) points += "NaN NaN -1\n";
    points += "\n\n";
  }
  out.write("accuracy_speed.dat", points);
  std::string front = "# wall_s worst_nrms id (Pareto front, by wall time)\n";
  for (std::size_t i : pareto_front(rows)) front += fmt::format("{} {} {}\n", *rows[i].wall, *rows[i].worst, rows[i].id);
  out.write("pareto.dat", front);
  std::string script = script_header("accuracy_speed", terminal, "1000,650");
  script += fmt::format(
      "set title \"Accuracy vs speed: every successful sweep run\\n{}\" noenhanced\n"
      "set xlabel 'wall time of the integration [s]'\n"
      "set ylabel 'worst normalized RMS error over the output channels'\n"
      "set key outside right\n"
      "plot 'accuracy_speed.dat' index 0 using 1:2 with points pt 5 ps 1.4 lc rgb '#444444' title 'rigid', \\\n"
      "     '' index 1 using 1:2 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'nodal', \\\n"
      "     '' index 2 using 1:2 with points pt 9 ps 1.3 lc rgb '#ff7f0e' title 'modal', \\\n"
      "     '' index 3 using 1:2 with points pt 13 ps 1.3 lc rgb '#2ca02c' title 'modal+static', \\\n"
      "     'pareto.dat' using 1:2 with steps lw 2 lc rgb '#d62728' title 'Pareto front'\n",
      subtitle);
  out.write("accuracy_speed.gp", script);
  run_gnuplot(out.staging(), "accuracy_speed.gp");

  // mode_count.dat: best error per model (over its integrator settings) vs k; nodal vs N.
  std::string modes = "# k worst_nrms cargo_heave_nrms (index 0: modal, 1: modal+static, 2: nodal vs N)\n";
  for (const std::string family : {"modal", "modal+static", "nodal"}) {
    std::map<int, const SweepRow*> best;
    for (const SweepRow* row : best_per_model(rows)) {
      if (row->family == family) best[family == "nodal" ? row->elements : row->modes] = row;
    }
    for (const auto& [count, row] : best) modes += fmt::format("{} {} {}\n", count, *row->worst, row->cargo_heave.value_or(NAN));
    if (best.empty()) modes += "NaN NaN NaN\n";
    modes += "\n\n";
  }
  out.write("mode_count.dat", modes);
  script = script_header("mode_count", terminal, "1200,550");
  script += fmt::format(
      "set multiplot layout 1,2 title \"Error vs basis size: the best run of each model\\n{}\" noenhanced\n"
      "set ylabel 'worst normalized RMS error'\nset key top right\n"
      "set xlabel 'vibration modes k (N = 16 mesh)'\nset logscale x 2\n"
      "plot 'mode_count.dat' index 0 using 1:2 with linespoints pt 9 lw 2 lc rgb '#ff7f0e' title 'modal', \\\n"
      "     '' index 1 using 1:2 with linespoints pt 13 lw 2 lc rgb '#2ca02c' title 'modal + static modes'\n"
      "set xlabel 'elements N'\n"
      "plot 'mode_count.dat' index 2 using 1:2 with linespoints pt 7 lw 2 lc rgb '#1f77b4' title 'nodal'\n"
      "unset multiplot\n",
      subtitle);
  out.write("mode_count.gp", script);
  run_gnuplot(out.staging(), "mode_count.gp");
}

std::string sweep_markdown(const std::vector<SweepRow>& rows, const std::string& preamble, double duration) {
  std::size_t ok = 0, failed = 0, skipped = 0;
  for (const SweepRow& row : rows) {
    ok += row.ok() ? 1 : 0;
    failed += row.status == "failed" ? 1 : 0;
    skipped += row.status == "skipped" ? 1 : 0;
  }
  std::string r = preamble;
  r += fmt::format("\n{} configurations: {} ok, {} failed, {} skipped. Every row is in `sweep.csv` (timing columns: "
                   "names ending in `_s`).\n\n",
                   rows.size(), ok, failed, skipped);
  r += "Error measure: the **worst normalized RMS error over the seven output channels** (cargo heave and pitch, "
       "crane heave and pitch, wire tension, tip deflection, joint moment) against the reference; cost: the wall time "
       "of the integration (static equilibrium and mode shapes excluded).\n\n";
  r += "## Pareto-optimal configurations\n\nNo other run is both faster and more accurate.\n\n"
       "| id | model | integrator | worst error | cargo heave error | DAF error | wall time [s] | real-time factor | steps |\n"
       "|--:|---|---|--:|--:|--:|--:|--:|--:|\n";
  for (std::size_t i : pareto_front(rows)) {
    const SweepRow& row = rows[i];
    r += fmt::format("| {} | {} | {} | {} | {} | {} | {:.3g} | {:.3g} | {} |\n", row.id, row.model, row.settings(),
                     sci(row.worst), sci(row.cargo_heave), sci(row.daf_error), *row.wall, duration / *row.wall, row.steps);
  }
  r += "\n## Charts\n\n![accuracy vs speed](accuracy_speed.png)\n\n![error vs basis size](mode_count.png)\n\n";
  r += "## Best run of each model\n\n| model | integrator | worst error | cargo heave error | wall time [s] |\n"
       "|---|---|--:|--:|--:|\n";
  for (const SweepRow* row : best_per_model(rows)) {
    r += fmt::format("| {} | {} | {} | {} | {:.3g} |\n", row->model, row->settings(), sci(row->worst),
                     sci(row->cargo_heave), *row->wall);
  }
  if (failed + skipped > 0) {
    r += "\n## Failed and skipped runs\n\n| id | model | integrator | status | reason |\n|--:|---|---|---|---|\n";
    for (const SweepRow& row : rows) {
      if (row.status == "ok") continue;
      std::string reason = row.reason;
      std::replace(reason.begin(), reason.end(), '|', '/');
      r += fmt::format("| {} | {} | {} | {} | {} |\n", row.id, row.model, row.settings(), row.status, reason);
    }
  }
  return r;
}

}  // namespace ffrf::app
