#pragma once
// The schema's history as an ordered list of SQL scripts: schema version N is the state after
// the first N scripts, recorded in PRAGMA user_version. Scripts are append-only: a released
// script never changes (databases in the field already ran it); a schema change is a new one.
#include <string>
#include <vector>

namespace grainbridge::db {

const std::vector<std::string>& migrations();

}  // namespace grainbridge::db
