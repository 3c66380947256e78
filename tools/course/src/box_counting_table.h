// The box-counting table `glass ifs` and `glass ifs3d` print: the count at each level, the levels
// fitted, and the slope.
#pragma once

#include <cstdio>
#include <ostream>

#include "glass/geometry/ifs_dimension.h"

namespace glass::course {

inline void printBoxCountingTable(const geometry::BoxCountingEstimate& box, std::ostream& out) {
  out << "    level  box side     boxes N\n";
  for (const geometry::BoxCount& count : box.counts) {
    char text[128];
    std::snprintf(text, sizeof text, "    %5d  %-11.4g  %8zu%s\n", count.level, count.boxSide, count.boxes,
                  count.level >= box.firstFittedLevel && count.level <= box.lastFittedLevel ? "  fitted" : "");
    out << text;
  }
  char text[160];
  std::snprintf(text, sizeof text, "  d is about %.3f: the slope of log2 N against the level, levels %d to %d (least squares)\n",
                box.dimension, box.firstFittedLevel, box.lastFittedLevel);
  out << text;
}

}  // namespace glass::course
