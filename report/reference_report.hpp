// The converged reference (study/reference.hpp) in the reports of compare, sweep and recommend:
// its label, the sentence that says whether it converged, its level table (Markdown and text) and
// its JSON object.
#pragma once

#include <string>

#include "report/json.hpp"
#include "study/reference.hpp"

namespace ffrf::report {

// "reference (nodal N=32, rtol 1e-08)"
std::string reference_label(const study::ConvergedReference& reference);
// One sentence: converged or not, at which level, against which bound.
std::string reference_verdict(const study::ConvergedReference& reference);
// The level table (elements, rtol, change, steps, wall time) as Markdown and as plain text.
std::string reference_levels_markdown(const study::ConvergedReference& reference);
std::string reference_levels_text(const study::ConvergedReference& reference);
// {model, relative_tolerance, converged, bound, window_start_s, levels: [...]}
Json reference_json(const study::ConvergedReference& reference);

}  // namespace ffrf::report
