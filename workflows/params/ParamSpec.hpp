#pragma once
// One declaration per stage parameter (STYLE.md 5): type, unit dimension, default or required,
// allowed range or values, whether it affects results, and a one-line doc. Validation,
// `grainbridge stages` and docs/stages.md are all derived from these declarations.
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/units/Dimension.hpp"

namespace grainbridge::workflows::params {

enum class ParamKind {
  Quantity,
  Integer,
  Boolean,
  String,
  StringList,
  QuantityList,
  IntegerList,
  Object,
  ObjectList,
  InputFile
};

class ParamSchema;

struct Bound {
  double value;
  bool inclusive;
};

class ParamSpec {
 public:
  // A real number with a physical dimension (accepts "<number> <unit>" strings).
  static ParamSpec quantity(std::string name, core::units::Dimension dim);
  static ParamSpec number(std::string name) { return quantity(std::move(name), core::units::Dimension::none()); }
  static ParamSpec integer(std::string name);
  static ParamSpec boolean(std::string name);
  static ParamSpec string(std::string name);
  // A list of distinct strings, each one of options() when given (the quantities a closure table
  // supplies); any length.
  static ParamSpec stringList(std::string name);
  // A fixed-length list of quantities, e.g. gravity [0, 0, "-9.81 m/s2"]; length 0 accepts any
  // length.
  static ParamSpec quantityList(std::string name, core::units::Dimension dim, int length);
  // A list of integers (particle ids, cell counts); length 0 accepts any length, and min/max
  // apply to each element. Elements resolve to JSON numbers with integral values (3.0, not 3):
  // the resolved text enters the stage key, and these parameters were number lists before, so
  // keeping their canonical text keeps the keys of existing configs.
  static ParamSpec integerList(std::string name, int length);
  // A nested object, or a non-empty list of objects, each validated by `schema` (species,
  // walls, per-pair materials): errors name the element, e.g. /stages/bed/params/walls/2/mu.
  static ParamSpec object(std::string name, std::shared_ptr<const ParamSchema> schema);
  // A file the stage reads (a LAMMPS data file, a saved frame): a path relative to the folder
  // grainbridge runs in. It resolves to {"path", "sha256"}, and only the sha256 enters the stage
  // key: a moved file changes nothing, an edited one reruns the stage. Top level only.
  static ParamSpec inputFile(std::string name);
  static ParamSpec objectList(std::string name, std::shared_ptr<const ParamSchema> schema);

  // The same declaration under another name: a closure law's parameter as a stage's config
  // names it (workflows/closures/ClosureCatalog declares it once, with its unit, range and doc).
  [[nodiscard]] ParamSpec renamed(std::string name) const;

  ParamSpec& required();
  ParamSpec& defaultValue(nlohmann::json value);  // in the same forms a config accepts
  // Drops the default a shared declaration carries, where the stage derives the value itself.
  ParamSpec& withoutDefault() {
    default_.reset();
    return *this;
  }
  ParamSpec& min(double value, bool inclusive = true);
  ParamSpec& max(double value, bool inclusive = true);
  ParamSpec& positive() { return min(0.0, false); }
  ParamSpec& options(std::vector<std::string> allowed);
  ParamSpec& doc(std::string text);
  // Plot styling, progress output: left out of the stage key (DESIGN.md, workflow semantics).
  ParamSpec& doesNotAffectResults();

  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] ParamKind kind() const { return kind_; }
  [[nodiscard]] const core::units::Dimension& dimension() const { return dim_; }
  [[nodiscard]] bool isRequired() const { return required_; }
  [[nodiscard]] const std::optional<nlohmann::json>& defaultJson() const { return default_; }
  [[nodiscard]] const std::optional<Bound>& lower() const { return min_; }
  [[nodiscard]] const std::optional<Bound>& upper() const { return max_; }
  [[nodiscard]] const std::vector<std::string>& allowed() const { return options_; }
  [[nodiscard]] const std::string& docText() const { return doc_; }
  [[nodiscard]] bool affectsResults() const { return affectsResults_; }
  [[nodiscard]] int listLength() const { return listLength_; }
  [[nodiscard]] const ParamSchema* nested() const { return nested_.get(); }

  // "quantity [m]", "integer", "string: one of a|b", ...
  [[nodiscard]] std::string typeDescription() const;
  // "> 0", "in [0, 1]", "" when unbounded.
  [[nodiscard]] std::string rangeDescription() const;

 private:
  ParamSpec(std::string name, ParamKind kind, core::units::Dimension dim);

  std::string name_;
  ParamKind kind_;
  core::units::Dimension dim_;
  bool required_ = false;
  std::optional<nlohmann::json> default_;
  std::optional<Bound> min_;
  std::optional<Bound> max_;
  std::vector<std::string> options_;
  std::string doc_;
  bool affectsResults_ = true;
  int listLength_ = 0;
  std::shared_ptr<const ParamSchema> nested_;
};

}  // namespace grainbridge::workflows::params
