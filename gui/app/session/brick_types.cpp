#include "session/brick_types.hpp"

#include <optional>

#include "styk/mesher/convert.hpp"

namespace styk::gui {
namespace {

const char* const kBricks[] = {"C3D20", "C3D8"};

}  // namespace

std::vector<std::string> brick_types(const ElementRegistry& registry) {
  std::vector<std::string> out;
  for (const char* brick : kBricks)
    if (registry.find(brick)) out.push_back(brick);
  for (const char* brick : kBricks)
    for (const std::string& type : mesher::conversions_from(registry, brick)) out.push_back(type);
  return out;
}

std::string brick_type_list(const ElementRegistry& registry) {
  const std::vector<std::string> types = brick_types(registry);
  std::string out;
  for (std::size_t k = 0; k < types.size(); ++k)
    out += (k == 0 ? "" : (k + 1 == types.size() ? " or " : ", ")) + types[k];
  return out;
}

std::string brick_of(const ElementRegistry& registry, const std::string& type) {
  const TElement* element = registry.find(type);
  const std::optional<ElementConversion> how = element ? element->conversion() : std::nullopt;
  return how ? to_upper(how->base) : to_upper(type);
}

bool needs_layer_side(const ElementRegistry& registry, const std::string& type) {
  return mesher::converts_a_layer(registry, type);
}

void convert_bricks(mesher::Mesh& mesh, const ElementRegistry& registry, const std::string& type,
                    const std::string& layer_surface) {
  if (brick_of(registry, type) == to_upper(type)) return;
  mesher::convert_elements(mesh, registry, type,
                           needs_layer_side(registry, type) ? layer_surface : std::string());
}

}  // namespace styk::gui
