#include "core/json/Diagnostics.hpp"

#include <algorithm>

namespace grainbridge::core::json {

std::string Diagnostics::format(const std::string& source) const {
  std::string out;
  for (const auto& d : items_) {
    out += source;
    out += ": ";
    out += d.where.empty() ? std::string("(document root)") : d.where;
    out += ": ";
    out += d.message;
    out += '\n';
  }
  if (!out.empty()) out.pop_back();
  return out;
}

namespace {
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1);
  std::vector<std::size_t> cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t subst = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}
}  // namespace

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = editDistance(word, c);
    if (d < bestDistance) {
      bestDistance = d;
      best = c;
    }
  }
  return best;
}

std::string describeFound(const std::string& dumpedValue, const char* typeName) {
  std::string shown = dumpedValue.size() > 60 ? dumpedValue.substr(0, 57) + "..." : dumpedValue;
  return std::string(typeName) + " " + shown;
}

}  // namespace grainbridge::core::json
