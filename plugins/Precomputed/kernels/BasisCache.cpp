// SPDX-License-Identifier: MIT
#include "Precomputed/kernels/BasisCache.h"

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace stroma::precomputed {
namespace {

constexpr char kMagic[8] = {'S', 'T', 'R', 'M', 'P', 'C', 'B', '1'};
constexpr std::uint32_t kVersion = 1;

struct Header {
  char magic[8];
  std::uint32_t version;
  std::uint32_t reserved;
  std::uint64_t key;
  std::uint64_t nodeCount;
  std::uint64_t rowCount;
  std::uint64_t basisCount;
  std::uint64_t payloadBytes;
  std::uint64_t payloadChecksum;
};
static_assert(sizeof(Header) == 64, "the cache header is 64 bytes without padding");

std::uint64_t payloadBytesOf(std::uint64_t r, std::uint64_t k) {
  return 4 * r + 4 * k + 3 * k + 8 * (3 * r) * (3 * k);
}

template <class T>
std::uint64_t hashVector(const std::vector<T>& v, std::uint64_t hash) {
  const std::uint64_t size = v.size();
  hash = fnv1a64(&size, sizeof size, hash);
  return v.empty() ? hash : fnv1a64(v.data(), v.size() * sizeof(T), hash);
}

}  // namespace

std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t hash) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= bytes[i];
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

std::uint64_t computeBasisKey(const std::vector<Eigen::Vector3d>& points,
                              const std::vector<TetrahedronNodes>& tetrahedra, double youngModulus,
                              double poissonRatio, const std::vector<int>& fixedDofs,
                              const std::vector<int>& basisNodes,
                              const std::vector<int>& rowNodes) {
  std::uint64_t hash = fnv1a64(kMagic, sizeof kMagic);
  hash = hashVector(points, hash);
  hash = hashVector(tetrahedra, hash);
  hash = fnv1a64(&youngModulus, sizeof youngModulus, hash);
  hash = fnv1a64(&poissonRatio, sizeof poissonRatio, hash);
  hash = hashVector(fixedDofs, hash);
  hash = hashVector(basisNodes, hash);
  return hashVector(rowNodes, hash);
}

std::uint64_t computeComplianceKey(const SparseMatrix& A,
                                   const std::vector<Eigen::Vector3d>& restPoints,
                                   const std::vector<int>& fixedDofs,
                                   const std::vector<int>& basisNodes,
                                   const std::vector<double>& factors) {
  // Another salt than computeBasisKey's: a stiffness basis and a compliance never share a key.
  constexpr char kSalt[8] = {'S', 'T', 'R', 'M', 'C', 'M', 'P', '1'};
  std::uint64_t hash = fnv1a64(kSalt, sizeof kSalt);
  const std::int64_t sizes[3] = {A.rows(), A.cols(), A.nonZeros()};
  hash = fnv1a64(sizes, sizeof sizes, hash);
  // The compressed storage, in its order (a pattern and the values in it).
  SparseMatrix compressed = A;
  compressed.makeCompressed();
  hash = fnv1a64(compressed.outerIndexPtr(), sizeof(int) * std::size_t(compressed.outerSize() + 1),
                 hash);
  hash =
      fnv1a64(compressed.innerIndexPtr(), sizeof(int) * std::size_t(compressed.nonZeros()), hash);
  hash = fnv1a64(compressed.valuePtr(), sizeof(double) * std::size_t(compressed.nonZeros()), hash);
  hash = hashVector(restPoints, hash);
  hash = hashVector(fixedDofs, hash);
  hash = hashVector(basisNodes, hash);
  return hashVector(factors, hash);
}

bool isBasisCacheFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[sizeof kMagic];
  return in.read(magic, sizeof magic) && std::memcmp(magic, kMagic, sizeof kMagic) == 0;
}

std::uint64_t basisCacheBytes(const DeformationBasis& basis) {
  return sizeof(Header) + payloadBytesOf(basis.rowNodes().size(), basis.basisNodes().size());
}

bool writeBasisCache(const std::string& path, std::uint64_t key, const DeformationBasis& basis,
                     std::string& error) {
  const std::uint64_t r = basis.rowNodes().size(), k = basis.basisNodes().size();
  // Checksum over the payload in file order.
  std::uint64_t checksum = fnv1a64(basis.rowNodes().data(), 4 * r);
  checksum = fnv1a64(basis.basisNodes().data(), 4 * k, checksum);
  checksum = fnv1a64(basis.fixedColumns().data(), 3 * k, checksum);
  checksum = fnv1a64(basis.columns().data(), 8 * 3 * r * 3 * k, checksum);
  Header header{};
  std::memcpy(header.magic, kMagic, sizeof kMagic);
  header.version = kVersion;
  header.key = key;
  header.nodeCount = std::uint64_t(basis.nodeCount());
  header.rowCount = r;
  header.basisCount = k;
  header.payloadBytes = payloadBytesOf(r, k);
  header.payloadChecksum = checksum;

  std::error_code ec;
  const std::filesystem::path target(path);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), ec);
  // One temporary name per process: two runs writing the same cache do not mix their bytes.
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      error = "cannot write '" + temporary + "'";
      return false;
    }
    out.write(reinterpret_cast<const char*>(&header), sizeof header);
    out.write(reinterpret_cast<const char*>(basis.rowNodes().data()), std::streamsize(4 * r));
    out.write(reinterpret_cast<const char*>(basis.basisNodes().data()), std::streamsize(4 * k));
    out.write(basis.fixedColumns().data(), std::streamsize(3 * k));
    out.write(reinterpret_cast<const char*>(basis.columns().data()),
              std::streamsize(8 * 3 * r * 3 * k));
    if (!out.flush()) {
      error = "writing '" + temporary + "' failed (disk full?)";
      std::filesystem::remove(temporary, ec);
      return false;
    }
  }
  std::filesystem::rename(temporary, target, ec);
  if (ec) {
    error = "cannot rename '" + temporary + "' to '" + path + "': " + ec.message();
    std::filesystem::remove(temporary, ec);
    return false;
  }
  return true;
}

std::optional<DeformationBasis> readBasisCache(const std::string& path, std::uint64_t key,
                                               std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "no cache file '" + path + "'";
    return std::nullopt;
  }
  Header header{};
  if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) {
    error = "'" + path + "' is truncated (shorter than its header)";
    return std::nullopt;
  }
  if (std::memcmp(header.magic, kMagic, sizeof kMagic) != 0) {
    error = "'" + path + "' is not a precomputed-basis file (wrong magic)";
    return std::nullopt;
  }
  if (header.version != kVersion) {
    error = "'" + path + "' has version " + std::to_string(header.version) + ", expected " +
            std::to_string(kVersion);
    return std::nullopt;
  }
  if (header.key != key) {
    error = "'" + path + "' holds the basis of another mesh, material or boundary (key differs)";
    return std::nullopt;
  }
  const std::uint64_t r = header.rowCount, k = header.basisCount;
  // Sizes bounded before any allocation: a corrupt header must not ask for terabytes.
  if (header.nodeCount == 0 || header.nodeCount > (1u << 30) || r > header.nodeCount ||
      k > header.nodeCount || r * k > (std::uint64_t(1) << 36) ||
      header.payloadBytes != payloadBytesOf(r, k)) {
    error = "'" + path + "' has inconsistent sizes (corrupt header)";
    return std::nullopt;
  }
  std::error_code ec;
  const auto fileSize = std::filesystem::file_size(path, ec);
  if (ec || fileSize != sizeof(Header) + header.payloadBytes) {
    error = "'" + path + "' is truncated or too long (" + std::to_string(ec ? 0 : fileSize) +
            " bytes, expected " + std::to_string(sizeof(Header) + header.payloadBytes) + ")";
    return std::nullopt;
  }
  std::vector<int> rowNodes(r), basisNodes(k);
  std::vector<char> fixedColumns(3 * k);
  MatrixXd columns(Eigen::Index(3 * r), Eigen::Index(3 * k));
  in.read(reinterpret_cast<char*>(rowNodes.data()), std::streamsize(4 * r));
  in.read(reinterpret_cast<char*>(basisNodes.data()), std::streamsize(4 * k));
  in.read(fixedColumns.data(), std::streamsize(3 * k));
  in.read(reinterpret_cast<char*>(columns.data()), std::streamsize(8 * 3 * r * 3 * k));
  if (!in) {
    error = "'" + path + "' is truncated";
    return std::nullopt;
  }
  std::uint64_t checksum = fnv1a64(rowNodes.data(), 4 * r);
  checksum = fnv1a64(basisNodes.data(), 4 * k, checksum);
  checksum = fnv1a64(fixedColumns.data(), 3 * k, checksum);
  checksum = fnv1a64(columns.data(), 8 * 3 * r * 3 * k, checksum);
  if (checksum != header.payloadChecksum) {
    error = "'" + path + "' is corrupt (payload checksum mismatch)";
    return std::nullopt;
  }
  std::string invalid;
  auto basis = DeformationBasis::fromColumns(int(header.nodeCount), std::move(rowNodes),
                                             std::move(basisNodes), std::move(fixedColumns),
                                             std::move(columns), invalid);
  if (!basis) error = "'" + path + "' holds an invalid basis: " + invalid;
  return basis;
}

}  // namespace stroma::precomputed
