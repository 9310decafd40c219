#pragma once
// Named crash points for the tests that kill a run mid-stage (as a batch system or a power cut
// would) and check that nothing already written is lost. GRAINBRIDGE_FAILPOINT=<name> in the
// environment makes failPoint("<name>") send SIGKILL to this process (<name>:N on its Nth
// hit); unset, it costs one
// branch on a cached flag. Used at the boundaries that matter: inside a stage, after its
// artifacts are written, after the rename, inside the database commit.
#include <string_view>

namespace grainbridge::core {
void failPoint(std::string_view name);
}  // namespace grainbridge::core
