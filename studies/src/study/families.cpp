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
    {"B31R", "CalculiX's name of B31 with its default (reduced) rule: the B31 family"},
    {"B32R", "CalculiX's name of B32 with its default (reduced) rule: the B32 family"},
};

constexpr const char* kBeamMeshing = "cantilever deck, RECT section, n elements along the axis";
constexpr const char* kPlateMeshing = "quarter-plate deck, n x n elements";
constexpr const char* kTriangleMeshing = "quarter-plate deck, n x n cells cut into 2 triangles";

ElementFamily solid(const char* name, int order, const char* meshing) {
  return {name, order, meshing, ElementKind::Solid, "", ""};
}

ElementFamily beam(const char* name, const char* type, int order, const char* integration) {
  return {name, order, kBeamMeshing, ElementKind::Beam, type, integration};
}

ElementFamily shell(const char* name, int order, const char* meshing = kPlateMeshing) {
  return {name, order, meshing, ElementKind::Shell, "", ""};
}

}  // namespace

const std::vector<ElementFamily>& family_catalogue() {
  static const std::vector<ElementFamily> families = {
      solid("C3D8", 1, "whole mesh"),
      solid("C3D8R", 1, "whole mesh"),
      solid("C3D8I", 1, "whole mesh"),
      solid("C3D14", 1, "whole mesh (C3D8 with face-centre nodes)"),
      solid("C3D20", 2, "whole mesh"),
      solid("C3D20R", 2, "whole mesh"),
      solid("C3D27", 2, "whole mesh"),
      solid("C3D21", 2,
            "the builder's contact layer, C3D20 elsewhere (one element thick: every element)"),
      solid("C3D28", 2,
            "the builder's contact layer, C3D20 elsewhere (one element thick: every element)"),
      beam("B31", "B31", 1, ""),
      beam("B31-FULL", "B31", 1, "FULL"),
      beam("B32", "B32", 2, ""),
      beam("B32-FULL", "B32", 2, "FULL"),
      beam("B21", "B21", 1, ""),
      beam("B21-FULL", "B21", 1, "FULL"),
      beam("B22", "B22", 2, ""),
      beam("B22-FULL", "B22", 2, "FULL"),
      shell("S4", 1),
      shell("S4R", 1, "quarter-plate deck, n x n elements (S4R is S4: docs/elements.md)"),
      shell("S8", 2),
      shell("S8R", 2),
      shell("S9", 2),
      shell("S9R", 2),
      shell("STRI3", 1, kTriangleMeshing),
  };
  return families;
}

std::vector<ElementFamily> families_of_kind(ElementKind kind) {
  std::vector<ElementFamily> out;
  for (const ElementFamily& f : family_catalogue())
    if (f.kind == kind) out.push_back(f);
  return out;
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
    if (registry.find(f.type()))
      out.push_back(f);
    else if (unavailable)
      unavailable->push_back(f.name + ": not registered (element plug-ins not loaded?)");
  }
  if (unavailable)
    for (const std::string& name : registry.names()) {
      if (find_family(name)) continue;  // every type is the name of its default family
      const auto excluded = std::find_if(std::begin(kExcluded), std::end(kExcluded),
                                         [&](const Excluded& e) { return name == e.name; });
      if (excluded == std::end(kExcluded))
        unavailable->push_back(name + ": registered, but not in the studies' family table yet");
    }
  return out;
}

}  // namespace styk::studies
