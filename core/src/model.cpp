#include "styk/core/model.hpp"

#include <cctype>

namespace styk {

std::string to_upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

int Model::node_index(Id id) const {
  const auto it = node_by_id_.find(id);
  return it == node_by_id_.end() ? -1 : it->second;
}

int Model::element_index(Id id) const {
  const auto it = element_by_id_.find(id);
  return it == element_by_id_.end() ? -1 : it->second;
}

int Model::material_index(const std::string& name) const {
  const std::string key = to_upper(name);
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == key) return static_cast<int>(i);
  return -1;
}

const NodeSet* Model::find_nset(const std::string& name) const {
  const auto it = nsets.find(to_upper(name));
  return it == nsets.end() ? nullptr : &it->second;
}

const ElementSet* Model::find_elset(const std::string& name) const {
  const auto it = elsets.find(to_upper(name));
  return it == elsets.end() ? nullptr : &it->second;
}

int Model::add_node(Id id, const Vec3& x, const SourceLoc& where) {
  const int index = node_count();
  const auto [it, inserted] = node_by_id_.emplace(id, index);
  if (!inserted)
    throw InputError(where, "node " + std::to_string(id) + " is defined twice (first at " +
                                "node index " + std::to_string(it->second + 1) + ")");
  node_ids.push_back(id);
  coords.push_back(x);
  return index;
}

int Model::add_element(Id id, const std::string& type, const std::vector<int>& node_indices,
                       const SourceLoc& where) {
  const int index = element_count();
  const auto [it, inserted] = element_by_id_.emplace(id, index);
  if (!inserted)
    throw InputError(where, "element " + std::to_string(id) + " is defined twice (first at " +
                                elements[it->second].where.str() + ")");
  Element e;
  e.id = id;
  e.type = type;
  e.first_node = static_cast<int>(connectivity.size());
  e.node_count = static_cast<int>(node_indices.size());
  e.where = where;
  elements.push_back(std::move(e));
  connectivity.insert(connectivity.end(), node_indices.begin(), node_indices.end());
  return index;
}

}  // namespace styk

namespace styk {

void BodyAcceleration::add(const BodyLoad& load) {
  if (load.kind == BodyLoad::Kind::Gravity) {
    for (int d = 0; d < 3; ++d) gravity[d] += load.magnitude * load.direction[d];
    return;
  }
  rotations.push_back({load.magnitude, load.point, load.direction});
}

Vec3 BodyAcceleration::at(const Vec3& x) const {
  Vec3 a = gravity;
  for (const Rotation& r : rotations) {
    // omega^2 times the part of (x - point) perpendicular to the axis.
    Vec3 d{x[0] - r.point[0], x[1] - r.point[1], x[2] - r.point[2]};
    const double along = d[0] * r.axis[0] + d[1] * r.axis[1] + d[2] * r.axis[2];
    for (int k = 0; k < 3; ++k) a[k] += r.omega_squared * (d[k] - along * r.axis[k]);
  }
  return a;
}

}  // namespace styk
