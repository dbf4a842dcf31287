// SPDX-License-Identifier: MIT
#include "CollisionResponse.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/NameSuggestions.h"
#include "core/Node.h"
#include "simulation/AnimationLoop.h"

namespace stroma {

namespace {

constexpr const char* kPenalty = "PenalityContactForceField";

// The constraint responses provided (SOFA's current and older names) and those that are not.
const std::vector<std::string> kFriction = {"FrictionContactConstraint", "FrictionContact"};
const std::vector<std::string> kStick = {"StickContactConstraint", "StickContact"};
const std::vector<std::string> kNotProvided = {"BilateralContactConstraint",
                                               "AugmentedLagrangianResponseConstraint",
                                               "UnilateralContact"};

bool among(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool needsConstraints(const std::string& name) { return among(kFriction, name) || among(kStick, name); }

// The nearest node that holds both (or is an ancestor of both).
Node* commonAncestor(Node* a, Node* b) {
  for (Node* x = a; x; x = x->parent())
    for (Node* y = b; y; y = y->parent())
      if (x == y) return x;
  return nullptr;
}

template <class D1, class D2>
std::unique_ptr<ContactConstraintBase> makeConstraint(BaseMechanicalState* s1,
                                                      BaseMechanicalState* s2,
                                                      ContactConstraintBase::Law law) {
  auto* t1 = dynamic_cast<MechanicalState<D1>*>(s1);
  auto* t2 = dynamic_cast<MechanicalState<D2>*>(s2);
  if (!t1 || !t2) return nullptr;
  return std::make_unique<ContactConstraint<D1, D2>>(t1, t2, law);
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
  std::string text;
  if (name == kPenalty || name == "default") return true;
  if (needsConstraints(name)) {
    const Node* here = node();
    const AnimationLoop* loop = here ? here->root().get<AnimationLoop>() : nullptr;
    if (!here || (loop && loop->solvesConstraints())) return true;
    text = "the response '" + name + "' gives Lagrangian constraints, which only "
           "FreeMotionAnimationLoop solves: add <FreeMotionAnimationLoop/> and a constraint "
           "solver (GenericConstraintSolver) to the root node" +
           (loop ? " instead of its " + loop->className() : std::string()) +
           ", or use the penalty response '" + kPenalty + "'";
  } else {
    std::vector<std::string> known{kPenalty};
    known.insert(known.end(), kFriction.begin(), kFriction.end());
    known.insert(known.end(), kStick.begin(), kStick.end());
    const std::string available = "'" + std::string(kPenalty) + "', '" + kFriction[0] + "', '" +
                                  kStick[0] + "'";
    if (among(kNotProvided, name)) {
      text = "the response '" + name + "' is not provided; available: " + available;
    } else {
      text = "unknown response '" + name + "'";
      const auto near = nearestNames(name, known);
      text += near.empty() ? "; available: " + available : "; did you mean " + quotedList(near) + "?";
    }
  }
  if (&where == this)
    msgError(text, field);
  else
    msgError(text + " (" + where.path() + ")", field);
  return false;
}

// 'name=value' items separated by '&': mu and tol for the constraint responses.
bool CollisionResponse::readResponseParams() {
  const std::string& params = d_responseParams.value();
  if (params.empty()) return true;
  const bool constraints = needsConstraints(d_response.value());
  std::size_t start = 0;
  while (start <= params.size()) {
    const std::size_t end = std::min(params.find('&', start), params.size());
    const std::string item = params.substr(start, end - start);
    start = end + 1;
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      msgError("expected 'name=value' items separated by '&', got '" + item + "'",
               "responseParams");
      return false;
    }
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    if (!constraints) continue;
    if (key != "mu" && key != "tol") {
      msgWarning("'" + key + "' is not a parameter of " + d_response.value() +
                     " ('mu', 'tol'): ignored",
                 "responseParams");
      continue;
    }
    char* rest = nullptr;
    const double number = std::strtod(value.c_str(), &rest);
    if (value.empty() || *rest != '\0' || !std::isfinite(number)) {
      msgError("'" + key + "' must be a number, got '" + value + "'", "responseParams");
      return false;
    }
    if (key == "mu") {
      if (number < 0) {
        msgError("the friction coefficient mu must be >= 0, got " + value, "responseParams");
        return false;
      }
      m_mu = number;
      m_muSet = true;
    }
  }
  if (!constraints && isValid())
    msgWarning("'" + params + "' has no meaning for the penalty response: the parameters are "
               "ignored",
               "responseParams");
  return true;
}

void CollisionResponse::init() {
  checkResponseName(d_response.value(), *this, "response");
  readResponseParams();
  // Models that name their own response.
  if (Node* here = node()) {
    std::vector<Node*> stack{&here->root()};
    while (!stack.empty()) {
      Node* n = stack.back();
      stack.pop_back();
      for (const auto& o : n->objects())
        if (auto* model = dynamic_cast<CollisionModel*>(o.get()))
          if (!model->d_contactResponse.value().empty())
            checkResponseName(model->d_contactResponse.value(), *model, "contactResponse");
      for (const auto& c : n->children()) stack.push_back(c.get());
    }
  }
}

CollisionResponse::Kind CollisionResponse::kindOf(const CollisionModel& first,
                                                  const CollisionModel& second) const {
  const std::string* name = &d_response.value();
  if (!first.d_contactResponse.value().empty()) name = &first.d_contactResponse.value();
  else if (!second.d_contactResponse.value().empty()) name = &second.d_contactResponse.value();
  if (among(kFriction, *name)) return Kind::friction;
  if (among(kStick, *name)) return Kind::stick;
  return Kind::penalty;
}

double CollisionResponse::frictionOf(const CollisionModel& first,
                                     const CollisionModel& second) const {
  if (m_muSet) return m_mu;
  const bool set1 = first.d_contactFriction.isSet(), set2 = second.d_contactFriction.isSet();
  if (set1 && set2) return first.d_contactFriction.value() * second.d_contactFriction.value();
  if (set1) return first.d_contactFriction.value();
  if (set2) return second.d_contactFriction.value();
  return m_mu;
}

const Base* CollisionResponse::responseOf(const CollisionModel& first,
                                          const CollisionModel& second) const {
  for (const Response& r : m_responses)
    if ((r.first == &first && r.second == &second) || (r.first == &second && r.second == &first))
      return r.component;
  return nullptr;
}

CollisionResponse::Response* CollisionResponse::createResponse(CollisionModel& first,
                                                               CollisionModel& second) {
  BaseMechanicalState* s1 = first.state();
  BaseMechanicalState* s2 = second.state();
  const Kind kind = kindOf(first, second);
  Response response{&first, &second};
  std::unique_ptr<Base> component;
  if (kind == Kind::penalty) {
    std::unique_ptr<BaseForceField> ff = makePenalty<Vec3Types, Vec3Types>(s1, s2, response.contacts);
    if (!ff) ff = makePenalty<Vec3Types, Rigid3Types>(s1, s2, response.contacts);
    if (!ff) ff = makePenalty<Rigid3Types, Vec3Types>(s1, s2, response.contacts);
    if (!ff) ff = makePenalty<Rigid3Types, Rigid3Types>(s1, s2, response.contacts);
    component = std::move(ff);
  } else {
    const auto law = kind == Kind::stick ? ContactConstraintBase::Law::stick
                                         : ContactConstraintBase::Law::friction;
    std::unique_ptr<ContactConstraintBase> c = makeConstraint<Vec3Types, Vec3Types>(s1, s2, law);
    if (!c) c = makeConstraint<Vec3Types, Rigid3Types>(s1, s2, law);
    if (!c) c = makeConstraint<Rigid3Types, Vec3Types>(s1, s2, law);
    if (!c) c = makeConstraint<Rigid3Types, Rigid3Types>(s1, s2, law);
    if (c) {
      c->setFriction(kind == Kind::friction ? frictionOf(first, second) : 0.0);
      response.constraint = c.get();
      response.contacts = &c->contacts();
    }
    component = std::move(c);
  }
  Node* where = commonAncestor(first.node(), second.node());
  const char* className = kind == Kind::penalty  ? kPenalty
                          : kind == Kind::stick ? "StickContactConstraint"
                                                : "FrictionContactConstraint";
  if (!component || !where) {
    msgError(std::string("no ") + className + " response between the states of " + first.path() +
             " and " + second.path() + " (Vec3d and Rigid3d states are supported)");
    return nullptr;
  }
  const char* prefix = kind == Kind::penalty ? "penality" : "contact";
  component->setName(prefix + std::to_string(m_created++) + "_" + first.name() + "_" + second.name());
  component->setClassName(className, std::string(s1->templateName()));
  response.component = component.get();
  where->addObject(std::move(component));
  response.component->init();
  m_responses.push_back(response);
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
    if (response->constraint) {
      // Friction acts at a sphere's surface point: its offset from the centre turns a frame.
      auto& offsets = response->constraint->surfaceOffsets();
      offsets.resize(out.size());
      for (std::size_t n = 0; n < out.size(); ++n) {
        const Contact& c = pair.contacts[n];
        const double r1 = g1.kind == PrimitiveKind::sphere ? g1.radius(c.primitive[0]) : 0.0;
        const double r2 = g2.kind == PrimitiveKind::sphere ? g2.radius(c.primitive[1]) : 0.0;
        offsets[n] = {Vec3d(r1 * c.normal), Vec3d(-r2 * c.normal)};
      }
    }
  }
  for (Response& r : m_responses)
    if (!r.touched) r.contacts->clear();
}

}  // namespace stroma
