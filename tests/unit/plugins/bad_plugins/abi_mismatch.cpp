// A plug-in "built for" a future ABI version 999: it follows the frozen handshake (answer with
// its version, return STYK_PLUGIN_ABI_MISMATCH, touch nothing else).
#include "styk/core/plugin_api.h"

extern "C" STYK_PLUGIN_EXPORT int styk_plugin_register(const StykPluginHost* host,
                                                       StykPluginReply* reply) {
  const uint32_t built_for = 999;
  reply->plugin_abi_version = built_for;
  if (host->abi_version != built_for) return STYK_PLUGIN_ABI_MISMATCH;
  return STYK_PLUGIN_OK;
}
