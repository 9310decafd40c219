#pragma once
// Columns of an engine stage's series.csv come from observers: each names its columns once and
// appends their values for the engine's current state whenever the driver samples it. The
// driver writes `time,step` first, then every observer's columns in the order they were added.
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace grainbridge::workflows::driver {

// One row being written: values in full precision (17 significant digits, so a value read back
// is the value written), each after a comma.
class SeriesRow {
 public:
  explicit SeriesRow(std::ostream& out) : out_(out) {}
  template <class T>
  requires std::is_arithmetic_v<T> SeriesRow& add(T value) {
    out_ << ',' << value;
    return *this;
  }

 private:
  std::ostream& out_;
};

class SeriesColumns {
 public:
  virtual ~SeriesColumns() = default;
  [[nodiscard]] virtual std::vector<std::string> names() const = 0;
  // Appends one value per name, in the order of names(), for the engine's current state.
  virtual void sample(SeriesRow& row) = 0;
};

}  // namespace grainbridge::workflows::driver
