// fluidbed — the C interface's errors, catalogue, closure handles, metadata and parameters
// (fluidbed_c.h), over the bindings' shared layer (bindings/common/any_closure.hpp).
#include <algorithm>
#include <array>
#include <cstring>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "closure_handle.hpp"

namespace fluidbed::c_api {

void set_error(fluidbed_error* error, fluidbed_status status, std::size_t index, std::string_view message) {
  if (error == nullptr) return;
  error->status = status;
  error->index = index;
  const std::size_t n = std::min(message.size(), sizeof error->message - 1);
  std::memcpy(error->message, message.data(), n);
  error->message[n] = '\0';
}

namespace {

// The families' texts as terminated strings, built once.
const std::array<std::string, family_count>& family_texts(bool convention) {
  static const auto make = [](bool c) {
    std::array<std::string, family_count> texts;
    for (std::size_t f = 0; f < family_count; ++f)
      texts[f] = std::string(c ? family_convention(f) : family_what(f));
    return texts;
  };
  static const std::array<std::string, family_count> what = make(false), conventions = make(true);
  return convention ? conventions : what;
}

}  // namespace

}  // namespace fluidbed::c_api

using namespace fluidbed::c_api;

extern "C" const char* fluidbed_status_name(fluidbed_status status) {
  switch (status) {
    case FLUIDBED_OK: return "FLUIDBED_OK";
    case FLUIDBED_UNKNOWN_NAME: return "FLUIDBED_UNKNOWN_NAME";
    case FLUIDBED_UNKNOWN_PARAMETER: return "FLUIDBED_UNKNOWN_PARAMETER";
    case FLUIDBED_DOMAIN_ERROR: return "FLUIDBED_DOMAIN_ERROR";
    case FLUIDBED_INVALID_ARGUMENT: return "FLUIDBED_INVALID_ARGUMENT";
    case FLUIDBED_INTERNAL_ERROR: return "FLUIDBED_INTERNAL_ERROR";
    default: break;
  }
  return "unknown fluidbed_status";
}

extern "C" const char* fluidbed_family_what(fluidbed_family family) {
  const auto f = static_cast<std::size_t>(family);
  return f < family_count ? family_texts(false)[f].c_str() : nullptr;
}

extern "C" const char* fluidbed_family_convention(fluidbed_family family) {
  const auto f = static_cast<std::size_t>(family);
  return f < family_count ? family_texts(true)[f].c_str() : nullptr;
}

extern "C" size_t fluidbed_closure_count(void) { return catalogue().size(); }

extern "C" const char* fluidbed_closure_name_at(size_t index) {
  return index < catalogue().size() ? catalogue()[index].name.c_str() : nullptr;
}

extern "C" fluidbed_status fluidbed_closure_create(const char* name, fluidbed_closure** closure, fluidbed_error* error) {
  return guarded(error, [&] {
    if (closure == nullptr || name == nullptr)
      throw InvalidArgument("fluidbed: fluidbed_closure_create: name and closure must not be NULL");
    *closure = nullptr;
    *closure = new fluidbed_closure{make_closure(name)};
  });
}

extern "C" fluidbed_closure* fluidbed_closure_copy(const fluidbed_closure* closure) {
  return closure == nullptr ? nullptr : new (std::nothrow) fluidbed_closure(*closure);
}

extern "C" void fluidbed_closure_destroy(fluidbed_closure* closure) { delete closure; }

extern "C" fluidbed_family fluidbed_closure_family(const fluidbed_closure* closure) {
  return closure == nullptr ? FLUIDBED_FAMILY_COUNT : static_cast<fluidbed_family>(closure->family());
}

extern "C" const char* fluidbed_closure_name(const fluidbed_closure* closure) {
  return closure == nullptr ? nullptr : closure->name.c_str();
}

extern "C" const char* fluidbed_closure_reference(const fluidbed_closure* closure) {
  return closure == nullptr ? nullptr : closure->reference.c_str();
}

extern "C" size_t fluidbed_closure_validity_count(const fluidbed_closure* closure) {
  return closure == nullptr ? 0 : closure_validity(*closure).size();
}

extern "C" fluidbed_status fluidbed_closure_validity(const fluidbed_closure* closure, size_t index,
                                                     const char** quantity, double* min, double* max,
                                                     fluidbed_error* error) {
  return guarded(error, [&] {
    const auto ranges = closure_validity(closure_of(closure, "fluidbed_closure_validity"));
    if (index >= ranges.size())
      throw InvalidArgument("fluidbed: " + closure->name + " has " + std::to_string(ranges.size()) +
                            " validity ranges, not " + std::to_string(index + 1));
    // The quantities' names are literals of the closures' types: static storage, terminated.
    if (quantity != nullptr) *quantity = ranges[index].quantity.data();
    if (min != nullptr) *min = ranges[index].min;
    if (max != nullptr) *max = ranges[index].max;
  });
}

extern "C" size_t fluidbed_closure_parameter_count(const fluidbed_closure* closure) {
  return closure == nullptr ? 0 : parameter_names_of(*closure).size();
}

extern "C" const char* fluidbed_closure_parameter_name(const fluidbed_closure* closure, size_t index) {
  if (closure == nullptr) return nullptr;
  const auto names = parameter_names_of(*closure);
  // The names are literals in the closures' parameters(): static storage, terminated.
  return index < names.size() ? names[index].data() : nullptr;
}

extern "C" fluidbed_status fluidbed_closure_get_parameter(const fluidbed_closure* closure, const char* name,
                                                          double* value, fluidbed_error* error) {
  return guarded(error, [&] {
    if (name == nullptr || value == nullptr)
      throw InvalidArgument("fluidbed: fluidbed_closure_get_parameter: name and value must not be NULL");
    *value = get_parameter(closure_of(closure, "fluidbed_closure_get_parameter"), name);
  });
}

extern "C" fluidbed_status fluidbed_closure_set_parameter(fluidbed_closure* closure, const char* name, double value,
                                                          fluidbed_error* error) {
  return guarded(error, [&] {
    if (closure == nullptr || name == nullptr)
      throw InvalidArgument("fluidbed: fluidbed_closure_set_parameter: closure and name must not be NULL");
    set_parameter(*closure, name, value);
  });
}
