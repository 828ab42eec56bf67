// fluidbed — Eigen's Core module, without the warnings of Eigen's own headers.
//
// Eigen 3.4's AVX and AVX-512 packet math declares variables it never uses (PacketMath.h, at
// -march=native: -Wunused-variable) and its Half.h uses a compound literal (clang -Wpedantic:
// -Wc99-extensions). A host that gets Eigen through -I (pkg-config), not -isystem, and builds
// with -Wall -Wextra -Werror would fail on them, in code that is not ours. They are silenced for
// Eigen's headers only: the pop restores the host's settings before any fluidbed code.
// The headers that need Eigen (batched.hpp, eigen_backend.hpp) include it through this one.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-variable"
#if defined(__clang__)
#pragma GCC diagnostic ignored "-Wc99-extensions"
#endif
#endif

#include <Eigen/Core>

#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic pop
#endif

// GCC 12 at -O3 with AVX-512 (e.g. -march=native) reports, inside its own avx512fintrin.h once
// Eigen's packet code is inlined into ours, uses of uninitialized values (GCC PR 105593: the
// `__Y = __Y` idiom of its intrinsics) and array bounds exceeded by Eigen's 512-bit loads of
// fixed-capacity vectors (loads the vector's run-time size rules out): false positives that
// would stop a host's -Werror build of invert_batched() or invert_eigen(). The code of
// batched.hpp and eigen_backend.hpp sits between these two macros, which silence those three
// warnings in that configuration only (GCC, AVX-512 enabled); every other build keeps them.
#if defined(__GNUC__) && !defined(__clang__) && defined(__AVX512F__)
#define FLUIDBED_EIGEN_CODE_BEGIN                                 \
  _Pragma("GCC diagnostic push")                                  \
  _Pragma("GCC diagnostic ignored \"-Wuninitialized\"")           \
  _Pragma("GCC diagnostic ignored \"-Wmaybe-uninitialized\"")     \
  _Pragma("GCC diagnostic ignored \"-Warray-bounds\"")
#define FLUIDBED_EIGEN_CODE_END _Pragma("GCC diagnostic pop")
#else
#define FLUIDBED_EIGEN_CODE_BEGIN
#define FLUIDBED_EIGEN_CODE_END
#endif
