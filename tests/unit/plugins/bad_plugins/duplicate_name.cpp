// A plug-in registering two types, "DUPOK" (new) and "C3D8" (a built-in name): the SDK must
// reject the whole registration, so DUPOK must not appear either.
#include <memory>
#include <string>

#include "styk/elements/c3d8.hpp"
#include "styk/plugin/sdk.hpp"

namespace {

class Renamed : public styk::C3D8 {
 public:
  explicit Renamed(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }

 private:
  std::string name_;
};

styk::plugin::ElementList make_elements() {
  styk::plugin::ElementList elements;
  elements.push_back(std::make_unique<Renamed>("DUPOK"));
  elements.push_back(std::make_unique<Renamed>("C3D8"));
  return elements;
}

}  // namespace

STYK_PLUGIN(make_elements)
