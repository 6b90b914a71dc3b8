// The sub-commands of `styk`. Each takes plain options (parsed in main.cpp) and returns an exit
// code; errors travel as exceptions to run_reporting_errors().
#pragma once

#include <string>

namespace styk::cli {

// How `styk solve` reports its progress on stderr: lines for people, or JSON lines for programs
// (json_progress.hpp).
enum class ProgressFormat { Text, JsonLines };

struct SolveArgs {
  std::string deck;
  std::string output_dir = ".";
  std::string solver = "auto";          // auto | cholmod | iterative
  std::string contact_solver = "auto";  // auto | dense | sparse
  int threads = 0;
  double memory_limit_gb = 0.0;  // 0: 80 % of the physical memory
  bool quiet = false;
  ProgressFormat progress = ProgressFormat::Text;
  int ranks = 0;  // > 1: start the MPI runner with this many ranks (mpi_launcher.hpp)
};
int solve_command(const SolveArgs& args);

struct InfoArgs {
  std::string deck;
};
int info_command(const InfoArgs& args);

enum class ExportFormat { Vtu, Frd };
struct ExportArgs {
  std::string input;   // .styk.h5 results file or .inp deck (mesh only)
  std::string output;  // .vtu / .frd path; default: input stem + .vtu / .frd
  ExportFormat format = ExportFormat::Vtu;
  int step = 0;       // VTU: 0 = last; .frd: 0 = every step
  int increment = 0;  // VTU: 0 = last of the step; .frd: 0 = every increment
};
int export_command(const ExportArgs& args);

int elements_command();

// `styk import MESH.msh`: a Gmsh mesh as a CalculiX mesh deck (command_import.cpp).
struct ImportArgs {
  std::string mesh;
  std::string output;          // default: the mesh's name with .inp
  std::string planar;          // cps | cpe | cax | shell: what a surface mesh's elements are
  std::string lines = "beam";  // beam | truss: what a line mesh's elements are
};
int import_command(const ImportArgs& args);

struct CheckArgs {
  std::string results;  // .styk.h5 results file
};
int check_command(const CheckArgs& args);

}  // namespace styk::cli
