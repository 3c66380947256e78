// The guide's extra question for homework 1: "check if your code draws the same lines as the
// standard OpenGL functions". Random segments are drawn with GL_LINES into the current GL context
// and read back, and the squares each teaching algorithm chooses are compared with GL's.
//
// GL's rule leaves out the last square of a segment (the diamond-exit rule; it keeps line strips
// from drawing shared vertices twice), so GL's squares are compared with the algorithm's without
// that last square. This file uses only GL 1.1 calls, so that the same code measures glass (in
// `glass lines --agreement`) and Mesa (in the lines_agreement_mesa program).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "glass/course/line_lab.h"

namespace glass::course {

struct AgreementResult {
  LineAlgorithm algorithm = LineAlgorithm::Float;
  std::size_t equal = 0;  // segments whose squares equal GL's
  std::size_t lines = 0;
  std::optional<GridSegment> firstDifference;
};

// Needs a current GL context of at least gridSize x gridSize pixels; leaves the projection set to
// the grid. One pixel is one square: the segment runs between pixel centres.
std::vector<AgreementResult> measureGlAgreement(std::size_t lines, int gridSize, std::uint64_t seed);

// "float      99.1% of 10000 ..." lines, naming the GL that drew them.
std::string formatAgreement(const std::vector<AgreementResult>& results, const std::string& glName,
                            int gridSize);

}  // namespace glass::course
