// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ContactConstraint.h"
#include "PenalityContactForceField.h"
#include "collision/CollisionPipeline.h"

namespace stroma {

/// SOFA's CollisionResponse (old name DefaultContactManager): turns each step's contacts into
/// responses. The response of a pair of models is the first model's `contactResponse`, else the
/// second's, else `response`:
///   - PenalityContactForceField (the default): penalty forces, with SOFA's constants: a contact
///     keeps the gap d0 = contactDistance (of the intersection) + both models' contactDistance
///     (+ the spheres' radii), and its stiffness is k = contactStiffness_1 contactStiffness_2 /
///     d0 (k1 k2 when d0 is 0);
///   - FrictionContactConstraint (SOFA's older FrictionContact): Lagrangian constraints with
///     Coulomb friction, solved by FreeMotionAnimationLoop; mu from `responseParams` ("mu=0.3"),
///     else the models' contactFriction where the scene sets it (the product of the two when
///     both do, as SOFA's penalty and compliant contacts combine them), else SOFA's 0.8;
///   - StickContactConstraint (StickContact): the contact points held together once touching.
/// One response per pair of models in contact, created at their first contact in the nearest
/// common ancestor of the two models' nodes and kept afterwards (its contacts are replaced each
/// step, no allocation once warm).
class CollisionResponse final : public ContactManager {
 public:
  Data<std::string> d_response{this, "response", "PenalityContactForceField",
                               "The response to contacts: PenalityContactForceField (penalty "
                               "forces), FrictionContactConstraint or StickContactConstraint "
                               "(Lagrangian constraints, under FreeMotionAnimationLoop)."};
  Data<std::string> d_responseParams{this, "responseParams", "",
                                     "Parameters of the response, 'name=value' separated by "
                                     "'&' (SOFA's syntax): 'mu' (friction coefficient, >= 0) "
                                     "and 'tol' (accepted) for the constraint responses; the "
                                     "penalty response takes none."};

  CollisionResponse();
  ~CollisionResponse() override;

  void init() override;
  void updateResponses(std::span<const ModelPairContacts> contacts,
                       const Intersection& intersection) override;

  /// The response component of a pair of models (a penalty force field, a contact constraint),
  /// or nullptr before their first contact.
  const Base* responseOf(const CollisionModel& first, const CollisionModel& second) const;

 private:
  enum class Kind { penalty, friction, stick };
  struct Response {
    const CollisionModel* first = nullptr;
    const CollisionModel* second = nullptr;
    Base* component = nullptr;                        // owned by the node it was added to
    ContactConstraintBase* constraint = nullptr;      // the same, for constraint responses
    std::vector<PenaltyContact>* contacts = nullptr;  // its contact list
    bool touched = false;                             // has contacts this step
  };
  bool checkResponseName(const std::string& name, const Base& where, const std::string& field);
  bool readResponseParams();
  Kind kindOf(const CollisionModel& first, const CollisionModel& second) const;
  double frictionOf(const CollisionModel& first, const CollisionModel& second) const;
  Response* createResponse(CollisionModel& first, CollisionModel& second);

  double m_mu = 0.8;
  bool m_muSet = false;
  std::vector<Response> m_responses;
  int m_created = 0;
};

}  // namespace stroma
