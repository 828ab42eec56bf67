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
