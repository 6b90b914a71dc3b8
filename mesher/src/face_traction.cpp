#include "styk/mesher/face_traction.hpp"

#include <map>
#include <utility>

namespace styk::mesher {

std::vector<ConcentratedLoad> uniform_traction_loads(const BoxMesh& box, int axis, int side,
                                                     const Vec3& total) {
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;  // the two in-plane directions
  const auto grid = box.grid_size();
  const int step = box.step();
  const int nb = (grid[b] - 1) / step, nc = (grid[c] - 1) / step;
  const double face_fraction = 1.0 / (static_cast<double>(nb) * nc);  // each element face's share
  const int fixed = side == 0 ? 0 : grid[axis] - 1;

  std::map<int, double> weight;  // node index -> share of the total force
  for (int eb = 0; eb < nb; ++eb)
    for (int ec = 0; ec < nc; ++ec)
      for (int ob = 0; ob <= step; ++ob)
        for (int oc = 0; oc <= step; ++oc) {
          double w = 0.0;
          if (step == 1) {
            w = 0.25;
          } else {
            const int odd = (ob % 2) + (oc % 2);
            if (odd == 0)
              w = -1.0 / 12.0;  // corner of an 8-node face
            else if (odd == 1)
              w = 1.0 / 3.0;  // mid-edge
            else
              continue;  // face centre: no node
          }
          int address[3];
          address[axis] = fixed;
          address[b] = eb * step + ob;
          address[c] = ec * step + oc;
          weight[box.node_at(address[0], address[1], address[2])] += w * face_fraction;
        }

  std::vector<ConcentratedLoad> loads;
  for (const auto& [node, w] : weight)
    for (int dof = 0; dof < 3; ++dof)
      if (total[dof] != 0.0 && w != 0.0) {
        ConcentratedLoad load;
        load.node = node;
        load.dof = dof + 1;
        load.value = w * total[dof];
        loads.push_back(load);
      }
  return loads;
}

}  // namespace styk::mesher
