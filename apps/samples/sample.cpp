#include "sample.hpp"

#include <algorithm>
#include <utility>

namespace impetus::samples {
namespace {

struct Registry {
  std::vector<SampleInfo> samples;
  bool sorted = false;
};

Registry& registry() {
  static Registry r; // constructed on first use: safe from any static registrar
  return r;
}

} // namespace

SampleRegistrar::SampleRegistrar(std::string category, std::string name, std::string description,
                                 SampleFactory create) {
  Registry& r = registry();
  r.samples.push_back({std::move(category), std::move(name), std::move(description), std::move(create)});
  r.sorted = false;
}

const std::vector<SampleInfo>& sampleRegistry() {
  Registry& r = registry();
  if (!r.sorted) {
    // Registration order is link order; sorting makes the list the same on every build.
    std::stable_sort(r.samples.begin(), r.samples.end(), [](const SampleInfo& a, const SampleInfo& b) {
      return a.category != b.category ? a.category < b.category : a.name < b.name;
    });
    r.sorted = true;
  }
  return r.samples;
}

std::optional<std::size_t> findSample(std::string_view fullName) {
  const std::vector<SampleInfo>& all = sampleRegistry();
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].fullName() == fullName) {
      return i;
    }
  }
  return std::nullopt;
}

} // namespace impetus::samples
