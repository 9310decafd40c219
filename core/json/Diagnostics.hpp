#pragma once
// Collects every problem found in one input (a config, a data file) so all of them are reported
// together, each with where it is (a JSON pointer such as /stages/bed/params/dt, or
// file:line:column for a syntax error), what was expected and what was found.
#include <string>
#include <vector>

#include "core/Error.hpp"

namespace grainbridge::core::json {

struct Diagnostic {
  std::string where;    // JSON pointer ("" = document root) or "line L, column C"
  std::string message;  // "expected ..., found ..." plus a hint where one helps
};

class Diagnostics {
 public:
  void add(std::string where, std::string message) { items_.push_back({std::move(where), std::move(message)}); }
  [[nodiscard]] bool empty() const { return items_.empty(); }
  [[nodiscard]] std::size_t size() const { return items_.size(); }
  [[nodiscard]] const std::vector<Diagnostic>& items() const { return items_; }
  // One line per problem: "<source>: <where>: <message>".
  [[nodiscard]] std::string format(const std::string& source) const;

 private:
  std::vector<Diagnostic> items_;
};

// Thrown when an input has one or more problems; the CLI prints format() and exits 2.
class InputError : public Error {
 public:
  InputError(std::string source, Diagnostics diagnostics)
      : Error(diagnostics.format(source)), source_(std::move(source)), diagnostics_(std::move(diagnostics)) {}
  [[nodiscard]] const Diagnostics& diagnostics() const { return diagnostics_; }
  [[nodiscard]] const std::string& source() const { return source_; }

 private:
  std::string source_;
  Diagnostics diagnostics_;
};

// "did you mean" helper: the candidate closest to `word` by edit distance, or "" if none is
// close enough to be a plausible typo.
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

// Short human description of a JSON value's type for "found ..." messages.
std::string describeFound(const std::string& dumpedValue, const char* typeName);

}  // namespace grainbridge::core::json
