// fluidbed — configuration: host/device annotation and debug-only precondition checks.
#pragma once

#include <cassert>

// Every per-cell function is usable from CUDA/HIP device code when the headers are
// compiled by a device compiler; on the host the macro expands to nothing.
#if defined(__CUDACC__) || defined(__HIPCC__)
#define FLUIDBED_HOST_DEVICE __host__ __device__
#else
#define FLUIDBED_HOST_DEVICE
#endif

// Hot-path preconditions: checked with assert() in debug builds, free in release builds.
// The checked entry points (`*_checked`) validate the same conditions and throw. Under
// NDEBUG the condition stays an unevaluated operand, so a parameter that only appears in a
// precondition is still "used" (no -Wunused-parameter in a release build of the host).
#ifdef NDEBUG
#define FLUIDBED_EXPECTS(condition) static_cast<void>(sizeof(!(condition)))
#else
#define FLUIDBED_EXPECTS(condition) assert(condition)
#endif
