// fluidbed — the C interface's errors, catalogue, closure handles, metadata and parameters
// (fluidbed_c.h), over fluidbed::Registries.
#include <algorithm>
#include <array>
#include <cstring>
#include <new>
#include <string>
#include <string_view>
#include <utility>
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

// One closure of the catalogue: its family and the instance, presets with their parameters.
struct Entry {
  AnyClosure closure;
  std::string name;
};

template <std::size_t... family>
std::vector<Entry> every_closure(std::index_sequence<family...>) {
  std::vector<Entry> entries;
  const auto add = [&]<std::size_t f>(std::integral_constant<std::size_t, f>) {
    for (const auto& law : RegistryOf<f>::all()) {
      AnyClosure closure(std::in_place_index<f>, law);
      entries.push_back({closure, std::string(RegistryOf<f>::name_of(law))});
    }
  };
  (add(std::integral_constant<std::size_t, family>{}), ...);
  return entries;
}

// Built once, on first use (thread-safe), never changed.
const std::vector<Entry>& catalogue() {
  static const std::vector<Entry> entries = every_closure(std::make_index_sequence<family_count>{});
  return entries;
}

template <std::size_t... family>
constexpr std::array<std::string_view, family_count> family_texts(bool convention, std::index_sequence<family...>) {
  return {(convention ? RegistryOf<family>::family::convention : RegistryOf<family>::family::what)...};
}

// The family tags' texts as terminated strings (string_view of literals are terminated, but
// this does not rely on it).
const std::array<std::string, family_count>& family_strings(bool convention) {
  static const auto make = [](bool c) {
    std::array<std::string, family_count> out;
    const auto views = family_texts(c, std::make_index_sequence<family_count>{});
    for (std::size_t i = 0; i < family_count; ++i) out[i] = std::string(views[i]);
    return out;
  };
  static const std::array<std::string, family_count> what = make(false), conventions = make(true);
  return convention ? conventions : what;
}

// The validity intervals of a closure as (quantity, min, max); a drag law's box as two.
template <class Law>
std::vector<ValidityInterval> validity_of(const Law& law) {
  const auto v = law.validity();
  if constexpr (requires { v.voidage_min; })
    return {{"voidage", v.voidage_min, v.voidage_max}, {"reynolds", v.reynolds_min, v.reynolds_max}};
  else
    return {v.begin(), v.end()};
}

const fluidbed_closure& require(const fluidbed_closure* closure, std::string_view function) {
  if (closure == nullptr) throw InvalidArgument("fluidbed: " + std::string(function) + ": the closure is NULL");
  return *closure;
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
  }
  return "unknown fluidbed_status";
}

extern "C" const char* fluidbed_family_what(fluidbed_family family) {
  const auto f = static_cast<std::size_t>(family);
  return f < family_count ? family_strings(false)[f].c_str() : nullptr;
}

extern "C" const char* fluidbed_family_convention(fluidbed_family family) {
  const auto f = static_cast<std::size_t>(family);
  return f < family_count ? family_strings(true)[f].c_str() : nullptr;
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
    std::string known;
    for (const Entry& entry : catalogue()) {
      if (entry.name == name) {
        const std::string reference(visit_closure(entry.closure, [](const auto& l) { return l.reference(); }));
        *closure = new fluidbed_closure{entry.closure, entry.name, reference};
        return;
      }
      known += (known.empty() ? "" : ", ") + entry.name;
    }
    throw UnknownName("fluidbed: unknown closure '" + std::string(name) + "'; known: " + known);
  });
}

extern "C" fluidbed_closure* fluidbed_closure_copy(const fluidbed_closure* closure) {
  return closure == nullptr ? nullptr : new (std::nothrow) fluidbed_closure(*closure);
}

extern "C" void fluidbed_closure_destroy(fluidbed_closure* closure) { delete closure; }

extern "C" fluidbed_family fluidbed_closure_family(const fluidbed_closure* closure) {
  return closure == nullptr ? FLUIDBED_FAMILY_COUNT : static_cast<fluidbed_family>(closure->closure.index());
}

extern "C" const char* fluidbed_closure_name(const fluidbed_closure* closure) {
  return closure == nullptr ? nullptr : closure->name.c_str();
}

extern "C" const char* fluidbed_closure_reference(const fluidbed_closure* closure) {
  return closure == nullptr ? nullptr : closure->reference.c_str();
}

extern "C" size_t fluidbed_closure_validity_count(const fluidbed_closure* closure) {
  return closure == nullptr ? 0 : visit_closure(closure->closure, [](const auto& l) { return validity_of(l).size(); });
}

extern "C" fluidbed_status fluidbed_closure_validity(const fluidbed_closure* closure, size_t index,
                                                     const char** quantity, double* min, double* max,
                                                     fluidbed_error* error) {
  return guarded(error, [&] {
    const auto ranges = visit_closure(require(closure, "fluidbed_closure_validity").closure,
                                      [](const auto& l) { return validity_of(l); });
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
  return closure == nullptr ? 0 : visit_closure(closure->closure, []<class Law>(const Law&) {
    return fluidbed::parameters_of<Law>().size();
  });
}

extern "C" const char* fluidbed_closure_parameter_name(const fluidbed_closure* closure, size_t index) {
  if (closure == nullptr) return nullptr;
  return visit_closure(closure->closure, [&]<class Law>(const Law&) -> const char* {
    const auto list = fluidbed::parameters_of<Law>();
    // The names are literals in the closures' parameters(): static storage, terminated.
    return index < list.size() ? list[index].name.data() : nullptr;
  });
}

extern "C" fluidbed_status fluidbed_closure_get_parameter(const fluidbed_closure* closure, const char* name,
                                                          double* value, fluidbed_error* error) {
  return guarded(error, [&] {
    if (name == nullptr || value == nullptr)
      throw InvalidArgument("fluidbed: fluidbed_closure_get_parameter: name and value must not be NULL");
    visit_closure(require(closure, "fluidbed_closure_get_parameter").closure, [&]<class Law>(const Law& law) {
      const auto got = fluidbed::get_parameter(law, name);
      if (!got)
        throw UnknownParameter("fluidbed: " + closure->name + " has no parameter '" + std::string(name) +
                               "'; its parameters: " + fluidbed::parameter_names<Law>());
      *value = *got;
    });
  });
}

extern "C" fluidbed_status fluidbed_closure_set_parameter(fluidbed_closure* closure, const char* name, double value,
                                                          fluidbed_error* error) {
  return guarded(error, [&] {
    if (closure == nullptr || name == nullptr)
      throw InvalidArgument("fluidbed: fluidbed_closure_set_parameter: closure and name must not be NULL");
    visit_closure(closure->closure, [&]<class Law>(Law& law) {
      if (!fluidbed::get_parameter(law, name))
        throw UnknownParameter("fluidbed: " + closure->name + " has no parameter '" + std::string(name) +
                               "'; its parameters: " + fluidbed::parameter_names<Law>());
      fluidbed::set_parameter_checked(law, name, value);
    });
  });
}
