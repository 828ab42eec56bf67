// fluidbed fuzzing — decoding a libFuzzer input into numbers, and reporting contract violations.
//
// Both fuzzers read their input through `Input`, which turns bytes into
//   * raw values (memcpy of the bytes): every bit pattern occurs, NaN payloads, ±∞, subnormals,
//     ±huge and negative values included — what the checked entry points and statuses must handle;
//   * edge values (`special`): the handful of values (0, −0, ±∞, NaN, the smallest subnormal, the
//     largest finite, ε, 1) that raw bytes reach only by luck;
//   * mapped values (`uniform`, `log_uniform`): physically plausible states, where the hot paths'
//     documented guarantees (finite, non-negative) must hold.
// Past the end of the input every read yields zero bytes, so any input decodes completely and a
// short input means "the first choice of everything": libFuzzer can grow inputs byte by byte.
#pragma once

#include <cinttypes>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace fluidbed::fuzz {

class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte() { return position_ < size_ ? data_[position_++] : 0; }

  // `count` bytes into `out`, zero-padded past the end.
  void bytes(void* out, std::size_t count) {
    const std::size_t available = position_ < size_ ? size_ - position_ : 0;
    const std::size_t taken = count < available ? count : available;
    if (taken > 0) std::memcpy(out, data_ + position_, taken);
    std::memset(static_cast<unsigned char*>(out) + taken, 0, count - taken);
    position_ += taken;
  }

  std::uint32_t u32() {
    std::uint32_t x;
    bytes(&x, sizeof x);
    return x;
  }

  bool boolean() { return byte() & 1; }

  // An integer in [low, high] (high - low < 256).
  int integer(int low, int high) { return low + int(byte() % unsigned(high - low + 1)); }

  // Every bit pattern of T.
  template <class T>
  T raw() {
    T x;
    bytes(&x, sizeof x);
    return x;
  }

  // One of the values where floating-point code most often breaks.
  template <class T>
  T special() {
    using limits = std::numeric_limits<T>;
    const T table[] = {T(0),
                       -T(0),
                       T(1),
                       T(-1),
                       limits::infinity(),
                       -limits::infinity(),
                       limits::quiet_NaN(),
                       limits::denorm_min(),
                       -limits::denorm_min(),
                       limits::min(),
                       limits::max(),
                       limits::lowest(),
                       limits::epsilon(),
                       T(1) - limits::epsilon() / T(2),
                       T(1) + limits::epsilon(),
                       T(0.5)};
    return table[byte() % (sizeof table / sizeof table[0])];
  }

  // Raw bytes three times in four, an edge value otherwise.
  template <class T>
  T garbage() {
    return byte() % 4 == 0 ? special<T>() : raw<T>();
  }

  // A number in [0, 1], both ends included (all-zero and all-one bytes map to them exactly).
  double unit() { return double(u32()) / double(std::numeric_limits<std::uint32_t>::max()); }

  double uniform(double low, double high) {
    const double u = unit();
    return u == 1.0 ? high : low + (high - low) * u;  // the end points exactly
  }

  // Log-uniform in [low, high], 0 < low < high: sizes, viscosities, Reynolds numbers.
  double log_uniform(double low, double high) {
    const double u = unit();
    return u == 1.0 ? high : low * std::pow(high / low, u);
  }

  std::size_t consumed() const { return position_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

// Prints what was violated and aborts: libFuzzer then saves the input as a crash reproducer.
[[noreturn]] inline void violation(const char* file, int line, const char* condition, const char* format, ...) {
  std::fprintf(stderr, "\n== fluidbed contract violation at %s:%d\n   condition: %s\n   ", file, line, condition);
  va_list arguments;
  va_start(arguments, format);
  std::vfprintf(stderr, format, arguments);
  va_end(arguments);
  std::fprintf(stderr, "\n");
  std::abort();
}

// Once per process and message: behaviour that breaks no contract but is worth a look (a status
// the documentation calls "never observed").
inline void note_once(const char* message, bool& printed) {
  if (printed) return;
  printed = true;
  std::fprintf(stderr, "== fluidbed fuzz note: %s\n", message);
}

template <class T>
bool is_finite(const T& x) {
  return std::isfinite(x);
}

// |a − b| <= tolerance · scale, false for NaN; an infinite scale (overflowed magnitudes) accepts.
template <class T>
bool close(const T& a, const T& b, const T& tolerance, const T& scale) {
  if (!std::isfinite(scale)) return !std::isnan(a) && !std::isnan(b);
  return std::abs(a - b) <= tolerance * scale;
}

}  // namespace fluidbed::fuzz

#define FUZZ_CHECK(condition, ...) \
  ((condition) ? void(0) : ::fluidbed::fuzz::violation(__FILE__, __LINE__, #condition, __VA_ARGS__))
