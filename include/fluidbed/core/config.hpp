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
// The checked entry points (`*_checked`) validate the same conditions and throw.
#define FLUIDBED_EXPECTS(condition) assert(condition)
