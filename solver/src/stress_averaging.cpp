#include "stress_averaging.hpp"

#include <stdexcept>

#include <Eigen/SVD>

#include "parallel.hpp"

namespace styk::solver_detail {
namespace {

// A fit whose point-value matrix is worse conditioned than this is treated as rank deficient:
// the fitted node values would amplify round-off of the point values by as much.
constexpr double kMaxCondition = 1e8;

enum class Space { Element, Trilinear, Linear, Constant };

const char* space_name(Space space) {
  switch (space) {
    case Space::Element:
      return "element";
    case Space::Trilinear:
      return "trilinear";
    case Space::Linear:
      return "linear";
    case Space::Constant:
      return "constant";
  }
  return "";
}

int space_size(Space space, const TElement& element) {
  switch (space) {
    case Space::Element:
      return element.node_count();
    case Space::Trilinear:
      return 8;
    case Space::Linear:
      return 4;
    case Space::Constant:
      return 1;
  }
  return 0;
}

// Values of the basis functions of `space` at xi, as one row.
void evaluate(Space space, const TElement& element, const Vec3& xi,
              Eigen::Ref<Eigen::RowVectorXd> row) {
  const double x = xi[0], y = xi[1], z = xi[2];
  switch (space) {
    case Space::Element: {
      Eigen::VectorXd N(element.node_count());
      Eigen::MatrixXd dN(element.node_count(), 3);
      element.der(xi, N, dN);
      row = N.transpose();
      return;
    }
    case Space::Trilinear:
      row << 1.0, x, y, z, x * y, y * z, z * x, x * y * z;
      return;
    case Space::Linear:
      row << 1.0, x, y, z;
      return;
    case Space::Constant:
      row << 1.0;
      return;
  }
}

// One row per point (row-major so that a row is a contiguous vector).
using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

RowMajorMatrix evaluate_at(Space space, const TElement& element, const std::vector<Vec3>& points) {
  RowMajorMatrix values(static_cast<Eigen::Index>(points.size()), space_size(space, element));
  for (std::size_t p = 0; p < points.size(); ++p)
    evaluate(space, element, points[p], values.row(static_cast<Eigen::Index>(p)));
  return values;
}

// Row-major views of Tensor6 arrays: one row per point or node, one column per component.
using Rows6 = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>;
using ConstRowsView = Eigen::Map<const Rows6>;
using RowsView = Eigen::Map<Rows6>;
using RowView = Eigen::Map<Eigen::Matrix<double, 1, 6>>;

}  // namespace

Extrapolation make_extrapolation(const TElement& element, const IntegrationRule& rule) {
  if (rule.size() == 0)
    throw std::logic_error("stress extrapolation of " + element.name() + ": rule " + rule.label +
                           " has no points");
  for (const Space space : {Space::Element, Space::Trilinear, Space::Linear, Space::Constant}) {
    if (space_size(space, element) > rule.size()) continue;
    const Eigen::MatrixXd at_points = evaluate_at(space, element, rule.points);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(at_points,
                                                Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd& sigma = svd.singularValues();
    if (sigma(sigma.size() - 1) * kMaxCondition <= sigma(0)) continue;
    // Least-squares fit: coefficients = pinv(A) * point values, pinv(A) = V S^-1 U^T.
    const Eigen::MatrixXd pseudo_inverse =
        svd.matrixV() * sigma.cwiseInverse().asDiagonal() * svd.matrixU().transpose();
    Extrapolation out;
    out.to_nodes = evaluate_at(space, element, element.natural_nodes()) * pseudo_inverse;
    out.to_centroid = evaluate_at(space, element, {natural_centroid(element)}) * pseudo_inverse;
    out.space = space_name(space);
    return out;
  }
  // Unreachable: the constant space has full rank for any rule with a point.
  throw std::logic_error("stress extrapolation of " + element.name() + " found no space");
}

StressAveraging::StressAveraging(const Model& model,
                                 const std::vector<const TElement*>& formulation, RuleKind kind)
    : StressAveraging(model, formulation, std::vector<RuleKind>(formulation.size(), kind)) {}

StressAveraging::StressAveraging(const Model& model,
                                 const std::vector<const TElement*>& formulation,
                                 const std::vector<RuleKind>& kinds)
    : model_(model), operator_of_element_(model.element_count(), 0) {
  if (static_cast<int>(formulation.size()) != model.element_count() ||
      kinds.size() != formulation.size())
    throw std::logic_error("stress averaging: one formulation and rule per element expected");
  for (int e = 0; e < model.element_count(); ++e) {
    const TElement* element = formulation[e];
    std::size_t k = 0;
    while (k < operators_.size() &&
           (operators_[k].element != element || operators_[k].kind != kinds[e]))
      ++k;
    if (k == operators_.size())
      operators_.push_back(
          {element, kinds[e], make_extrapolation(*element, element->rule(kinds[e]))});
    operator_of_element_[e] = static_cast<int>(k);
  }

  // Node -> connectivity positions (CSR), built by counting.
  const int nodes = model.node_count();
  slot_offset_.assign(nodes + 1, 0);
  element_of_slot_.assign(model.connectivity.size(), -1);
  for (int e = 0; e < model.element_count(); ++e) {
    const Element& element = model.elements[e];
    for (int k = 0; k < element.node_count; ++k) {
      element_of_slot_[element.first_node + k] = e;
      ++slot_offset_[model.connectivity[element.first_node + k] + 1];
    }
  }
  for (int n = 0; n < nodes; ++n) slot_offset_[n + 1] += slot_offset_[n];
  slots_.resize(slot_offset_.back());
  std::vector<int> fill(slot_offset_.begin(), slot_offset_.end() - 1);
  for (int c = 0; c < static_cast<int>(element_of_slot_.size()); ++c)
    if (element_of_slot_[c] >= 0) slots_[fill[model.connectivity[c]]++] = c;
}

void StressAveraging::apply(int threads, IncrementResult& inc) const {
  threads = resolve_threads(threads);
  const int elements = model_.element_count();
  if (static_cast<int>(inc.ip_offset.size()) != elements + 1)
    throw std::logic_error("stress averaging: ip_offset does not match the elements");
  for (int e = 0; e < elements; ++e)
    if (inc.ip_offset[e + 1] - inc.ip_offset[e] != extrapolation(e).to_nodes.cols())
      throw std::logic_error("stress averaging: element " + std::to_string(model_.elements[e].id) +
                             " has a different number of integration points than its rule");
  const auto points = static_cast<std::size_t>(inc.ip_offset.back());
  if (!inc.S.empty()) {
    if (inc.S.size() != points)
      throw std::logic_error("stress averaging: S does not fit ip_offset");
    extrapolate(threads, inc.ip_offset, inc.S, inc.S_element_nodes, inc.S_centroid);
    average(threads, inc.S_element_nodes, inc.S_centroid, inc.S_nodal_I, inc.S_nodal_II);
  }
  if (!inc.E.empty()) {
    if (inc.E.size() != points)
      throw std::logic_error("stress averaging: E does not fit ip_offset");
    extrapolate(threads, inc.ip_offset, inc.E, inc.E_element_nodes, inc.E_centroid);
    average(threads, inc.E_element_nodes, inc.E_centroid, inc.E_nodal_I, inc.E_nodal_II);
  }
}

void StressAveraging::extrapolate(int threads, const std::vector<int>& ip_offset,
                                  const std::vector<Tensor6>& ip_values,
                                  std::vector<Tensor6>& element_nodes,
                                  std::vector<Tensor6>& centroid) const {
  element_nodes.assign(model_.connectivity.size(), Tensor6{});
  centroid.assign(model_.element_count(), Tensor6{});
  parallel_for(model_.element_count(), threads, 64, [&](int begin, int end, int /*worker*/) {
    for (int e = begin; e < end; ++e) {
      const Extrapolation& op = extrapolation(e);
      const Element& element = model_.elements[e];
      const ConstRowsView at_points(ip_values[ip_offset[e]].data(), op.to_nodes.cols(), 6);
      RowsView at_nodes(element_nodes[element.first_node].data(), element.node_count, 6);
      at_nodes.noalias() = op.to_nodes * at_points;
      RowView(centroid[e].data()).noalias() = op.to_centroid * at_points;
    }
  });
}

void StressAveraging::average(int threads, const std::vector<Tensor6>& element_nodes,
                              const std::vector<Tensor6>& centroid, std::vector<Tensor6>& nodal_I,
                              std::vector<Tensor6>& nodal_II) const {
  const int nodes = model_.node_count();
  nodal_I.assign(nodes, Tensor6{});
  nodal_II.assign(nodes, Tensor6{});
  parallel_for(nodes, threads, 256, [&](int begin, int end, int /*worker*/) {
    for (int n = begin; n < end; ++n) {
      const int first = slot_offset_[n], last = slot_offset_[n + 1];
      if (first == last) continue;
      Tensor6 sum_I{}, sum_II{};
      for (int s = first; s < last; ++s) {
        const int c = slots_[s];
        for (int k = 0; k < 6; ++k) {
          sum_I[k] += element_nodes[c][k];
          sum_II[k] += centroid[element_of_slot_[c]][k];
        }
      }
      const double scale = 1.0 / static_cast<double>(last - first);
      for (int k = 0; k < 6; ++k) {
        nodal_I[n][k] = scale * sum_I[k];
        nodal_II[n][k] = scale * sum_II[k];
      }
    }
  });
}

}  // namespace styk::solver_detail
