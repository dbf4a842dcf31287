// SPDX-License-Identifier: MIT
#pragma once

#include "BarycentricCoordinates.h"
#include "MappedOutput.h"
#include "core/StateTypes.h"
#include "simulation/Mapping.h"

namespace stroma {

class Topology;

/// Points embedded in a volume mesh (SOFA's BarycentricMapping, Vec3d -> Vec3d): each output
/// point follows the element of the input's topology it lies in, x_out = sum_k w_k x_in[n_k],
/// with its barycentric weights in a tetrahedron or trilinear weights in a hexahedron
/// (BarycentricCoordinates.h). J holds the weights and is constant.
///
/// The element of each point is the one containing it at init, else the nearest, whose weights
/// then extrapolate; a warning gives how many points are outside and the farthest distance. The
/// topology is `input_topology`, else the one in the input's node (MeshTopology, the
/// *SetTopologyContainer components, RegularGridTopology): its tetrahedra and hexahedra are
/// used. With useRestPosition, the weights come from the rest positions of input and output.
/// A visual output is not mapped in batch runs, so its weights are not computed.
///
/// When tetrahedra are removed at run time (cutting, Topology::removeTetrahedra), the mapping
/// follows at its next use: points whose tetrahedron moved get its new index, and points whose
/// tetrahedron was removed are embedded again, in the geometry of init, in the nearest
/// remaining element (a warning the first time, with the count; reattachedCount() after). The
/// cost is a pass over the mapped points plus a search for the re-attached ones.
class BarycentricMapping final : public Mapping<Vec3Types, Vec3Types> {
 public:
  Data<bool> d_useRestPosition{this, "useRestPosition", false,
                               "Compute the weights from the rest positions of the input and "
                               "the output (default: their positions)."};
  Link<Base> l_inputTopology{this, "input_topology",
                             "The input's volume mesh (default: the topology in the input's "
                             "node)."};
  SofaMappingOptions m_options{this};

  void init() override;

  void apply(OutVecCoord& out, const InVecCoord& in) override;
  void applyJ(OutVecDeriv& out, const InVecDeriv& in) override;
  void applyJT(InVecDeriv& in, const OutVecDeriv& out) override;
  /// nbOutput*3 x nbInput*3, the weights on the diagonal of 3x3 blocks.
  const Eigen::SparseMatrix<double>& jacobian() override;

  /// The element and weights of each output point (after init), up to date with the topology.
  const std::vector<barycentric::EmbeddedPoint>& embedding() {
    refresh();
    return m_points;
  }
  /// How many times an output point was re-attached because its tetrahedron was removed.
  std::size_t reattachedCount() const { return m_reattached; }

 protected:
  bool prepareVisual(const OutVecCoord& points) override;

 private:
  const Topology* findTopology();
  bool embedOutput(const std::vector<Vec3d>& points, VecId inputPoints);
  /// Follows the topology's changes since the embedding was made.
  void refresh();
  /// Embeds the output points `which` (all when empty) in the current elements.
  void embed(const std::vector<std::size_t>& which);

  const Topology* m_topology = nullptr;
  std::uint64_t m_revision = 0;
  std::vector<Vec3d> m_nodes;         ///< the input points the weights were computed on
  std::vector<Vec3d> m_outputPoints;  ///< the output points the weights were computed on
  std::size_t m_reattached = 0;
  std::vector<barycentric::EmbeddedPoint> m_points;
  Eigen::SparseMatrix<double> m_J;
  bool m_jacobianReady = false;
};

}  // namespace stroma
