#include "core/io/XdmfText.hpp"

#include <array>
#include <charconv>

namespace grainbridge::core::io {

std::string xmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string formatReal(double value) {
  std::array<char, 64> buf{};
  const auto result = std::to_chars(buf.data(), buf.data() + buf.size(), value);
  return {buf.data(), result.ptr};
}

std::string xdmfHdfItem(const std::string& dimensions, std::string_view numberType, int precision,
                        const std::string& fileAndDataset) {
  return "<DataItem Dimensions=\"" + dimensions + "\" NumberType=\"" + std::string(numberType) + "\" Precision=\"" +
         std::to_string(precision) + "\" Format=\"HDF\">" + xmlEscape(fileAndDataset) + "</DataItem>";
}

std::string xdmfAttribute(const std::string& name, std::string_view attributeType, std::string_view center,
                          const std::string& dataItem) {
  return "<Attribute Name=\"" + xmlEscape(name) + "\" AttributeType=\"" + std::string(attributeType) + "\" Center=\"" +
         std::string(center) + "\">" + dataItem + "</Attribute>";
}

}  // namespace grainbridge::core::io
