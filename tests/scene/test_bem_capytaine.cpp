// A [bem] hull from a Capytaine NetCDF dataset (bem.capytaine_file; scene/capytaine_files.hpp): the
// shipped scene cases/capytaine_barge_crane.toml on the fixture of tests/hydro/data (README there),
// the dataset's values scaled from its ρ = 1000 to the scene's 1025 kg/m³, A∞ estimated with a
// warning that says how, and the key rules and file errors named at their keys.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "scene/scene_loader.hpp"

namespace ffrf::scene {
namespace {

const std::string kCase = std::string(FFRF_SOURCE_DIR "/cases/capytaine_barge_crane.toml");
const std::string kDataset = std::string(FFRF_SOURCE_DIR "/tests/hydro/data/barge_100x30x4.nc");

std::string case_text() {
  std::ifstream in(kCase);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The shipped scene with `from` replaced by `to` (the dataset's path made absolute first).
std::string variant(const std::string& from = "", const std::string& to = "") {
  std::string text = case_text();
  const auto replace = [&](const std::string& a, const std::string& b) {
    const auto at = text.find(a);
    EXPECT_NE(at, std::string::npos) << a;
    if (at != std::string::npos) text.replace(at, a.size(), b);
  };
  replace("\"../tests/hydro/data/barge_100x30x4.nc\"", "\"" + kDataset + "\"");
  if (!from.empty()) replace(from, to);
  return text;
}

std::vector<SceneProblem> problems_of(const std::string& text) {
  try {
    (void)load_scene_text(text, "capytaine.toml");
  } catch (const SceneError& error) {
    return error.problems();
  }
  ADD_FAILURE() << "accepted";
  return {};
}

// A problem at `key` whose message holds every part.
void expect_problem(const std::vector<SceneProblem>& problems, const std::string& key, std::initializer_list<const char*> parts) {
  for (const SceneProblem& p : problems) {
    if (p.key != key) continue;
    for (const char* part : parts) EXPECT_NE(p.message.find(part), std::string::npos) << "'" << part << "' not in: " << p.message;
    return;
  }
  ADD_FAILURE() << "no problem at " << key << ": " << SceneError(problems).what();
}

TEST(BemCapytaine, TheShippedSceneReadsTheDatasetAtTheScenesDensity) {
  const Scene scene = load_scene(kCase);
  ASSERT_TRUE(scene.bem.has_value());
  const BemHull& bem = *scene.bem;
  EXPECT_EQ(bem.format, BemFormat::capytaine);
  EXPECT_EQ(std::filesystem::path(bem.radiation_file).filename(), "barge_100x30x4.nc");
  EXPECT_EQ(bem.excitation_file, bem.radiation_file);
  // ncdump -p 17,17 -f c -v added_mass barge_100x30x4.nc: "45050646.034849569,   // added_mass(13,0,0)"
  // (heave, ω = 0.5 rad/s, at the file's ρ = 1000): at the scene's 1025 kg/m³, ×1.025.
  ASSERT_EQ(bem.radiation.frequency[13], 0.5);
  EXPECT_DOUBLE_EQ(bem.radiation.added_mass[13](1, 1), 1.025 * 45050646.034849569);
  ASSERT_TRUE(bem.excitation_table.has_value());
  EXPECT_EQ(bem.excitation_table->heading_degrees.size(), 9u);
  EXPECT_FALSE(bem.hydrostatics.has_value());  // the box hull's pressure gives the stiffness
  // No ω = ∞ in the file: A∞ estimated by Kramers–Kronig and put where the Cummins models take it.
  ASSERT_TRUE(bem.infinite_frequency_estimate.has_value());
  EXPECT_EQ(bem.infinite_frequency_estimate->method, hydro::InfiniteFrequencyMethod::kramers_kronig);
  EXPECT_TRUE(bem.radiation.has_infinite_frequency);
  // The model takes the estimate's symmetric part, as it does every added mass of a BEM file.
  const Eigen::Matrix3d kk = bem.infinite_frequency_estimate->kramers_kronig;
  EXPECT_EQ(bem.radiation.infinite_frequency_added_mass, Eigen::Matrix3d(0.5 * (kk + kk.transpose())));
  // The heave A∞ lies between A(ω) at the table's high end and its low-frequency values (A33 falls
  // from 6.6e7 kg at 0.01 rad/s to 3.4e7 at 2 rad/s, 3.6e7 at 4 rad/s).
  const double a33 = bem.radiation.infinite_frequency_added_mass(1, 1);
  EXPECT_GT(a33, 1.025 * 3.0e7);
  EXPECT_LT(a33, 1.025 * 4.5e7);
  // Two warnings: the estimated A∞, and the dataset's asymmetric added mass (A15 and A51 differ).
  ASSERT_EQ(scene.warnings.size(), 2u);
  const std::string& warning = scene.warnings.front();
  EXPECT_NE(scene.warnings.back().find("is not symmetric"), std::string::npos) << scene.warnings.back();
  for (const char* part : {"bem.capytaine_file", "holds no infinite-frequency added mass", "A∞ estimated by Kramers–Kronig from B(ω) (median over 27 frequencies)",
                           "the high-frequency end gives", "bem.infinite_frequency_added_mass chooses"})
    EXPECT_NE(warning.find(part), std::string::npos) << "'" << part << "' not in: " << warning;
}

TEST(BemCapytaine, TheHighFrequencyEstimateIsTheOneAskedFor) {
  const Scene scene = load_scene_text(variant("infinite_frequency_added_mass = \"kramers-kronig\"",
                                              "infinite_frequency_added_mass = \"high-frequency\""), "capytaine.toml");
  const BemHull& bem = *scene.bem;
  ASSERT_TRUE(bem.infinite_frequency_estimate.has_value());
  EXPECT_EQ(bem.infinite_frequency_estimate->method, hydro::InfiniteFrequencyMethod::high_frequency);
  const Eigen::Matrix3d fit = bem.infinite_frequency_estimate->high_frequency;
  EXPECT_EQ(bem.radiation.infinite_frequency_added_mass, Eigen::Matrix3d(0.5 * (fit + fit.transpose())));
  ASSERT_EQ(scene.warnings.size(), 2u);
  EXPECT_NE(scene.warnings.front().find("the high-frequency end of A(ω) (A∞ + c/ω² fitted to the last 5 frequencies)"),
            std::string::npos) << scene.warnings.front();
}

TEST(BemCapytaine, WamitKeysBesideTheDatasetAndNoSourceAreNamed) {
  const std::string path = "capytaine_file = \"" + kDataset + "\"";
  expect_problem(problems_of(variant(path, path + "\nradiation_file = \"barge.1\"")), "bem.radiation_file",
                 {"belongs to WAMIT files", "remove one of the two"});
  expect_problem(problems_of(variant(path, path + "\nlength_scale = 2.0")), "bem.length_scale", {"belongs to WAMIT files"});
  expect_problem(problems_of(variant(path, "")), "bem.radiation_file | bem.capytaine_file",
                 {"missing: [bem] needs the WAMIT .1 file (bem.radiation_file) or a Capytaine NetCDF dataset"});
  expect_problem(problems_of(variant(path, "radiation_file = \"barge.1\"")), "bem.infinite_frequency_added_mass",
                 {"belongs to bem.capytaine_file", "PER = 0"});
}

TEST(BemCapytaine, TheRunsGravityAndDepthMustBeTheScenes) {
  expect_problem(problems_of(variant("gravity = 9.81 ", "gravity = 9.80665 ")), "bem.capytaine_file",
                 {"barge_100x30x4.nc: variable g = 9.81 m/s^2 differs from environment.gravity = 9.80665 m/s^2"});
  expect_problem(problems_of(variant("water_depth = inf ", "water_depth = 200.0 ")), "bem.capytaine_file",
                 {"variable water_depth = inf m differs from environment.water_depth = 200 m"});
}

TEST(BemCapytaine, AMissingOrUnreadableDatasetIsNamedAtItsKey) {
  expect_problem(problems_of(variant(kDataset, kDataset + ".absent")), "bem.capytaine_file", {"not found", ".nc.absent"});
  const auto fake = std::filesystem::path(::testing::TempDir()) / "not_netcdf.nc";
  std::ofstream(fake) << "not a dataset\n";
  expect_problem(problems_of(variant(kDataset, fake.string())), "bem.capytaine_file",
                 {"not_netcdf.nc: cannot read it as NetCDF", "valid: a NetCDF file written by Capytaine"});
}

}  // namespace
}  // namespace ffrf::scene
