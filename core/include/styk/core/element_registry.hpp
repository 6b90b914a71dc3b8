// ElementRegistry: element formulations by type name. Owned by whoever runs an analysis and passed
// explicitly (no global registry). Built-in elements and plug-ins register through the same add().
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk {

class ElementRegistry {
 public:
  struct Entry {
    std::unique_ptr<const TElement> element;
    std::string source;  // "built-in" or the path of the plug-in that registered it
  };

  // Registers a formulation under element->name(). A duplicate name throws std::invalid_argument
  // naming both sources.
  void add(std::unique_ptr<const TElement> element, const std::string& source);

  // nullptr when no formulation of that (case-insensitive) name is registered.
  const TElement* find(const std::string& name) const;
  const Entry* entry(const std::string& name) const;

  // Names in alphabetical order.
  std::vector<std::string> names() const;

  // Where plug-ins were searched (for "unknown element type" messages); empty if none.
  std::string searched_paths;

 private:
  std::map<std::string, Entry> entries_;
};

}  // namespace styk
