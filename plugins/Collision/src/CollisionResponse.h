// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "PenalityContactForceField.h"
#include "collision/CollisionPipeline.h"

namespace stroma {

/// SOFA's CollisionResponse (old name DefaultContactManager): turns each step's contacts into
/// responses. The response is `response` (or a model's own `contactResponse`); the one provided
/// is PenalityContactForceField (the default): one force field per pair of models in contact,
/// created at their first contact in the nearest common ancestor of the two models' nodes and
/// kept afterwards (its contacts are replaced each step, no allocation once warm), with SOFA's
/// constants: a contact keeps the gap d0 = contactDistance (of the intersection) + both
/// models' contactDistance (+ the spheres' radii), and its stiffness is
/// k = contactStiffness_1 contactStiffness_2 / d0 (k1 k2 when d0 is 0).
class CollisionResponse final : public ContactManager {
 public:
  Data<std::string> d_response{this, "response", "PenalityContactForceField",
                               "The response to contacts: PenalityContactForceField (penalty "
                               "forces). Constraint-based responses are not provided yet."};
  Data<std::string> d_responseParams{this, "responseParams", "",
                                     "Parameters of the response, 'name=value' separated by "
                                     "'&' (SOFA's syntax); the penalty response takes none."};

  CollisionResponse();
  ~CollisionResponse() override;

  void init() override;
  void updateResponses(std::span<const ModelPairContacts> contacts,
                       const Intersection& intersection) override;

  /// The penalty force field of a pair of models, or nullptr before their first contact.
  const BaseForceField* responseOf(const CollisionModel& first, const CollisionModel& second) const;

 private:
  struct Response {
    const CollisionModel* first = nullptr;
    const CollisionModel* second = nullptr;
    BaseForceField* forceField = nullptr;             // owned by the node it was added to
    std::vector<PenaltyContact>* contacts = nullptr;  // its contact list
    bool touched = false;                             // has contacts this step
  };
  bool checkResponseName(const std::string& name, const Base& where, const std::string& field);
  Response* createResponse(CollisionModel& first, CollisionModel& second);

  std::vector<Response> m_responses;
  int m_created = 0;
};

}  // namespace stroma
