// Every closure of every family, through the registries (registries.hpp): names unique across
// the whole library, lookup by name, unknown names rejected with the list, and the metadata of
// each closure (reference, validity) in one place — its type — against the catalogue in
// docs/closures/*.md, which must give, in the section that names the closure, the DOI and the
// year of its reference.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "closure_metadata.hpp"
#include "fluidbed/registries.hpp"

namespace {

using namespace fluidbed;

// Every closure instance of every registry, as (name, reference, validity intervals).
std::vector<test::ClosureMetadata> every_closure() {
  std::vector<test::ClosureMetadata> entries;
  for (const test::FamilyMetadata& family : test::every_family())
    entries.insert(entries.end(), family.closures.begin(), family.closures.end());
  return entries;
}

// The docs' sections (from one "### " heading to the next), all catalogue pages together.
std::vector<std::string> catalogue_sections() {
  const std::filesystem::path docs = std::filesystem::path(FLUIDBED_REFERENCE_DIR) / ".." / ".." / "docs" / "closures";
  std::vector<std::string> sections;
  for (const auto& page : std::filesystem::directory_iterator(docs)) {
    std::ifstream in(page.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::size_t start = text.find("\n### ");
    while (start != std::string::npos) {
      const std::size_t next = text.find("\n#", start + 1);
      sections.push_back(text.substr(start, next == std::string::npos ? std::string::npos : next - start));
      start = text.find("\n### ", start + 1);
    }
  }
  return sections;
}

// A user's own drag law, β_classical = 1 − ε (defined outside the library).
struct MyDrag : drag::DragLaw<MyDrag> {
  static constexpr drag::Buoyancy native_buoyancy = drag::Buoyancy::classical;
  constexpr std::string_view name() const { return "MyDrag"; }
  constexpr std::string_view reference() const { return "a user's own law"; }
  constexpr drag::ValidityRange validity() const { return {0.4, 1.0, 0.0, 1.0}; }
  template <class S, class T>
  S native_beta(const S& voidage, const S&, const Fluid<T>&, const T&) const {
    return 1 - voidage;
  }
};

}  // namespace

TEST_CASE("registries: every closure's name is unique across the library and found by name") {
  std::set<std::string> seen;
  for (const test::ClosureMetadata& e : every_closure()) {
    INFO("closure ", e.name);
    CHECK(seen.insert(e.name).second);
  }
  Registries::for_each([](auto registry) {
    using Registry = typename decltype(registry)::type;
    static_assert(Registry::names_are_unique());
    for (const auto& law : Registry::all()) {
      const auto found = Registry::find(Registry::name_of(law));
      REQUIRE(found.has_value());
      CHECK(Registry::name_of(*found) == Registry::name_of(law));
    }
    CHECK_FALSE(Registry::find("NoSuchClosure").has_value());
    CHECK_THROWS_WITH_AS(Registry::make("NoSuchClosure"),
                         doctest::Contains(("'NoSuchClosure'; known: " + std::string(Registry::name_of(Registry::all()[0])))
                                               .c_str()),
                         std::invalid_argument);
  });
}

TEST_CASE("registries: a user's law joins a family without editing the library") {
  using MyDragLaws = drag::DragLaws::with<MyDrag>;
  static_assert(MyDragLaws::size == drag::DragLaws::size + 1);
  const auto law = MyDragLaws::make("MyDrag");
  const drag::DragState<double> state{0.75, 0.1, {1.2, 1.8e-5}, 1e-4};
  CHECK(std::visit([&](const auto& l) { return l(state).classical(); }, law) == 0.25);
  CHECK(MyDragLaws::find("Ergun").has_value());
}

TEST_CASE("registries: each closure's metadata — reference and validity — is well formed and catalogued") {
  const std::vector<std::string> sections = catalogue_sections();
  const std::regex year(R"(\((1[89]\d\d|20\d\d)\))");
  for (const test::ClosureMetadata& e : every_closure()) {
    INFO("closure ", e.name, ", reference: ", e.reference);
    std::smatch year_match;
    REQUIRE(std::regex_search(e.reference, year_match, year));
    // One spelling per quantity across the library: the argument names of the closures.
    static const std::set<std::string> quantities{"voidage",      "solid_fraction", "total_solid_fraction",
                                                  "reynolds",     "terminal_reynolds", "archimedes",
                                                  "wall_ratio",   "sphericity"};
    for (const ValidityInterval& range : e.validity) {
      INFO("validity of ", range.quantity);
      CHECK(quantities.count(std::string(range.quantity)) == 1);
      CHECK(range.min <= range.max);
    }
    // The catalogue section that gives the run-time name "Name".
    std::vector<const std::string*> matching;
    for (const std::string& section : sections)
      if (section.find("\"" + e.name + "\"") != std::string::npos) matching.push_back(&section);
    REQUIRE(matching.size() >= 1);
    const std::string& section = *matching.front();
    CHECK(section.find(year_match[1].str()) != std::string::npos);
    for (const std::string& doi : test::dois_of(e.reference)) {
      INFO("DOI ", doi);
      CHECK(section.find(doi) != std::string::npos);
    }
  }
}
