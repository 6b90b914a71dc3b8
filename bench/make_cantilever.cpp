// Writes the block-cantilever deck of PERFORMANCE.md (and the samples): a C3D20 (or C3D8) block
// L x W x H clamped at x = 0 with a unit tip shear as consistent nodal forces on x = L.
//   make_cantilever NX NY NZ OUT.inp [--type C3D8|C3D20] [--size L W H] [--solver
//   auto|cholmod|iterative]
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

#include "styk/inp/writer.hpp"
#include "styk/mesher/cantilever.hpp"

int main(int argc, char** argv) {
  if (argc < 5) {
    std::cerr << "usage: make_cantilever NX NY NZ OUT.inp [--type C3D8|C3D20] [--size L W H] "
                 "[--solver auto|cholmod|iterative]\n";
    return 1;
  }
  styk::mesher::CantileverSpec spec;
  spec.box.type = "C3D20";
  spec.box.size = {10.0, 1.0, 1.0};
  spec.box.divisions = {std::atoi(argv[1]), std::atoi(argv[2]), std::atoi(argv[3])};
  spec.young = 210000.0;
  spec.poisson = 0.3;
  spec.force = {0.0, 0.0, 1.0};
  std::string solver = "auto";
  for (int a = 5; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--type" && a + 1 < argc) {
      spec.box.type = argv[++a];
    } else if (arg == "--size" && a + 3 < argc) {
      for (int k = 0; k < 3; ++k) spec.box.size[k] = std::atof(argv[++a]);
    } else if (arg == "--solver" && a + 1 < argc) {
      solver = argv[++a];
    } else {
      std::cerr << "make_cantilever: unknown argument " << arg << "\n";
      return 1;
    }
  }
  styk::Model model = styk::mesher::make_cantilever(spec);
  if (solver == "cholmod") model.steps[0].procedure.solver = styk::LinearSolverKind::Cholmod;
  if (solver == "iterative") model.steps[0].procedure.solver = styk::LinearSolverKind::Iterative;
  std::ofstream out(argv[4]);
  styk::write_inp(model, out);
  if (!out) {
    std::cerr << "make_cantilever: cannot write " << argv[4] << "\n";
    return 1;
  }
  long long active = model.node_count();
  std::cerr << "make_cantilever: " << model.element_count() << " elements, " << model.node_count()
            << " nodes, " << 3 * active << " dofs\n";
  return 0;
}
