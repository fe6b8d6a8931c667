// Small RAII helpers around the SUNDIALS 6 C API shared by the KINSOL, CVODE and IDA adapters:
// the context, serial vectors viewed as Eigen vectors, dense matrix + dense linear solver, and a
// terminal progress line.
#pragma once

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Dense>
#include <memory>
#include <stdexcept>

namespace ffrf::coupling::sundials {

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
  Vector(sunindextype n, SUNContext ctx) : v(N_VNew_Serial(n, ctx)) {
    if (!v) throw std::runtime_error("SUNDIALS vector allocation failed");
  }
  ~Vector() { N_VDestroy(v); }
  Vector(const Vector&) = delete;
  Vector& operator=(const Vector&) = delete;
  Eigen::Map<Eigen::VectorXd> map() { return view(v); }
  static Eigen::Map<Eigen::VectorXd> view(N_Vector x) {
    return {N_VGetArrayPointer(x), static_cast<Eigen::Index>(N_VGetLength(x))};
  }
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

}  // namespace ffrf::coupling::sundials
