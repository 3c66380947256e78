#include "glass/course/point_cloud.h"

#include <charconv>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "glass/geometry/byte_order_mark.h"

namespace glass::course {

namespace {

struct Field {
  std::string_view text;
  int column = 0;
};

// The fields of a line: separated by spaces, tabs and commas, up to a `#`.
std::vector<Field> splitFields(std::string_view line) {
  std::vector<Field> fields;
  std::size_t i = 0;
  auto separator = [](char c) { return c == ' ' || c == '\t' || c == ','; };
  while (i < line.size() && line[i] != '#') {
    if (separator(line[i])) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < line.size() && !separator(line[end]) && line[end] != '#') ++end;
    fields.push_back({line.substr(i, end - i), static_cast<int>(i) + 1});
    i = end;
  }
  return fields;
}

std::optional<double> toNumber(std::string_view text) {
  double value = 0.0;
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

// A line of column names, as spreadsheets and other tools write before their points ("x y z",
// "X,Y,Z"): every field starts with a letter.
bool isColumnNames(const std::vector<Field>& fields) {
  return std::all_of(fields.begin(), fields.end(), [](const Field& f) {
    const char c = f.text.front();
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
  });
}

}  // namespace

PointCloud parsePointCloud(std::string_view text) {
  PointCloud cloud;
  std::optional<long long> declared;
  int declaredLine = 0;
  bool sawData = false;
  int lineNumber = 0;
  std::size_t start = geometry::byteOrderMarkLength(text);
  while (start <= text.size()) {
    // Lines end in LF, CR LF or a lone CR (older Mac files).
    std::size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) end = text.size();
    std::size_t next = end + 1;
    if (end < text.size() && text[end] == '\r' && next < text.size() && text[next] == '\n') ++next;
    const std::vector<Field> fields = splitFields(text.substr(start, end - start));
    ++lineNumber;
    if (!fields.empty()) {
      if (!sawData && fields.size() == 3 && isColumnNames(fields)) {
        // Column names before the points: not a point, and not data.
      } else if (!sawData && fields.size() == 1) {
        // The count line some course files begin with.
        long long count = 0;
        const auto [ptr, ec] = std::from_chars(fields[0].text.data(), fields[0].text.data() + fields[0].text.size(), count);
        if (ec == std::errc() && ptr == fields[0].text.data() + fields[0].text.size() && count >= 0) {
          declared = count;
          declaredLine = lineNumber;
        } else {
          cloud.errors.push_back({lineNumber, fields[0].column,
                                  "expected a point 'x y z' or the number of points, found '" + std::string(fields[0].text) + "'"});
        }
      } else if (fields.size() != 3) {
        cloud.errors.push_back({lineNumber, fields.size() > 3 ? fields[3].column : fields[0].column,
                                "a point is three numbers x y z; this line has " + std::to_string(fields.size())});
      } else {
        glm::dvec3 p;
        bool good = true;
        for (int k = 0; k < 3 && good; ++k) {
          auto v = toNumber(fields[static_cast<std::size_t>(k)].text);
          if (!v) {
            cloud.errors.push_back({lineNumber, fields[static_cast<std::size_t>(k)].column,
                                    "expected a finite number, found '" + std::string(fields[static_cast<std::size_t>(k)].text) + "'"});
            good = false;
          } else {
            p[k] = *v;
          }
        }
        if (good) cloud.points.push_back(p);
      }
      sawData = true;
      if (cloud.errors.size() >= 20) {
        cloud.errors.push_back({lineNumber, 0, "too many errors; stopping"});
        return cloud;
      }
    }
    if (end == text.size()) break;
    start = next;
  }
  if (!cloud.ok()) return cloud;
  if (cloud.points.empty()) {
    cloud.errors.push_back({0, 0, "the file has no points"});
    return cloud;
  }
  if (declared && static_cast<std::size_t>(*declared) != cloud.points.size()) {
    cloud.warnings.push_back({declaredLine, 1, "the first line says " + std::to_string(*declared) + " points, but the file has " +
                                                   std::to_string(cloud.points.size())});
  }
  if (cloud.points.size() < kFewCloudPoints) {
    cloud.warnings.push_back({0, 0, "only " + std::to_string(cloud.points.size()) + " points; a fit needs a few thousand to be reliable"});
  }
  glm::dvec3 lo = cloud.points[0], hi = lo;
  for (const glm::dvec3& p : cloud.points) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  constexpr double kMargin = 0.1;  // "near" the unit cube
  if (lo.x < -kMargin || lo.y < -kMargin || lo.z < -kMargin || hi.x > 1 + kMargin || hi.y > 1 + kMargin || hi.z > 1 + kMargin) {
    char text[200];
    std::snprintf(text, sizeof text, "the points are not in the unit cube: they span [%.3g, %.3g] x [%.3g, %.3g] x [%.3g, %.3g]",
                  lo.x, hi.x, lo.y, hi.y, lo.z, hi.z);
    cloud.warnings.push_back({0, 0, text});
  }
  return cloud;
}

PointCloud loadPointCloud(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    PointCloud cloud;
    cloud.errors.push_back({0, 0, "cannot read the file"});
    return cloud;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parsePointCloud(text.str());
}

std::string formatCloudMessages(const PointCloud& cloud, std::string_view fileName) {
  std::string out;
  auto add = [&](const CloudMessage& m, const char* kind) {
    out += fileName;
    if (m.line > 0) {
      out += ':';
      out += std::to_string(m.line);
      if (m.column > 0) {
        out += ':';
        out += std::to_string(m.column);
      }
    }
    out += ": ";
    out += kind;
    out += ": ";
    out += m.message;
    out += '\n';
  };
  for (const CloudMessage& m : cloud.errors) add(m, "error");
  for (const CloudMessage& m : cloud.warnings) add(m, "warning");
  return out;
}

std::string formatPointCloud(const std::vector<glm::dvec3>& points, std::string_view header) {
  std::string out = "# ";
  out += header;
  out += '\n';
  char line[96];
  for (const glm::dvec3& p : points) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
    out += line;
  }
  return out;
}

}  // namespace glass::course
