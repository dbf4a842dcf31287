// SPDX-License-Identifier: MIT
// The deformation basis on disk, so that a second run loads it instead of factorising again.
//
// File layout (host byte order, little-endian on every platform Stroma builds on):
//   header   magic "STRMPCB1" (8 bytes), version (u32), reserved (u32, 0), key (u64),
//            nodeCount, rowCount r, basisCount k (u64 each), payloadBytes (u64),
//            payloadChecksum (u64, FNV-1a 64 of the payload)
//   payload  rowNodes (r x i32), basisNodes (k x i32), fixedColumns (3k x u8),
//            columns (3r x 3k doubles, column-major)
// The key (computeBasisKey) hashes everything the basis depends on; a file whose magic,
// version, key, sizes or checksum disagree is refused with the reason, never used.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "Precomputed/kernels/DeformationBasis.h"
#include "Precomputed/kernels/LinearStiffnessAssembly.h"

namespace stroma::precomputed {

/// FNV-1a 64-bit hash of `size` bytes, continuing from `hash` (Fowler, Noll, Vo).
std::uint64_t fnv1a64(const void* data, std::size_t size,
                      std::uint64_t hash = 0xcbf29ce484222325ULL);

/// The cache key of a basis: rest points, elements, material, fixed dofs, basis nodes and the
/// row nodes kept (all bit-exact: any change gives another key).
std::uint64_t computeBasisKey(const std::vector<Eigen::Vector3d>& points,
                              const std::vector<TetrahedronNodes>& tetrahedra, double youngModulus,
                              double poissonRatio, const std::vector<int>& fixedDofs,
                              const std::vector<int>& basisNodes, const std::vector<int>& rowNodes);

/// The cache key of a compliance basis: the columns of A^-1 for a solver's system matrix A
/// (a constraint correction's precomputation, A = mFactor M + bFactor B + kFactor K with
/// identity rows and columns on the fixed dofs). Hashes A's pattern and values (the mesh, the
/// material, the masses, the time step and the solver's factors all enter them), the rest
/// points the rotations are measured from, the fixed dofs, the basis nodes and `factors` (the
/// solver's m, b, k factors and dt, already in A, hashed again so that a key never depends on
/// the values happening to cancel). All bit-exact: any change gives another key. Differs from
/// every computeBasisKey.
std::uint64_t computeComplianceKey(const SparseMatrix& A,
                                   const std::vector<Eigen::Vector3d>& restPoints,
                                   const std::vector<int>& fixedDofs,
                                   const std::vector<int>& basisNodes,
                                   const std::vector<double>& factors);

/// Whether `path` begins like a cache file of this format (its magic), whatever its key or
/// content: a caller can then leave a file of another program alone instead of overwriting it.
bool isBasisCacheFile(const std::string& path);

/// Writes `basis` under `key` to `path` (through a temporary file of this process renamed at the
/// end, so that an interrupted or concurrent write leaves no partial file under that name). false
/// and `error` on failure.
bool writeBasisCache(const std::string& path, std::uint64_t key, const DeformationBasis& basis,
                     std::string& error);

/// Reads the basis stored under `key` in `path`. nullopt and `error` (missing file, not a
/// basis file, other version, other key: another mesh or material, truncated, checksum
/// mismatch: corrupt) otherwise.
std::optional<DeformationBasis> readBasisCache(const std::string& path, std::uint64_t key,
                                               std::string& error);

/// Bytes a basis takes in a cache file (header included).
std::uint64_t basisCacheBytes(const DeformationBasis& basis);

}  // namespace stroma::precomputed
