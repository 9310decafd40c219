#include "db/BusyError.hpp"

namespace grainbridge::db {

// Out of line so the vtable and type_info have one home (the db library).
BusyError::BusyError(const std::string& what) : grainbridge::Error(what) {}

}  // namespace grainbridge::db
