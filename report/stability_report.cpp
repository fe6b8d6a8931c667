// The whole stability report (see stability_section.hpp): the sections of the experiments that
// ran, report.md embedding their charts and summary.json with every cell.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "report/stability_section.hpp"

namespace ffrf::report {
namespace {

std::string report_markdown(const scene::Scene& scene, const std::string& file, bool quick,
                            const std::vector<StabilitySection>& sections, double wall) {
  std::string md = fmt::format(
      "# Stability map: {}\n\nScene `{}`{}. Which method fails where: each experiment below names every failure "
      "(✅ held, with the number that says how well; ❌ the failure kind, when it was detected and the number behind "
      "it). docs/stability.md explains each failure, its detector and its remedy. Computed in {} s.\n\n",
      scene.name.empty() ? file : scene.name, file, quick ? " (--quick: fewer models, shorter horizons)" : "", shown(wall, 3));
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const StabilitySection& s = sections[i];
    md += fmt::format("## {}. {}\n\n**What was run.** {}\n\n{}\n", i + 1, s.title, s.provenance, s.table);
    for (const std::string& chart : s.charts) md += fmt::format("![{}]({})\n\n", chart, chart);
    md += fmt::format("**What it shows.** {}\n\n", s.finding);
  }
  return md;
}

std::string summary_json(const scene::Scene& scene, const std::string& file, bool quick,
                         const std::vector<StabilitySection>& sections, double wall) {
  Json json{{"command", "stability"}, {"scene_file", file},       {"scene_name", scene.name},
            {"quick", quick},         {"wall_seconds", wall},     {"sections", Json::object()}};
  for (const StabilitySection& section : sections) json["sections"][section.key] = section_json(section);
  return json_text(json);
}

}  // namespace

StabilityReport stability_report(const scene::Scene& scene, const std::string& scene_file, bool quick,
                                 const study::StabilityMap& map, const StagedDirectory& out) {
  std::vector<StabilitySection> sections;
  if (map.explicit_steps) sections.push_back(explicit_step_section(*map.explicit_steps, out));
  if (map.drift) sections.push_back(constraint_drift_section(scene, *map.drift, out));
  if (map.spin) sections.push_back(spin_section(scene, *map.spin, out));
  if (map.wire) sections.push_back(wire_section(scene, *map.wire, out));
  if (map.bdf_order) sections.push_back(bdf_order_section(scene, *map.bdf_order));
  if (map.buckling) sections.push_back(buckling_section(scene, *map.buckling));
  return {report_markdown(scene, scene_file, quick, sections, map.wall_seconds),
          summary_json(scene, scene_file, quick, sections, map.wall_seconds)};
}

}  // namespace ffrf::report
