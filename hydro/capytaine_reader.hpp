// Capytaine's NetCDF output (an xarray dataset written by `cpt.export_dataset(..., format="netcdf")`
// or `separate_complex_values(ds).to_netcdf(...)`), read for the planar model. Variables, found by
// name, with their dimensions found by name (their order differs between Capytaine versions):
//   added_mass, radiation_damping     (ω, influenced_dof, radiating_dof), real
//   Froude_Krylov_force, diffraction_force (or excitation_force)
//                                     (complex, ω, wave_direction, influenced_dof), re/im split
//   hydrostatic_stiffness (optional)  (influenced_dof, radiating_dof)
//   omega [rad/s] along the frequency dimension (omega, period, freq, wavelength or wavenumber);
//   ω = 0 and ω = ∞ rows are A(0) and A∞; rho, g, water_depth (inf: deep), forward_speed (0).
// Values are dimensional SI at the file's ρ and g (WAMIT's are non-dimensional): A [kg, kg m, kg m²],
// B [N s/m, ...], the forces per unit wave amplitude [N/m, N m/m]. Any other dimension of a
// variable must have length 1 (one water depth, one ρ, one g, one body).
// Degrees of freedom by name (case-insensitive): "Surge" (+x), "Heave" (+z, up), "Pitch" (the
// right-handed rotation about +y, which lowers the bow, as WAMIT's mode 5). ffrf's pitch is bow up,
// so q_ffrf = T q_capytaine with T = diag(1, 1, −1): A, B, C become T M T and the force T F, as for
// WAMIT (wamit_reader.hpp). Entry A_ij is the force along influenced_dof i per acceleration of
// radiating_dof j.
// Time convention (Capytaine user manual, "Conventions and differences to other codes"): phasors are
// x(t) = Re{X e^{−iωt}}, and the incident wave of direction β (radians; β = 0 travels +x) is
// Φ0 = −i(g/ω)e^{kz}e^{ik(x cos β + y sin β)}, so η(0, t) = cos ωt: unit amplitude, crest at the origin
// at t = 0. ffrf writes η(0, t) = Re{a e^{iωt}} and F(t) = Re{X a e^{iωt}}; since Re z = Re z̄, the
// same real force is Re{F̄ e^{iωt}}: X_ffrf = T conj(F_capytaine), the WAMIT-convention force (the
// manual: F_e = conj(F_e,WAMIT)). A and B are coefficients of real accelerations and velocities:
// no convention enters them. Datasets of Capytaine < 1.4 record the convention as the attribute
// incoming_waves_convention: "Nemoh" is the one above; "WAMIT" is refused (that option's forces
// are not the conjugate of these).
// Errors: CapytaineFileError naming the file, the variable and what was expected.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "hydro/planar_coefficients.hpp"

namespace ffrf::hydro {

class CapytaineFileError : public std::runtime_error {
 public:
  CapytaineFileError(std::string file, std::string variable, const std::string& message);
  const std::string& file() const { return file_; }
  const std::string& variable() const { return variable_; }  // "" when the problem is the file as a whole

 private:
  std::string file_;
  std::string variable_;
};

struct CapytaineDataset {
  PlanarRadiation radiation;                   // has_infinite_frequency: the file has an ω = ∞ row
  std::optional<PlanarExcitation> excitation;  // Froude–Krylov + diffraction at the finite ω > 0
  std::optional<PlanarMatrix> hydrostatics;    // hydrostatic_stiffness, when the file has it
  std::string excitation_variables;            // which variables gave the excitation ("" = none)
  double density = 0.0;                        // ρ of the run [kg/m³]
  double gravity = 0.0;                        // g [m/s²]
  double water_depth = 0.0;                    // [m], inf: deep water
};

CapytaineDataset read_capytaine(const std::string& path);

// The dataset as if computed with water density `density`: at fixed ω, g and geometry every
// linear potential-flow coefficient is proportional to ρ (A, B, X, C).
CapytaineDataset at_density(CapytaineDataset dataset, double density);

}  // namespace ffrf::hydro
