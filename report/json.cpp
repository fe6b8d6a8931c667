// JSON text of a report document (see json.hpp).
#include "report/json.hpp"

#include <nlohmann/json.hpp>

namespace ffrf::report {

std::string json_text(const Json& document) {
  // Invalid UTF-8 (never expected: every text is ours or a solver's ASCII message) is replaced.
  return document.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace ffrf::report
