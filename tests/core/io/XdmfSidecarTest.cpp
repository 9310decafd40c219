// The .xmf sidecars: well-formed XML, one entry per frame, relative HDF5 paths that resolve
// from the sidecar's folder, the grids and shapes ParaView needs, and a restarted writer
// that keeps the frames of the earlier run. (ParaView itself opens them in
// tests/integration/paraview_check.py.)
#include <gtest/gtest.h>

#include <cctype>
#include <charconv>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/Files.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "core/io/ParticleFrameWriter.hpp"
#include "tests/core/io/IoTestSupport.hpp"

namespace grainbridge::core::io {
namespace {

using iotest::sampleFieldFrame;
using iotest::sampleParticleFrame;
using iotest::TempDir;

// A strict little XML reader, enough to check well-formedness of what we generate (no
// DTD, no CDATA): every tag closes in order, attributes are quoted and unique, and '&'
// only starts a known entity. Throws std::runtime_error on anything else.
struct XmlNode {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
  std::vector<std::unique_ptr<XmlNode>> children;

  [[nodiscard]] std::vector<const XmlNode*> all(const std::string& tag) const {
    std::vector<const XmlNode*> out;
    for (const auto& c : children) {
      if (c->name == tag) out.push_back(c.get());
    }
    return out;
  }
  [[nodiscard]] const XmlNode& one(const std::string& tag) const {
    const auto found = all(tag);
    if (found.size() != 1) throw std::runtime_error("expected one <" + tag + "> in <" + name + ">");
    return *found.front();
  }
  void collect(const std::string& tag, std::vector<const XmlNode*>& out) const {
    if (name == tag) out.push_back(this);
    for (const auto& c : children) c->collect(tag, out);
  }
};

class XmlParser {
 public:
  explicit XmlParser(std::string text) : s_(std::move(text)) {}

  std::unique_ptr<XmlNode> parseDocument() {
    skipSpace();
    if (s_.compare(pos_, 5, "<?xml") == 0) {
      pos_ = s_.find("?>", pos_);
      if (pos_ == std::string::npos) fail("unterminated XML declaration");
      pos_ += 2;
    }
    skipSpace();
    auto root = parseElement();
    skipSpace();
    if (pos_ != s_.size()) fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("XML error at offset " + std::to_string(pos_) + ": " + what);
  }
  void skipSpace() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  std::string name() {
    const std::size_t start = pos_;
    while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_' ||
                                s_[pos_] == '-' || s_[pos_] == ':' || s_[pos_] == '.')) {
      ++pos_;
    }
    if (pos_ == start) fail("expected a name");
    return s_.substr(start, pos_ - start);
  }
  std::string unescape(const std::string& raw) {
    static const std::map<std::string, char> entities{
        {"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
    std::string out;
    for (std::size_t k = 0; k < raw.size(); ++k) {
      if (raw[k] == '<') fail("'<' in text or attribute");
      if (raw[k] != '&') {
        out += raw[k];
        continue;
      }
      const std::size_t semi = raw.find(';', k);
      if (semi == std::string::npos || !entities.count(raw.substr(k + 1, semi - k - 1))) fail("bad entity");
      out += entities.at(raw.substr(k + 1, semi - k - 1));
      k = semi;
    }
    return out;
  }
  std::unique_ptr<XmlNode> parseElement() {
    if (s_[pos_] != '<') fail("expected '<'");
    ++pos_;
    auto node = std::make_unique<XmlNode>();
    node->name = name();
    for (;;) {
      skipSpace();
      if (s_.compare(pos_, 2, "/>") == 0) {
        pos_ += 2;
        return node;
      }
      if (s_[pos_] == '>') {
        ++pos_;
        break;
      }
      const std::string key = name();
      skipSpace();
      if (s_[pos_] != '=') fail("expected '=' after attribute " + key);
      ++pos_;
      skipSpace();
      const char quote = s_[pos_];
      if (quote != '"' && quote != '\'') fail("unquoted attribute " + key);
      const std::size_t end = s_.find(quote, pos_ + 1);
      if (end == std::string::npos) fail("unterminated attribute " + key);
      if (!node->attributes.emplace(key, unescape(s_.substr(pos_ + 1, end - pos_ - 1))).second) {
        fail("repeated attribute " + key);
      }
      pos_ = end + 1;
    }
    for (;;) {
      const std::size_t lt = s_.find('<', pos_);
      if (lt == std::string::npos) fail("unterminated <" + node->name + ">");
      node->text += unescape(s_.substr(pos_, lt - pos_));
      pos_ = lt;
      if (s_.compare(pos_, 2, "</") == 0) {
        pos_ += 2;
        if (name() != node->name) fail("mismatched end tag for <" + node->name + ">");
        skipSpace();
        if (s_[pos_] != '>') fail("expected '>'");
        ++pos_;
        return node;
      }
      node->children.push_back(parseElement());
    }
  }

  std::string s_;
  std::size_t pos_ = 0;
};

std::unique_ptr<XmlNode> parseXml(const std::filesystem::path& path) {
  return XmlParser(readFile(path)).parseDocument();
}

double toDouble(const std::string& s) {
  double v = 0;
  std::from_chars(s.data(), s.data() + s.size(), v);
  return v;
}

// Every HDF data item must be "<relative file>:<dataset>" resolving from the .xmf folder.
void expectRelativeHdfPaths(const XmlNode& root, const std::filesystem::path& dir) {
  std::vector<const XmlNode*> items;
  root.collect("DataItem", items);
  ASSERT_FALSE(items.empty());
  for (const XmlNode* item : items) {
    if (item->attributes.at("Format") != "HDF") continue;
    const std::string& ref = item->text;
    const std::size_t colon = ref.find(':');
    ASSERT_NE(colon, std::string::npos) << ref;
    const std::filesystem::path file = ref.substr(0, colon);
    EXPECT_TRUE(file.is_relative()) << ref;
    EXPECT_EQ(file.begin()->string(), "frames") << ref;
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << ref;
    EXPECT_EQ(ref[colon + 1], '/') << ref;
  }
}

TEST(XdmfCollection, ParticlesListEveryFrameWithContactGridsOnlyWhereThereAreContacts) {
  const TempDir dir;
  ParticleFrameWriter writer(dir.path(), {"k"});
  writer.write(sampleParticleFrame(0, 0.0, 5, 4));
  writer.write(sampleParticleFrame(10, 0.1, 5, 0, false));
  writer.write(sampleParticleFrame(20, 0.2, 6, 3));
  core::data::ParticleFrame empty;
  empty.step = 30;
  empty.time = 0.3;
  writer.write(empty);

  const auto root = parseXml(writer.xdmfPath());
  EXPECT_EQ(root->name, "Xdmf");
  const XmlNode& temporal = root->one("Domain").one("Grid");
  EXPECT_EQ(temporal.attributes.at("CollectionType"), "Temporal");
  const auto steps = temporal.all("Grid");
  ASSERT_EQ(steps.size(), 4U);
  // An empty frame keeps its time step but has no grids (ParaView rejects an empty geometry).
  EXPECT_EQ(toDouble(steps[3]->one("Time").attributes.at("Value")), 0.3);
  EXPECT_TRUE(steps[3]->all("Grid").empty());
  const double times[] = {0.0, 0.1, 0.2};
  const std::size_t contacts[] = {4, 0, 3};
  const std::size_t particles[] = {5, 5, 6};
  for (std::size_t s = 0; s < 3; ++s) {
    EXPECT_EQ(steps[s]->attributes.at("CollectionType"), "Spatial");
    EXPECT_EQ(toDouble(steps[s]->one("Time").attributes.at("Value")), times[s]);
    const auto grids = steps[s]->all("Grid");
    ASSERT_EQ(grids.size(), contacts[s] > 0 ? 2U : 1U);
    const XmlNode& p = *grids[0];
    EXPECT_EQ(p.one("Topology").attributes.at("TopologyType"), "Polyvertex");
    EXPECT_EQ(p.one("Topology").attributes.at("NumberOfElements"), std::to_string(particles[s]));
    std::vector<std::string> names;
    for (const XmlNode* a : p.all("Attribute")) names.push_back(a->attributes.at("Name"));
    std::vector<std::string> expected{"id", "species", "radius", "mass", "velocity", "angular_velocity"};
    if (s != 1) expected.push_back("external_force");
    EXPECT_EQ(names, expected);
    if (contacts[s] > 0) {
      const XmlNode& c = *grids[1];
      const XmlNode& topo = c.one("Topology");
      EXPECT_EQ(topo.attributes.at("TopologyType"), "Polyline");
      EXPECT_EQ(topo.attributes.at("NodesPerElement"), "2");
      EXPECT_EQ(topo.attributes.at("NumberOfElements"), std::to_string(contacts[s]));
      EXPECT_EQ(c.one("Geometry").one("DataItem").attributes.at("Dimensions"), std::to_string(2 * contacts[s]) + " 3");
      for (const XmlNode* a : c.all("Attribute")) EXPECT_EQ(a->attributes.at("Center"), "Cell");
      EXPECT_EQ(c.all("Attribute").size(), 4U);
    }
  }
  expectRelativeHdfPaths(*root, dir.path());
  EXPECT_FALSE(std::filesystem::exists(writer.xdmfPath().string() + ".tmp"));
}

TEST(XdmfCollection, MovedFolderStillResolves) {
  const TempDir parent;
  const auto before = parent.path() / "run";
  ParticleFrameWriter(before, {"k"}).write(sampleParticleFrame(1, 0.5, 3, 2));
  const auto after = parent.path() / "moved" / "elsewhere";
  std::filesystem::create_directories(after.parent_path());
  std::filesystem::rename(before, after);
  expectRelativeHdfPaths(*parseXml(after / "particles.xmf"), after);
}

TEST(XdmfCollection, RestartedWriterKeepsEarlierFrames) {
  const TempDir dir;
  {
    ParticleFrameWriter first(dir.path(), {"k"});
    first.write(sampleParticleFrame(10, 1.0, 4, 2));
    first.write(sampleParticleFrame(20, 2.0, 4, 2));
  }
  // A sidecar lost in a crash is rebuilt from the frames when the run restarts.
  std::filesystem::remove(dir.path() / "particles.xmf");
  ParticleFrameWriter second(dir.path(), {"k"});
  EXPECT_EQ(second.frameCount(), 2U);
  ASSERT_TRUE(std::filesystem::exists(second.xdmfPath()));
  EXPECT_EQ(parseXml(second.xdmfPath())->one("Domain").one("Grid").all("Grid").size(), 2U);

  second.write(sampleParticleFrame(20, 2.0, 4, 3));  // the restart rewrites step 20
  second.write(sampleParticleFrame(30, 3.0, 4, 2));
  const auto root = parseXml(second.xdmfPath());
  const auto steps = root->one("Domain").one("Grid").all("Grid");
  ASSERT_EQ(steps.size(), 3U);
  EXPECT_EQ(steps[0]->attributes.at("Name"), "step_10");
  EXPECT_EQ(steps[1]->attributes.at("Name"), "step_20");
  EXPECT_EQ(steps[2]->attributes.at("Name"), "step_30");
  EXPECT_EQ(steps[1]->all("Grid")[1]->one("Topology").attributes.at("NumberOfElements"), "3");
  expectRelativeHdfPaths(*root, dir.path());

  // Field writers restart the same way.
  {
    FieldFrameWriter fields(dir.path(), {"k"});
    fields.write(sampleFieldFrame(1, 0.1));
  }
  FieldFrameWriter fields(dir.path(), {"k"});
  fields.write(sampleFieldFrame(2, 0.2));
  EXPECT_EQ(parseXml(fields.xdmfPath())->one("Domain").one("Grid").all("Grid").size(), 2U);
}

TEST(XdmfCollection, FieldsAreCellCentredOnACoRectMeshOrderedZYX) {
  const TempDir dir;
  FieldFrameWriter writer(dir.path(), {"k"});
  writer.write(sampleFieldFrame(5, 0.5));
  writer.write(sampleFieldFrame(6, 0.625));
  const auto root = parseXml(writer.xdmfPath());
  const auto steps = root->one("Domain").one("Grid").all("Grid");
  ASSERT_EQ(steps.size(), 2U);
  EXPECT_EQ(toDouble(steps[1]->one("Time").attributes.at("Value")), 0.625);
  const XmlNode& g = *steps[0];
  // 4 x 3 x 2 cells -> node counts nz+1 ny+1 nx+1.
  EXPECT_EQ(g.one("Topology").attributes.at("TopologyType"), "3DCoRectMesh");
  EXPECT_EQ(g.one("Topology").attributes.at("Dimensions"), "3 4 5");
  const XmlNode& geometry = g.one("Geometry");
  EXPECT_EQ(geometry.attributes.at("GeometryType"), "ORIGIN_DXDYDZ");
  const auto items = geometry.all("DataItem");
  ASSERT_EQ(items.size(), 2U);
  EXPECT_EQ(items[0]->text, "0.3 0.2 -0.1");
  EXPECT_EQ(items[1]->text, "0.2 0.1 0.05");
  std::vector<std::string> names;
  for (const XmlNode* a : g.all("Attribute")) {
    names.push_back(a->attributes.at("Name"));
    EXPECT_EQ(a->attributes.at("Center"), "Cell");
    const std::string dims = a->one("DataItem").attributes.at("Dimensions");
    EXPECT_EQ(dims, a->attributes.at("AttributeType") == "Vector" ? "2 3 4 3" : "2 3 4");
  }
  EXPECT_EQ(names, (std::vector<std::string>{"ep_g", "p_g", "u_g", "ep_s_small", "u_s_small", "theta_small",
                                             "ep_s_large", "u_s_large", "theta_large"}));
  expectRelativeHdfPaths(*root, dir.path());
}

}  // namespace
}  // namespace grainbridge::core::io
