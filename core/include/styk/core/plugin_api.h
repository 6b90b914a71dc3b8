/* The element plug-in ABI: what a Styk plug-in (.so) exports and what the host hands it.
 *
 * A plug-in is a shared library exporting exactly one C entry point,
 *
 *     int styk_plugin_register(const StykPluginHost* host, StykPluginReply* reply);
 *
 * The host (styk::load_plugins) fills a StykPluginHost and a zeroed StykPluginReply and calls it.
 * The entry must FIRST compare host->abi_version with the STYK_PLUGIN_ABI_VERSION it was compiled
 * with; on a mismatch it writes its own version to reply->plugin_abi_version and returns
 * STYK_PLUGIN_ABI_MISMATCH without touching anything else. Only when the versions agree may it
 * use host->registry (a styk::ElementRegistry*) and register its element types; any failure is
 * reported as STYK_PLUGIN_FAILED with a readable reply->message. Plug-ins written with the SDK
 * (plugins/sdk/include/styk/plugin/sdk.hpp, macro STYK_PLUGIN) get all of this for free.
 *
 * Why a version number at all: the entry itself is plain C, but what it registers are C++ objects
 * (styk::TElement subclasses) whose vtables, together with ElementRegistry and the Eigen types in
 * TElement's signatures, cross the library boundary. Bump STYK_PLUGIN_ABI_VERSION whenever any of
 * these changes: the virtual functions of TElement (order, signatures, added/removed hooks), the
 * data layout of FaceDef / IntegrationRule / ElementGeometry / Material, ElementRegistry's
 * interface or layout, or the layout of the structs below (beyond the frozen parts).
 *
 * Frozen forever (so that a plug-in of ANY version can detect the mismatch and say which version
 * it was built for): the entry's name and signature, StykPluginHost::abi_version being the first
 * member, the whole StykPluginReply struct, and the return codes.
 */
#ifndef STYK_CORE_PLUGIN_API_H
#define STYK_CORE_PLUGIN_API_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The version of the plug-in ABI this header describes. History: 1 = first release; 2 = TElement
 * gained ElementOptions on its template methods, thermal_load/internal_force, and the
 * incompatible-mode and stabilisation hooks (new virtual functions); 3 = TElement gained
 * active_displacements(), section_measure() and the kinematics hooks point_measure(),
 * face_quadrature(), complete_strain() (plane and truss elements), ElementGeometry gained
 * cross_section; 4 = rotational dofs: TElement gained node_dofs() and active_dofs() (replacing
 * active_displacements()), distributed_load_labels(), section_stations() and
 * section_resultants() (beam section forces), and its template methods (stiffness,
 * thermal_load, internal_force, pressure_load, strains_stresses) became virtual; ElementGeometry
 * gained section; SectionMeasure gained Beam; 5 = TElement describes itself: form(), vtk_cell()
 * and conversion() (new virtual functions); 6 = point_measure() takes the shape-function values
 * and strain_operator() is new (axisymmetric elements), FaceDef::axis = -1 marks faces off the
 * cube's planes. */
#define STYK_PLUGIN_ABI_VERSION 7u

/* The name of the entry point, for dlsym. */
#define STYK_PLUGIN_ENTRY_NAME "styk_plugin_register"

/* Marks the entry point as exported when the plug-in is compiled with -fvisibility=hidden. */
#if defined(__GNUC__)
#define STYK_PLUGIN_EXPORT __attribute__((visibility("default")))
#else
#define STYK_PLUGIN_EXPORT
#endif

/* What the host gives the plug-in. Valid only during the call. */
typedef struct StykPluginHost {
  uint32_t abi_version;    /* the host's STYK_PLUGIN_ABI_VERSION (frozen: always first) */
  const char* plugin_path; /* the path the library was loaded from (the registry "source") */
  void* registry;          /* a styk::ElementRegistry*; use only if abi_version matches */
} StykPluginHost;

/* What the plug-in tells the host (frozen layout). The host zeroes it before the call. */
#define STYK_PLUGIN_MESSAGE_SIZE 512
typedef struct StykPluginReply {
  uint32_t plugin_abi_version; /* the STYK_PLUGIN_ABI_VERSION the plug-in was built with */
  char message[STYK_PLUGIN_MESSAGE_SIZE]; /* NUL-terminated reason when the result is not OK */
} StykPluginReply;

/* Return codes of the entry point (frozen). */
#define STYK_PLUGIN_OK 0
#define STYK_PLUGIN_ABI_MISMATCH 1 /* host->abi_version != the plug-in's; nothing registered */
#define STYK_PLUGIN_FAILED 2       /* registration failed; reply->message says why */

typedef int (*StykPluginRegisterFn)(const StykPluginHost* host, StykPluginReply* reply);

#ifdef __cplusplus
}
#endif

#endif /* STYK_CORE_PLUGIN_API_H */
