#include "styk/studies/study/families.hpp"

#include <algorithm>

namespace styk::studies {
namespace {

// Registered types that are not families of their own in the studies, and why.
struct Excluded {
  const char* name;
  const char* reason;
};
constexpr Excluded kExcluded[] = {
    {"C3D8R0", "C3D8R without hourglass control: a demonstration of hourglassing"},
    {"CPE4", "plane element"},
    {"CPE8", "plane element"},
    {"CPS4", "plane element"},
    {"CPS8", "plane element"},
    {"T3D2", "truss"},
};

}  // namespace

const std::vector<ElementFamily>& family_catalogue() {
  static const std::vector<ElementFamily> families = {
      {"C3D8", 1, "whole mesh"},
      {"C3D8R", 1, "whole mesh"},
      {"C3D8I", 1, "whole mesh"},
      {"C3D14", 1, "whole mesh (C3D8 with face-centre nodes)"},
      {"C3D20", 2, "whole mesh"},
      {"C3D20R", 2, "whole mesh"},
      {"C3D27", 2, "whole mesh"},
      {"C3D21", 2,
       "the builder's contact layer, C3D20 elsewhere (one element thick: every element)"},
      {"C3D28", 2,
       "the builder's contact layer, C3D20 elsewhere (one element thick: every element)"},
  };
  return families;
}

const ElementFamily* find_family(const std::string& name) {
  for (const ElementFamily& f : family_catalogue())
    if (f.name == name) return &f;
  return nullptr;
}

std::vector<ElementFamily> available_families(const ElementRegistry& registry,
                                              std::vector<std::string>* unavailable) {
  std::vector<ElementFamily> out;
  for (const ElementFamily& f : family_catalogue()) {
    if (registry.find(f.name))
      out.push_back(f);
    else if (unavailable)
      unavailable->push_back(f.name + ": not registered (element plug-ins not loaded?)");
  }
  if (unavailable)
    for (const std::string& name : registry.names()) {
      if (find_family(name)) continue;
      const auto excluded = std::find_if(std::begin(kExcluded), std::end(kExcluded),
                                         [&](const Excluded& e) { return name == e.name; });
      if (excluded == std::end(kExcluded))
        unavailable->push_back(name + ": registered, but not in the studies' family table yet");
    }
  return out;
}

}  // namespace styk::studies
