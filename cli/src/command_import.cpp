// `styk import MESH.msh -o MODEL.inp`: a Gmsh mesh as a CalculiX mesh deck (nodes, elements and
// the physical groups as sets), to be completed with materials, sections and steps (*INCLUDE).
#include <iostream>

#include <fmt/core.h>

#include "atomic_file.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "styk/gmsh/gmsh_import.hpp"
#include "styk/inp/writer.hpp"

namespace styk::cli {
namespace {

PlanarElements parse_planar(const std::string& name) {
  if (name.empty()) return PlanarElements::Unset;
  if (name == "cps") return PlanarElements::PlaneStress;
  if (name == "cpe") return PlanarElements::PlaneStrain;
  if (name == "cax") return PlanarElements::Axisymmetric;
  if (name == "shell") return PlanarElements::Shell;
  throw InputError({}, "--planar must be cps, cpe, cax or shell, not '" + name + "'");
}

LineElements parse_lines(const std::string& name) {
  if (name == "beam") return LineElements::Beam;
  if (name == "truss") return LineElements::Truss;
  throw InputError({}, "--lines must be beam or truss, not '" + name + "'");
}

std::string default_deck(const std::string& mesh) {
  const std::string ext = ".msh";
  if (mesh.size() > ext.size() && mesh.compare(mesh.size() - ext.size(), ext.size(), ext) == 0)
    return mesh.substr(0, mesh.size() - ext.size()) + ".inp";
  return mesh + ".inp";
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

int import_command(const ImportArgs& args) {
  GmshImportOptions options;
  options.planar = parse_planar(args.planar);
  options.lines = parse_lines(args.lines);
  GmshImportSummary summary;
  const Model model = import_gmsh(args.mesh, options, &summary);
  const std::string output = args.output.empty() ? default_deck(args.mesh) : args.output;
  AtomicTextFile deck(output);
  write_inp(model, deck.stream());
  deck.commit();

  std::vector<std::string> sets;
  for (const auto& entry : model.elsets) sets.push_back("ELSET " + entry.first);
  for (const auto& entry : model.nsets) sets.push_back("NSET " + entry.first);
  std::cout << fmt::format("wrote {}: {} nodes, {} elements ({}) from MSH {} ({}-D mesh)\n", output,
                           model.node_count(), model.element_count(), joined(summary.element_types),
                           summary.format, summary.dimension);
  std::cout << "sets: " << joined(sets) << "\n";
  if (summary.lower_dimension_elements > 0)
    std::cout << fmt::format(
        "{} elements of lower dimension gave their physical groups' node sets "
        "only\n",
        summary.lower_dimension_elements);
  if (summary.unused_nodes > 0)
    std::cout << fmt::format("{} nodes belong to no imported element and were left out\n",
                             summary.unused_nodes);
  return kOk;
}

}  // namespace styk::cli
