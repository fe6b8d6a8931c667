// The scene text of a crane whose hull is the WAMIT fixture's barge (tests/hydro/data: 80 m × 10 m ×
// 8 m, centre of gravity at the waterline origin, 5 m above the keel) and whose boom (40 m of
// 1 kg/m) and cargo (1 kg) weigh 41 kg: the hull alone to ~1e-5, for free decays with the [bem]
// radiation models (tests/study/test_bem_crane.cpp, test_cummins_crane.cpp).
#pragma once

#include <fmt/format.h>

#include <string>

namespace ffrf::test {

// `total_mass` [kg] is the hull's with the boom and cargo; `bem_keys` the lines of the [bem] section.
inline std::string barge_hull_scene(double total_mass, double pitch_radius_of_gyration, const std::string& bem_keys) {
  constexpr double boom_and_cargo_mass = 40.0 * 1.0 + 1.0;
  return fmt::format(R"([hull]
mass = {}
pitch_radius_of_gyration = {}
length = 80.0
width = 10.0
depth = 8.0
g1_above_keel = 5.0
g1_aft_of_mid_length = 0.0
[boom]
length = 40.0
angle = "60 deg"
root_x = 30.0
root_y = 3.0
youngs_modulus = 2.1e11
area = 0.32
second_moment = 0.9
mass_per_length = 1.0
elements = 1
[cargo]
mass = 1.0
length = 1.0
height = 1.0
hook_x = 0.0
hook_y = 0.5
[wire]
unstretched_length = 12.0
stiffness = 1.0e4
[mooring]
surge_stiffness = 1.0
[environment]
water_density = 1000.0
gravity = 9.81
[bem]
{}
)",
                     total_mass - boom_and_cargo_mass, pitch_radius_of_gyration, bem_keys);
}

}  // namespace ffrf::test
