// Spectra's shift-invert solver for K φ = λ M φ (SymGEigsShiftSolver in GEigsMode::ShiftInvert,
// K − σM factored by a sparse LU), the independent cross-check of the ARPACK solver. Same
// conventions: the nev eigenvalues nearest σ, ascending, M-normalized eigenvectors.
#pragma once

#include "modal/eigen_solver.hpp"

namespace ffrf::modal {

// Throws EigenSolverError for an invalid request, a singular K − σM or no convergence.
EigenPairs solve_spectra_shift_invert(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                      const EigenRequest& request);

}  // namespace ffrf::modal
