// Crane equations, the stresses along the boom at an output sample (multibody/boom_stress.hpp): the
// boom's frame and elastic motion with their accelerations and the wires' pulls on it go to the
// stress recovery, by mode displacement and, where the model offers it, by mode acceleration.
// In full coordinates the accelerations come from the boom's own rows with the heel's reaction
// (λ1, λ2, −λ3; no moment through a pin), M_boom a = Q_boom + (reaction, 0), solved by the Schur
// complement of the factored M_ff:
//   (M_RR − M_Rf M_ff⁻¹ M_fR) q̈_B = Q_B + reaction − M_Rf M_ff⁻¹ Q_f,   η̈ = M_ff⁻¹ (Q_f − M_fR q̈_B).
#pragma once

namespace ffrf::multibody::detail {

template <fem::ElasticCoordinates Coords, bool Articulated>
const BoomStressProfile* CraneEquationsOf<Coords, Articulated>::boom_stress_profile() const {
  if (!m_.stress) return nullptr;
  const bool acceleration = m_.stress->method == StressRecovery::mode_acceleration && !m_.stress->identity_basis;
  return &stress_profiles_[acceleration ? 1 : 0];
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::add_boom_stress(const Eigen::Vector3d& frame_acceleration, ConstRef elastic_acceleration,
                                                       CraneOutputs& out) {
  if (!m_.stress) return;
  const BoomStressModel& model = *m_.stress;
  stress_motion_.frame_pose = boom_q_.head<3>();
  stress_motion_.frame_velocity = boom_v_.head<3>();
  stress_motion_.frame_acceleration = frame_acceleration;
  stress_motion_.elastic = boom_q_.tail(n_);
  stress_motion_.elastic_rate = boom_v_.tail(n_);
  stress_motion_.elastic_acceleration = elastic_acceleration;
  boom_loads_.clear();  // (its capacity stays: no allocation after the first sample)
  for (std::size_t i = 0; i < m_.wires.size(); ++i) {
    const Eigen::Vector2d pull = wires_[i].tension * wires_[i].direction;  // on `from`, towards `to`
    if (m_.wires[i].from.body == Body::boom) boom_loads_.push_back({m_.wires[i].from.point.undeformed.x(), pull});
    if (m_.wires[i].to.body == Body::boom) boom_loads_.push_back({m_.wires[i].to.point.undeformed.x(), -pull});
  }
  const Eigen::Vector2d gravity(0.0, -m_.gravity);
  recover_boom_stress(model, StressRecovery::mode_displacement, stress_motion_, boom_loads_, gravity, stress_profiles_[0], stress_work_);
  if (model.identity_basis || !model.has_mode_acceleration()) {
    stress_profiles_[1] = stress_profiles_[0];  // (nodal: the finite-element answer either way)
  } else {
    recover_boom_stress(model, StressRecovery::mode_acceleration, stress_motion_, boom_loads_, gravity, stress_profiles_[1],
                        stress_work_);
  }
  out.boom_peak_stress_by = {stress_profiles_[0].peak, stress_profiles_[1].peak};
  const BoomStressProfile& own = *boom_stress_profile();
  out.boom_peak_stress = own.peak;
  out.boom_peak_stress_position = own.peak_position;
  out.boom_stress_utilisation = model.allowable_stress > 0.0 ? own.peak / model.allowable_stress : 0.0;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
Eigen::Vector3d CraneEquationsOf<Coords, Articulated>::full_boom_accelerations(ConstRef lambda, Eigen::VectorXd& elastic_acceleration) const {
  Eigen::Vector3d frame_force = boom_force_.head<3>();
  frame_force += Eigen::Vector3d(lambda(0), lambda(1), clamped() ? -lambda(2) : 0.0);
  if (n_ == 0) {
    elastic_acceleration.resize(0);
    return boom_reference_mass_.ldlt().solve(frame_force);
  }
  const Eigen::VectorXd elastic_force = boom_force_.tail(n_);
  const Eigen::MatrixXd coupling_t = boom_coupling_.transpose();
  const Eigen::MatrixXd mass_inverse_coupling = shared_->elastic_mass_factor.solve(coupling_t);  // M_ff⁻¹ M_fR
  const Eigen::VectorXd mass_inverse_force = shared_->elastic_mass_factor.solve(elastic_force);  // M_ff⁻¹ Q_f
  const Eigen::Matrix3d schur = boom_reference_mass_ - boom_coupling_ * mass_inverse_coupling;
  const Eigen::Vector3d frame_acceleration = schur.ldlt().solve(frame_force - boom_coupling_ * mass_inverse_force);
  elastic_acceleration = mass_inverse_force - mass_inverse_coupling * frame_acceleration;
  return frame_acceleration;
}

}  // namespace ffrf::multibody::detail
