#pragma once
// Eigen's unsupported Levenberg-Marquardt (MINPACK lmder port), included as a system header so
// that -Werror applies to our code only (DESIGN.md "Build and CI": third-party includes are
// SYSTEM). Include this wrapper, never the unsupported header directly.
#pragma GCC system_header
#include <unsupported/Eigen/NonLinearOptimization>
