#include "core/io/LammpsDataReader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string_view>
#include <system_error>
#include <unordered_map>

#include "core/Error.hpp"

namespace grainbridge::core::io {

namespace {

constexpr std::string_view kSpace = " \t\r\f\v";

std::string_view trim(std::string_view s) {
  const auto b = s.find_first_not_of(kSpace);
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(kSpace) - b + 1);
}

// The whitespace-separated fields of one line. Sphere lines have at most 10; more are counted
// (for the column-count message) but not kept.
struct Fields {
  static constexpr std::size_t kMax = 12;
  std::array<std::string_view, kMax> f{};
  std::size_t n = 0;

  explicit Fields(std::string_view s) {
    std::size_t i = 0;
    while (true) {
      i = s.find_first_not_of(kSpace, i);
      if (i == std::string_view::npos) break;
      std::size_t e = s.find_first_of(kSpace, i);
      if (e == std::string_view::npos) e = s.size();
      if (n < kMax) f[n] = s.substr(i, e - i);
      ++n;
      i = e;
    }
  }
  [[nodiscard]] std::string_view operator[](std::size_t k) const { return f[k]; }
};

// std::from_chars rejects a leading '+', which hand-written files may have.
std::string_view dropPlus(std::string_view s) {
  if (s.size() > 1 && s.front() == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
  return s;
}

std::optional<double> toDouble(std::string_view s) {
  s = dropPlus(s);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

template <class Int>
std::optional<Int> toInt(std::string_view s) {
  s = dropPlus(s);
  Int v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

std::string quote(std::string_view s) { return "'" + std::string(s) + "'"; }

class Reader {
 public:
  Reader(const std::filesystem::path& path, double boxTolerance) : path_(path), boxTolerance_(boxTolerance) {}

  LammpsData read() {
    const std::string text = slurp();
    std::string_view rest = text;
    while (!rest.empty()) {
      const auto nl = rest.find('\n');
      std::string_view line = rest.substr(0, nl);
      rest = nl == std::string_view::npos ? std::string_view{} : rest.substr(nl + 1);
      ++line_;
      if (line_ == 1) {  // the title: never parsed, even if it looks like a header line
        data_.title = std::string(trim(line));
        continue;
      }
      const auto hash = line.find('#');
      const std::string_view comment = hash == std::string_view::npos ? std::string_view{} : line.substr(hash + 1);
      const std::string_view body = trim(line.substr(0, hash));
      if (body.empty()) continue;
      if (std::isalpha(static_cast<unsigned char>(body.front())) != 0) {
        startSection(body, trim(comment));
        continue;
      }
      switch (section_) {
        case Section::Header:
          headerLine(Fields(body));
          break;
        case Section::Atoms:
          atomLine(Fields(body));
          break;
        case Section::Velocities:
          velocityLine(Fields(body));
          break;
        case Section::Skipped:
          break;
      }
    }
    endSection();
    if (section_ == Section::Header) checkHeader();  // a file with a header only
    if (!atomsSeen_ && natoms_ > 0)
      fail("the header says " + std::to_string(natoms_) + " atoms but the file has no Atoms section");
    return std::move(data_);
  }

 private:
  enum class Section { Header, Atoms, Velocities, Skipped };

  [[noreturn]] void fail(const std::string& what) const {
    throw Error("LAMMPS data file '" + path_.string() + "': " + what);
  }
  [[noreturn]] void failLine(const std::string& what) const {
    throw Error("LAMMPS data file '" + path_.string() + "', line " + std::to_string(line_) + ": " + what);
  }

  std::string slurp() const {
    std::error_code ec;
    if (!std::filesystem::exists(path_, ec)) fail("does not exist");
    if (std::filesystem::is_directory(path_, ec)) fail("is a directory, not a data file");
    std::ifstream in(path_, std::ios::binary);
    if (!in) fail("cannot be opened for reading");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) fail("cannot be read");
    if (text.size() >= 2 && static_cast<unsigned char>(text[0]) == 0x1f && static_cast<unsigned char>(text[1]) == 0x8b)
      fail("is gzip-compressed; gunzip it first");
    return text;
  }

  // ---- header ----------------------------------------------------------------------------
  template <class Int>
  Int headerInt(std::string_view s, const char* what) const {
    const auto v = toInt<Int>(s);
    if (!v || *v < 0)
      failLine("the number of " + std::string(what) + " " + quote(s) + " is not a non-negative integer");
    return *v;
  }
  double headerDouble(std::string_view s, const char* what) const {
    const auto v = toDouble(s);
    if (!v) failLine(std::string(what) + " " + quote(s) + " is not a number");
    return *v;
  }

  void headerLine(const Fields& t) {
    if (t.n == 2 && t[1] == "atoms") {
      natoms_ = headerInt<std::int64_t>(t[0], "atoms");
      natomsLine_ = line_;
    } else if (t.n == 3 && t[1] == "atom" && t[2] == "types") {
      data_.atomTypes = headerInt<std::int64_t>(t[0], "atom types");
    } else if (t.n == 4 && t[3].size() == 3 && t[2].size() == 3 && t[2].substr(1) == "lo" && t[3].substr(1) == "hi" &&
               t[2][0] == t[3][0] && (t[2][0] == 'x' || t[2][0] == 'y' || t[2][0] == 'z')) {
      const int axis = t[2][0] - 'x';
      const std::string name(1, t[2][0]);
      const double lo = headerDouble(t[0], (name + "lo").c_str());
      const double hi = headerDouble(t[1], (name + "hi").c_str());
      if (!(hi > lo)) failLine(name + "hi " + quote(t[1]) + " is not greater than " + name + "lo " + quote(t[0]));
      data_.lo[axis] = lo;
      data_.hi[axis] = hi;
      boxSeen_[static_cast<std::size_t>(axis)] = true;
    } else if (t.n == 6 && t[3] == "xy" && t[4] == "xz" && t[5] == "yz") {
      failLine("the box is triclinic (tilt factors xy xz yz = " + std::string(t[0]) + " " + std::string(t[1]) + " " +
               std::string(t[2]) + "), which is not supported; write the data from an orthogonal box");
    }
    // Any other header line (bonds, ellipsoids, extra ... per atom) does not concern spheres.
  }

  void checkHeader() const {
    if (natomsLine_ == 0) fail("the header has no 'N atoms' line");
    if (data_.atomTypes < 1) fail("the header has no 'N atom types' line (or it says 0)");
    for (std::size_t a = 0; a < 3; ++a) {
      if (!boxSeen_[a]) {
        const char c = static_cast<char>('x' + a);
        fail("the header has no '" + std::string(1, c) + "lo " + c + "hi' line");
      }
    }
  }

  // ---- sections ----------------------------------------------------------------------------
  void startSection(std::string_view keyword, std::string_view styleComment) {
    if (section_ == Section::Header) checkHeader();
    endSection();
    if (keyword == "Atoms") {
      if (atomsSeen_) failLine("a second Atoms section (the first is on line " + std::to_string(atomsLine_) + ")");
      // write_data names the style: "Atoms # sphere". Other styles have other columns.
      const std::string_view style = styleComment.substr(0, styleComment.find_first_of(kSpace));
      if (!style.empty() && style != "sphere")
        failLine("the Atoms section is written for atom_style " + quote(style) +
                 "; only atom_style sphere (atom-ID atom-type diameter density x y z) can be read");
      atomsSeen_ = true;
      atomsLine_ = line_;
      beginAtoms();
      section_ = Section::Atoms;
    } else if (keyword == "Velocities") {
      if (!atomsSeen_) failLine("the Velocities section comes before the Atoms section");
      if (data_.hasVelocities) failLine("a second Velocities section");
      data_.hasVelocities = true;
      section_ = Section::Velocities;
    } else {
      section_ = Section::Skipped;
    }
  }

  void endSection() {
    if (section_ != Section::Atoms) return;
    const auto n = static_cast<std::int64_t>(data_.id.size());
    if (n != natoms_) {
      fail("the Atoms section (line " + std::to_string(atomsLine_) + ") has " + std::to_string(n) +
           " atom lines, but the header (line " + std::to_string(natomsLine_) + ") says " + std::to_string(natoms_) +
           " atoms");
    }
    data_.velocity.assign(data_.id.size(), Vec3::Zero());
    data_.angularVelocity.assign(data_.id.size(), Vec3::Zero());
    velocityLine_.assign(data_.id.size(), 0);
  }

  void beginAtoms() {
    // A corrupt header must not make us reserve terabytes: an atom line has at least 14 bytes.
    const auto n = static_cast<std::size_t>(std::min<std::int64_t>(natoms_, 1 << 24));
    data_.id.reserve(n);
    data_.type.reserve(n);
    data_.diameter.reserve(n);
    data_.density.reserve(n);
    data_.position.reserve(n);
    data_.image.reserve(n);
    atomLine_.reserve(n);
    index_.reserve(n);
  }

  // ---- fields ------------------------------------------------------------------------------
  [[noreturn]] void badField(const char* section, std::size_t column, const char* name, std::string_view value,
                             const char* expected) const {
    failLine(std::string(section) + " line, column " + std::to_string(column + 1) + " (" + name + ") is " +
             quote(value) + ", not " + expected);
  }
  double number(const Fields& t, std::size_t k, const char* section, const char* name) const {
    const auto v = toDouble(t[k]);
    if (!v) badField(section, k, name, t[k], "a finite number");
    return *v;
  }
  template <class Int>
  Int integer(const Fields& t, std::size_t k, const char* section, const char* name) const {
    const auto v = toInt<Int>(t[k]);
    if (!v) badField(section, k, name, t[k], "an integer");
    return *v;
  }
  std::int64_t atomId(const Fields& t, const char* section) const {
    const auto id = integer<std::int64_t>(t, 0, section, "atom-ID");
    if (id < 1) badField(section, 0, "atom-ID", t[0], "a positive integer");
    return id;
  }

  void atomLine(const Fields& t) {
    constexpr const char* kSection = "Atoms";
    if (static_cast<std::int64_t>(data_.id.size()) == natoms_)
      failLine("more atom lines than the header's " + std::to_string(natoms_) + " atoms (line " +
               std::to_string(natomsLine_) + ")");
    if (t.n != 7 && t.n != 10)
      failLine(
          "an atom_style sphere Atoms line has 7 columns (atom-ID atom-type diameter density x y z) or 10 (then "
          "ix iy iz), found " +
          std::to_string(t.n));
    const std::int64_t id = atomId(t, kSection);
    const int type = integer<int>(t, 1, kSection, "atom-type");
    if (type < 1 || type > data_.atomTypes)
      failLine("atom " + std::to_string(id) + " has type " + std::to_string(type) + ", outside 1.." +
               std::to_string(data_.atomTypes) + " (the header's atom types)");
    const double diameter = number(t, 2, kSection, "diameter");
    if (diameter < 0.0) badField(kSection, 2, "diameter", t[2], "a non-negative diameter");
    const double density = number(t, 3, kSection, "density");
    if (!(density > 0.0)) badField(kSection, 3, "density", t[3], "a positive density");
    static constexpr std::array<const char*, 3> kCoord{"x", "y", "z"};
    static constexpr std::array<const char*, 3> kImage{"ix", "iy", "iz"};
    Vec3 x;
    Vec3i image = Vec3i::Zero();
    for (std::size_t a = 0; a < 3; ++a) {
      const auto ai = static_cast<Eigen::Index>(a);
      x[ai] = number(t, 4 + a, kSection, kCoord[a]);
      if (t.n == 10) image[ai] = integer<int>(t, 7 + a, kSection, kImage[a]);
      const double tol = boxTolerance_ * (data_.hi[ai] - data_.lo[ai]);
      if (x[ai] < data_.lo[ai] - tol || x[ai] > data_.hi[ai] + tol) {
        std::ostringstream msg;
        msg.precision(17);
        msg << "atom " << id << " is outside the box: " << kCoord[a] << " = " << x[ai] << " is not in [" << data_.lo[ai]
            << ", " << data_.hi[ai] << "] (tolerance " << tol << ")";
        failLine(msg.str());
      }
    }
    const auto [it, inserted] = index_.emplace(id, data_.id.size());
    if (!inserted)
      failLine("atom id " + std::to_string(id) + " appears twice (first on line " +
               std::to_string(atomLine_[it->second]) + ")");
    data_.id.push_back(id);
    data_.type.push_back(type);
    data_.diameter.push_back(diameter);
    data_.density.push_back(density);
    data_.position.push_back(x);
    data_.image.push_back(image);
    atomLine_.push_back(line_);
  }

  void velocityLine(const Fields& t) {
    constexpr const char* kSection = "Velocities";
    if (t.n != 7)
      failLine("an atom_style sphere Velocities line has 7 columns (atom-ID vx vy vz wx wy wz), found " +
               std::to_string(t.n));
    const std::int64_t id = atomId(t, kSection);
    const auto it = index_.find(id);
    if (it == index_.end())
      failLine("velocity for atom id " + std::to_string(id) + ", which is not in the Atoms section");
    const std::size_t i = it->second;
    if (velocityLine_[i] != 0)
      failLine("velocity for atom id " + std::to_string(id) + " given twice (first on line " +
               std::to_string(velocityLine_[i]) + ")");
    velocityLine_[i] = line_;
    static constexpr std::array<const char*, 6> kName{"vx", "vy", "vz", "wx", "wy", "wz"};
    for (std::size_t a = 0; a < 3; ++a) {
      const auto ai = static_cast<Eigen::Index>(a);
      data_.velocity[i][ai] = number(t, 1 + a, kSection, kName[a]);
      data_.angularVelocity[i][ai] = number(t, 4 + a, kSection, kName[3 + a]);
    }
  }

  std::filesystem::path path_;
  double boxTolerance_;
  LammpsData data_;
  Section section_ = Section::Header;
  std::int64_t line_ = 0;
  std::int64_t natoms_ = 0, natomsLine_ = 0;
  std::array<bool, 3> boxSeen_{};
  bool atomsSeen_ = false;
  std::int64_t atomsLine_ = 0;
  std::vector<std::int64_t> atomLine_, velocityLine_;    // where each atom / its velocity was read
  std::unordered_map<std::int64_t, std::size_t> index_;  // atom id -> position in file order
};

}  // namespace

LammpsData readLammpsData(const std::filesystem::path& path, double boxTolerance) {
  return Reader(path, boxTolerance).read();
}

}  // namespace grainbridge::core::io
