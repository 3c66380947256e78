// Reading the course commands' arguments: numbers (fractions like 2/3 allowed, as the exam
// writes them), sizes WxH, and options with their values. A problem is thrown as UsageError,
// which the commands turn into a message and exit status 2.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace glass::course {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "3", "-0.5", "2/3", "1e-3". Throws UsageError naming `what`.
double parseNumber(const std::string& text, const std::string& what);
long long parseInteger(const std::string& text, const std::string& what, long long min, long long max);
// "800x600".
void parseSize(const std::string& text, int& width, int& height);

// The arguments left to read, front to back.
class ArgumentList {
 public:
  explicit ArgumentList(std::vector<std::string> args) : args_(std::move(args)) {}

  bool empty() const { return next_ >= args_.size(); }
  const std::string& peek() const { return args_[next_]; }
  std::string take() { return args_[next_++]; }

  // The value after an option: `--grid 32`. Throws when it is missing.
  std::string value(const std::string& option);
  double number(const std::string& option) { return parseNumber(value(option), option); }
  std::vector<double> numbers(const std::string& option, int count);

 private:
  std::vector<std::string> args_;
  std::size_t next_ = 0;
};

// True for a word that is a number (so "-90" is an angle, not an option).
bool looksLikeNumber(const std::string& text);

}  // namespace glass::course
