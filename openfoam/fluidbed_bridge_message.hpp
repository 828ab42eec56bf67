// fluidbed — the C++20 sides of the OpenFOAM plugin's C interfaces report errors as text in a
// caller's buffer (exceptions never cross them).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>

namespace fluidbed::openfoam {

// Writes `text` into message[0, message_size), truncated and always terminated.
inline void write_message(std::string_view text, char* message, std::size_t message_size) {
  if (message == nullptr || message_size == 0) return;
  const std::size_t n = std::min(text.size(), message_size - 1);
  std::memcpy(message, text.data(), n);
  message[n] = '\0';
}

// The message for a dictionary entry `key` that is not a parameter of the law `law`, listing the
// parameters it has (`known`, comma-separated; empty: none).
inline std::string unknown_parameter(std::string_view law, std::string_view key, std::string_view known) {
  return "fluidbed: " + std::string(law) + " has no parameter '" + std::string(key) +
         "'; its parameters: " + (known.empty() ? std::string("none") : std::string(known));
}

}  // namespace fluidbed::openfoam
