// SPDX-License-Identifier: MIT
#include "CollisionResponse.h"

#include <algorithm>

#include "core/NameSuggestions.h"
#include "core/Node.h"

namespace stroma {

namespace {

constexpr const char* kPenalty = "PenalityContactForceField";

// SOFA's constraint-based responses: the next step of contact (FreeMotionAnimationLoop).
const std::vector<std::string> kConstraintResponses = {"FrictionContactConstraint",
                                                       "StickContactConstraint",
                                                       "FrictionContact",
                                                       "StickContact",
                                                       "BilateralContactConstraint",
                                                       "AugmentedLagrangianResponseConstraint",
                                                       "UnilateralContact"};

// The nearest node that holds both (or is an ancestor of both).
Node* commonAncestor(Node* a, Node* b) {
  for (Node* x = a; x; x = x->parent())
    for (Node* y = b; y; y = y->parent())
      if (x == y) return x;
  return nullptr;
}

template <class D1, class D2>
std::unique_ptr<BaseForceField> makePenalty(BaseMechanicalState* s1, BaseMechanicalState* s2,
                                            std::vector<PenaltyContact>*& contacts) {
  auto* t1 = dynamic_cast<MechanicalState<D1>*>(s1);
  auto* t2 = dynamic_cast<MechanicalState<D2>*>(s2);
  if (!t1 || !t2) return nullptr;
  auto ff = std::make_unique<PenalityContactForceField<D1, D2>>(t1, t2);
  contacts = &ff->contacts();
  return ff;
}

// The vertices of a primitive (SOFA's contact mappers: a point, a segment's ends, a triangle's
// corners, a sphere's centre, a box's frame).
void primitiveVertices(const CollisionGeometry& g, std::uint32_t i, PenaltyContact& c, int side) {
  switch (g.kind) {
    case PrimitiveKind::point:
    case PrimitiveKind::sphere:
    case PrimitiveKind::box:
      c.vertices[side] = {i, 0, 0};
      c.vertexCount[side] = 1;
      break;
    case PrimitiveKind::line:
      c.vertices[side] = {g.edges[i][0], g.edges[i][1], 0};
      c.vertexCount[side] = 2;
      break;
    case PrimitiveKind::triangle:
      c.vertices[side] = g.triangles[i];
      c.vertexCount[side] = 3;
      break;
  }
}

// The contact point's offset from its box's centre (the frame's origin) in the box's axes;
// zero for the other primitives.
Vec3d frameArm(const CollisionGeometry& g, std::uint32_t i, const Vec3d& point) {
  if (g.kind != PrimitiveKind::box) return Vec3d::Zero();
  const OrientedBox& b = g.boxes[i];
  return b.rotation.transpose() * (point - b.center);
}

}  // namespace

CollisionResponse::CollisionResponse() = default;
CollisionResponse::~CollisionResponse() = default;

bool CollisionResponse::checkResponseName(const std::string& name, const Base& where,
                                          const std::string& field) {
  if (name == kPenalty || name == "default") return true;
  std::string text;
  if (std::find(kConstraintResponses.begin(), kConstraintResponses.end(), name) !=
      kConstraintResponses.end()) {
    text = "the response '" + name +
           "' is a constraint-based response (FreeMotionAnimationLoop and a constraint solver), "
           "which Stroma does not provide yet; available: '" +
           kPenalty + "'";
  } else {
    std::vector<std::string> known = kConstraintResponses;
    known.push_back(kPenalty);
    text = "unknown response '" + name + "'";
    const auto near = nearestNames(name, known);
    text += near.empty() ? "; available: '" + std::string(kPenalty) + "'"
                         : "; did you mean " + quotedList(near) + "?";
  }
  if (&where == this)
    msgError(text, field);
  else
    msgError(text + " (" + where.path() + ")", field);
  return false;
}

void CollisionResponse::init() {
  checkResponseName(d_response.value(), *this, "response");
  const std::string& params = d_responseParams.value();
  if (!params.empty()) {
    std::size_t start = 0;
    while (start <= params.size()) {
      const std::size_t end = std::min(params.find('&', start), params.size());
      const std::string item = params.substr(start, end - start);
      if (item.find('=') == std::string::npos || item.front() == '=')
        msgError("expected 'name=value' items separated by '&', got '" + item + "'",
                 "responseParams");
      start = end + 1;
    }
    if (isValid())
      msgWarning("'" + params +
                     "' has no meaning for the penalty response: the parameters "
                     "are ignored",
                 "responseParams");
  }
  // Models that name their own response.
  if (Node* here = node())
    for (Node* root = &here->root(); root;) {
      std::vector<Node*> stack{root};
      while (!stack.empty()) {
        Node* n = stack.back();
        stack.pop_back();
        for (const auto& o : n->objects())
          if (auto* model = dynamic_cast<CollisionModel*>(o.get()))
            if (!model->d_contactResponse.value().empty())
              checkResponseName(model->d_contactResponse.value(), *model, "contactResponse");
        for (const auto& c : n->children()) stack.push_back(c.get());
      }
      root = nullptr;
    }
}

const BaseForceField* CollisionResponse::responseOf(const CollisionModel& first,
                                                    const CollisionModel& second) const {
  for (const Response& r : m_responses)
    if ((r.first == &first && r.second == &second) || (r.first == &second && r.second == &first))
      return r.forceField;
  return nullptr;
}

CollisionResponse::Response* CollisionResponse::createResponse(CollisionModel& first,
                                                               CollisionModel& second) {
  BaseMechanicalState* s1 = first.state();
  BaseMechanicalState* s2 = second.state();
  std::vector<PenaltyContact>* contacts = nullptr;
  std::unique_ptr<BaseForceField> ff = makePenalty<Vec3Types, Vec3Types>(s1, s2, contacts);
  if (!ff) ff = makePenalty<Vec3Types, Rigid3Types>(s1, s2, contacts);
  if (!ff) ff = makePenalty<Rigid3Types, Vec3Types>(s1, s2, contacts);
  if (!ff) ff = makePenalty<Rigid3Types, Rigid3Types>(s1, s2, contacts);
  Node* where = commonAncestor(first.node(), second.node());
  if (!ff || !where) {
    msgError("no penalty response between the states of " + first.path() + " and " + second.path() +
             " (Vec3d and Rigid3d states are supported)");
    return nullptr;
  }
  ff->setName("penality" + std::to_string(m_created++) + "_" + first.name() + "_" + second.name());
  ff->setClassName(kPenalty, std::string(s1->templateName()));
  BaseForceField* raw = ff.get();
  where->addObject(std::move(ff));
  raw->init();
  m_responses.push_back({&first, &second, raw, contacts, false});
  return &m_responses.back();
}

void CollisionResponse::updateResponses(std::span<const ModelPairContacts> contacts,
                                        const Intersection& intersection) {
  for (Response& r : m_responses) r.touched = false;
  for (const ModelPairContacts& pair : contacts) {
    Response* response = nullptr;
    for (Response& r : m_responses)
      if (r.first == pair.first && r.second == pair.second) response = &r;
    if (!response) response = createResponse(*pair.first, *pair.second);
    if (!response) continue;
    response->touched = true;
    const CollisionGeometry &g1 = pair.first->geometry(), &g2 = pair.second->geometry();
    const double d0 = intersection.contactDistance() + pair.first->d_contactDistance.value() +
                      pair.second->d_contactDistance.value();
    const double k12 =
        pair.first->d_contactStiffness.value() * pair.second->d_contactStiffness.value();
    std::vector<PenaltyContact>& out = *response->contacts;
    out.resize(pair.contacts.size());
    for (std::size_t n = 0; n < pair.contacts.size(); ++n) {
      const Contact& c = pair.contacts[n];
      PenaltyContact& p = out[n];
      primitiveVertices(g1, c.primitive[0], p, 0);
      primitiveVertices(g2, c.primitive[1], p, 1);
      p.weights[0] = c.weights[0];
      p.weights[1] = c.weights[1];
      // A box's contact point is off its frame's origin: its arm in the frame's axes, so that
      // it turns with the frame (a sphere's force goes through its centre: no arm).
      p.arm[0] = frameArm(g1, c.primitive[0], c.point[0]);
      p.arm[1] = frameArm(g2, c.primitive[1], c.point[1]);
      p.normal = c.normal;
      const double r1 = g1.kind == PrimitiveKind::sphere ? g1.radius(c.primitive[0]) : 0.0;
      const double r2 = g2.kind == PrimitiveKind::sphere ? g2.radius(c.primitive[1]) : 0.0;
      p.restDistance = d0 + r1 + r2;
      p.stiffness = p.restDistance != 0 ? k12 / p.restDistance : k12;
    }
  }
  for (Response& r : m_responses)
    if (!r.touched) r.contacts->clear();
}

}  // namespace stroma
