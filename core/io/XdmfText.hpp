#pragma once
// Small text helpers for the XDMF sidecars (particles.xmf, fields.xmf). XDMF is plain XML
// whose data items point into the HDF5 frames by relative path, so a moved results folder
// still opens in ParaView.
#include <cstdint>
#include <string>
#include <string_view>

namespace grainbridge::core::io {

// Escapes &, <, >, " and ' for use in element text and attribute values.
std::string xmlEscape(std::string_view text);

// Shortest text that reads back to the same double (frame times must match exactly).
std::string formatReal(double value);

// <DataItem Format="HDF" ...>file:/dataset</DataItem>. `dimensions` is the space-separated
// shape, slowest axis first; numberType is "Float" or "Int"; precision is bytes.
std::string xdmfHdfItem(const std::string& dimensions, std::string_view numberType, int precision,
                        const std::string& fileAndDataset);

// <Attribute Name=... AttributeType=... Center=...> with one HDF data item inside.
std::string xdmfAttribute(const std::string& name, std::string_view attributeType, std::string_view center,
                          const std::string& dataItem);

}  // namespace grainbridge::core::io
