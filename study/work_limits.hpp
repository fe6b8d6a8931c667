// Work and memory a run will need, estimated before anything is allocated, against fixed limits
// (below; solve::WorkLimits bounds the run itself as it goes): a setting beyond them is a SettingError naming the limit, never an allocation that
// ends in std::bad_alloc or a run that never ends.
//  * memory: the integrators' dense Newton matrices — SUNDIALS' dense linear solver keeps the
//    Jacobian, its saved copy and the LU factors, 3 n² doubles for a state of size n; the largest
//    state of a model is the full-coordinate DAE's n = 2 (9 + m) + 3 (hull, boom frame and cargo
//    poses, m elastic coordinates, their velocities, three clamp multipliers);
//  * output samples: duration / output interval (each sample and its CSV row about half a kB);
//  * fixed steps: duration / step of generalized-α and fixed-step explicit Runge–Kutta.
#pragma once

#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"

namespace ffrf::study {

inline constexpr double memory_limit_bytes = 4.0 * 1024.0 * 1024.0 * 1024.0;  // 4 GiB
inline constexpr double max_fixed_steps = 1e7;

// The elastic coordinates of a boom choice (3 N nodal, k + static modes modal, 0 rigid).
int elastic_coordinates(const scene::BoomChoice& choice);
// Bytes of the dense Newton matrices of a model with m elastic coordinates.
double newton_matrix_bytes(int elastic);
// The largest element count of a nodal boom within the memory limit.
int max_nodal_elements();
// Throws SettingError(Setting::elements) when the choice's run would need more than memory_limit_bytes.
void check_run_memory(const scene::BoomChoice& choice);

}  // namespace ffrf::study
