// Clouds of points in text files, as homework 3 gives them: one point `x y z` per line, the
// numbers separated by spaces, tabs or commas; `#` starts a comment; an optional first line with
// just the number of points, or with three column names (`x,y,z`). Lines may end in LF, CR LF or
// CR, and a UTF-8 byte order mark is skipped. Bad lines are errors with their line and column; a
// cloud that is small or not in (or near) the unit cube gets a warning, since the homework's
// clouds are.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace glass::course {

struct CloudMessage {
  int line = 0;    // 1-based; 0 for the whole file
  int column = 0;  // 1-based; 0 for the whole line
  std::string message;
};

struct PointCloud {
  std::vector<glm::dvec3> points;
  std::vector<CloudMessage> errors;    // the cloud is unusable when there is one
  std::vector<CloudMessage> warnings;
  bool ok() const { return errors.empty(); }
};

// Fewer points than this get a warning: the fit then has too little to go on.
inline constexpr std::size_t kFewCloudPoints = 500;

PointCloud parsePointCloud(std::string_view text);
PointCloud loadPointCloud(const std::string& path);  // an unreadable file is one error at line 0

// "file:line:col: error: message" and "...: warning: ..." lines.
std::string formatCloudMessages(const PointCloud& cloud, std::string_view fileName);

// One "x y z" line per point with 17 significant digits, after a comment line `header`.
std::string formatPointCloud(const std::vector<glm::dvec3>& points, std::string_view header);

}  // namespace glass::course
