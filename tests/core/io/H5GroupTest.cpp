// Groups inside one HDF5 file: a writer given its group ("/" or "/dem") builds every path with
// memberPath, and what it writes there reads back from that group only, so two writers sharing
// one file (a coupled engine's checkpoint) cannot see each other's arrays.
#include <gtest/gtest.h>

#include "core/io/H5InputFile.hpp"
#include "core/io/H5OutputFile.hpp"
#include "core/io/H5Path.hpp"
#include "tests/core/io/IoTestSupport.hpp"

namespace grainbridge::core::io {
namespace {

using iotest::TempDir;

TEST(H5Group, MemberPathJoinsTheRootAndOtherGroups) {
  EXPECT_EQ(memberPath("/", "id"), "/id");
  EXPECT_EQ(memberPath("", "id"), "/id");
  EXPECT_EQ(memberPath("/dem", "id"), "/dem/id");
  EXPECT_EQ(memberPath("/dem/", "id"), "/dem/id");
  EXPECT_EQ(memberPath("/coupled/fluid", "pressure"), "/coupled/fluid/pressure");
}

TEST(H5Group, DatasetsAndAttributesOfNestedGroupsReadBackFromTheirGroup) {
  const TempDir dir;
  const auto path = dir.path() / "groups.h5";
  {
    H5OutputFile f(path);
    f.createGroup("/outer");
    f.createGroup("/outer/inner");
    f.writeDataset(memberPath("/outer", "values"), std::vector<double>{1.0, 2.5});
    f.writeDataset(memberPath("/outer/inner", "values"), std::vector<std::int64_t>{7, 8, 9});
    f.writeAttribute("/outer/inner", "time", 0.125);
    f.writeAttribute("/", "time", 4.0);
    f.close();
  }
  const H5InputFile f(path);
  EXPECT_TRUE(f.exists("/outer/inner/values"));
  EXPECT_FALSE(f.exists("/inner"));
  EXPECT_EQ(f.children("/outer"), (std::vector<std::string>{"inner", "values"}));
  EXPECT_EQ(f.readDoubles("/outer/values", {2}), (std::vector<double>{1.0, 2.5}));
  EXPECT_EQ(f.readInt64s("/outer/inner/values", {3}), (std::vector<std::int64_t>{7, 8, 9}));
  EXPECT_EQ(f.readDoubleAttribute("/outer/inner", "time"), 0.125);
  EXPECT_EQ(f.readDoubleAttribute("/", "time"), 4.0);
}

}  // namespace
}  // namespace grainbridge::core::io
