// *TIE (tied contact): each tied slave node follows its master face point in every direction
// (contact::tie_surfaces finds the points); with ADJUST=YES the slave node is first moved there.
#include "constraint_lowering.hpp"
#include "styk/contact/tied_contact.hpp"

namespace styk::solver_detail {

void lower_ties(Model& lowered, const ElementRegistry& registry, EquationBuilder& equations,
                std::vector<std::string>* notes) {
  for (const Tie& tie : lowered.ties) {
    const contact::TiedSurfaces tied = contact::tie_surfaces(lowered, registry, tie);
    if (tied.tied.empty())
      throw InputError(tie.where, "*TIE " + tie.name + ": no node of slave surface " + tie.slave +
                                      " lies within the position tolerance " +
                                      std::to_string(tied.tolerance) + " of master surface " +
                                      tie.master);
    for (const contact::TiedNode& t : tied.tied) {
      if (tie.adjust) lowered.coords[t.slave] = t.projection;
      for (int d = 0; d < 3; ++d) {
        std::vector<DirectionalTerm> terms{{t.slave, Eigen::Vector3d::Unit(d)}};
        for (const auto& [node, weight] : t.master)
          terms.push_back({node, -weight * Eigen::Vector3d::Unit(d)});
        equations.add(terms, t.slave, tie.where);
      }
    }
    if (notes && !tied.missed.empty()) {
      std::string ids;
      for (std::size_t i = 0; i < tied.missed.size() && i < 10; ++i)
        ids += (i ? ", " : "") + std::to_string(lowered.node_ids[tied.missed[i]]);
      if (tied.missed.size() > 10) ids += " ...";
      notes->push_back(tie.where.str() + ": *TIE " + tie.name + ": " +
                       std::to_string(tied.missed.size()) +
                       " slave nodes lie farther than the position tolerance from the master "
                       "surface and are not tied (" +
                       ids + ")");
    }
  }
}

}  // namespace styk::solver_detail
