// Compiles: the judged outputs' enumerators name exactly the table's judged rows.
#include "multibody/error_metrics.hpp"
#include "multibody/output_channel_table.hpp"

static_assert(ffrf::multibody::channel_table::judged_rows_named(ffrf::multibody::channel_table::channels,
                                                               ffrf::multibody::judged_names),
              "judged rows and enumerators disagree");
