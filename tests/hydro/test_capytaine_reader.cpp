// Reading the Capytaine fixture (tests/hydro/data/barge_100x30x4.nc: the 100 m × 30 m × 4 m draft box
// barge of mafredo, Capytaine 1.1, MPL 2.0; README there). The expected numbers are the file's
// entries as printed by an independent reader, `ncdump -p 17,17 -f c -v VARIABLE barge_100x30x4.nc`
// (Debian netcdf-bin), quoted below with ncdump's C indices; ffrf's values follow from them by hand:
// A_ffrf(i, j) = s_i s_j added_mass(ω, radiating = j, influenced = i), s = (1, 1, −1) for (surge,
// heave, pitch), and X_ffrf = s·conj(Froude_Krylov_force + diffraction_force). The file's dof order
// is Heave 0, Pitch 1, Roll 2, Surge 3, Sway 4, Yaw 5; omega(13) = 0.5 rad/s; wave_direction(8) = π.
// The conventions themselves are checked against the long-wave limit of a box (closed form), and
// the error messages on copies of the file broken on purpose with the netCDF C library.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>

#include "hydro/capytaine_reader.hpp"

namespace {

using namespace ffrf::hydro;
using Complex = std::complex<double>;
const std::string kFixture = std::string(FFRF_SOURCE_DIR "/tests/hydro/data/barge_100x30x4.nc");

void expect_relative(double actual, double expected, double tolerance, const char* what) {
  EXPECT_NEAR(actual, expected, tolerance * std::abs(expected)) << what;
}

TEST(CapytaineReader, RadiationIsTheFileEntriesInFfrfsSigns) {
  const CapytaineDataset data = read_capytaine(kFixture);
  EXPECT_EQ(data.density, 1000.0);  // rho = 1000 ;
  EXPECT_EQ(data.gravity, 9.81);    // g = 9.81 ;
  EXPECT_TRUE(std::isinf(data.water_depth));  // water_depth = Infinity ;
  const PlanarRadiation& r = data.radiation;
  EXPECT_FALSE(r.has_infinite_frequency);
  EXPECT_FALSE(r.has_zero_frequency);
  ASSERT_EQ(r.frequency.size(), 28u);
  EXPECT_EQ(r.frequency.front(), 0.01);
  EXPECT_EQ(r.frequency.back(), 4.0);
  ASSERT_EQ(r.frequency[13], 0.5);  // 0.5,   // omega(13)
  // 1470480.9686954999,   // added_mass(13,3,3)     Surge ← Surge
  // 45050646.034849569,   // added_mass(13,0,0)     Heave ← Heave
  // 32237929159.039864,   // added_mass(13,1,1)     Pitch ← Pitch
  // 76306586.742610678,   // added_mass(13,1,3)     radiating Pitch, influenced Surge
  // 86320730.46167998,    // added_mass(13,3,1)     radiating Surge, influenced Pitch
  EXPECT_EQ(r.added_mass[13](0, 0), 1470480.9686954999);
  EXPECT_EQ(r.added_mass[13](1, 1), 45050646.034849569);
  EXPECT_EQ(r.added_mass[13](2, 2), 32237929159.039864);
  EXPECT_EQ(r.added_mass[13](0, 2), -76306586.742610678);  // surge force per pitch acceleration, pitch sign flipped
  EXPECT_EQ(r.added_mass[13](2, 0), -86320730.46167998);
  // 151628.89584525942,   // radiation_damping(13,3,3)
  // 14320310.486253209,   // radiation_damping(13,0,0)
  // 3521978055.1931739,   // radiation_damping(13,1,1)
  // 21832418.475959476,   // radiation_damping(13,1,3)
  // 24404673.536519036,   // radiation_damping(13,3,1)
  EXPECT_EQ(r.damping[13](0, 0), 151628.89584525942);
  EXPECT_EQ(r.damping[13](1, 1), 14320310.486253209);
  EXPECT_EQ(r.damping[13](2, 2), 3521978055.1931739);
  EXPECT_EQ(r.damping[13](0, 2), -21832418.475959476);
  EXPECT_EQ(r.damping[13](2, 0), -24404673.536519036);
  EXPECT_FALSE(data.hydrostatics.has_value());
}

TEST(CapytaineReader, ExcitationIsTheConjugateOfFroudeKrylovPlusDiffraction) {
  const CapytaineDataset data = read_capytaine(kFixture);
  ASSERT_TRUE(data.excitation.has_value());
  EXPECT_EQ(data.excitation_variables, "Froude_Krylov_force + diffraction_force");
  const PlanarExcitation& x = *data.excitation;
  ASSERT_EQ(x.heading_degrees.size(), 9u);
  EXPECT_EQ(x.heading_degrees[0], 0.0);
  EXPECT_NEAR(x.heading_degrees[8], 180.0, 1e-12);  // 3.1415926535897931;  // wave_direction(8)
  ASSERT_EQ(x.frequency.size(), 28u);
  ASSERT_EQ(x.frequency[13], 0.5);
  // Following sea, β = 0 (wave_direction index 0), complex index 0 = re, 1 = im:
  //  19950983.859571412,   // Froude_Krylov_force(0,13,0,0)   1.862645149230957e-09, // Froude_Krylov_force(1,13,0,0)
  //  -8279619.1016832413,  // diffraction_force(0,13,0,0)     -5528401.6676632017,   // diffraction_force(1,13,0,0)
  //  0,                    // Froude_Krylov_force(0,13,0,3)   -2140589.6275221575,   // Froude_Krylov_force(1,13,0,3)
  //  -194314.2793550622,   // diffraction_force(0,13,0,3)     274047.66228587204,    // diffraction_force(1,13,0,3)
  //  -2.9802322387695312e-08, // Froude_Krylov_force(0,13,0,1) -473547874.55102086,  // Froude_Krylov_force(1,13,0,1)
  //  -31356299.064373758,  // diffraction_force(0,13,0,1)     154170677.4427124,     // diffraction_force(1,13,0,1)
  const Complex heave = std::conj(Complex(19950983.859571412, 1.862645149230957e-09) + Complex(-8279619.1016832413, -5528401.6676632017));
  const Complex surge = std::conj(Complex(0.0, -2140589.6275221575) + Complex(-194314.2793550622, 274047.66228587204));
  const Complex pitch = -std::conj(Complex(-2.9802322387695312e-08, -473547874.55102086) + Complex(-31356299.064373758, 154170677.4427124));
  const PlanarComplexVector& following = x.force[0][13];
  EXPECT_NEAR(std::abs(following(0) - surge), 0.0, 1e-12 * std::abs(surge));
  EXPECT_NEAR(std::abs(following(1) - heave), 0.0, 1e-12 * std::abs(heave));
  EXPECT_NEAR(std::abs(following(2) - pitch), 0.0, 1e-12 * std::abs(pitch));
  // Head sea, β = π: 2140589.6275221575, // Froude_Krylov_force(1,13,8,3); 194314.27935506249, // diffraction_force(0,13,8,3);
  // -274047.66228587128, // diffraction_force(1,13,8,3)
  const Complex head_surge = std::conj(Complex(0.0, 2140589.6275221575) + Complex(194314.27935506249, -274047.66228587128));
  EXPECT_NEAR(std::abs(x.force[8][13](0) - head_surge), 0.0, 1e-12 * std::abs(head_surge));
}

// The conventions against a closed form: long waves (ω = 0.01 rad/s, kL = 10⁻³) on a box (L = 100,
// B = 30, T = 4 m, origin on the waterline at mid-length), G. I. Taylor's long-wave limit: the
// excitation is the Froude–Krylov force plus the added mass times the incident fluid acceleration
// at the body, X ≈ X_FK + A(ω)·a. In ffrf's e^{iωt} convention a unit wave travelling +x is
// η(x) = e^{−ikx}; the fluid's horizontal acceleration at the origin is iω², the vertical −ω². The
// box's Froude–Krylov force: heave ρgLB; surge, on the end walls, ρgBT(e^{ikL/2} − e^{−ikL/2})
// ≈ iρgBTkL; bow-up pitch ρgB∫x e^{−ikx}dx + (T/2)·F_x ≈ −ikρgBL³/12 + (T/2)·iρgBTkL (the walls'
// force acts T/2 below the origin). So X_surge ≈ i(ρgBTkL + A11ω²), X_heave ≈ ρgLB − A33ω²,
// X_pitch ≈ i(−kρgBL³/12 + (T/2)ρgBTkL + A31ω²) with ffrf's A31 (pitch moment per surge
// acceleration). A wrong conjugation or pitch sign flips an imaginary part; measured agreement
// 6·10⁻⁵ (surge), 4·10⁻⁵ (heave), 7.7·10⁻⁴ (pitch).
TEST(CapytaineReader, LongWaveForcesAreTaylorsLimitOfTheBoxInFfrfsConvention) {
  const CapytaineDataset data = read_capytaine(kFixture);
  const double rho = 1000.0, g = 9.81, length = 100.0, beam = 30.0, draft = 4.0;
  const double omega = data.excitation->frequency.front(), k = omega * omega / g, w2 = omega * omega;
  ASSERT_EQ(omega, 0.01);
  const PlanarMatrix& a = data.radiation.added_mass.front();
  const PlanarComplexVector& x = data.excitation->force[0][0];
  const double walls = rho * g * beam * draft * k * length;
  const double surge = walls + a(0, 0) * w2;
  const double heave = rho * g * length * beam - a(1, 1) * w2;
  const double pitch = -k * rho * g * beam * std::pow(length, 3) / 12.0 + 0.5 * draft * walls + a(2, 0) * w2;
  EXPECT_NEAR(x(0).imag(), surge, 5e-4 * surge);
  EXPECT_NEAR(x(1).real(), heave, 2e-4 * heave);
  EXPECT_NEAR(x(2).imag(), pitch, 2e-3 * std::abs(pitch));
  EXPECT_LT(std::abs(x(0).real()), 1e-3 * surge);
  EXPECT_LT(std::abs(x(2).real()), 1e-3 * std::abs(pitch));
  // The head sea (β = π) reverses surge and pitch.
  const PlanarComplexVector& head = data.excitation->force[8][0];
  EXPECT_NEAR(head(0).imag(), -surge, 5e-4 * surge);
  EXPECT_NEAR(head(2).imag(), -pitch, 2e-3 * std::abs(pitch));
}

TEST(CapytaineReader, AtDensityScalesEveryCoefficientByTheDensityRatio) {
  const CapytaineDataset file = read_capytaine(kFixture);
  const CapytaineDataset sea = at_density(file, 1025.0);
  EXPECT_EQ(sea.density, 1025.0);
  expect_relative(sea.radiation.added_mass[13](2, 0), 1.025 * file.radiation.added_mass[13](2, 0), 1e-15, "A");
  expect_relative(sea.radiation.damping[13](1, 1), 1.025 * file.radiation.damping[13](1, 1), 1e-15, "B");
  expect_relative(sea.excitation->force[8][13](2).imag(), 1.025 * file.excitation->force[8][13](2).imag(), 1e-15, "X");
  EXPECT_THROW(at_density(file, 0.0), std::invalid_argument);
}

// ---- Files broken on purpose (copies of the fixture changed with the netCDF C library) ----

std::string copy_of_fixture(const std::string& name) {
  const auto path = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::copy_file(kFixture, path, std::filesystem::copy_options::overwrite_existing);
  return path.string();
}

// Opens `path` for writing, runs `change(ncid)`, closes it.
template <class Change>
void edit(const std::string& path, Change&& change) {
  int id = 0;
  ASSERT_EQ(nc_open(path.c_str(), NC_WRITE, &id), NC_NOERR);
  change(id);
  ASSERT_EQ(nc_close(id), NC_NOERR);
}

int variable(int id, const char* name) {
  int v = -1;
  EXPECT_EQ(nc_inq_varid(id, name, &v), NC_NOERR) << name;
  return v;
}

std::string error_of(const std::string& path) {
  try {
    read_capytaine(path);
  } catch (const CapytaineFileError& error) {
    EXPECT_EQ(error.file(), path);
    return error.what();
  }
  ADD_FAILURE() << "no CapytaineFileError for " << path;
  return {};
}

void expect_mentions(const std::string& message, std::initializer_list<const char*> parts) {
  for (const char* part : parts) EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

TEST(CapytaineReader, AMissingVariableIsNamed) {
  const std::string path = copy_of_fixture("no_damping.nc");
  edit(path, [](int id) {
    nc_redef(id);
    EXPECT_EQ(nc_rename_var(id, variable(id, "radiation_damping"), "damping_renamed"), NC_NOERR);
    nc_enddef(id);
  });
  expect_mentions(error_of(path), {"variable radiation_damping: missing from the dataset"});
}

TEST(CapytaineReader, AMissingDofIsNamedWithTheDofsTheFileHas) {
  const std::string path = copy_of_fixture("no_pitch.nc");
  edit(path, [](int id) {
    const char* trim[] = {"Trim"};
    const std::size_t at[] = {1};  // "Pitch" is entry 1 of influenced_dof
    EXPECT_EQ(nc_put_var1_string(id, variable(id, "influenced_dof"), at, trim), NC_NOERR);
  });
  expect_mentions(error_of(path), {"variable influenced_dof: holds Heave, Trim, Roll, Surge, Sway, Yaw",
                                   "needs Surge, Heave and Pitch", "no Pitch"});
}

TEST(CapytaineReader, AMissingProblemIsNamedByItsFrequencyAndDofs) {
  const std::string path = copy_of_fixture("nan_entry.nc");
  edit(path, [](int id) {
    const std::size_t at[] = {13, 0, 0};  // added_mass(13,0,0): radiating Heave, influenced Heave at 0.5 rad/s
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(nc_put_var1_double(id, variable(id, "added_mass"), at, &nan), NC_NOERR);
  });
  expect_mentions(error_of(path), {"variable added_mass: is missing (NaN", "ω = 0.5 rad/s, influenced_dof = Heave, radiating_dof = Heave"});
}

TEST(CapytaineReader, TheWamitConventionOfOldCapytaineIsRefused) {
  const std::string path = copy_of_fixture("wamit_convention.nc");
  edit(path, [](int id) {
    nc_redef(id);
    EXPECT_EQ(nc_put_att_text(id, NC_GLOBAL, "incoming_waves_convention", 5, "WAMIT"), NC_NOERR);
    nc_enddef(id);
  });
  expect_mentions(error_of(path), {"incoming_waves_convention = \"WAMIT\"", "valid: \"Nemoh\""});
}

TEST(CapytaineReader, WrongDimensionsAreNamedWithTheExpectedOnes) {
  // A dataset whose added mass lacks the influenced_dof dimension.
  const auto path = (std::filesystem::path(::testing::TempDir()) / "wrong_dimensions.nc").string();
  int id = 0, omega_dim = 0, dof_dim = 0, omega = 0, dofs_i = 0, dofs_r = 0, added = 0, rho = 0, g = 0, depth = 0;
  ASSERT_EQ(nc_create(path.c_str(), NC_CLOBBER | NC_NETCDF4, &id), NC_NOERR);
  nc_def_dim(id, "omega", 2, &omega_dim);
  nc_def_dim(id, "radiating_dof", 3, &dof_dim);
  nc_def_var(id, "omega", NC_DOUBLE, 1, &omega_dim, &omega);
  nc_def_var(id, "radiating_dof", NC_STRING, 1, &dof_dim, &dofs_r);
  nc_def_var(id, "influenced_dof", NC_STRING, 1, &dof_dim, &dofs_i);
  const int dims[] = {omega_dim, dof_dim};
  nc_def_var(id, "added_mass", NC_DOUBLE, 2, dims, &added);
  for (auto [name, v] : {std::pair{"rho", &rho}, std::pair{"g", &g}, std::pair{"water_depth", &depth}}) nc_def_var(id, name, NC_DOUBLE, 0, nullptr, v);
  nc_enddef(id);
  const double w[] = {0.5, 1.0}, values[] = {1, 2, 3, 4, 5, 6}, water[] = {1025.0}, gravity[] = {9.81}, deep[] = {INFINITY};
  const char* names[] = {"Surge", "Heave", "Pitch"};
  nc_put_var_double(id, omega, w);
  nc_put_var_double(id, added, values);
  nc_put_var_string(id, dofs_r, names);
  nc_put_var_string(id, dofs_i, names);
  nc_put_var_double(id, rho, water);
  nc_put_var_double(id, g, gravity);
  nc_put_var_double(id, depth, deep);
  ASSERT_EQ(nc_close(id), NC_NOERR);
  expect_mentions(error_of(path), {"variable added_mass: has dimensions (omega = 2, radiating_dof = 3)",
                                   "expected (omega, influenced_dof, radiating_dof), in any order"});
}

TEST(CapytaineReader, AFileThatIsNotNetcdfIsNamed) {
  const auto path = (std::filesystem::path(::testing::TempDir()) / "not_netcdf.nc").string();
  std::ofstream(path) << "PER I J A B\n";
  expect_mentions(error_of(path), {"cannot read it as NetCDF", "valid: a NetCDF file written by Capytaine"});
}

}  // namespace
