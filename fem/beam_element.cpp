// Element matrices of the planar Euler–Bernoulli frame element (paper eq. 4 shape functions),
// integrated in closed form; docs/derivations/beam_element.py re-derives them symbolically.
#include "fem/beam_element.hpp"

namespace ffrf::fem {

ElementShape element_shape(double xi, double l) {
  const double xi2 = xi * xi;
  const double xi3 = xi2 * xi;
  ElementShape shape = ElementShape::Zero();
  shape(0, 0) = 1.0 - xi;
  shape(0, 3) = xi;
  shape(1, 1) = 1.0 - 3.0 * xi2 + 2.0 * xi3;
  shape(1, 2) = l * (xi - 2.0 * xi2 + xi3);
  shape(1, 4) = 3.0 * xi2 - 2.0 * xi3;
  shape(1, 5) = l * (-xi2 + xi3);
  return shape;
}

ElementShape element_shape_slope(double xi, double l) {
  const double xi2 = xi * xi;
  ElementShape slope = ElementShape::Zero();
  slope(0, 0) = -1.0 / l;
  slope(0, 3) = 1.0 / l;
  slope(1, 1) = (-6.0 * xi + 6.0 * xi2) / l;
  slope(1, 2) = 1.0 - 4.0 * xi + 3.0 * xi2;
  slope(1, 4) = (6.0 * xi - 6.0 * xi2) / l;
  slope(1, 5) = -2.0 * xi + 3.0 * xi2;
  return slope;
}

ElementMatrix element_mass(const BeamSection& section, double l) {
  const double axial = section.mass_per_length * l / 6.0;
  const double bend = section.mass_per_length * l / 420.0;
  ElementMatrix mass = ElementMatrix::Zero();
  mass(0, 0) = 2.0 * axial;
  mass(0, 3) = axial;
  mass(3, 3) = 2.0 * axial;
  const int v[4] = {1, 2, 4, 5};
  const double b[4][4] = {{156.0, 22.0 * l, 54.0, -13.0 * l},
                          {22.0 * l, 4.0 * l * l, 13.0 * l, -3.0 * l * l},
                          {54.0, 13.0 * l, 156.0, -22.0 * l},
                          {-13.0 * l, -3.0 * l * l, -22.0 * l, 4.0 * l * l}};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) mass(v[i], v[j]) = bend * b[i][j];
  }
  mass(3, 0) = mass(0, 3);
  return mass;
}

ElementMatrix element_stiffness(const BeamSection& section, double l) {
  const double axial = section.axial_rigidity() / l;
  const double bend = section.bending_rigidity() / (l * l * l);
  ElementMatrix stiffness = ElementMatrix::Zero();
  stiffness(0, 0) = axial;
  stiffness(3, 3) = axial;
  stiffness(0, 3) = -axial;
  stiffness(3, 0) = -axial;
  const int v[4] = {1, 2, 4, 5};
  const double b[4][4] = {{12.0, 6.0 * l, -12.0, 6.0 * l},
                          {6.0 * l, 4.0 * l * l, -6.0 * l, 2.0 * l * l},
                          {-12.0, -6.0 * l, 12.0, -6.0 * l},
                          {6.0 * l, 2.0 * l * l, -6.0 * l, 4.0 * l * l}};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) stiffness(v[i], v[j]) = bend * b[i][j];
  }
  return stiffness;
}

ElementMatrix element_geometric_stiffness(double axial_force, double l) {
  const double scale = axial_force / (30.0 * l);
  ElementMatrix geometric = ElementMatrix::Zero();
  const int v[4] = {1, 2, 4, 5};
  const double b[4][4] = {{36.0, 3.0 * l, -36.0, 3.0 * l},
                          {3.0 * l, 4.0 * l * l, -3.0 * l, -l * l},
                          {-36.0, -3.0 * l, 36.0, -3.0 * l},
                          {3.0 * l, -l * l, -3.0 * l, 4.0 * l * l}};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) geometric(v[i], v[j]) = scale * b[i][j];
  }
  return geometric;
}

}  // namespace ffrf::fem
