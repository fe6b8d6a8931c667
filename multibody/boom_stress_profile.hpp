// The stresses along the boom as a run sees them: one sample's profile (section forces and the two
// extreme fibres' stresses at every section, multibody/boom_stress.hpp recovers it) and the envelope
// of a run (each section's extremes over the samples, and the profile at the run's peak stress).
#pragma once

#include <Eigen/Dense>
#include <cmath>

#include "fem/section_forces.hpp"

namespace ffrf::multibody {

struct BoomStressProfile {
  // position, N (tension > 0), M at each section: the nodes and, between them, the element's own
  // linear N and M under its mean transverse load at each quarter of its length
  fem::SectionForces forces;
  Eigen::VectorXd top, bottom;  // the extreme fibres' stresses at y = ±c [Pa]
  double peak = 0.0;            // the largest |σ| along the boom, between the sections too [Pa]
  double peak_position = 0.0;   // where [m]
};

struct BoomStressEnvelope {
  Eigen::VectorXd position;                 // [m]
  Eigen::VectorXd axial_min, axial_max;     // [N]
  Eigen::VectorXd moment_min, moment_max;   // [N m]
  Eigen::VectorXd stress_min, stress_max;   // the most compressive and the most tensile fibre stress [Pa]
  BoomStressProfile at_peak;                // the profile at the sample of the largest peak
  double peak_time = 0.0;                   // [s]
  long samples = 0;

  bool empty() const { return samples == 0; }
  // Folds one sample's profile in.
  void add(double time, const BoomStressProfile& profile) {
    const Eigen::VectorXd& axial = profile.forces.axial_force;
    const Eigen::VectorXd& moment = profile.forces.bending_moment;
    const Eigen::VectorXd low = profile.top.cwiseMin(profile.bottom), high = profile.top.cwiseMax(profile.bottom);
    if (samples == 0) {
      position = profile.forces.position;
      axial_min = axial_max = axial;
      moment_min = moment_max = moment;
      stress_min = low;
      stress_max = high;
    } else {
      axial_min = axial_min.cwiseMin(axial);
      axial_max = axial_max.cwiseMax(axial);
      moment_min = moment_min.cwiseMin(moment);
      moment_max = moment_max.cwiseMax(moment);
      stress_min = stress_min.cwiseMin(low);
      stress_max = stress_max.cwiseMax(high);
    }
    if (samples == 0 || profile.peak > at_peak.peak) {
      at_peak = profile;
      peak_time = time;
    }
    ++samples;
  }
};

}  // namespace ffrf::multibody
