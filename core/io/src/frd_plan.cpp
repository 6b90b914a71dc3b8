// Which blocks each increment of the .frd holds: from the deck's *NODE FILE / *EL FILE requests
// (styk solve) or everything the results hold (styk export --frd).
#include <algorithm>
#include <set>

#include "styk/core/output_requests.hpp"
#include "styk/io/frd_writer.hpp"

namespace styk {
namespace {

bool holds(const IncrementResult& inc, FrdField field) {
  switch (field) {
    case FrdField::Displacement:
      return !inc.U.empty();
    case FrdField::Force:
      return !inc.RF.empty();
    case FrdField::Stress:
      return !inc.S_nodal_I.empty();
    case FrdField::Strain:
      return !inc.E_nodal_I.empty();
    case FrdField::Temperature:
      return inc.scalar.kind == ScalarFieldResult::Kind::Temperature && !inc.scalar.value.empty();
    case FrdField::HeatFlux:
      return inc.scalar.kind == ScalarFieldResult::Kind::Temperature &&
             !inc.scalar.flux_nodal.empty();
  }
  return false;
}

int block_rank(FrdField field) {
  switch (field) {
    case FrdField::Displacement:
      return 0;
    case FrdField::Temperature:
      return 1;
    case FrdField::Stress:
      return 2;
    case FrdField::Strain:
      return 3;
    case FrdField::Force:
      return 4;
    case FrdField::HeatFlux:
      return 5;
  }
  return 6;
}

const char* variable_of(FrdField field) {
  switch (field) {
    case FrdField::Displacement:
      return "U";
    case FrdField::Force:
      return "RF";
    case FrdField::Stress:
      return "S";
    case FrdField::Strain:
      return "E";
    case FrdField::Temperature:
      return "NT";
    case FrdField::HeatFlux:
      return "HFL";
  }
  return "";
}

// The field a request variable writes; false for a variable the .frd does not carry.
bool field_of(OutputRequest::Kind kind, const std::string& var, FrdField& field) {
  if (kind == OutputRequest::Kind::NodeFile) {
    if (var == "U")
      field = FrdField::Displacement;
    else if (var == "RF")
      field = FrdField::Force;
    else if (var == "NT")
      field = FrdField::Temperature;
    else
      return false;
    return true;
  }
  if (var == "S")
    field = FrdField::Stress;
  else if (var == "E")
    field = FrdField::Strain;
  else if (var == "HFL")
    field = FrdField::HeatFlux;
  else
    return false;
  return true;
}

// The nodes a request covers: its node set, the nodes of its element set, or every node.
void add_request_nodes(const Model& model, const OutputRequest& request, FrdFieldOutput& out) {
  if (request.set.empty()) {
    out.all_nodes = true;
    out.nodes.clear();
    return;
  }
  if (out.all_nodes) return;
  std::set<int> nodes(out.nodes.begin(), out.nodes.end());
  if (request.kind == OutputRequest::Kind::NodeFile) {
    if (const NodeSet* set = model.find_nset(request.set))
      nodes.insert(set->nodes.begin(), set->nodes.end());
  } else if (const ElementSet* set = model.find_elset(request.set)) {
    for (int e : set->elements)
      nodes.insert(model.element_nodes(e), model.element_nodes(e) + model.elements[e].node_count);
  }
  out.all_nodes = false;
  out.nodes.assign(nodes.begin(), nodes.end());
}

class RequestPlanner {
 public:
  RequestPlanner(const Model& model, FrdPlan& plan) : model_(model), plan_(plan) {}

  void add(const IncrementResult& inc, bool last_of_step) {
    const std::size_t step = static_cast<std::size_t>(inc.step - 1);
    if (step >= model_.steps.size() || !output_due(model_, step, inc.increment, last_of_step))
      return;
    FrdIncrement out{&inc, {}};
    for (OutputRequest::Kind kind :
         {OutputRequest::Kind::NodeFile, OutputRequest::Kind::ElementFile})
      for (const OutputRequest* request : effective_requests(model_, step, kind))
        for (const std::string& var : request->vars) add_variable(inc, *request, var, out);
    // ccx's order of the blocks, whatever the order of the requests.
    std::stable_sort(out.fields.begin(), out.fields.end(),
                     [](const FrdFieldOutput& a, const FrdFieldOutput& b) {
                       return block_rank(a.field) < block_rank(b.field);
                     });
    if (!out.fields.empty()) plan_.increments.push_back(std::move(out));
  }

 private:
  void add_variable(const IncrementResult& inc, const OutputRequest& request,
                    const std::string& var, FrdIncrement& out) {
    FrdField field{};
    if (!field_of(request.kind, var, field)) {
      // NOE only switches the error estimate off; ERR comes along with S (CalculiX).
      if (var != "NOE" && var != "ERR") note(var + " is not written to the .frd");
      return;
    }
    if (!holds(inc, field)) {
      note(std::string(variable_of(field)) + " has no nodal values in step " +
           std::to_string(inc.step) + " and is not written to the .frd there");
      return;
    }
    auto found = std::find_if(out.fields.begin(), out.fields.end(),
                              [&](const FrdFieldOutput& f) { return f.field == field; });
    if (found == out.fields.end()) {
      out.fields.push_back({field, false, {}});
      found = out.fields.end() - 1;
    }
    add_request_nodes(model_, request, *found);
  }

  void note(const std::string& text) {
    if (std::find(plan_.notes.begin(), plan_.notes.end(), text) == plan_.notes.end())
      plan_.notes.push_back(text);
  }

  const Model& model_;
  FrdPlan& plan_;
};

}  // namespace

FrdPlan frd_plan_from_requests(const Model& model, const Results& results) {
  FrdPlan plan;
  RequestPlanner planner(model, plan);
  const auto& incs = results.increments;
  for (std::size_t i = 0; i < incs.size(); ++i) {
    const bool last = i + 1 == incs.size() || incs[i + 1].step != incs[i].step;
    planner.add(incs[i], last);
  }
  return plan;
}

FrdPlan frd_plan_everything(const Results& results, int step, int increment) {
  FrdPlan plan;
  for (const IncrementResult& inc : results.increments) {
    if ((step > 0 && inc.step != step) || (increment > 0 && inc.increment != increment)) continue;
    FrdIncrement out{&inc, {}};
    for (FrdField field : {FrdField::Displacement, FrdField::Temperature, FrdField::Stress,
                           FrdField::Strain, FrdField::Force, FrdField::HeatFlux})
      if (holds(inc, field)) out.fields.push_back({field, true, {}});
    if (!out.fields.empty()) plan.increments.push_back(std::move(out));
  }
  return plan;
}

}  // namespace styk
