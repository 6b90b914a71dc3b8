#include "styk/elements/builtin.hpp"

#include <memory>

#include "styk/elements/axisymmetric.hpp"
#include "styk/elements/beam.hpp"
#include "styk/elements/c3d20.hpp"
#include "styk/elements/c3d20r.hpp"
#include "styk/elements/c3d27.hpp"
#include "styk/elements/c3d8.hpp"
#include "styk/elements/c3d8i.hpp"
#include "styk/elements/c3d8r.hpp"
#include "styk/elements/plane_quads.hpp"
#include "styk/elements/shell.hpp"
#include "styk/elements/stri3.hpp"
#include "styk/elements/t3d2.hpp"
#include "styk/elements/tetrahedra.hpp"
#include "styk/elements/wedges.hpp"

namespace styk {

void register_builtin_elements(ElementRegistry& registry) {
  const std::string source = "built-in";
  registry.add(std::make_unique<C3D8>(), source);
  registry.add(std::make_unique<C3D8R>(), source);
  registry.add(std::make_unique<C3D8R>(0.0), source);  // C3D8R0: no hourglass control (demo)
  registry.add(std::make_unique<C3D8I>(), source);
  registry.add(std::make_unique<C3D20>(), source);
  registry.add(std::make_unique<C3D20R>(), source);
  registry.add(std::make_unique<C3D27>(), source);
  registry.add(std::make_unique<PlaneQuad4>(PlaneKind::Stress), source);        // CPS4
  registry.add(std::make_unique<PlaneQuad4>(PlaneKind::Strain), source);        // CPE4
  registry.add(std::make_unique<PlaneQuad8>(PlaneKind::Stress), source);        // CPS8
  registry.add(std::make_unique<PlaneQuad8>(PlaneKind::Strain), source);        // CPE8
  registry.add(std::make_unique<PlaneQuad8>(PlaneKind::Stress, true), source);  // CPS8R
  registry.add(std::make_unique<PlaneQuad8>(PlaneKind::Strain, true), source);  // CPE8R
  registry.add(std::make_unique<C3D4>(), source);
  registry.add(std::make_unique<C3D10>(), source);
  registry.add(std::make_unique<C3D6>(), source);
  registry.add(std::make_unique<C3D15>(), source);
  registry.add(std::make_unique<CAX4>(false), source);
  registry.add(std::make_unique<CAX4>(true), source);  // CAX4R
  registry.add(std::make_unique<CAX8>(false), source);
  registry.add(std::make_unique<CAX8>(true), source);  // CAX8R
  registry.add(std::make_unique<T3D2>(), source);
  for (const BeamType type :
       {BeamType::B21, BeamType::B22, BeamType::B31, BeamType::B31R, BeamType::B32, BeamType::B32R})
    registry.add(std::make_unique<Beam>(type), source);
  for (const ShellType type : {ShellType::S4, ShellType::S4R, ShellType::S8, ShellType::S8R,
                               ShellType::S9, ShellType::S9R})
    registry.add(std::make_unique<Shell>(type), source);
  registry.add(std::make_unique<Stri3>(), source);
}

}  // namespace styk
