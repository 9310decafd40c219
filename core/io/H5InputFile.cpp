#include "core/io/H5InputFile.hpp"

#include <system_error>

#include "core/io/H5ErrorSilencer.hpp"
#include "core/io/H5OutputFile.hpp"

namespace grainbridge::core::io {

namespace {
std::string shapeText(const std::vector<hsize_t>& dims) {
  std::string s = "[";
  for (std::size_t d = 0; d < dims.size(); ++d) s += (d ? ", " : "") + std::to_string(dims[d]);
  return s + "]";
}

std::string shapeText(const H5InputFile::Shape& dims) {
  std::string s = "[";
  for (std::size_t d = 0; d < dims.size(); ++d) s += (d ? ", " : "") + (dims[d] ? std::to_string(*dims[d]) : "any");
  return s + "]";
}

const char* className(H5T_class_t cls) {
  switch (cls) {
    case H5T_FLOAT:
      return "floating point";
    case H5T_INTEGER:
      return "integer";
    case H5T_STRING:
      return "string";
    default:
      return "other";
  }
}
}  // namespace

H5InputFile::H5InputFile(std::filesystem::path path) : path_(std::move(path)) {
  const H5ErrorSilencer silence;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path_, ec)) {
    throw Error("file '" + path_.string() + "': does not exist or is not a regular file");
  }
  if (H5Fis_hdf5(path_.c_str()) <= 0) throw Error("file '" + path_.string() + "': is not an HDF5 file");
  file_ = H5Handle(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file_) throw Error("file '" + path_.string() + "': cannot be opened by HDF5 (damaged?)");
}

Error H5InputFile::error(const std::string& kind, const std::string& object, const std::string& what) const {
  return Error("file '" + path_.string() + "': " + kind + " '" + object + "': " + what);
}

bool H5InputFile::exists(const std::string& objectPath) const {
  const H5ErrorSilencer silence;
  if (objectPath == "/") return true;
  // H5Lexists fails (rather than returning false) when an intermediate group is missing,
  // so each prefix is checked in turn.
  std::size_t pos = 0;
  while (pos != std::string::npos) {
    pos = objectPath.find('/', pos + 1);
    const std::string prefix = objectPath.substr(0, pos);
    if (H5Lexists(file_.get(), prefix.c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return true;
}

std::vector<std::string> H5InputFile::children(const std::string& group) const {
  const H5ErrorSilencer silence;
  if (!exists(group)) throw error("group", group, "is missing");
  H5Handle g(H5Gopen2(file_.get(), group.c_str(), H5P_DEFAULT), H5Gclose);
  H5G_info_t info{};
  if (!g || H5Gget_info(g.get(), &info) < 0) throw error("group", group, "cannot be opened as a group");
  std::vector<std::string> names;
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    const ssize_t len = H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
    if (len < 0) throw error("group", group, "cannot list its members");
    std::string name(static_cast<std::size_t>(len) + 1, '\0');
    H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size(), H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(len));
    names.push_back(std::move(name));
  }
  return names;
}

std::vector<hsize_t> H5InputFile::shape(const std::string& dataset) const {
  const H5ErrorSilencer silence;
  if (!exists(dataset)) throw error("dataset", dataset, "is missing");
  H5Handle dset(H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dset) throw error("dataset", dataset, "cannot be opened as a dataset");
  H5Handle space(H5Dget_space(dset.get()), H5Sclose);
  const int rank = space ? H5Sget_simple_extent_ndims(space.get()) : -1;
  if (rank < 0) throw error("dataset", dataset, "has an unreadable shape");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0) H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

H5Handle H5InputFile::openChecked(const std::string& dataset, const Shape& expectedShape, H5T_class_t cls,
                                  std::size_t& count) const {
  const std::vector<hsize_t> dims = shape(dataset);
  bool match = dims.size() == expectedShape.size();
  for (std::size_t d = 0; match && d < dims.size(); ++d) {
    if (expectedShape[d] && *expectedShape[d] != dims[d]) match = false;
  }
  if (!match) {
    throw error("dataset", dataset, "expected shape " + shapeText(expectedShape) + ", found " + shapeText(dims));
  }
  const H5ErrorSilencer silence;
  H5Handle dset(H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT), H5Dclose);
  H5Handle type(dset ? H5Dget_type(dset.get()) : H5I_INVALID_HID, H5Tclose);
  const H5T_class_t found = type ? H5Tget_class(type.get()) : H5T_NO_CLASS;
  if (found != cls) {
    throw error("dataset", dataset, std::string("expected ") + className(cls) + " values, found " + className(found));
  }
  count = 1;
  for (const hsize_t d : dims) count *= static_cast<std::size_t>(d);
  return dset;
}

void H5InputFile::readInto(const std::string& dataset, const H5Handle& dset, hid_t memType, void* out,
                           std::size_t count) const {
  const H5ErrorSilencer silence;
  // HDF5 converts the stored byte order and width to the native type (or fails on overflow).
  if (count > 0 && H5Dread(dset.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, out) < 0) {
    throw error("dataset", dataset, "cannot be read (damaged file or values out of range)");
  }
}

std::vector<double> H5InputFile::readDoubles(const std::string& dataset, const Shape& expectedShape) const {
  std::size_t count = 0;
  const H5Handle dset = openChecked(dataset, expectedShape, H5T_FLOAT, count);
  std::vector<double> out(count);
  readInto(dataset, dset, H5T_NATIVE_DOUBLE, out.data(), count);
  return out;
}

std::vector<std::int64_t> H5InputFile::readInt64s(const std::string& dataset, const Shape& expectedShape) const {
  std::size_t count = 0;
  const H5Handle dset = openChecked(dataset, expectedShape, H5T_INTEGER, count);
  std::vector<std::int64_t> out(count);
  readInto(dataset, dset, H5T_NATIVE_INT64, out.data(), count);
  return out;
}

std::vector<std::int32_t> H5InputFile::readInt32s(const std::string& dataset, const Shape& expectedShape) const {
  std::size_t count = 0;
  const H5Handle dset = openChecked(dataset, expectedShape, H5T_INTEGER, count);
  std::vector<std::int32_t> out(count);
  readInto(dataset, dset, H5T_NATIVE_INT32, out.data(), count);
  return out;
}

std::vector<std::uint8_t> H5InputFile::readBytes(const std::string& dataset) const {
  std::size_t count = 0;
  const H5Handle dset = openChecked(dataset, {std::nullopt}, H5T_INTEGER, count);
  std::vector<std::uint8_t> out(count);
  readInto(dataset, dset, H5T_NATIVE_UINT8, out.data(), count);
  return out;
}

std::vector<Vec3> H5InputFile::readVec3s(const std::string& dataset, Shape leading) const {
  leading.emplace_back(3);
  std::size_t count = 0;
  const H5Handle dset = openChecked(dataset, leading, H5T_FLOAT, count);
  std::vector<Vec3> out(count / 3);
  readInto(dataset, dset, H5T_NATIVE_DOUBLE, flatView(out).data(), count);
  return out;
}

bool H5InputFile::hasAttribute(const std::string& objectPath, const std::string& name) const {
  const H5ErrorSilencer silence;
  return exists(objectPath) && H5Aexists_by_name(file_.get(), objectPath.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

H5Handle H5InputFile::openAttribute(const std::string& objectPath, const std::string& name) const {
  const std::string where = objectPath == "/" ? "/" : objectPath + "/";
  if (!hasAttribute(objectPath, name)) throw error("attribute", where + "@" + name, "is missing");
  const H5ErrorSilencer silence;
  H5Handle attr(H5Aopen_by_name(file_.get(), objectPath.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr) throw error("attribute", where + "@" + name, "cannot be opened");
  return attr;
}

void H5InputFile::readNumericAttribute(const std::string& objectPath, const std::string& name, H5T_class_t cls,
                                       hid_t memType, void* out, hsize_t count) const {
  const H5Handle attr = openAttribute(objectPath, name);
  const std::string where = (objectPath == "/" ? "/" : objectPath + "/") + "@" + name;
  const H5ErrorSilencer silence;
  H5Handle type(H5Aget_type(attr.get()), H5Tclose);
  H5Handle space(H5Aget_space(attr.get()), H5Sclose);
  const H5T_class_t found = type ? H5Tget_class(type.get()) : H5T_NO_CLASS;
  if (found != cls) {
    throw error("attribute", where, std::string("expected ") + className(cls) + " values, found " + className(found));
  }
  const hssize_t n = space ? H5Sget_simple_extent_npoints(space.get()) : -1;
  if (n != static_cast<hssize_t>(count)) {
    throw error("attribute", where, "expected " + std::to_string(count) + " value(s), found " + std::to_string(n));
  }
  if (H5Aread(attr.get(), memType, out) < 0) throw error("attribute", where, "cannot be read");
}

double H5InputFile::readDoubleAttribute(const std::string& objectPath, const std::string& name) const {
  double v = 0.0;
  readNumericAttribute(objectPath, name, H5T_FLOAT, H5T_NATIVE_DOUBLE, &v, 1);
  return v;
}

std::int64_t H5InputFile::readIntAttribute(const std::string& objectPath, const std::string& name) const {
  std::int64_t v = 0;
  readNumericAttribute(objectPath, name, H5T_INTEGER, H5T_NATIVE_INT64, &v, 1);
  return v;
}

std::array<double, 3> H5InputFile::readDouble3Attribute(const std::string& objectPath, const std::string& name) const {
  std::array<double, 3> v{};
  readNumericAttribute(objectPath, name, H5T_FLOAT, H5T_NATIVE_DOUBLE, v.data(), 3);
  return v;
}

std::array<std::int64_t, 3> H5InputFile::readInt3Attribute(const std::string& objectPath,
                                                           const std::string& name) const {
  std::array<std::int64_t, 3> v{};
  readNumericAttribute(objectPath, name, H5T_INTEGER, H5T_NATIVE_INT64, v.data(), 3);
  return v;
}

std::string H5InputFile::readStringAttribute(const std::string& objectPath, const std::string& name) const {
  const H5Handle attr = openAttribute(objectPath, name);
  const std::string where = (objectPath == "/" ? "/" : objectPath + "/") + "@" + name;
  const H5ErrorSilencer silence;
  H5Handle type(H5Aget_type(attr.get()), H5Tclose);
  if (!type || H5Tget_class(type.get()) != H5T_STRING) throw error("attribute", where, "expected a string");
  // Our writer stores fixed-length strings; variable-length ones (h5py's default) are
  // accepted too so a file edited by hand still reads.
  if (H5Tis_variable_str(type.get()) > 0) {
    H5Handle memType(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(memType.get(), H5T_VARIABLE);
    char* text = nullptr;
    if (H5Aread(attr.get(), memType.get(), &text) < 0) throw error("attribute", where, "cannot be read");
    std::string out = text != nullptr ? text : "";
    H5free_memory(text);
    return out;
  }
  const std::size_t size = H5Tget_size(type.get());
  std::string buffer(size + 1, '\0');
  if (H5Aread(attr.get(), type.get(), buffer.data()) < 0) throw error("attribute", where, "cannot be read");
  buffer.resize(buffer.find('\0'));
  return buffer;
}

}  // namespace grainbridge::core::io
