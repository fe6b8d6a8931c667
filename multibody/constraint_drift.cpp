// Constraint drift per formulation (see constraint_drift.hpp).
#include "multibody/constraint_drift.hpp"

#include <algorithm>
#include <stdexcept>

namespace ffrf::multibody {

std::vector<Integrator> constraint_formulations() {
  return {Integrator::cvode, Integrator::ida, Integrator::index1, Integrator::baumgarte, Integrator::projection};
}

std::vector<FormulationDrift> compare_constraint_drift(const EquationsFactory& make_equations, const Eigen::VectorXd& z0,
                                                       const RunSettings& settings,
                                                       const std::vector<Integrator>& formulations) {
  std::vector<FormulationDrift> drifts;
  drifts.reserve(formulations.size());
  for (Integrator formulation : formulations) {
    std::unique_ptr<CraneEquations> equations = make_equations();
    if (!equations) throw std::invalid_argument("compare_constraint_drift: the factory returned no equations");
    RunSettings run_settings = settings;
    run_settings.kind = formulation;
    FormulationDrift drift{formulation, simulate(*equations, z0, run_settings), {}, 0.0, 0.0};
    drift.residual.reserve(drift.run.samples.size());
    for (const CraneOutputs& sample : drift.run.samples) drift.residual.push_back(sample.constraint_residual);
    if (!drift.residual.empty()) {
      drift.max_residual = *std::max_element(drift.residual.begin(), drift.residual.end());
      drift.final_residual = drift.residual.back();
    }
    drifts.push_back(std::move(drift));
  }
  return drifts;
}

}  // namespace ffrf::multibody
