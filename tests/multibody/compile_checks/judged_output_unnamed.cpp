// Must not compile: a row of the table marked judged (the luffing wires' tension) without its
// OutputChannel enumerator is caught by the same check multibody/error_metrics.cpp makes.
#include "multibody/error_metrics.hpp"
#include "multibody/output_channel_table.hpp"

constexpr auto with_a_new_judged_row = [] {
  auto table = ffrf::multibody::channel_table::channels;
  for (auto& row : table) {
    if (row.name == "luffing_tension") row.judged = true;
  }
  return table;
}();
static_assert(ffrf::multibody::channel_table::judged_rows_named(with_a_new_judged_row, ffrf::multibody::judged_names),
              "judged rows and enumerators disagree");
