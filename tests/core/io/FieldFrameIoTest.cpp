#include <gtest/gtest.h>

#include "core/Files.hpp"
#include "core/Sha256.hpp"
#include "core/io/FieldFrameReader.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "core/io/H5InputFile.hpp"
#include "tests/core/io/IoTestSupport.hpp"

namespace grainbridge::core::io {
namespace {

using iotest::expectError;
using iotest::sampleFieldFrame;
using iotest::TempDir;

TEST(FieldFrameSerialization, RoundTripWithTwoSolidsPhases) {
  const TempDir dir;
  FieldFrameWriter writer(dir.path(), {"field-key"});
  const data::FieldFrame frame = sampleFieldFrame(200, 0.75);
  const auto path = writer.write(frame);
  EXPECT_EQ(path, dir.path() / "frames" / "fields_000000200.h5");

  const data::FieldFrame back = readFieldFrame(path);
  EXPECT_EQ(back.grid, frame.grid);
  EXPECT_EQ(back.ep_g, frame.ep_g);
  EXPECT_EQ(back.p_g, frame.p_g);
  EXPECT_EQ(back.u_g, frame.u_g);
  ASSERT_EQ(back.solids.size(), 2U);
  // Phase order is the engine's ("small" before "large"), not HDF5's name order.
  EXPECT_EQ(back.solids[0].name, "small");
  EXPECT_EQ(back.solids[1].name, "large");
  EXPECT_EQ(back.solids, frame.solids);
  EXPECT_EQ(back, frame);

  const FileStamp stamp = readStamp(path);
  EXPECT_EQ(stamp.stageKey, "field-key");
  EXPECT_EQ(stamp.formatVersion, kFieldFormatVersion);
}

// A continuum frame carries what its fields are of (DESIGN.md, field frames): gravity and each
// solids phase's name, diameter and density, so a reader needs no stage params.
TEST(FieldFrameSerialization, MaterialsRoundTripAndMustNameTheSolidsPhases) {
  const TempDir dir;
  FieldFrameWriter writer(dir.path(), {"field-key"});
  data::FieldFrame frame = sampleFieldFrame(3, 0.25);
  frame.materials.gravity = Vec3(0.0, -9.81, 0.0);
  frame.materials.species = {{"small", 1.5e-3, 2526.0}, {"large", 2.5e-3, 2526.0}};
  const data::FieldFrame back = readFieldFrame(writer.write(frame));
  EXPECT_EQ(back.materials, frame.materials);
  EXPECT_EQ(back, frame);
  // Without materials a frame reads back without them (coarse-grained DEM fields, older files).
  EXPECT_TRUE(readFieldFrame(writer.write(sampleFieldFrame(4, 0.5))).materials.empty());

  frame.materials.species = {{"large", 2.5e-3, 2526.0}, {"small", 1.5e-3, 2526.0}};
  expectError([&] { writer.write(frame); }, {"materials species 0 is 'large'", "solids phase 'small'"});
  frame.materials.species.pop_back();
  expectError([&] { writer.write(frame); }, {"1 species for 2 solids phases"});
  frame.materials.species = {{"small", 0.0, 2526.0}, {"large", 2.5e-3, 2526.0}};
  expectError([&] { writer.write(frame); }, {"positive diameter"});
}

// Coarse-grained DEM carries more than the continuum fields: named scalar, vector and tensor
// cell fields, in their own group, listed in the XDMF so ParaView shows them.
TEST(FieldFrameSerialization, ExtraCellFieldsRoundTripAndAppearInTheXdmf) {
  const TempDir dir;
  FieldFrameWriter writer(dir.path(), {"field-key"});
  data::FieldFrame frame = sampleFieldFrame(3, 0.5);
  const std::size_t n = frame.grid.cellCount();
  data::NamedCellField pressure{"pressure", 1, {}};
  data::NamedCellField stress{"stress", 9, {}};
  data::NamedCellField force{"contact_force", 3, {}};
  for (std::size_t c = 0; c < n; ++c) {
    pressure.values.push_back(0.5 * static_cast<double>(c));
    for (int k = 0; k < 9; ++k) stress.values.push_back(static_cast<double>(c) + 0.1 * k);
    for (int k = 0; k < 3; ++k) force.values.push_back(-static_cast<double>(c) - k);
  }
  frame.extras = {stress, pressure, force};
  const auto path = writer.write(frame);
  const data::FieldFrame back = readFieldFrame(path);
  EXPECT_EQ(back.extras, frame.extras);  // the writer's order, not HDF5's name order
  EXPECT_EQ(back, frame);
  const std::string xdmf = readFile(writer.xdmfPath());
  EXPECT_NE(xdmf.find("Name=\"stress\" AttributeType=\"Tensor\""), std::string::npos) << xdmf;
  EXPECT_NE(xdmf.find("Name=\"pressure\" AttributeType=\"Scalar\""), std::string::npos);
  EXPECT_NE(xdmf.find("Name=\"contact_force\" AttributeType=\"Vector\""), std::string::npos);

  frame.extras = {data::NamedCellField{"bad name", 1, pressure.values}};
  expectError([&] { writer.write(frame); }, {"field name 'bad name'"});
  frame.extras = {data::NamedCellField{"p", 2, std::vector<double>(2 * n, 0.0)}};
  expectError([&] { writer.write(frame); }, {"2 components per cell"});
}

TEST(FieldFrameSerialization, CellArraysAreStoredKJI) {
  const TempDir dir;
  const data::FieldFrame frame = sampleFieldFrame(1, 0.0);
  const H5InputFile f(FieldFrameWriter(dir.path(), {"k"}).write(frame));
  // [nz][ny][nx] with nx = 4, ny = 3, nz = 2, as the XDMF 3DCoRectMesh expects.
  EXPECT_EQ(f.shape("/ep_g"), (std::vector<hsize_t>{2, 3, 4}));
  EXPECT_EQ(f.shape("/u_g"), (std::vector<hsize_t>{2, 3, 4, 3}));
  EXPECT_EQ(f.shape("/solids/large/theta"), (std::vector<hsize_t>{2, 3, 4}));
  const std::vector<double> p = f.readDoubles("/p_g", {2, 3, 4});
  // Cell (i=3, j=1, k=1) sits at flat index (k*ny + j)*nx + i = 19 and encodes 3 + 10 + 100.
  EXPECT_EQ(p[19], 101325.0 + 113.0);
  EXPECT_EQ(f.readDouble3Attribute("/grid", "spacing"), (std::array<double, 3>{0.05, 0.1, 0.2}));
  EXPECT_EQ(f.readInt3Attribute("/grid", "cells"), (std::array<std::int64_t, 3>{4, 3, 2}));
}

TEST(FieldFrameSerialization, EqualContentGivesEqualBytes) {
  const TempDir a, b;
  const data::FieldFrame frame = sampleFieldFrame(9, 0.5);
  const auto first = FieldFrameWriter(a.path(), {"k"}).write(frame);
  const auto second = FieldFrameWriter(b.path(), {"k"}).write(frame);
  EXPECT_EQ(sha256File(first), sha256File(second));
}

TEST(FieldFrameSerialization, RejectsBadFrames) {
  const TempDir dir;
  FieldFrameWriter writer(dir.path(), {"k"});
  data::FieldFrame frame = sampleFieldFrame(1, 0.0);
  frame.solids[1].theta.pop_back();
  expectError([&] { writer.write(frame); }, {"step 1", "'solids/large/theta'", "23 entries", "expected 24"});

  frame = sampleFieldFrame(1, 0.0);
  frame.solids[1].name = "small";
  expectError([&] { writer.write(frame); }, {"'small' is repeated"});

  frame = sampleFieldFrame(1, 0.0);
  frame.solids[0].name = "a/b";
  expectError([&] { writer.write(frame); }, {"'a/b'", "letters, digits"});

  frame = sampleFieldFrame(1, 0.0);
  frame.grid.cells[2] = 0;
  expectError([&] { writer.write(frame); }, {"0 cells along axis 2"});
  EXPECT_TRUE(listFieldFrames(dir.path()).empty());
}

}  // namespace
}  // namespace grainbridge::core::io
