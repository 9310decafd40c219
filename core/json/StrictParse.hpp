#pragma once
// JSON parsing that refuses what a plain nlohmann::json::parse silently accepts: a key repeated
// within one object (parse keeps the last one, so a stage given twice would vanish). Syntax
// errors are reported with line and column.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/json/Diagnostics.hpp"

namespace grainbridge::core::json {

// Parses `text`. On success returns the document; otherwise adds every repeated key (by JSON
// pointer) or the syntax error (by line and column) to `diagnostics` and returns nullopt.
std::optional<nlohmann::json> parseStrict(const std::string& text, Diagnostics& diagnostics);

// Reads and parses a file; an unreadable file is a diagnostic naming the path and the reason.
std::optional<nlohmann::json> parseFileStrict(const std::string& path, Diagnostics& diagnostics);

// Escapes one reference token for a JSON pointer (RFC 6901: "~" -> "~0", "/" -> "~1").
std::string pointerToken(const std::string& key);

}  // namespace grainbridge::core::json
