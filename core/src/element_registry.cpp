#include "styk/core/element_registry.hpp"

#include <stdexcept>

namespace styk {

void ElementRegistry::add(std::unique_ptr<const TElement> element, const std::string& source) {
  if (!element) throw std::invalid_argument("ElementRegistry::add: null element");
  const std::string key = to_upper(element->name());
  const auto it = entries_.find(key);
  if (it != entries_.end())
    throw std::invalid_argument("element type " + key + " from " + source +
                                " is already registered by " + it->second.source);
  entries_.emplace(key, Entry{std::move(element), source});
}

const ElementRegistry::Entry* ElementRegistry::entry(const std::string& name) const {
  const auto it = entries_.find(to_upper(name));
  return it == entries_.end() ? nullptr : &it->second;
}

const TElement* ElementRegistry::find(const std::string& name) const {
  const Entry* e = entry(name);
  return e ? e->element.get() : nullptr;
}

std::vector<std::string> ElementRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& kv : entries_) out.push_back(kv.first);
  return out;
}

}  // namespace styk
