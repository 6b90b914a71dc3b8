#include "styk/core/output_requests.hpp"

#include <algorithm>
#include <utility>

namespace styk {

std::vector<const OutputRequest*> effective_requests(const Model& model, std::size_t step,
                                                     OutputRequest::Kind kind) {
  std::vector<const OutputRequest*> in_effect;
  for (std::size_t k = 0; k <= step && k < model.steps.size(); ++k) {
    std::vector<const OutputRequest*> own;
    for (const OutputRequest& request : model.steps[k].outputs)
      if (request.kind == kind) own.push_back(&request);
    if (!own.empty()) in_effect = std::move(own);
  }
  return in_effect;
}

std::vector<const OutputRequest*> effective_outputs(const Model& model, std::size_t step) {
  using K = OutputRequest::Kind;
  std::vector<const OutputRequest*> all;
  for (K kind : {K::NodePrint, K::ElementPrint, K::NodeFile, K::ElementFile, K::ContactPrint,
                 K::SectionPrint}) {
    const std::vector<const OutputRequest*> of_kind = effective_requests(model, step, kind);
    all.insert(all.end(), of_kind.begin(), of_kind.end());
  }
  // Deck order: requests live in their steps' vectors, which lie in step order.
  auto position = [&](const OutputRequest* r) {
    for (std::size_t k = 0; k < model.steps.size(); ++k) {
      const std::vector<OutputRequest>& outputs = model.steps[k].outputs;
      if (!outputs.empty() && r >= outputs.data() && r < outputs.data() + outputs.size())
        return std::make_pair(k, static_cast<std::size_t>(r - outputs.data()));
    }
    return std::make_pair(model.steps.size(), std::size_t{0});
  };
  std::sort(all.begin(), all.end(), [&](const OutputRequest* a, const OutputRequest* b) {
    return position(a) < position(b);
  });
  return all;
}

int output_frequency(const Model& model, std::size_t step) {
  int frequency = 1;
  for (std::size_t k = 0; k <= step && k < model.steps.size(); ++k)
    for (const OutputRequest& request : model.steps[k].outputs)
      if (request.frequency) frequency = *request.frequency;
  return frequency;
}

bool output_due(const Model& model, std::size_t step, int increment, bool last) {
  const int frequency = output_frequency(model, step);
  if (frequency <= 0) return false;
  return last || increment % frequency == 0;
}

}  // namespace styk
