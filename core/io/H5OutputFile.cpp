#include "core/io/H5OutputFile.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "core/Error.hpp"
#include "core/io/H5ErrorSilencer.hpp"

namespace grainbridge::core::io {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles to be written as [n, 3]");

std::span<const double> flatView(const std::vector<Vec3>& v) {
  if (v.empty()) return {};
  return {v.front().data(), 3 * v.size()};
}

std::span<double> flatView(std::vector<Vec3>& v) {
  if (v.empty()) return {};
  return {v.front().data(), 3 * v.size()};
}

namespace {
// Object creation property list without timestamps: the one setting that otherwise makes
// two writes of the same frame differ in bytes.
H5Handle untimedCreationList(hid_t cls) {
  H5Handle plist(H5Pcreate(cls), H5Pclose);
  if (!plist || H5Pset_obj_track_times(plist.get(), false) < 0) return {};
  return plist;
}
}  // namespace

H5OutputFile::H5OutputFile(std::filesystem::path path, int deflateLevel)
    : path_(std::move(path)), deflateLevel_(std::clamp(deflateLevel, 0, 9)) {
  const H5ErrorSilencer silence;
  // The root group is created with the file, so its timestamp setting lives on the fcpl.
  H5Handle fcpl = untimedCreationList(H5P_FILE_CREATE);
  H5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  // Pinning the format bounds keeps the bytes stable across HDF5 upgrades and the files
  // readable by any HDF5 >= 1.8 (ParaView, h5py, MATLAB).
  if (!fcpl || !fapl || H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_EARLIEST, H5F_LIBVER_V18) < 0) {
    fail("/", "cannot set up file creation properties");
  }
  file_ = H5Handle(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get()), H5Fclose);
  if (!file_) fail("/", "cannot create the file (is the folder writable?)");
}

void H5OutputFile::fail(const std::string& object, const std::string& what) const {
  throw Error("file '" + path_.string() + "': '" + object + "': " + what);
}

void H5OutputFile::createGroup(const std::string& path) {
  const H5ErrorSilencer silence;
  H5Handle gcpl = untimedCreationList(H5P_GROUP_CREATE);
  H5Handle group(H5Gcreate2(file_.get(), path.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
  if (!gcpl || !group) fail(path, "cannot create group");
}

void H5OutputFile::writeRaw(const std::string& path, hid_t memType, hid_t fileType, const void* data, std::size_t count,
                            const std::vector<hsize_t>& dims) {
  const H5ErrorSilencer silence;
  const hsize_t expected = std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
  GB_ASSERT(expected == count, "dataset '" + path + "': data size does not match its shape");
  H5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  H5Handle dcpl = untimedCreationList(H5P_DATASET_CREATE);
  if (!space || !dcpl) fail(path, "cannot set up dataset");
  // Chunks must be non-empty, so empty datasets stay contiguous even when deflating.
  if (deflateLevel_ > 0 && count > 0) {
    std::vector<hsize_t> chunk = dims;
    // Chunk along the first axis only: about 64 Ki elements per chunk.
    const hsize_t rowSize = count / dims.front();
    chunk.front() = std::clamp<hsize_t>(65536 / std::max<hsize_t>(rowSize, 1), 1, dims.front());
    if (H5Pset_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data()) < 0 ||
        H5Pset_deflate(dcpl.get(), static_cast<unsigned>(deflateLevel_)) < 0) {
      fail(path, "cannot set up deflate compression");
    }
  }
  H5Handle dset(H5Dcreate2(file_.get(), path.c_str(), fileType, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                H5Dclose);
  if (!dset) fail(path, "cannot create dataset");
  if (count > 0 && H5Dwrite(dset.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) {
    fail(path, "cannot write dataset (disk full?)");
  }
}

void H5OutputFile::writeDataset(const std::string& path, std::span<const double> data,
                                const std::vector<hsize_t>& dims) {
  writeRaw(path, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, data.data(), data.size(), dims);
}
void H5OutputFile::writeDataset(const std::string& path, std::span<const std::int64_t> data,
                                const std::vector<hsize_t>& dims) {
  writeRaw(path, H5T_NATIVE_INT64, H5T_STD_I64LE, data.data(), data.size(), dims);
}
void H5OutputFile::writeDataset(const std::string& path, std::span<const std::int32_t> data,
                                const std::vector<hsize_t>& dims) {
  writeRaw(path, H5T_NATIVE_INT32, H5T_STD_I32LE, data.data(), data.size(), dims);
}
void H5OutputFile::writeBytes(const std::string& path, std::span<const std::uint8_t> data) {
  writeRaw(path, H5T_NATIVE_UINT8, H5T_STD_U8LE, data.data(), data.size(), {data.size()});
}
void H5OutputFile::writeDataset(const std::string& path, const std::vector<double>& data) {
  writeDataset(path, std::span<const double>(data), {data.size()});
}
void H5OutputFile::writeDataset(const std::string& path, const std::vector<std::int64_t>& data) {
  writeDataset(path, std::span<const std::int64_t>(data), {data.size()});
}
void H5OutputFile::writeDataset(const std::string& path, const std::vector<std::int32_t>& data) {
  writeDataset(path, std::span<const std::int32_t>(data), {data.size()});
}
void H5OutputFile::writeDataset(const std::string& path, const std::vector<Vec3>& data) {
  writeDataset(path, flatView(data), {data.size(), 3});
}

void H5OutputFile::writeAttributeRaw(const std::string& objectPath, const std::string& name, hid_t memType,
                                     hid_t fileType, const void* data, hsize_t count) {
  const H5ErrorSilencer silence;
  // A single value is a scalar attribute; a triple is a 1-D array of 3.
  H5Handle space(count == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr), H5Sclose);
  if (!space) fail(objectPath, "cannot set up attribute '" + name + "'");
  H5Handle attr(H5Acreate_by_name(file_.get(), objectPath.c_str(), name.c_str(), fileType, space.get(), H5P_DEFAULT,
                                  H5P_DEFAULT, H5P_DEFAULT),
                H5Aclose);
  if (!attr || H5Awrite(attr.get(), memType, data) < 0) fail(objectPath, "cannot write attribute '" + name + "'");
}

void H5OutputFile::writeAttribute(const std::string& objectPath, const std::string& name, double value) {
  writeAttributeRaw(objectPath, name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, &value, 1);
}
void H5OutputFile::writeAttribute(const std::string& objectPath, const std::string& name, std::int64_t value) {
  writeAttributeRaw(objectPath, name, H5T_NATIVE_INT64, H5T_STD_I64LE, &value, 1);
}
void H5OutputFile::writeAttribute(const std::string& objectPath, const std::string& name, std::int32_t value) {
  writeAttributeRaw(objectPath, name, H5T_NATIVE_INT32, H5T_STD_I32LE, &value, 1);
}
void H5OutputFile::writeAttribute(const std::string& objectPath, const std::string& name,
                                  const std::array<double, 3>& value) {
  writeAttributeRaw(objectPath, name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, value.data(), 3);
}
void H5OutputFile::writeAttribute(const std::string& objectPath, const std::string& name,
                                  const std::array<std::int32_t, 3>& value) {
  writeAttributeRaw(objectPath, name, H5T_NATIVE_INT32, H5T_STD_I32LE, value.data(), 3);
}
void H5OutputFile::writeAttribute(const std::string& objectPath, const std::string& name, const std::string& value) {
  const H5ErrorSilencer silence;
  // Fixed-length, null-terminated ASCII: no global heap object, so the bytes depend on the
  // text only, and every HDF5 reader (h5dump, h5py, ParaView) shows it as a string.
  H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (!type || H5Tset_size(type.get(), value.size() + 1) < 0 || H5Tset_strpad(type.get(), H5T_STR_NULLTERM) < 0) {
    fail(objectPath, "cannot set up string attribute '" + name + "'");
  }
  writeAttributeRaw(objectPath, name, type.get(), type.get(), value.c_str(), 1);
}

void H5OutputFile::close() {
  const H5ErrorSilencer silence;
  if (file_ && !file_.close()) fail("/", "cannot flush and close the file (disk full?)");
}

}  // namespace grainbridge::core::io
