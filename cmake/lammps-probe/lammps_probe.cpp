// Links against liblammps: the call must resolve, it is never run.
#include <library.h>

int main() { return lammps_version(nullptr) > 0 ? 0 : 1; }
