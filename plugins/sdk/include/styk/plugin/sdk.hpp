// The C++ side of the plug-in SDK: turns "here are my element types" into the C entry point of
// core/include/styk/core/plugin_api.h. A plug-in writes a factory and one macro line:
//
//   styk::plugin::ElementList make_elements() { ... return list of std::make_unique<MyElement>() }
//   STYK_PLUGIN(make_elements)
//
// The macro defines `extern "C" int styk_plugin_register(const StykPluginHost*, StykPluginReply*)`
// which (1) answers with its ABI version and stops if the host's differs, (2) builds the elements,
// (3) checks every name against the host registry and within the list, and only then (4) adds
// them all, so a clash registers nothing; every exception is turned into STYK_PLUGIN_FAILED with
// its what() text (no exception crosses the C boundary).
#pragma once

#include <cstdio>
#include <exception>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/plugin_api.h"

namespace styk::plugin {

using ElementList = std::vector<std::unique_ptr<const TElement>>;
using ElementFactory = ElementList (*)();

inline void write_reply_message(StykPluginReply& reply, const std::string& text) {
  std::snprintf(reply.message, sizeof reply.message, "%s", text.c_str());
}

// Adds every element of `elements` to `registry` under `source`, or none of them: names are
// checked against the registry and against each other before the first add().
inline void add_all_or_none(ElementRegistry& registry, ElementList elements,
                            const std::string& source) {
  std::set<std::string> names;
  for (const auto& element : elements) {
    if (!element) throw std::invalid_argument("the plug-in's element list holds a null element");
    const std::string name = to_upper(element->name());
    if (const ElementRegistry::Entry* existing = registry.entry(name))
      throw std::invalid_argument("element type " + name + " is already registered by " +
                                  existing->source);
    if (!names.insert(name).second)
      throw std::invalid_argument("element type " + name + " is listed twice by the plug-in");
  }
  for (auto& element : elements) registry.add(std::move(element), source);
}

// The body of every SDK plug-in's entry point. Never throws.
inline int register_elements(const StykPluginHost* host, StykPluginReply* reply,
                             ElementFactory make_elements) noexcept {
  if (!host || !reply) return STYK_PLUGIN_FAILED;
  reply->plugin_abi_version = STYK_PLUGIN_ABI_VERSION;
  // The handshake comes first: with another ABI version nothing else in *host can be trusted.
  if (host->abi_version != STYK_PLUGIN_ABI_VERSION) return STYK_PLUGIN_ABI_MISMATCH;
  if (!host->registry) {
    write_reply_message(*reply, "the host passed no element registry");
    return STYK_PLUGIN_FAILED;
  }
  try {
    const std::string source = host->plugin_path ? host->plugin_path : "(unnamed plug-in)";
    add_all_or_none(*static_cast<ElementRegistry*>(host->registry), make_elements(), source);
    return STYK_PLUGIN_OK;
  } catch (const std::exception& error) {
    write_reply_message(*reply, error.what());
  } catch (...) {
    write_reply_message(*reply, "an exception that is not a std::exception");
  }
  return STYK_PLUGIN_FAILED;
}

}  // namespace styk::plugin

// Defines the plug-in's exported entry point around an ElementList (*)() factory.
#define STYK_PLUGIN(make_elements)                                                   \
  extern "C" STYK_PLUGIN_EXPORT int styk_plugin_register(const StykPluginHost* host, \
                                                         StykPluginReply* reply) {   \
    return ::styk::plugin::register_elements(host, reply, make_elements);            \
  }
