// libFuzzer harness of the Gmsh importer (styk import, the GUI's File > Open of .msh files:
// docs/input.md "Importing Gmsh meshes"): the input is the .msh file; it is asked for its
// dimension, imported (surface meshes as plane-stress elements, line meshes as beams) and the
// imported model written as a deck, as `styk import` does. Accepted outcomes: a deck, or
// InputError / ResourceLimitError (a malformed or unsupported file refused by name, "path:line:
// message"); anything else — another exception, a crash, a sanitizer report, a hang — is a
// finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>

#include "fuzz_scratch.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/gmsh/gmsh_import.hpp"
#include "styk/inp/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = styk::fuzz::scratch_path("mesh.msh");
  styk::fuzz::write_bytes(path, data, size);
  try {
    (void)styk::gmsh_mesh_dimension(path);
    styk::GmshImportOptions options;
    options.planar = styk::PlanarElements::PlaneStress;
    const styk::Model model = styk::import_gmsh(path, options);
    std::ostringstream deck;
    styk::write_inp(model, deck);
  } catch (const styk::InputError&) {
  } catch (const styk::ResourceLimitError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "finding: the Gmsh importer threw %s\n", e.what());
    std::abort();
  }
  return 0;
}
