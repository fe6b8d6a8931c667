// Free decays of the fixture's barge (m = 4.0e6 kg, I55 = 2.166667e9 kg m² about the waterline origin,
// the centre of gravity; README of the fixture) in the crane code — the hull of a crane scene with
// [bem] (a 40 kg boom and a 1 kg cargo: the hull alone to 1e-5), its BEM radiation model and the
// nonlinear hydrostatic pressure on the box, integrated by CVODE through the crane's structured Newton
// solves — against the frequency domain: the complex root ω of det[−ω² (M + A(ω)) + iω B(ω) + C] = 0,
// with A and B continued from the tabulated real frequencies to complex ω by their Taylor series to
// second order,
//   A(ω_r + iω_i) ≈ A(ω_r) + iω_i A'(ω_r) − ½ ω_i² A''(ω_r)  (the same for B),
// the derivatives by central differences of the table. Damped period 2π/Re ω, damping ratio
// Im ω / |ω|. Also against the exact poles of the sampled Cummins equation,
// s² (M + A∞) + s K̂(s) + C, K̂(s) = ∫ K e^{−st} dt (trapezoid on the kernel samples).
// Time series are reduced to (period, ratio) by zero up-crossings and logarithmic decrements of
// cycles 1–4 (local_decay): a memory model's decay is not one exponential (the kernel adds a
// non-oscillatory part), so a global fit would be biased.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "barge_hull_scene.hpp"
#include "multibody/crane_run.hpp"
#include "hydro/retardation.hpp"
#include "hydro/state_space_fit.hpp"
#include "hydro/wamit_reader.hpp"
#include "scene/bem_hull_model.hpp"
#include "scene/scene_loader.hpp"
#include "study/run_pipeline.hpp"

namespace cummins_crane_test {

using namespace ffrf::hydro;
using cd = std::complex<double>;
constexpr double kPi = std::numbers::pi;

struct Decay {
  double period = 0.0, ratio = 0.0;
};

Decay from_pole(cd omega) { return {2 * kPi / omega.real(), omega.imag() / std::abs(omega)}; }

// Local estimates from the record, cycles first..last (cycle k from the k-th zero up-crossing):
// the mean spacing of up-crossings (linear interpolation) and the mean logarithmic decrement δ of
// successive maxima (parabolic interpolation), ratio δ / sqrt(4π² + δ²). A slowly varying offset
// (the surge drift in pitch) is removed first as the running mean over the last whole cycle.
struct Record {
  std::vector<double> time;
  std::vector<PlanarVector> position;  // hull (x, y, θ) less its static value
};

Decay local_decay(const Record& rec, int dof, double period_guess, int first, int last) {
  const double h = rec.time[1] - rec.time[0];
  const auto window = static_cast<std::size_t>(std::lround(period_guess / h));
  std::vector<double> t, x;
  for (std::size_t i = window; i < rec.time.size(); ++i) {
    double mean = 0.0;
    for (std::size_t k = i - window; k < i; ++k) mean += rec.position[k](dof);
    t.push_back(rec.time[i] - 0.5 * period_guess);
    x.push_back(rec.position[i - window / 2](dof) - mean / static_cast<double>(window));
  }
  std::vector<double> up, peaks;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i - 1] < 0 && x[i] >= 0) up.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-x[i - 1]) / (x[i] - x[i - 1]));
  for (std::size_t i = 1; i + 1 < x.size(); ++i)
    if (x[i] > x[i - 1] && x[i] >= x[i + 1] && x[i] > 0) {
      const double a = x[i - 1], b = x[i], c = x[i + 1], offset = 0.5 * (a - c) / (a - 2 * b + c);
      peaks.push_back(b - 0.25 * (a - c) * offset);
    }
  Decay d;
  for (int k = first; k <= last; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const double delta = std::log(peaks[i] / peaks[i + 1]);
    d.period += up[i + 1] - up[i];
    d.ratio += delta / std::sqrt(4 * kPi * kPi + delta * delta);
  }
  d.period /= last - first + 1;
  d.ratio /= last - first + 1;
  return d;
}

class BargeDecay : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string data = std::string(FFRF_SOURCE_DIR "/tests/hydro/data/");
    radiation = read_wamit_radiation(data + "barge.1", {1.0, 1000.0, 9.81});
    stiffness = read_wamit_hydrostatics(data + "barge.hst", {1.0, 1000.0, 9.81});
    mass.setZero();
    mass.diagonal() << 4.0e6, 4.0e6, 2.166667e9;
    kernel = retardation_function(radiation);
  }

  // Root near `guess` of det over the dofs (1: heave alone; {0, 2}: surge–pitch), A, B continued.
  cd frequency_domain_root(const std::vector<int>& dofs, cd guess) const {
    auto z = [&](cd w) {
      const double h = 0.02, wi = w.imag();
      const auto mid = radiation_at(radiation, w.real()), up = radiation_at(radiation, w.real() + h),
                 down = radiation_at(radiation, w.real() - h);
      auto continued = [&](const PlanarMatrix& m, const PlanarMatrix& u, const PlanarMatrix& d) {
        return Eigen::Matrix3cd(m.cast<cd>() + cd(0, wi) * ((u - d) / (2 * h)).cast<cd>() - (0.5 * wi * wi * (u - 2 * m + d) / (h * h)).cast<cd>());
      };
      const Eigen::Matrix3cd a = continued(mid.added_mass, up.added_mass, down.added_mass);
      const Eigen::Matrix3cd b = continued(mid.damping, up.damping, down.damping);
      const Eigen::Matrix3cd full = -w * w * (mass.cast<cd>() + a) + cd(0, 1) * w * b + stiffness.cast<cd>();
      Eigen::MatrixXcd sub(dofs.size(), dofs.size());
      for (std::size_t i = 0; i < dofs.size(); ++i)
        for (std::size_t j = 0; j < dofs.size(); ++j) sub(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = full(dofs[i], dofs[j]);
      return sub.determinant();
    };
    return newton(z, guess);
  }

  // Pole s of the sampled Cummins equation, returned as ω = −i s.
  cd cummins_root(const std::vector<int>& dofs, cd guess) const {
    auto z = [&](cd w) {
      const cd s(0, 1);
      const cd sv = s * w;
      Eigen::Matrix3cd transform = Eigen::Matrix3cd::Zero();
      for (std::size_t k = 0; k < kernel.kernel.size(); ++k) {
        const double weight = (k == 0 || k + 1 == kernel.kernel.size() ? 0.5 : 1.0) * kernel.time_step;
        transform += weight * kernel.kernel[k].cast<cd>() * std::exp(-sv * (static_cast<double>(k) * kernel.time_step));
      }
      const Eigen::Matrix3cd full = sv * sv * (mass + kernel.infinite_frequency_added_mass).cast<cd>() + sv * transform + stiffness.cast<cd>();
      Eigen::MatrixXcd sub(dofs.size(), dofs.size());
      for (std::size_t i = 0; i < dofs.size(); ++i)
        for (std::size_t j = 0; j < dofs.size(); ++j) sub(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = full(dofs[i], dofs[j]);
      return sub.determinant();
    };
    return newton(z, guess);
  }

  template <class F>
  static cd newton(F&& f, cd w) {
    for (int it = 0; it < 60; ++it) {
      const cd h = 1e-7;
      const cd step = f(w) / ((f(w + h) - f(w - h)) / (2.0 * h));
      w -= step;
      if (std::abs(step) < 1e-13) break;
    }
    return w;
  }

  // The barge of the fixture as the hull of a crane scene ([bem] with `model`), released at rest
  // from its static equilibrium moved by `offset` (surge, heave, pitch); CVODE, rtol 1e-8.
  static Record crane_decay(const std::string& model, const PlanarVector& offset, double duration,
                            const std::string& extra_bem_keys = "") {
    const std::string data = std::string(FFRF_SOURCE_DIR "/tests/hydro/data/");
    const std::string text = ffrf::test::barge_hull_scene(4.0e6, std::sqrt(2.166667e9 / 4.0e6), fmt::format(R"(radiation_file = "{}barge.1"
hydrostatics_file = "{}barge.hst"
origin_above_keel = 5.0
radiation_model = "{}"
{})",
                                                                                                  data, data, model, extra_bem_keys));
    const ffrf::scene::Scene scene = ffrf::scene::load_scene_text(text, "barge_decay.toml");
    ffrf::study::PreparedRun prepared = ffrf::study::prepare_run(scene, {ffrf::scene::BoomKind::rigid, 1});
    Eigen::VectorXd z0 = prepared.initial_state;
    z0.head<3>() += offset;
    ffrf::multibody::RunSettings settings;
    settings.relative_tolerance = 1e-8;
    settings.absolute_tolerance = 1e-9;
    settings.duration = duration;
    settings.output_interval = 0.05;
    const auto result = ffrf::multibody::simulate(*prepared.equations, z0, settings);
    Record rec;
    rec.time = result.time;
    for (const auto& sample : result.samples) rec.position.push_back(sample.hull - prepared.initial_state.head<3>());
    return rec;
  }

  PlanarRadiation radiation;
  PlanarMatrix stiffness, mass;
  RetardationFunction kernel;
};


TEST_F(BargeDecay, HeaveByConvolutionMatchesTheFrequencyDomainRoot) {
  const Record rec = crane_decay("convolution", PlanarVector(0, 0.1, 0), 40.0);
  const Decay measured = local_decay(rec, 1, 5.95, 1, 4);
  const Decay frequency_domain = from_pole(frequency_domain_root({1}, cd(1.05, 0.09)));
  const Decay exact = from_pole(cummins_root({1}, cd(1.05, 0.09)));
  ::testing::Test::RecordProperty("heave_time_domain", fmt::format("{:.4f} s, ratio {:.4f}", measured.period, measured.ratio));
  ::testing::Test::RecordProperty("heave_frequency_domain", fmt::format("{:.4f} s, ratio {:.4f}", frequency_domain.period, frequency_domain.ratio));
  ::testing::Test::RecordProperty("heave_cummins_pole", fmt::format("{:.4f} s, ratio {:.4f}", exact.period, exact.ratio));
  EXPECT_NEAR(measured.period, frequency_domain.period, 0.005 * frequency_domain.period);
  EXPECT_NEAR(measured.ratio, frequency_domain.ratio, 0.03 * frequency_domain.ratio);
  EXPECT_NEAR(measured.period, exact.period, 0.002 * exact.period);
  EXPECT_NEAR(measured.ratio, exact.ratio, 0.02 * exact.ratio);
  // The barge's heave: period about 5.95 s, 8.4 % of critical.
  EXPECT_NEAR(exact.period, 5.95, 0.05);
  EXPECT_NEAR(exact.ratio, 0.084, 0.003);
}

TEST_F(BargeDecay, StateSpaceAndConstantModelsAgainstTheirOwnPredictions) {
  const Record rec = crane_decay("state-space", PlanarVector(0, 0.1, 0), 40.0, "state_space_tolerance = 0.01");
  const Decay ss = local_decay(rec, 1, 5.95, 1, 4);
  const Decay exact = from_pole(cummins_root({1}, cd(1.05, 0.09)));
  ::testing::Test::RecordProperty("heave_state_space", fmt::format("{:.4f} s, ratio {:.4f}", ss.period, ss.ratio));
  EXPECT_NEAR(ss.period, exact.period, 0.005 * exact.period);  // a 1 % impulse-response fit
  EXPECT_NEAR(ss.ratio, exact.ratio, 0.05 * exact.ratio);
  // Constant A, B at the undamped natural frequency (the scene's default without a wave): a
  // constant-coefficient oscillator, whose decay is the classical estimate (A, B at real ω).
  double w = 1.0;
  for (int it = 0; it < 100; ++it) w = std::sqrt(stiffness(1, 1) / (mass(1, 1) + radiation_at(radiation, w).added_mass(1, 1)));
  const auto at_w = radiation_at(radiation, w);
  const Record rc = crane_decay("constant", PlanarVector(0, 0.1, 0), 40.0);
  const Decay measured = local_decay(rc, 1, 6.0, 1, 4);
  const double total = mass(1, 1) + at_w.added_mass(1, 1), sigma = at_w.damping(1, 1) / (2 * total);
  EXPECT_NEAR(measured.period, 2 * kPi / std::sqrt(stiffness(1, 1) / total - sigma * sigma), 1e-3 * measured.period);
  EXPECT_NEAR(measured.ratio, sigma * std::sqrt(total / stiffness(1, 1)), 3e-3 * measured.ratio);
}

TEST_F(BargeDecay, PitchWithSurgeCouplingMatchesTheFrequencyDomainRoot) {
  const Record rec = crane_decay("convolution", PlanarVector(0, 0, 0.02), 40.0);
  const Decay measured = local_decay(rec, 2, 5.9, 1, 4);
  const Decay frequency_domain = from_pole(frequency_domain_root({0, 2}, cd(1.06, 0.08)));
  const Decay exact = from_pole(cummins_root({0, 2}, cd(1.06, 0.08)));
  ::testing::Test::RecordProperty("pitch", fmt::format("time domain {:.4f} s ratio {:.4f}; frequency domain {:.4f} s ratio {:.4f}; pole {:.4f} s ratio {:.4f}",
                                                       measured.period, measured.ratio, frequency_domain.period, frequency_domain.ratio, exact.period, exact.ratio));
  EXPECT_NEAR(measured.period, frequency_domain.period, 0.005 * frequency_domain.period);
  EXPECT_NEAR(measured.ratio, frequency_domain.ratio, 0.06 * frequency_domain.ratio);
  EXPECT_NEAR(measured.period, exact.period, 0.004 * exact.period);
  EXPECT_NEAR(measured.ratio, exact.ratio, 0.03 * exact.ratio);
  // Surge is excited through the surge–pitch added mass and damping (no surge restoring).
  double surge = 0.0;
  for (const auto& x : rec.position) surge = std::max(surge, std::abs(x(0)));
  EXPECT_GT(surge, 1e-4);
}

}  // namespace cummins_crane_test
