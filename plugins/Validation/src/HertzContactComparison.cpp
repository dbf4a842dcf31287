// SPDX-License-Identifier: MIT
#include "HertzContactComparison.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/Message.h"
#include "core/Node.h"
#include "simulation/VecId.h"

namespace stroma {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The normal part of the 'force' outputs of the responses under `node`. A response's force is
// the one on its second model: the sphere may be either side, so each counts by its size.
void addResponseForces(const Node& node, const std::vector<std::string>& classes,
                       const Vec3d& normal, double& sum) {
  for (const auto& object : node.objects()) {
    if (std::find(classes.begin(), classes.end(), object->className()) == classes.end()) continue;
    const BaseData* force = object->findData("force");
    if (!force) continue;
    // Read as text: the responses live in another plugin (no shared type information).
    const std::string text = force->valueText();
    const char* at = text.c_str();
    Vec3d f;
    for (int k = 0; k < 3; ++k) {
      char* end = nullptr;
      f[k] = std::strtod(at, &end);
      at = end;
    }
    sum += std::abs(f.dot(normal));
  }
  for (const auto& child : node.children()) addResponseForces(*child, classes, normal, sum);
}

}  // namespace

HertzContactComparison::HertzContactComparison() {
  for (BaseData* output :
       {static_cast<BaseData*>(&d_indentation), static_cast<BaseData*>(&d_force),
        static_cast<BaseData*>(&d_hertzForce), static_cast<BaseData*>(&d_halfSpaceForce),
        static_cast<BaseData*>(&d_hertzError), static_cast<BaseData*>(&d_halfSpaceError),
        static_cast<BaseData*>(&d_maxHertzError), static_cast<BaseData*>(&d_rmsHertzError),
        static_cast<BaseData*>(&d_maxHalfSpaceError), static_cast<BaseData*>(&d_rmsHalfSpaceError),
        static_cast<BaseData*>(&d_comparisons)})
    addOutput(output);
}

void HertzContactComparison::init() {
  m_ready = false;
  m_history.clear();
  publish();
  if (!l_state) l_state.set(node() ? node()->template get<State>() : nullptr);
  bool ok = true;
  if (!l_state) {
    msgError("no 3-D mechanical state in the node: add a MechanicalObject or set state=\"@...\"",
             "state");
    ok = false;
  }
  m_hertz = {d_youngModulus.value(), d_poissonRatio.value(), d_radius.value()};
  if (!(m_hertz.youngModulus > 0))
    ok = false,
    msgError("youngModulus must be > 0, got " + formatNumber(m_hertz.youngModulus), "youngModulus");
  if (!(m_hertz.poissonRatio > -1 && m_hertz.poissonRatio < 0.5))
    ok = false,
    msgError("poissonRatio must be in (-1, 0.5), got " + formatNumber(m_hertz.poissonRatio),
             "poissonRatio");
  if (!(m_hertz.radius > 0))
    ok = false, msgError("radius must be > 0, got " + formatNumber(m_hertz.radius), "radius");
  if (!(d_normal.value().norm() > 0)) ok = false, msgError("the normal must not be zero", "normal");
  if (!(d_forceScale.value() > 0))
    ok = false,
    msgError("forceScale must be > 0, got " + formatNumber(d_forceScale.value()), "forceScale");
  if (d_indices.value().empty()) ok = false, msgError("no driven point given", "indices");
  if (l_state)
    for (unsigned i : d_indices.value())
      if (i >= l_state->size()) {
        msgError("index " + std::to_string(i) + " is out of range: the state has " +
                     std::to_string(l_state->size()) + " points",
                 "indices");
        ok = false;
        break;
      }
  m_ready = ok;
  setDirty();
}

double HertzContactComparison::measureForce() const {
  double sum = 0;
  if (node())
    addResponseForces(node()->root(), d_responses.value(), d_normal.value().normalized(), sum);
  return sum * d_forceScale.value();
}

void HertzContactComparison::compareNow() {
  // Indentation: the driven points' mean displacement against the normal, less the gap.
  const Vec3d n = d_normal.value().normalized();
  const auto& x = l_state->readCoord(VecId::position());
  const auto& rest = l_state->readCoord(VecId::restPosition());
  const auto& x0 = rest.size() == x.size() ? rest : x;
  double moved = 0;
  for (unsigned i : d_indices.value()) moved -= (x[i] - x0[i]).dot(n);
  const double delta = moved / static_cast<double>(d_indices.value().size()) - d_gap.value();
  if (!(delta > d_minIndentation.value()) || !(delta > 0)) return;

  const double depth = d_depth.value() > 0 ? d_depth.value() : m_hertz.radius;
  const double d = m_hertz.indentationForApproachAt(delta, depth);
  m_history.push_back({node()->time(), delta, measureForce(), m_hertz.force(delta),
                       std::isfinite(d) ? m_hertz.force(d) : kNaN});
  publish();
}

void HertzContactComparison::publish() {
  double maxHertz = m_history.empty() ? kNaN : 0, maxHalf = maxHertz, sumHertz = 0, sumHalf = 0;
  for (const Comparison& c : m_history) {
    const double e = c.force / c.hertzForce - 1, h = c.force / c.halfSpaceForce - 1;
    maxHertz = std::max(maxHertz, std::abs(e));
    maxHalf = std::isnan(h) ? h : std::max(maxHalf, std::abs(h));  // NaN sticks
    sumHertz += e * e;
    sumHalf += h * h;
  }
  const double count = static_cast<double>(m_history.size());
  const Comparison last = m_history.empty() ? Comparison{0, 0, 0, 0, 0} : m_history.back();
  d_indentation.setValue(last.indentation);
  d_force.setValue(last.force);
  d_hertzForce.setValue(last.hertzForce);
  d_halfSpaceForce.setValue(last.halfSpaceForce);
  d_hertzError.setValue(m_history.empty() ? kNaN : last.force / last.hertzForce - 1);
  d_halfSpaceError.setValue(m_history.empty() ? kNaN : last.force / last.halfSpaceForce - 1);
  d_maxHertzError.setValue(maxHertz);
  d_rmsHertzError.setValue(m_history.empty() ? kNaN : std::sqrt(sumHertz / count));
  d_maxHalfSpaceError.setValue(maxHalf);
  d_rmsHalfSpaceError.setValue(m_history.empty() ? kNaN : std::sqrt(sumHalf / count));
  d_comparisons.setValue(static_cast<int>(m_history.size()));
}

void HertzContactComparison::updatePosition(double) {
  // At the start of a step: the state and the responses' forces of the end of the last one.
  if (!m_ready || !node()) return;
  if (m_history.empty() || m_history.back().time != node()->time()) compareNow();
  setDirty();  // the step changes the state: a later read compares again
}

void HertzContactComparison::doUpdate() {
  if (!m_ready || !node()) return;
  // The state may have changed since a comparison at this same time: that one is replaced.
  if (!m_history.empty() && m_history.back().time == node()->time()) m_history.pop_back();
  compareNow();
  publish();
}

std::vector<std::string> HertzContactComparison::runSummaryLines() const {
  d_maxHertzError.value();  // compares now (the end of a run)
  if (!m_ready) return {"no comparison (see the errors above)"};
  if (m_history.empty()) return {"no comparison: the sphere never pressed on the plane"};
  std::vector<std::string> lines;
  for (const Comparison& c : m_history)
    lines.push_back("time " + formatNumber(c.time) + " s: indentation " +
                    formatNumber(c.indentation) + ", force " + formatNumber(c.force) +
                    " N; Hertz " + formatNumber(c.hertzForce) + " N (" +
                    formatNumber(100 * (c.force / c.hertzForce - 1)) + " %), half-space at depth " +
                    formatNumber(c.halfSpaceForce) + " N (" +
                    formatNumber(100 * (c.force / c.halfSpaceForce - 1)) + " %)");
  return lines;
}

}  // namespace stroma
