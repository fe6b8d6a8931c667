// Nodal elastic coordinates: the rotation row is the x-derivative of the transverse displacement
// row (central finite differences inside an element), and the displacement rows reproduce the
// cantilever's exact cubic deflection under a tip load at arbitrary points.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <memory>

#include "fem/point_shape.hpp"
#include "nodal/nodal_coordinates.hpp"

namespace {

using namespace ffrf;

TEST(NodalCoordinates, RotationRowIsSlopeOfDisplacementRow) {
  auto beam = std::make_shared<const fem::BeamModel>(fem::make_beam_model({10.0, 5, {2.1e11, 0.01, 8.333e-6, 78.5}}, fem::Boundary::clamped_free));
  const nodal::NodalCoordinates coords(beam);
  const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(coords.size(), 0.1, 1.3).array().sin();
  for (double x : {0.7, 3.3, 9.1}) {
    const double h = 1e-5;
    const double slope = ((coords.displacement_rows(x + h) * q)(1) - (coords.displacement_rows(x - h) * q)(1)) / (2 * h);
    EXPECT_NEAR((coords.rotation_row(x) * q)(0), slope, 1e-7 * std::abs(slope));
  }
}

TEST(NodalCoordinates, DisplacementRowsGiveCubicCantileverDeflection) {
  auto beam = std::make_shared<const fem::BeamModel>(fem::make_beam_model({10.0, 4, {2.1e11, 0.01, 8.333e-6, 78.5}}, fem::Boundary::clamped_free));
  const nodal::NodalCoordinates coords(beam);
  const double force = 500.0, length = 10.0, ei = beam->mesh.section.bending_rigidity();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> k(coords.stiffness());
  const Eigen::VectorXd q = k.solve(fem::point_load(beam->mesh, beam->dofs, length, {0.0, force}, 0.0));
  for (double x : {1.1, 4.9, 7.5, 10.0}) {
    const double exact = force * x * x * (3 * length - x) / (6 * ei);
    EXPECT_NEAR((coords.displacement_rows(x) * q)(1), exact, 1e-10 * exact);
  }
  EXPECT_EQ(coords.to_nodal(q), q);
}

TEST(NodalCoordinates, RejectsNonPhysicalMesh) {
  EXPECT_THROW(fem::make_beam_model({-1.0, 4, {2.1e11, 0.01, 8.333e-6, 78.5}}, fem::Boundary::clamped_free), std::invalid_argument);
  EXPECT_THROW(fem::make_beam_model({10.0, 0, {2.1e11, 0.01, 8.333e-6, 78.5}}, fem::Boundary::clamped_free), std::invalid_argument);
  EXPECT_THROW(fem::make_beam_model({10.0, 4, {2.1e11, 0.01, std::nan(""), 78.5}}, fem::Boundary::clamped_free), std::invalid_argument);
}

}  // namespace
