// Where an integrator hands the state at each output time: the system's own recorder (what it
// samples, in which units, and which watches it runs on each sample) lives with the system, so the
// integrators sample without naming an output. A sink may throw (a SolverFailure from a watch, or
// the model's own error) to stop the run at that sample.
#pragma once

#include <Eigen/Core>

namespace ffrf::solve {

class OutputSink {
 public:
  using ConstRef = Eigen::Ref<const Eigen::VectorXd>;
  virtual ~OutputSink() = default;
  // A state in minimal coordinates at t (the sink solves for what needs the accelerations).
  virtual void minimal_sample(double t, ConstRef z, ConstRef z_dot) = 0;
  // The same with the accelerations known (an integrator's interpolant): nothing to solve.
  virtual void minimal_sample(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot) { minimal_sample(t, z, z_dot); (void)z_ddot; }
  // A state in full coordinates with the constraints' multipliers.
  virtual void full_sample(double t, ConstRef q, ConstRef v, ConstRef lambda) = 0;
};

// Samples nothing (trial runs that only ask whether a run completes).
class DiscardSamples final : public OutputSink {
 public:
  void minimal_sample(double, ConstRef, ConstRef) override {}
  void minimal_sample(double, ConstRef, ConstRef, ConstRef) override {}
  void full_sample(double, ConstRef, ConstRef, ConstRef) override {}
};

}  // namespace ffrf::solve
