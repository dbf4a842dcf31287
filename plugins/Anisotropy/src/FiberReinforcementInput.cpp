// SPDX-License-Identifier: MIT
#include "FiberReinforcementInput.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "core/Node.h"

namespace stroma::reinforcement {

namespace {

/// The numbers of a Data's text ("3000", "3000 2000"), or fewer when one does not parse.
std::vector<double> parseNumbers(const std::string& text) {
  std::vector<double> numbers;
  const char* p = text.data();
  const char* end = p + text.size();
  while (p < end) {
    while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
    if (p == end) break;
    double value = 0;
    const auto [next, error] = std::from_chars(p, end, value);
    if (error != std::errc()) break;
    numbers.push_back(value);
    p = next;
  }
  return numbers;
}

}  // namespace

std::string describeElements(const std::vector<std::size_t>& indices) {
  constexpr std::size_t kShown = 10;
  std::string text;
  for (std::size_t i = 0; i < indices.size() && i < kShown; ++i)
    text += (i ? ", " : "") + std::to_string(indices[i]);
  if (indices.size() > kShown) text += ", ... (" + std::to_string(indices.size()) + " in all)";
  return text;
}

bool computeRestShapes(Base& owner, const Topology& topology,
                       const std::vector<Vec3d>& restPositions,
                       std::vector<fem::TetrahedronShape>& shapes) {
  const std::vector<Tetrahedron>& tetrahedra = topology.tetrahedra();
  std::vector<std::size_t> outOfRange, flat;
  shapes.assign(tetrahedra.size(), {});
  for (std::size_t t = 0; t < tetrahedra.size(); ++t) {
    fem::TetrahedronVectors rest;
    bool inRange = true;
    for (int i = 0; i < 4; ++i) {
      const Index p = tetrahedra[t][i];
      if (p >= restPositions.size()) {
        inRange = false;
        break;
      }
      rest.col(i) = restPositions[p];
    }
    if (!inRange)
      outOfRange.push_back(t);
    else if (fem::computeTetrahedronShape(rest, shapes[t]) != fem::ElementStatus::ok)
      flat.push_back(t);
  }
  const std::string where = " of " + topology.path();
  if (!outOfRange.empty())
    owner.msgError(std::to_string(outOfRange.size()) + " tetrahedra" + where +
                       " use points out of range of the " + std::to_string(restPositions.size()) +
                       " points of the mechanical state: elements " + describeElements(outOfRange),
                   "topology");
  if (!flat.empty())
    owner.msgError(
        std::to_string(flat.size()) + " tetrahedra" + where +
            " are flat in the rest shape (zero volume, or non-finite positions): elements " +
            describeElements(flat),
        "topology");
  return outOfRange.empty() && flat.empty();
}

std::vector<IsotropicPartner> findIsotropicPartners(const Node& node, const Base& self,
                                                    const BaseMechanicalState* state) {
  std::vector<IsotropicPartner> partners;
  for (const BaseForceField* field : node.getAll<BaseForceField>()) {
    if (field == &self) continue;
    const auto states = field->states();
    if (std::find(states.begin(), states.end(), state) == states.end()) continue;
    const BaseData* youngData = field->findData("youngModulus");
    const BaseData* poissonData = field->findData("poissonRatio");
    if (!youngData || !poissonData) continue;
    const std::vector<double> young = parseNumbers(youngData->valueText());
    const std::vector<double> poisson = parseNumbers(poissonData->valueText());
    if (young.size() != 1 || poisson.size() != 1) continue;  // per-element moduli: not checked
    partners.push_back({.field = field,
                        .youngModulus = young[0],
                        .poissonRatio = poisson[0],
                        .method = field->findData("method")});
  }
  return partners;
}

}  // namespace stroma::reinforcement
