// Evaluator state (glMap1, glMap2, the grid). Placeholder until the evaluator stage lands:
// replaced by the evaluator stage.
#pragma once

namespace glass::gl {

struct EvaluatorState {};

}  // namespace glass::gl
