#include "workflows/params/ParamSpec.hpp"

#include <sstream>

#include "core/Error.hpp"

namespace grainbridge::workflows::params {

ParamSpec::ParamSpec(std::string name, ParamKind kind, core::units::Dimension dim)
    : name_(std::move(name)), kind_(kind), dim_(dim) {}

ParamSpec ParamSpec::quantity(std::string name, core::units::Dimension dim) {
  return ParamSpec(std::move(name), ParamKind::Quantity, dim);
}
ParamSpec ParamSpec::renamed(std::string name) const {
  ParamSpec copy = *this;
  copy.name_ = std::move(name);
  return copy;
}

ParamSpec ParamSpec::integer(std::string name) { return ParamSpec(std::move(name), ParamKind::Integer, {}); }
ParamSpec ParamSpec::boolean(std::string name) { return ParamSpec(std::move(name), ParamKind::Boolean, {}); }
ParamSpec ParamSpec::string(std::string name) { return ParamSpec(std::move(name), ParamKind::String, {}); }
ParamSpec ParamSpec::stringList(std::string name) { return ParamSpec(std::move(name), ParamKind::StringList, {}); }
ParamSpec ParamSpec::quantityList(std::string name, core::units::Dimension dim, int length) {
  ParamSpec p(std::move(name), ParamKind::QuantityList, dim);
  p.listLength_ = length;
  return p;
}

ParamSpec ParamSpec::integerList(std::string name, int length) {
  ParamSpec p(std::move(name), ParamKind::IntegerList, {});
  p.listLength_ = length;
  return p;
}

ParamSpec ParamSpec::object(std::string name, std::shared_ptr<const ParamSchema> schema) {
  ParamSpec p(std::move(name), ParamKind::Object, {});
  p.nested_ = std::move(schema);
  return p;
}

ParamSpec ParamSpec::inputFile(std::string name) { return ParamSpec(std::move(name), ParamKind::InputFile, {}); }

ParamSpec ParamSpec::objectList(std::string name, std::shared_ptr<const ParamSchema> schema) {
  ParamSpec p(std::move(name), ParamKind::ObjectList, {});
  p.nested_ = std::move(schema);
  return p;
}

ParamSpec& ParamSpec::required() {
  GB_ASSERT(!default_, "parameter '" + name_ + "' cannot be both required and defaulted");
  required_ = true;
  return *this;
}
ParamSpec& ParamSpec::defaultValue(nlohmann::json value) {
  GB_ASSERT(!required_, "parameter '" + name_ + "' cannot be both required and defaulted");
  default_ = std::move(value);
  return *this;
}
ParamSpec& ParamSpec::min(double value, bool inclusive) {
  min_ = Bound{value, inclusive};
  return *this;
}
ParamSpec& ParamSpec::max(double value, bool inclusive) {
  max_ = Bound{value, inclusive};
  return *this;
}
ParamSpec& ParamSpec::options(std::vector<std::string> allowed) {
  GB_ASSERT(kind_ == ParamKind::String || kind_ == ParamKind::StringList, "options() applies to string parameters");
  options_ = std::move(allowed);
  return *this;
}
ParamSpec& ParamSpec::doc(std::string text) {
  doc_ = std::move(text);
  return *this;
}
ParamSpec& ParamSpec::doesNotAffectResults() {
  affectsResults_ = false;
  return *this;
}

std::string ParamSpec::typeDescription() const {
  switch (kind_) {
    case ParamKind::Quantity:
      return dim_.isNone() ? "number" : "quantity [" + dim_.siUnit() + "]";
    case ParamKind::Integer:
      return "integer";
    case ParamKind::Boolean:
      return "boolean";
    case ParamKind::String: {
      if (options_.empty()) return "string";
      std::string s = "string: one of ";
      for (std::size_t i = 0; i < options_.size(); ++i) s += (i ? "|" : "") + options_[i];
      return s;
    }
    case ParamKind::StringList: {
      if (options_.empty()) return "list of strings";
      std::string s = "list of strings, each one of ";
      for (std::size_t i = 0; i < options_.size(); ++i) s += (i ? "|" : "") + options_[i];
      return s;
    }
    case ParamKind::Object:
      return "object";
    case ParamKind::InputFile:
      return "file path";
    case ParamKind::ObjectList:
      return "list of objects";
    case ParamKind::IntegerList:
      return "list of " + (listLength_ > 0 ? std::to_string(listLength_) : std::string("any number of")) + " integers";
    case ParamKind::QuantityList:
      return "list of " + (listLength_ > 0 ? std::to_string(listLength_) : std::string("any number of")) +
             (dim_.isNone() ? " numbers" : " quantities [" + dim_.siUnit() + "]");
  }
  return "?";
}

std::string ParamSpec::rangeDescription() const {
  std::ostringstream s;
  if (min_ && max_) {
    s << "in " << (min_->inclusive ? "[" : "(") << min_->value << ", " << max_->value << (max_->inclusive ? "]" : ")");
  } else if (min_) {
    s << (min_->inclusive ? ">= " : "> ") << min_->value;
  } else if (max_) {
    s << (max_->inclusive ? "<= " : "< ") << max_->value;
  }
  return s.str();
}

}  // namespace grainbridge::workflows::params
