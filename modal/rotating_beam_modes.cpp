// The spinning / prestressed beam's eigenproblem (see header): the assembled K_Ω, a shift below
// the spectrum from the inertia of LDLᵀ(K_Ω − σM), the solve and the bending/axial classification.
#include "modal/rotating_beam_modes.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fem/axial_force.hpp"

namespace ffrf::modal {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

// Number of negative pivots of LDLᵀ(K − σM) = number of eigenvalues below σ (Sylvester's law of
// inertia; the fill-reducing permutation is a congruence too). −1 when a pivot is zero or not finite.
int eigenvalues_below(const SparseMatrix& stiffness, const SparseMatrix& mass, double sigma) {
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> factor(stiffness - sigma * mass);
  if (factor.info() != Eigen::Success || !factor.vectorD().allFinite() || (factor.vectorD().array() == 0.0).any()) {
    return -1;
  }
  return static_cast<int>((factor.vectorD().array() < 0.0).count());
}

std::vector<RotatingMode> classify(const fem::DofMap& dofs, const SparseMatrix& mass, const EigenPairs& pairs) {
  Eigen::VectorXd axial_mask = Eigen::VectorXd::Zero(dofs.free_count());
  for (int i = 0; i < dofs.free_count(); ++i) {
    if (dofs.free_to_full[static_cast<std::size_t>(i)] % 3 == static_cast<int>(fem::NodeDof::axial)) axial_mask(i) = 1.0;
  }
  std::vector<RotatingMode> modes;
  int bending_order = 0, axial_order = 0;
  for (Eigen::Index j = 0; j < pairs.eigenvalues.size(); ++j) {
    const Eigen::VectorXd phi = pairs.eigenvectors.col(j);
    const Eigen::VectorXd axial_part = phi.cwiseProduct(axial_mask);
    const double total = phi.dot(mass * phi);
    const double share = total > 0.0 ? axial_part.dot(mass * axial_part) / total : 0.0;
    const bool axial = share > 0.5;
    modes.push_back({pairs.eigenvalues(j), axial ? fem::ModeKind::axial : fem::ModeKind::bending,
                     axial ? ++axial_order : ++bending_order, share});
  }
  return modes;
}

}  // namespace

double RotatingMode::angular_frequency() const { return stable() ? std::sqrt(omega_squared) : 0.0; }
double RotatingMode::growth_rate() const { return stable() ? 0.0 : std::sqrt(-omega_squared); }

Eigen::SparseMatrix<double> rotating_stiffness(const fem::BeamModel& model, const RotatingBeamState& state) {
  require(std::isfinite(state.spin_rate) && state.spin_rate >= 0.0,
          "spin rate Omega = " + std::to_string(state.spin_rate) + " rad/s is outside the valid range [0, inf)");
  require(std::isfinite(state.hub_radius) && state.hub_radius >= 0.0,
          "hub radius r = " + std::to_string(state.hub_radius) + " m is outside the valid range [0, inf)");
  require(std::isfinite(state.axial_force), "axial force P = " + std::to_string(state.axial_force) + " N is not finite");
  const bool loaded = state.spin_rate > 0.0 || state.axial_force != 0.0;
  require(!(loaded && model.boundary == fem::Boundary::free_free),
          "a spinning or axially loaded beam needs a held root (clamped-free or pinned-pinned), not free-free");
  const double spin2 = state.spin_rate * state.spin_rate;
  SparseMatrix k = model.stiffness + state.axial_force * model.unit_geometric_stiffness - spin2 * model.mass;
  if (state.centrifugal_stiffening && spin2 > 0.0) {
    const fem::AxialForce per_spin2 = fem::centrifugal_axial_force(model.mesh, state.hub_radius);
    k += spin2 * fem::assemble_geometric_stiffness(model.mesh, model.dofs, per_spin2);
  }
  return k;
}

double shift_below_spectrum(const SparseMatrix& stiffness, const SparseMatrix& mass, double start) {
  double sigma = start;
  const double step = std::max(1.0, std::abs(start));
  for (int attempt = 0; attempt < 200; ++attempt) {
    if (eigenvalues_below(stiffness, mass, sigma) == 0) return sigma;
    sigma -= step * std::pow(2.0, attempt);  // geometric descent: the spectrum is bounded below
  }
  std::ostringstream why;
  why << "no shift below the spectrum of (K, M) found down to sigma = " << sigma << " rad^2/s^2";
  throw EigenSolverError(why.str());
}

RotatingBeamModes rotating_beam_modes(const fem::BeamModel& model, const RotatingBeamState& state, int count,
                                      EigenSolverKind solver) {
  const SparseMatrix k = rotating_stiffness(model, state);
  // First try: half the "ω² of βL = 1" below −Ω². Without compression the spectrum starts above
  // 12.36 EI/(ρA L⁴) − Ω² (tension only raises it), so this try succeeds; compression lowers it.
  const fem::BeamSection& s = model.mesh.section;
  const double unit = s.bending_rigidity() / (s.mass_per_length * std::pow(model.mesh.length, 4));
  EigenRequest request;
  request.nev = count;
  request.sigma = shift_below_spectrum(k, model.mass, -state.spin_rate * state.spin_rate - 0.5 * unit);
  RotatingBeamModes out{state, request.sigma, solve_generalized(k, model.mass, request, solver), {}};
  out.modes = classify(model.dofs, model.mass, out.pairs);
  return out;
}

}  // namespace ffrf::modal
