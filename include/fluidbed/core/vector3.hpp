// fluidbed — the small 3-vector algebra the force closures need (device-friendly, no Eigen).
#pragma once

#include <array>

#include "config.hpp"

namespace fluidbed {

// A Cartesian 3-vector; host codes pass their own components in any right-handed frame.
template <class T>
using Vector3 = std::array<T, 3>;

template <class T>
FLUIDBED_HOST_DEVICE constexpr T dot(const Vector3<T>& a, const Vector3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr Vector3<T> cross(const Vector3<T>& a, const Vector3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr Vector3<T> scaled(const T& factor, const Vector3<T>& a) {
  return {factor * a[0], factor * a[1], factor * a[2]};
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr Vector3<T> difference(const Vector3<T>& a, const Vector3<T>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

}  // namespace fluidbed
