#pragma once
// An HDF5 file opened read-only, with typed reads that check the stored shape. Every failure
// throws grainbridge::Error naming the file and the dataset or attribute, so a user with a
// damaged or foreign file learns which one and what was expected of it.
#include <hdf5.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "core/Types.hpp"
#include "core/io/H5Handle.hpp"

namespace grainbridge::core::io {

class H5InputFile {
 public:
  // Throws if the file does not exist or is not HDF5.
  explicit H5InputFile(std::filesystem::path path);

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  // True if every component of the absolute path `objectPath` exists.
  [[nodiscard]] bool exists(const std::string& objectPath) const;
  // Dataset shape; throws if the dataset is missing.
  [[nodiscard]] std::vector<hsize_t> shape(const std::string& dataset) const;

  // Reads a dataset whose shape must equal `expectedShape`; a std::nullopt entry accepts
  // any extent on that axis (used to discover N from the first array).
  using Shape = std::vector<std::optional<hsize_t>>;
  [[nodiscard]] std::vector<double> readDoubles(const std::string& dataset, const Shape& expectedShape) const;
  [[nodiscard]] std::vector<std::int64_t> readInt64s(const std::string& dataset, const Shape& expectedShape) const;
  [[nodiscard]] std::vector<std::int32_t> readInt32s(const std::string& dataset, const Shape& expectedShape) const;
  // A 1-D dataset of opaque bytes (H5OutputFile::writeBytes).
  [[nodiscard]] std::vector<std::uint8_t> readBytes(const std::string& dataset) const;
  // Shape `leading` + [3], returned as one Vec3 per leading element.
  [[nodiscard]] std::vector<Vec3> readVec3s(const std::string& dataset, Shape leading) const;

  [[nodiscard]] bool hasAttribute(const std::string& objectPath, const std::string& name) const;
  [[nodiscard]] double readDoubleAttribute(const std::string& objectPath, const std::string& name) const;
  [[nodiscard]] std::int64_t readIntAttribute(const std::string& objectPath, const std::string& name) const;
  [[nodiscard]] std::string readStringAttribute(const std::string& objectPath, const std::string& name) const;
  [[nodiscard]] std::array<double, 3> readDouble3Attribute(const std::string& objectPath,
                                                           const std::string& name) const;
  [[nodiscard]] std::array<std::int64_t, 3> readInt3Attribute(const std::string& objectPath,
                                                              const std::string& name) const;

  // Names of the direct children of a group, in HDF5's name order.
  [[nodiscard]] std::vector<std::string> children(const std::string& group) const;

  // "file '<path>': <kind> '<object>': <what>" — the one message format readers use.
  [[nodiscard]] Error error(const std::string& kind, const std::string& object, const std::string& what) const;

 private:
  // Opens `dataset`, checks its type class and shape, and returns it with its element count.
  H5Handle openChecked(const std::string& dataset, const Shape& expectedShape, H5T_class_t cls,
                       std::size_t& count) const;
  void readInto(const std::string& dataset, const H5Handle& dset, hid_t memType, void* out, std::size_t count) const;
  H5Handle openAttribute(const std::string& objectPath, const std::string& name) const;
  void readNumericAttribute(const std::string& objectPath, const std::string& name, H5T_class_t cls, hid_t memType,
                            void* out, hsize_t count) const;

  std::filesystem::path path_;
  H5Handle file_;
};

}  // namespace grainbridge::core::io
