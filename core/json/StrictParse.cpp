#include "core/json/StrictParse.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace grainbridge::core::json {

std::string pointerToken(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

namespace {

using nlohmann::json;

// SAX handler building the DOM while tracking the JSON pointer of the current value and the
// keys already seen in each open object.
class DuplicateCheckingBuilder {
 public:
  explicit DuplicateCheckingBuilder(Diagnostics& diagnostics) : diagnostics_(diagnostics) {}

  bool null() { return put(json(nullptr)); }
  bool boolean(bool v) { return put(json(v)); }
  bool number_integer(json::number_integer_t v) { return put(json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return put(json(v)); }
  bool number_float(json::number_float_t v, const json::string_t&) { return put(json(v)); }
  bool string(json::string_t& v) { return put(json(v)); }
  bool binary(json::binary_t& v) { return put(json(v)); }

  bool start_object(std::size_t) {
    json* obj = place(json::object());
    frames_.push_back({obj, {}, 0, {}});
    return true;
  }
  bool key(json::string_t& k) {
    Frame& f = frames_.back();
    f.currentKey = k;
    if (!f.seenKeys.insert(k).second) {
      diagnostics_.add(
          pointerOfFrame() + "/" + pointerToken(k),
          "key \"" + k +
              "\" is given more than once in this object (a plain JSON parse would silently keep only the last one)");
    }
    return true;
  }
  bool end_object() {
    frames_.pop_back();
    return true;
  }
  bool start_array(std::size_t) {
    json* arr = place(json::array());
    frames_.push_back({arr, {}, 0, {}});
    return true;
  }
  bool end_array() {
    frames_.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& ex) {
    // nlohmann's message already says "syntax error while parsing ... at line L, column C".
    std::string msg = ex.what();
    const auto pos = msg.find("] ");
    if (pos != std::string::npos) msg = msg.substr(pos + 2);
    const std::string where = locationOf(msg);
    // "parse error at line 4, column 36: syntax error ..." -> the location goes in `where`.
    const auto colon = msg.find(": ");
    if (!where.empty() && colon != std::string::npos) msg = msg.substr(colon + 2);
    diagnostics_.add(where, msg);
    syntaxError_ = true;
    return false;
  }

  json takeResult() { return std::move(root_); }
  [[nodiscard]] bool syntaxError() const { return syntaxError_; }

 private:
  struct Frame {
    json* value;
    std::string currentKey;
    std::size_t arrayIndex;
    std::set<std::string> seenKeys;
  };

  static std::string locationOf(const std::string& msg) {
    const auto pos = msg.find("at line ");
    if (pos == std::string::npos) return "";
    auto end = msg.find(':', pos);
    return msg.substr(pos + 3, end == std::string::npos ? std::string::npos : end - pos - 3);
  }

  std::string pointerOfFrame() const {
    std::string p;
    for (std::size_t i = 1; i < frames_.size(); ++i) {
      const Frame& parent = frames_[i - 1];
      if (parent.value->is_object())
        p += "/" + pointerToken(parent.currentKey);
      else
        p += "/" + std::to_string(parent.arrayIndex - 1);
    }
    return p;
  }

  json* place(json value) {
    if (frames_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Frame& f = frames_.back();
    if (f.value->is_object()) {
      json& slot = (*f.value)[f.currentKey];
      slot = std::move(value);
      return &slot;
    }
    f.value->push_back(std::move(value));
    ++f.arrayIndex;
    return &f.value->back();
  }
  bool put(json value) {
    place(std::move(value));
    return true;
  }

  Diagnostics& diagnostics_;
  json root_;
  std::vector<Frame> frames_;
  bool syntaxError_ = false;
};

}  // namespace

std::optional<nlohmann::json> parseStrict(const std::string& text, Diagnostics& diagnostics) {
  const std::size_t before = diagnostics.size();
  DuplicateCheckingBuilder builder(diagnostics);
  json::sax_parse(text, &builder, nlohmann::json::input_format_t::json, /*strict=*/true,
                  /*ignore_comments=*/false);
  if (builder.syntaxError() || diagnostics.size() != before) return std::nullopt;
  return builder.takeResult();
}

std::optional<nlohmann::json> parseFileStrict(const std::string& path, Diagnostics& diagnostics) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diagnostics.add("", "cannot read file '" + path + "': " + std::strerror(errno));
    return std::nullopt;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) {
    diagnostics.add("", "cannot read file '" + path + "': " + std::strerror(errno));
    return std::nullopt;
  }
  return parseStrict(buffer.str(), diagnostics);
}

}  // namespace grainbridge::core::json
