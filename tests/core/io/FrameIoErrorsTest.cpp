// The readers' errors must name the file and the dataset or attribute: the user facing a
// damaged or foreign frame needs to know which one and what was expected of it. Damage is
// made with the HDF5 C API directly, as a third-party tool would.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <fstream>

#include "core/io/FieldFrameReader.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "core/io/ParticleFrameReader.hpp"
#include "core/io/ParticleFrameWriter.hpp"
#include "tests/core/io/IoTestSupport.hpp"

namespace grainbridge::core::io {
namespace {

using iotest::expectError;
using iotest::sampleFieldFrame;
using iotest::sampleParticleFrame;
using iotest::TempDir;

// Opens a written frame read-write and applies `edit` to it.
template <class Edit>
void damage(const std::filesystem::path& path, Edit&& edit) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  edit(file);
  H5Fclose(file);
}

std::filesystem::path writeParticles(const TempDir& dir) {
  return ParticleFrameWriter(dir.path(), {"k"}).write(sampleParticleFrame(8, 0.5, 4, 3));
}

TEST(FrameFileValidation, MissingFileIsNamed) {
  const TempDir dir;
  const auto path = dir.path() / "frames" / "particles_000000001.h5";
  expectError([&] { readParticleFrame(path); }, {path.string(), "does not exist"});
  expectError([&] { readStamp(path); }, {path.string(), "does not exist"});
  expectError([&] { readFieldFrame(path); }, {path.string(), "does not exist"});
}

TEST(FrameFileValidation, NonHdf5FileIsNamed) {
  const TempDir dir;
  const auto path = dir.path() / "not_a_frame.h5";
  std::ofstream(path) << "this is text, not HDF5\n";
  expectError([&] { readParticleFrame(path); }, {path.string(), "not an HDF5 file"});
}

TEST(FrameFileValidation, MissingDatasetIsNamed) {
  const TempDir dir;
  const auto path = writeParticles(dir);
  damage(path, [](hid_t f) { H5Ldelete(f, "/velocity", H5P_DEFAULT); });
  expectError([&] { readParticleFrame(path); }, {"file '" + path.string() + "'", "dataset '/velocity'", "missing"});

  // A whole group lost: the first dataset looked for in it is named.
  const TempDir dir2;
  const auto path2 = writeParticles(dir2);
  damage(path2, [](hid_t f) { H5Ldelete(f, "/contacts", H5P_DEFAULT); });
  expectError([&] { readParticleFrame(path2); }, {path2.string(), "dataset '/contacts/i'", "missing"});
}

TEST(FrameFileValidation, WrongShapeIsNamed) {
  const TempDir dir;
  const auto path = writeParticles(dir);
  damage(path, [](hid_t f) {
    // Replace force_normal [3,3] with a [3,2] dataset.
    H5Ldelete(f, "/contacts/force_normal", H5P_DEFAULT);
    const hsize_t dims[2] = {3, 2};
    const hid_t space = H5Screate_simple(2, dims, nullptr);
    const hid_t dset =
        H5Dcreate2(f, "/contacts/force_normal", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const double zeros[6] = {};
    H5Dwrite(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, zeros);
    H5Dclose(dset);
    H5Sclose(space);
  });
  expectError([&] { readParticleFrame(path); },
              {path.string(), "dataset '/contacts/force_normal'", "expected shape [3, 3], found [3, 2]"});
}

TEST(FrameFileValidation, UnsupportedFormatVersionIsNamed) {
  const TempDir dir;
  const auto path = writeParticles(dir);
  damage(path, [](hid_t f) {
    const hid_t attr = H5Aopen(f, "format_version", H5P_DEFAULT);
    const int future = 99;
    H5Awrite(attr, H5T_NATIVE_INT, &future);
    H5Aclose(attr);
  });
  expectError([&] { readParticleFrame(path); }, {path.string(), "format_version", "unsupported format version 99"});
  // The stamp itself still reads: it is how a newer file is recognised.
  EXPECT_EQ(readStamp(path).formatVersion, 99);
}

TEST(FrameFileValidation, MissingAttributeIsNamed) {
  const TempDir dir;
  const auto path = writeParticles(dir);
  damage(path, [](hid_t f) { H5Adelete_by_name(f, "/domain", "lees_edwards_shear_rate", H5P_DEFAULT); });
  expectError([&] { readParticleFrame(path); }, {path.string(), "/domain/@lees_edwards_shear_rate", "missing"});
}

TEST(FrameFileValidation, FieldFrameDatasetIsNamed) {
  const TempDir dir;
  const auto path = FieldFrameWriter(dir.path(), {"k"}).write(sampleFieldFrame(3, 0.1));
  damage(path, [](hid_t f) { H5Ldelete(f, "/solids/large/theta", H5P_DEFAULT); });
  expectError([&] { readFieldFrame(path); }, {path.string(), "dataset '/solids/large/theta'", "missing"});
  // Reading a particle frame as a field frame says what is missing, not a crash.
  const TempDir other;
  const auto particles = writeParticles(other);
  expectError([&] { readFieldFrame(particles); }, {particles.string(), "/grid"});
}

}  // namespace
}  // namespace grainbridge::core::io
