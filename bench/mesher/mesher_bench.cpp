// Mesher benchmark (bench/mesher/README.md): (1) mesh a 1M-element C3D8 block and write its deck,
// (2) node merging from 10k to 1M elements. Prints CSV lines; times are wall-clock seconds.
//   mesher_bench [deck_path]      (default: a temporary file, removed afterwards)
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "styk/inp/writer.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/merge.hpp"

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

styk::mesher::BlockMap box(double x0, double lx) {
  return [=](const styk::Vec3& xi) {
    return styk::Vec3{x0 + lx * 0.5 * (xi[0] + 1), 0.5 * (xi[1] + 1), 0.5 * (xi[2] + 1)};
  };
}

}  // namespace

int main(int argc, char** argv) {
  using namespace styk::mesher;
  const std::string deck =
      argc > 1 ? argv[1]
               : (std::filesystem::temp_directory_path() / "styk_mesher_bench.inp").string();

  // (1) 100 x 100 x 100 C3D8 block -> Model -> .inp
  {
    const auto t0 = Clock::now();
    Mesh mesh;
    mesh_block(mesh, box(0, 1), {"C3D8", {100, 100, 100}, {1, 1, 1}, "EALL"});
    const double t_mesh = since(t0);
    const auto t1 = Clock::now();
    const styk::Model model = to_model(mesh);
    const double t_model = since(t1);
    const auto t2 = Clock::now();
    {
      std::ofstream out(deck);
      styk::write_inp(model, out);
    }
    const double t_write = since(t2);
    std::printf("task,elements,nodes,mesh_s,to_model_s,write_s,total_s,deck_MB\n");
    std::printf("block_1M,%d,%d,%.3f,%.3f,%.3f,%.3f,%.1f\n", model.element_count(),
                model.node_count(), t_mesh, t_model, t_write, since(t0),
                std::filesystem::file_size(deck) / 1e6);
    if (argc <= 1) std::filesystem::remove(deck);
  }

  // (2) Merge scaling: two C3D8 blocks side by side (n/2 elements each), merged into one part.
  std::printf("task,elements,nodes_before,nodes_merged,merge_s,ns_per_node\n");
  for (int n : {10, 22, 46, 100}) {  // 2 x (n/2 x n x n): 1e4 ... 1e6 elements
    Mesh mesh;
    mesh_block(mesh, box(0, 1), {"C3D8", {n / 2, n, n}, {1, 1, 1}, ""});
    mesh_block(mesh, box(1, 1), {"C3D8", {n / 2, n, n}, {1, 1, 1}, ""});
    const std::size_t before = mesh.nodes.size();
    const auto t0 = Clock::now();
    const int merged = merge_coincident_nodes(mesh);
    const double t = since(t0);
    std::printf("merge,%zu,%zu,%d,%.3f,%.0f\n", mesh.elements.size(), before, merged, t,
                1e9 * t / before);
  }
  return 0;
}
