#pragma once
// A new HDF5 file created with the settings that make equal content give equal bytes
// (DESIGN.md "Data contracts"): no object timestamps on groups or datasets, pinned file
// format version bounds, explicit little-endian file types, and plain contiguous datasets
// (deflate only when asked). Paths are absolute inside the file ("/contacts/i"). Every
// failure throws grainbridge::Error naming the file and the object.
#include <hdf5.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "core/io/H5Handle.hpp"

namespace grainbridge::core::io {

class H5OutputFile {
 public:
  // Creates or truncates `path`. deflateLevel 0 stores datasets contiguous; 1..9 chunks
  // and deflates them (still deterministic, but slower to write).
  explicit H5OutputFile(std::filesystem::path path, int deflateLevel = 0);

  void createGroup(const std::string& path);

  // `dims` is the dataset shape; its product must equal data.size(). Zero-sized
  // dimensions are allowed (an empty contact list is a valid [0, 3] dataset).
  void writeDataset(const std::string& path, std::span<const double> data, const std::vector<hsize_t>& dims);
  void writeDataset(const std::string& path, std::span<const std::int64_t> data, const std::vector<hsize_t>& dims);
  void writeDataset(const std::string& path, std::span<const std::int32_t> data, const std::vector<hsize_t>& dims);
  // Opaque bytes (another program's file carried inside ours, e.g. a LAMMPS restart), 1-D.
  void writeBytes(const std::string& path, std::span<const std::uint8_t> data);
  // Shapes [n] and [n, 3].
  void writeDataset(const std::string& path, const std::vector<double>& data);
  void writeDataset(const std::string& path, const std::vector<std::int64_t>& data);
  void writeDataset(const std::string& path, const std::vector<std::int32_t>& data);
  void writeDataset(const std::string& path, const std::vector<Vec3>& data);

  // Attributes on the object at `objectPath` ("/" for the file root).
  void writeAttribute(const std::string& objectPath, const std::string& name, double value);
  void writeAttribute(const std::string& objectPath, const std::string& name, std::int64_t value);
  void writeAttribute(const std::string& objectPath, const std::string& name, std::int32_t value);
  void writeAttribute(const std::string& objectPath, const std::string& name, const std::string& value);
  void writeAttribute(const std::string& objectPath, const std::string& name, const std::array<double, 3>& value);
  void writeAttribute(const std::string& objectPath, const std::string& name, const std::array<std::int32_t, 3>& value);

  // Flushes and closes; throws if HDF5 reports a failure. The destructor closes silently.
  void close();

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  void writeRaw(const std::string& path, hid_t memType, hid_t fileType, const void* data, std::size_t count,
                const std::vector<hsize_t>& dims);
  void writeAttributeRaw(const std::string& objectPath, const std::string& name, hid_t memType, hid_t fileType,
                         const void* data, hsize_t count);
  [[noreturn]] void fail(const std::string& object, const std::string& what) const;

  std::filesystem::path path_;
  int deflateLevel_;
  H5Handle file_;
};

// Views a vector of Vec3 as the [n, 3] doubles it is laid out as (Eigen's Vector3d has
// no padding), without a copy; an empty vector gives an empty span.
std::span<const double> flatView(const std::vector<Vec3>& v);
std::span<double> flatView(std::vector<Vec3>& v);

}  // namespace grainbridge::core::io
