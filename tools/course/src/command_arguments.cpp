#include "command_arguments.h"

#include <charconv>
#include <cmath>

namespace glass::course {

namespace {

std::optional<double> plainNumber(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<double> numberOrFraction(const std::string& text) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) return plainNumber(text);
  const auto top = plainNumber(std::string_view(text).substr(0, slash));
  const auto bottom = plainNumber(std::string_view(text).substr(slash + 1));
  if (!top || !bottom || *bottom == 0.0) return std::nullopt;
  return *top / *bottom;
}

}  // namespace

bool looksLikeNumber(const std::string& text) { return numberOrFraction(text).has_value(); }

double parseNumber(const std::string& text, const std::string& what) {
  const auto value = numberOrFraction(text);
  if (!value) throw UsageError(what + " expects a number (like 3, -0.5 or 2/3), not '" + text + "'");
  return *value;
}

long long parseInteger(const std::string& text, const std::string& what, long long min, long long max) {
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) {
    throw UsageError(what + " expects a whole number, not '" + text + "'");
  }
  if (value < min || value > max) {
    throw UsageError(what + " must lie in " + std::to_string(min) + ".." + std::to_string(max) + ", not " + text);
  }
  return value;
}

void parseSize(const std::string& text, int& width, int& height) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) throw UsageError(std::string("--size expects WIDTHxHEIGHT, like 800x600, not '") + text + "'");
  width = static_cast<int>(parseInteger(text.substr(0, x), "--size width", 1, 16384));
  height = static_cast<int>(parseInteger(text.substr(x + 1), "--size height", 1, 16384));
}

std::string ArgumentList::value(const std::string& option) {
  if (empty()) throw UsageError(option + " needs a value");
  return take();
}

std::vector<double> ArgumentList::numbers(const std::string& option, int count) {
  std::vector<double> values;
  for (int i = 0; i < count; ++i) {
    if (empty()) throw UsageError(option + " needs " + std::to_string(count) + " numbers");
    values.push_back(parseNumber(take(), option));
  }
  return values;
}

}  // namespace glass::course
