// Beam cross-section data: the constants of a planar Euler–Bernoulli beam (paper eq. 15.b:
// E, area a, second moment I; mass per unit length for eq. 19.d). Pure data, SI units.
#pragma once

namespace ffrf::fem {

struct BeamSection {
  double youngs_modulus;   // E [Pa]
  double area;             // A [m^2]
  double second_moment;    // I [m^4], bending about the axis normal to the plane
  double mass_per_length;  // rho*A [kg/m]

  double axial_rigidity() const { return youngs_modulus * area; }             // EA [N]
  double bending_rigidity() const { return youngs_modulus * second_moment; }  // EI [N m^2]
};

}  // namespace ffrf::fem
