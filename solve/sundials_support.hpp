// Small RAII helpers around the SUNDIALS 6 C API shared by the KINSOL, CVODE, IDA and ARKODE
// adapters: the context, serial vectors viewed as Eigen vectors, dense matrix + dense linear solver,
// a terminal progress line; and what every adapter does the same way: set-up calls checked by name
// (SetupCheck), one guard for every callback (CallbackGuard: no C++ exception crosses SUNDIALS' C
// frames, and the wall-clock limit is checked there), the output loop; the run's step budget and the
// failure a solver's error flag means are in solve/solver_steps.hpp.
#pragma once

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <stdexcept>
#include <vector>

#include "solve/integration.hpp"
#include "solve/nvector_view.hpp"
#include "solve/stop_request.hpp"

namespace ffrf::solve::sundials {

// SUNDIALS' *GetReturnFlagName functions return a malloc'd string: copy it and free it.
inline std::string flag_name(char* name) {
  std::string text = name != nullptr ? name : "unknown flag";
  std::free(name);
  return text;
}

// An event function's value for the root finders, never exactly zero: an exact 0 counts as negative.
// A value such as a wire's stretch ℓ − L0 is the difference of positions ~100 m from the origin, so it
// is quantized in steps of ~1e-14 m, while the root finders restart after an event by checking g at
// the root and 100·ε·(|t| + |h|) ≈ 2e-14 s later (CVODE's cvRcheck2, IDA's and ARKODE's alike): with
// a body moving at ~1 m/s both can round to exactly 0, which SUNDIALS rejects as "Root found at and
// very near t" (an illegal-input failure). The system's event functions put their boundary (a wire's
// slack branch at ℓ = L0) on the negative side.
inline double nonzero_event(double value) {
  return value > 0.0 ? value : std::min(value, -std::numeric_limits<double>::min());
}

// The event functions at a state into SUNDIALS' root array g[0 .. count): evaluate(Ref) fills them.
template <class Evaluate>
void event_values(int count, sunrealtype* g, Evaluate evaluate) {
  EventVector values = EventVector::Zero(count);
  evaluate(Eigen::Ref<Eigen::VectorXd>(values));  // a view: the system writes into `values`
  for (int i = 0; i < count; ++i) g[i] = nonzero_event(values(i));
}

struct Context {
  SUNContext ctx = nullptr;
  Context() {
    if (SUNContext_Create(nullptr, &ctx) != 0) throw std::runtime_error("SUNDIALS context creation failed");
  }
  ~Context() { SUNContext_Free(&ctx); }
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
};

struct Vector {
  N_Vector v = nullptr;
  // With SUNDIALS' fused vector operations (N_VLinearCombination etc. in one pass instead of a chain
  // of N_VLinearSum calls); the integrators' internal vectors are clones and inherit them.
  Vector(sunindextype n, SUNContext ctx) : v(N_VNew_Serial(n, ctx)) {
    if (!v) throw std::runtime_error("SUNDIALS vector allocation failed");
    N_VEnableFusedOps_Serial(v, SUNTRUE);
  }
  ~Vector() { N_VDestroy(v); }
  Vector(const Vector&) = delete;
  Vector& operator=(const Vector&) = delete;
  Eigen::Map<Eigen::VectorXd> map() { return view(v); }
  static Eigen::Map<Eigen::VectorXd> view(N_Vector x) { return sundials::view(x); }
};

struct DenseSolver {
  SUNMatrix matrix = nullptr;
  SUNLinearSolver solver = nullptr;
  DenseSolver(N_Vector y, SUNContext ctx) {
    const sunindextype n = N_VGetLength(y);
    matrix = SUNDenseMatrix(n, n, ctx);
    solver = SUNLinSol_Dense(y, matrix, ctx);
    if (!matrix || !solver) throw std::runtime_error("SUNDIALS dense linear solver allocation failed");
  }
  ~DenseSolver() {
    SUNLinSolFree(solver);
    SUNMatDestroy(matrix);
  }
  DenseSolver(const DenseSolver&) = delete;
  DenseSolver& operator=(const DenseSolver&) = delete;
};

// SUNDIALS' own error messages ("reltol < 0 illegal.", "At t = 0 and h = 0.05, the error test failed
// repeatedly or with |h| = hmin."), kept for the failure's cause instead of printed on stderr:
// register `handler` with this object right after the solver is created (CVodeSetErrHandlerFn, ...).
struct LibraryMessage {
  std::string text;
  static void handler(int, const char*, const char* function, char* message, void* self) {
    static_cast<LibraryMessage*>(self)->text = std::string(function) + ": " + message;
  }
  std::string suffix() const { return text.empty() ? std::string() : " (" + text + ")"; }
};

// Set-up calls checked by name, as SUNDIALS' own examples do (cvRoberts_dns.c's check_retval): a
// call that returns a negative flag, or a constructor that returns null, throws
// SolverFailure(set-up) naming the call, the flag and SUNDIALS' message, e.g. "CVodeSVtolerances returned
// CV_ILL_INPUT (CVodeSVtolerances: reltol < 0 illegal.)".
class SetupCheck {
 public:
  using FlagName = char* (*)(long int);
  SetupCheck(std::string solver, FlagName flag_name, const LibraryMessage& message)
      : solver_(std::move(solver)), flag_name_(flag_name), message_(message) {}
  void operator()(int flag, const char* call) const {
    if (flag < 0) {
      throw SolverFailure(FailureKind::setup, solver_,
                          std::string(call) + " returned " + flag_name(flag_name_(flag)) + message_.suffix(), 0.0);
    }
  }
  void operator()(const void* created, const char* call) const {
    if (created == nullptr) throw SolverFailure(FailureKind::setup, solver_, std::string(call) + " returned null", 0.0);
  }

 private:
  std::string solver_;
  FlagName flag_name_;
  const LibraryMessage& message_;
};

// One guard for every solver callback (right-hand side, residual, Jacobian, linear system, root
// function, projection, post-step check). A C++ exception never crosses SUNDIALS' C frames: the
// guard stores it (its failure kind from model_failure_kind, its message) and returns −1, SUNDIALS'
// unrecoverable callback failure; the adapter turns it into a SolverFailure when the solver returns
// (rethrow). Every call also checks the run's wall-clock limit (WorkLimits::max_wall_seconds),
// ending the run the same way with "too much work".
class CallbackGuard {
 public:
  CallbackGuard(std::string solver, const WorkLimits& limits)
      : solver_(std::move(solver)), wall_limit_(limits.max_wall_seconds), start_(std::chrono::steady_clock::now()) {}
  CallbackGuard(const CallbackGuard&) = delete;
  CallbackGuard& operator=(const CallbackGuard&) = delete;

  template <class Body>
  int operator()(Body&& body) noexcept {
    if (failed_) return -1;
    if (std::isfinite(wall_limit_) && elapsed() > wall_limit_) {
      store(FailureKind::too_much_work, "the wall-clock limit of " + number(wall_limit_) + " s was reached");
      return -1;
    }
    try {
      return body();
    } catch (const SolverFailure& failure) {
      store(failure.kind(), failure.cause());
    } catch (const std::exception& error) {
      store(model_failure_kind(error), std::string("the model failed: ") + error.what());
    } catch (...) {
      store(FailureKind::model_error, "the model failed: an exception of unknown type");
    }
    return -1;
  }
  bool failed() const { return failed_; }
  FailureKind kind() const { return kind_; }
  // The stored failure as a SolverFailure at t (with the remedy of its kind); nothing when none.
  void rethrow(double t) const {
    if (failed_) throw SolverFailure(kind_, solver_, cause_, t);
  }
  // For loops outside SUNDIALS (generalized-α): throws "too much work" past the wall-clock limit.
  void check_wall_clock(double t) const {
    if (std::isfinite(wall_limit_) && elapsed() > wall_limit_) {
      throw SolverFailure(FailureKind::too_much_work, solver_, "the wall-clock limit of " + number(wall_limit_) + " s was reached", t);
    }
  }
  const std::string& solver() const { return solver_; }

 private:
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  static std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return text;
  }
  void store(FailureKind kind, std::string cause) noexcept {
    failed_ = true;
    kind_ = kind;
    try {
      cause_ = std::move(cause);
    } catch (...) {
    }
  }

  std::string solver_;
  double wall_limit_;
  std::chrono::steady_clock::time_point start_;
  bool failed_ = false;
  FailureKind kind_ = FailureKind::model_error;
  std::string cause_;
};

// Progress on stderr, only when enabled (callers enable it for terminals).
class Progress {
 public:
  Progress(bool enabled, double end, const char* label) : enabled_(enabled), end_(end), label_(label) {}
  void update(double t);
  void finish();

 private:
  bool enabled_;
  double end_;
  const char* label_;
  int last_percent_ = -1;
};

// The minimal-coordinate adapters' start y = (z0, 0) at rest, and their absolute tolerances: atol
// times each coordinate's typical size, for positions and velocities alike.
inline void start_at_rest(const Eigen::VectorXd& z0, const Eigen::VectorXd& scale, double absolute_tolerance, Vector& y,
                          Vector& tolerance) {
  const Eigen::Index n = z0.size();
  y.map().head(n) = z0;
  y.map().tail(n).setZero();
  tolerance.map().head(n) = absolute_tolerance * scale;
  tolerance.map().tail(n) = absolute_tolerance * scale;
}

// SUNDIALS root functions (CVODE's and ARKODE's signature) over a system's event functions at a
// minimal or a full state: `Data` (the adapter's user data) holds `equations` (the system), `events`
// (their count), `size` (the coordinates' count) and `guard` (the CallbackGuard every callback runs in).
template <class Data>
int minimal_event_root(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
  auto* data = static_cast<Data*>(user);
  return (*data->guard)([&] {
    event_values(data->events, g, [&](auto values) { data->equations->minimal_events(t, Vector::view(y).head(data->size), values); });
    return 0;
  });
}
template <class Data>
int full_event_root(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
  auto* data = static_cast<Data*>(user);
  return (*data->guard)([&] {
    event_values(data->events, g, [&](auto values) { data->equations->full_events(t, Vector::view(y).head(data->size), values); });
    return 0;
  });
}

// The output loop shared by the CVODE, IDA and ARKODE adapters: samples t = 0, then advances the
// solver to each output time. `advance(t_out, t)` calls the solver and returns its flag (t: the
// time reached); on `root_return` an event function crossed zero and `root_directions(int*)` (one
// direction per event function, < 0: falling) gives the events recorded before the solver continues; a negative flag goes to
// `fail(flag, t)`, which throws. `record(t)` samples the outputs at t; an exception the model throws
// there (the outputs solve for the accelerations outside the solver's callbacks, first at t = 0)
// becomes a SolverFailure of its kind (model_failure_kind), as inside the callbacks.
template <class Advance, class RootDirections, class Fail, class Record>
void sample_outputs(const IntegratorSettings& settings, const char* label, int root_return, Advance advance,
                    RootDirections root_directions, Fail fail, Record record, int event_count, std::vector<Event>& events) {
  Progress progress(settings.progress, settings.duration, label);
  const auto sample = [&](double t) {
    throw_if_stop_requested();
    try {
      record(t);
    } catch (const SolverFailure&) {
      throw;
    } catch (const std::exception& error) {
      throw SolverFailure(model_failure_kind(error), label, std::string("the model failed: ") + error.what(), t);
    }
  };
  try {
    sample(0.0);
    const long outputs = std::lround(settings.duration / settings.output_interval);
    double t = 0.0;
    for (long k = 1; k <= outputs; ++k) {
      const double t_out = static_cast<double>(k) * settings.output_interval;
      for (int flag = advance(t_out, t);; flag = advance(t_out, t)) {
        if (flag == root_return) {
          int directions[max_events] = {};
          root_directions(directions);
          for (int i = 0; i < event_count; ++i) {
            if (directions[i] != 0) events.push_back({t, i, directions[i] < 0});
          }
          continue;
        }
        if (flag < 0) fail(flag, t);
        break;
      }
      sample(t_out);
      progress.update(t_out);
    }
  } catch (...) {
    progress.finish();
    throw;
  }
  progress.finish();
}

// Forward-difference Jacobian of the second-order ODE y = (x, ẋ), ẏ = (ẋ, a(t, x, ẋ)), column by
// column with increments δ_j = 10⁻⁷·max(|y_j|, 1) (integrate_minimal.cpp says why SUNDIALS' own
// difference quotient does not do here). `acceleration(t, x, ẋ, a)` returns false for a state the
// model refuses. Returns 0, or 1 (recoverable) for a refused or non-finite column; exceptions
// propagate to the calling SUNDIALS callback, which must catch them.
template <class Acceleration>
int second_order_jacobian(double t, N_Vector y, N_Vector f_y, SUNMatrix jacobian, N_Vector work_y, N_Vector work_f,
                          Acceleration acceleration) {
  const auto state = Vector::view(y);
  const auto rate = Vector::view(f_y);
  auto shifted = Vector::view(work_y);
  auto shifted_rate = Vector::view(work_f);
  const Eigen::Index n = state.size() / 2;
  shifted = state;
  for (Eigen::Index j = 0; j < 2 * n; ++j) {
    const double delta = 1e-7 * std::max(std::abs(state(j)), 1.0);
    shifted(j) = state(j) + delta;
    shifted_rate.head(n) = shifted.tail(n);
    const bool accepted = acceleration(t, shifted.head(n), shifted.tail(n), shifted_rate.tail(n));
    shifted(j) = state(j);
    if (!accepted || !shifted_rate.allFinite()) return 1;
    sunrealtype* column = SUNDenseMatrix_Column(jacobian, static_cast<sunindextype>(j));
    for (Eigen::Index i = 0; i < 2 * n; ++i) column[i] = (shifted_rate(i) - rate(i)) / delta;
  }
  return 0;
}

// CVODE's counters into the run's statistics; `jacobian_rhs_evaluations` are the right-hand sides
// our own difference-quotient Jacobian (second_order_jacobian) spent, which CVODE does not count.
inline void cvode_statistics(void* cvode, long jacobian_rhs_evaluations, SolverStats& stats) {
  long rhs = 0, linear_rhs = 0;
  CVodeGetNumSteps(cvode, &stats.steps);
  CVodeGetNumRhsEvals(cvode, &rhs);
  CVodeGetNumLinRhsEvals(cvode, &linear_rhs);
  stats.function_evaluations = rhs + linear_rhs + jacobian_rhs_evaluations;
  CVodeGetNumJacEvals(cvode, &stats.jacobian_evaluations);
  CVodeGetNumLinSolvSetups(cvode, &stats.linear_setups);
  CVodeGetNumNonlinSolvIters(cvode, &stats.newton_iterations);
  CVodeGetNumErrTestFails(cvode, &stats.error_test_failures);
  CVodeGetNumNonlinSolvConvFails(cvode, &stats.convergence_failures);
}

// sample_outputs, and on a SolverFailure the record so far attached to it as its partial result.
template <class... Args>
void sample_outputs_keeping_partial(IntegrationRecord& result, const IntegratorSettings& settings, Args&&... args) {
  const auto samples = static_cast<std::size_t>(std::lround(settings.duration / settings.output_interval)) + 1;
  result.time.reserve(samples);
  try {
    sample_outputs(settings, std::forward<Args>(args)...);
  } catch (SolverFailure& failure) {
    failure.attach_partial(std::make_shared<const IntegrationRecord>(result));
    throw;
  }
}

}  // namespace ffrf::solve::sundials
