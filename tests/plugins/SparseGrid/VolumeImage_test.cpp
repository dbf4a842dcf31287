// SPDX-License-Identifier: MIT
// The volume image readers (plugins/SparseGrid/src/image): small MetaImage and NRRD files of
// every sample type, byte order, encoding and layout are written here and read back exactly;
// axes given with negative directions are flipped in place; each bad header is an error naming
// the file, the line and the field.
#include "image/VolumeImage.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#ifdef STROMA_HAS_ZLIB
#include <zlib.h>
#endif

namespace stroma::image {
namespace {

/// The bytes of `values` stored as T, in big- or little-endian order.
template <typename T>
std::string pack(const std::vector<double>& values, bool bigEndian) {
  std::string bytes;
  for (double v : values) {
    const T t = static_cast<T>(v);
    std::array<char, sizeof(T)> raw;
    std::memcpy(raw.data(), &t, sizeof(T));
    if (bigEndian != (std::endian::native == std::endian::big))
      std::reverse(raw.begin(), raw.end());
    bytes.append(raw.data(), raw.size());
  }
  return bytes;
}

/// Values that T holds exactly, including its extremes (3 x 2 x 2 voxels).
template <typename T>
std::vector<double> sampleValues() {
  const double lo = double(std::numeric_limits<T>::lowest());
  const double hi = double(std::numeric_limits<T>::max());
  if constexpr (std::is_floating_point_v<T>)
    return {-1.5, 0.25, 3e4, 0, 1, -0.125, 7, 8.5, -0.0625, 2, 1e6, 4};
  else if constexpr (sizeof(T) == 8)  // doubles hold integers up to 2^53 exactly
    return {lo < 0 ? -9007199254740992.0 : 0, 9007199254740992.0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  else
    return {lo, hi, 0, 1, 2, 3, 4, 5, 6, 7, 8, hi - 1};
}

class VolumeImageTest : public ::testing::Test {
 protected:
  VolumeImageTest() {
    static std::atomic<int> counter{0};
    m_folder = std::filesystem::temp_directory_path() /
               ("stroma-volume-image-test-" + std::to_string(::getpid()) + "-" +
                std::to_string(counter++));
    std::filesystem::create_directories(m_folder);
  }
  ~VolumeImageTest() override {
    std::error_code ignored;
    std::filesystem::remove_all(m_folder, ignored);
  }
  std::string write(const std::string& name, const std::string& bytes) {
    const auto path = m_folder / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
  }
  /// Reads `path`, expecting success.
  VolumeImage read(const std::string& path) {
    VolumeImage image;
    std::string error;
    EXPECT_TRUE(readVolumeImage(path, image, error)) << error;
    return image;
  }
  /// Reads `path`, expecting an error that contains each of `parts`; returns it.
  std::string readError(const std::string& path, std::initializer_list<std::string> parts) {
    VolumeImage image;
    std::string error;
    EXPECT_FALSE(readVolumeImage(path, image, error)) << path << " was read";
    for (const std::string& part : parts)
      EXPECT_NE(error.find(part), std::string::npos) << "'" << part << "' not in: " << error;
    return error;
  }

  /// Writes a 3 x 2 x 2 image of type T as .mhd + .raw and as .mha, and checks both read back.
  template <typename T>
  void metaImageRoundTrip(const std::string& metType, bool bigEndian) {
    const std::vector<double> values = sampleValues<T>();
    const std::string header =
        "ObjectType = Image\nNDims = 3\nDimSize = 3 2 2\n"
        "ElementSpacing = 0.5 0.25 2\nOffset = -1 2 3.5\n"
        "ElementType = " +
        metType + "\nElementByteOrderMSB = " + (bigEndian ? "True" : "False") + "\n";
    const std::string stem = metType + (bigEndian ? "_big" : "_little");
    write(stem + ".raw", pack<T>(values, bigEndian));
    const std::string mhd = write(stem + ".mhd", header + "ElementDataFile = " + stem + ".raw\n");
    const std::string mha =
        write(stem + ".mha", header + "ElementDataFile = LOCAL\n" + pack<T>(values, bigEndian));
    for (const std::string& path : {mhd, mha}) {
      SCOPED_TRACE(path);
      const VolumeImage image = read(path);
      EXPECT_EQ(image.size, (std::array<int, 3>{3, 2, 2}));
      EXPECT_EQ(image.values, values);
      EXPECT_EQ(image.spacing, Vec3d(0.5, 0.25, 2));
      EXPECT_EQ(image.origin, Vec3d(-1, 2, 3.5));
    }
  }

  /// The same with a NRRD header, attached (.nrrd) and detached (.nhdr).
  template <typename T>
  void nrrdRoundTrip(const std::string& nrrdType, bool bigEndian) {
    const std::vector<double> values = sampleValues<T>();
    const std::string header = "NRRD0004\n# a comment\ntype: " + nrrdType +
                               "\ndimension: 3\nsizes: 3 2 2\nspacings: 0.5 0.25 2\n"
                               "endian: " +
                               (bigEndian ? "big" : "little") +
                               "\nencoding: raw\nspace origin: (-1,2,3.5)\nkey:=value\n";
    std::string stem = nrrdType + (bigEndian ? "_big" : "_little");
    std::replace(stem.begin(), stem.end(), ' ', '_');
    write(stem + ".raw", pack<T>(values, bigEndian));
    const std::string nhdr = write(stem + ".nhdr", header + "data file: " + stem + ".raw\n");
    const std::string nrrd = write(stem + ".nrrd", header + "\n" + pack<T>(values, bigEndian));
    for (const std::string& path : {nhdr, nrrd}) {
      SCOPED_TRACE(path);
      const VolumeImage image = read(path);
      EXPECT_EQ(image.size, (std::array<int, 3>{3, 2, 2}));
      EXPECT_EQ(image.values, values);
      EXPECT_EQ(image.spacing, Vec3d(0.5, 0.25, 2));
      EXPECT_EQ(image.origin, Vec3d(-1, 2, 3.5));
    }
  }

 private:
  std::filesystem::path m_folder;
};

TEST_F(VolumeImageTest, MetaImageRoundTripsEveryTypeAndByteOrder) {
  for (bool big : {false, true}) {
    metaImageRoundTrip<std::uint8_t>("MET_UCHAR", big);
    metaImageRoundTrip<std::int8_t>("MET_CHAR", big);
    metaImageRoundTrip<std::uint16_t>("MET_USHORT", big);
    metaImageRoundTrip<std::int16_t>("MET_SHORT", big);
    metaImageRoundTrip<std::uint32_t>("MET_UINT", big);
    metaImageRoundTrip<std::int32_t>("MET_INT", big);
    metaImageRoundTrip<std::int64_t>("MET_LONG_LONG", big);
    metaImageRoundTrip<std::uint64_t>("MET_ULONG_LONG", big);
    metaImageRoundTrip<float>("MET_FLOAT", big);
    metaImageRoundTrip<double>("MET_DOUBLE", big);
  }
}

TEST_F(VolumeImageTest, NrrdRoundTripsEveryTypeAndByteOrder) {
  for (bool big : {false, true}) {
    nrrdRoundTrip<std::uint8_t>("uchar", big);
    nrrdRoundTrip<std::int8_t>("signed char", big);
    nrrdRoundTrip<std::uint16_t>("unsigned short", big);
    nrrdRoundTrip<std::int16_t>("short", big);
    nrrdRoundTrip<std::uint32_t>("uint32", big);
    nrrdRoundTrip<std::int32_t>("int", big);
    nrrdRoundTrip<std::int64_t>("int64_t", big);
    nrrdRoundTrip<std::uint64_t>("unsigned long long int", big);
    nrrdRoundTrip<float>("float", big);
    nrrdRoundTrip<double>("double", big);
  }
}

TEST_F(VolumeImageTest, NrrdTextEncodingAndSkips) {
  // Text data, with line skip in a detached file.
  write("text.txt", "a line to skip\n1 2 3\n4, 5, 6\n-7 8.5 9 10 11 12\n");
  const VolumeImage text =
      read(write("text.nhdr",
                 "NRRD0004\ntype: float\ndimension: 3\nsizes: 3 2 2\nencoding: ascii\n"
                 "line skip: 1\ndata file: text.txt\n"));
  EXPECT_EQ(text.values, (std::vector<double>{1, 2, 3, 4, 5, 6, -7, 8.5, 9, 10, 11, 12}));
  EXPECT_EQ(text.spacing, Vec3d::Ones());
  // byte skip -1: the data ends the file, after any preamble.
  const std::vector<double> values{1, 2, 3, 4, 5, 6, 7, 8};
  write("tail.raw", "PREAMBLE" + pack<std::uint16_t>(values, true));
  const VolumeImage tail =
      read(write("tail.nhdr",
                 "NRRD0004\ntype: ushort\ndimension: 3\nsizes: 2 2 2\nendian: big\n"
                 "encoding: raw\nbyte skip: -1\ndata file: tail.raw\n"));
  EXPECT_EQ(tail.values, values);
  // MetaImage HeaderSize: bytes skipped at the start of the data file.
  write("skip.raw", "0123" + pack<std::int16_t>(values, false));
  const VolumeImage skipped =
      read(write("skip.mhd",
                 "NDims = 3\nDimSize = 2 2 2\nElementType = MET_SHORT\nHeaderSize = 4\n"
                 "ElementDataFile = skip.raw\n"));
  EXPECT_EQ(skipped.values, values);
}

#ifdef STROMA_HAS_ZLIB
TEST_F(VolumeImageTest, GzipAndZlibCompressedData) {
  const std::vector<double> values{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  const std::string raw = pack<std::int32_t>(values, false);
  // gzip (NRRD encoding gzip) through a gz stream, zlib (MetaImage CompressedData) by compress().
  std::string gz(compressBound(uLong(raw.size())) + 64, '\0');
  z_stream s{};
  ASSERT_EQ(deflateInit2(&s, 6, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY), Z_OK);
  s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(raw.data()));
  s.avail_in = uInt(raw.size());
  s.next_out = reinterpret_cast<Bytef*>(gz.data());
  s.avail_out = uInt(gz.size());
  ASSERT_EQ(deflate(&s, Z_FINISH), Z_STREAM_END);
  gz.resize(s.total_out);
  deflateEnd(&s);
  const VolumeImage nrrd =
      read(write("gz.nrrd",
                 "NRRD0004\ntype: int32\ndimension: 3\nsizes: 3 2 2\nendian: little\n"
                 "encoding: gzip\n\n" +
                     gz));
  EXPECT_EQ(nrrd.values, values);

  uLongf size = compressBound(uLong(raw.size()));
  std::string zlib(size, '\0');
  ASSERT_EQ(compress(reinterpret_cast<Bytef*>(zlib.data()), &size,
                     reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size())),
            Z_OK);
  zlib.resize(size);
  write("z.zraw", zlib);
  const VolumeImage meta =
      read(write("z.mhd",
                 "NDims = 3\nDimSize = 3 2 2\nElementType = MET_INT\nCompressedData = True\n"
                 "ElementDataFile = z.zraw\n"));
  EXPECT_EQ(meta.values, values);
  // Truncated compressed data is an error, not garbage.
  readError(write("cut.nrrd",
                  "NRRD0004\ntype: int32\ndimension: 3\nsizes: 3 2 2\n"
                  "endian: little\nencoding: gzip\n\n" +
                      gz.substr(0, gz.size() / 2)),
            {"cut.nrrd", "encoding"});
}
#endif

TEST_F(VolumeImageTest, NegativeDirectionsAreFlippedInPlace) {
  // x stored from +x to -x: voxel i of the file is at 10 - 2 i.
  const std::vector<double> values{1, 2, 3, 4, 5, 6};
  const VolumeImage image =
      read(write("flip.nrrd",
                 "NRRD0005\ntype: uint8\ndimension: 3\nsizes: 3 2 1\nencoding: raw\nspace: "
                 "left-posterior-superior\n"
                 "space directions: (-2,0,0) (0,1,0) (0,0,0.5)\nspace origin: (10,0,0)\n\n" +
                     pack<std::uint8_t>(values, false)));
  EXPECT_EQ(image.spacing, Vec3d(2, 1, 0.5));
  EXPECT_EQ(image.origin, Vec3d(6, 0, 0));
  EXPECT_EQ(image.values, (std::vector<double>{3, 2, 1, 6, 5, 4}));
  // The same through a MetaImage TransformMatrix with -1 on the diagonal.
  const VolumeImage meta =
      read(write("flip.mha",
                 "NDims = 3\nDimSize = 3 2 1\nElementSpacing = 2 1 0.5\nOffset = 10 0 0\n"
                 "TransformMatrix = -1 0 0 0 1 0 0 0 1\nElementType = MET_UCHAR\n"
                 "ElementDataFile = LOCAL\n" +
                     pack<std::uint8_t>(values, false)));
  EXPECT_EQ(meta.origin, image.origin);
  EXPECT_EQ(meta.values, image.values);
  // The box the voxels cover.
  EXPECT_EQ(image.lowerCorner(), Vec3d(5, -0.5, -0.25));
  EXPECT_EQ(image.upperCorner(), Vec3d(11, 1.5, 0.25));
}

TEST_F(VolumeImageTest, TwoDimensionalImageIsOneSlice) {
  const VolumeImage image =
      read(write("slice.mha",
                 "NDims = 2\nDimSize = 2 3\nElementSpacing = 1 3\nElementType = MET_UCHAR\n"
                 "ElementDataFile = LOCAL\n" +
                     std::string("\1\2\3\4\5\6")));
  EXPECT_EQ(image.size, (std::array<int, 3>{2, 3, 1}));
  EXPECT_EQ(image.at(1, 2, 0), 6);
  EXPECT_EQ(image.spacing, Vec3d(1, 3, 2));  // the slice is as thick as the mean spacing
}

TEST_F(VolumeImageTest, SofaRawVoxels) {
  const std::string path = write("sofa.raw", std::string("\0\1\2\3\4\5\6\7\10\377", 10));
  VolumeImage image;
  std::string error;
  ASSERT_TRUE(readRawVoxels(path, {2, 2, 2}, Vec3d(1, 2, 3), Vec3d(0.5, 1, 1.5), image, error))
      << error;
  EXPECT_EQ(image.values, (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(image.voxelCenter(1, 1, 1), Vec3d(1.5, 3, 4.5));
  EXPECT_FALSE(readRawVoxels(path, {3, 2, 2}, Vec3d::Ones(), Vec3d::Zero(), image, error));
  EXPECT_NE(error.find("expected 12"), std::string::npos) << error;
  EXPECT_NE(error.find("holds 10"), std::string::npos) << error;
  EXPECT_FALSE(readRawVoxels(path, {0, 2, 2}, Vec3d::Ones(), Vec3d::Zero(), image, error));
  EXPECT_NE(error.find("empty image"), std::string::npos) << error;
}

TEST_F(VolumeImageTest, MetaImageHeaderErrorsNameFileLineAndField) {
  const std::string good = "NDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\n";
  readError(write("nodata.mhd", good + "ElementDataFile = absent.raw\n"),
            {"nodata.mhd", "line 4", "ElementDataFile", "absent.raw"});
  write("short.raw", "1234567");
  readError(write("short.mhd", good + "ElementDataFile = short.raw\n"),
            {"short.mhd", "ElementDataFile", "holds 7 bytes", "expected 8"});
  readError(write("type.mhd",
                  "NDims = 3\nDimSize = 2 2 2\nElementType = MET_FLOAT16\n"
                  "ElementDataFile = LOCAL\n"),
            {"type.mhd", "line 3", "ElementType", "MET_FLOAT16"});
  readError(write("dims.mhd",
                  "NDims = 4\nDimSize = 2 2 2 2\nElementType = MET_UCHAR\n"
                  "ElementDataFile = LOCAL\n"),
            {"dims.mhd", "line 1", "NDims"});
  readError(write("rgb.mhd", good + "ElementNumberOfChannels = 3\nElementDataFile = LOCAL\n"),
            {"rgb.mhd", "line 4", "ElementNumberOfChannels", "single-channel"});
  readError(write("empty.mhd",
                  "NDims = 3\nDimSize = 2 0 2\nElementType = MET_UCHAR\n"
                  "ElementDataFile = LOCAL\n"),
            {"empty.mhd", "line 2", "DimSize", "empty image (zero voxels)"});
  readError(write("sizes.mhd",
                  "NDims = 3\nDimSize = 2 2\nElementType = MET_UCHAR\n"
                  "ElementDataFile = LOCAL\n"),
            {"sizes.mhd", "line 2", "DimSize", "expected NDims = 3 sizes, got 2"});
  readError(write("rotated.mha", good + "TransformMatrix = 0 1 0 1 0 0 0 0 1\n"
                                        "ElementDataFile = LOCAL\n12345678"),
            {"rotated.mha", "line 4", "TransformMatrix", "axis-aligned"});
  readError(write("huge.mhd",
                  "NDims = 3\nDimSize = 2000000000 2000000000 2000000000\n"
                  "ElementType = MET_UCHAR\nElementDataFile = LOCAL\n"),
            {"huge.mhd", "line 2", "DimSize", "beyond what can be read"});
  readError(write("noend.mhd", good), {"noend.mhd", "ElementDataFile", "missing"});
  readError(write("notmeta.mhd", "hello\n"), {"notmeta.mhd", "line 1", "Key = Value"});
  readError((std::filesystem::path(write("x", "")).parent_path() / "absent.mhd").string(),
            {"absent.mhd", "cannot open"});
}

TEST_F(VolumeImageTest, NrrdHeaderErrorsNameFileLineAndField) {
  const std::string head = "NRRD0004\ntype: short\ndimension: 3\nsizes: 2 2 2\n";
  readError(write("nodata.nhdr", head + "endian: little\nencoding: raw\ndata file: gone.raw\n"),
            {"nodata.nhdr", "line 7", "data file", "gone.raw"});
  readError(write("short.nrrd", head + "endian: little\nencoding: raw\n\n0123456789"),
            {"short.nrrd", "sizes", "holds 10 bytes", "expected 16"});
  readError(write("type.nrrd", "NRRD0004\ntype: half\ndimension: 3\nsizes: 2 2 2\n\n"),
            {"type.nrrd", "line 2", "type", "half"});
  readError(write("dim.nrrd", "NRRD0004\ntype: uchar\ndimension: 5\nsizes: 2 2 2 2 2\n\n"),
            {"dim.nrrd", "line 3", "dimension"});
  readError(write("vector.nrrd", "NRRD0004\ntype: uchar\ndimension: 4\nsizes: 3 2 2 2\n\n"),
            {"vector.nrrd", "line 3", "dimension", "multi-channel"});
  readError(write("rgb.nrrd",
                  "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 3 2 2\n"
                  "kinds: RGB-color domain domain\n\n"),
            {"rgb.nrrd", "line 5", "kinds", "multi-channel"});
  readError(write("empty.nrrd", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 0\n\n"),
            {"empty.nrrd", "line 4", "sizes", "empty image (zero voxels)"});
  readError(write("endian.nrrd", head + "encoding: raw\n\n0123456789abcdef"),
            {"endian.nrrd", "endian", "missing"});
  readError(write("bzip.nrrd", head + "endian: little\nencoding: bzip2\n\nxx"),
            {"bzip.nrrd", "line 6", "encoding", "bzip2"});
  readError(write("oblique.nrrd",
                  "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\n"
                  "space directions: (1,1,0) (0,1,0) (0,0,1)\n\n12345678"),
            {"oblique.nrrd", "line 5", "space directions", "axis-aligned"});
  readError(write("huge.nrrd",
                  "NRRD0004\ntype: uchar\ndimension: 3\n"
                  "sizes: 100000 100000 100000\nencoding: raw\n\n1234"),
            {"huge.nrrd", "line 4", "sizes", "beyond what can be read"});
  // A header announcing more voxels than the file holds: the size check, no allocation.
  readError(write("big.nrrd",
                  "NRRD0004\ntype: double\ndimension: 3\nsizes: 10000 10000 100\n"
                  "endian: little\nencoding: raw\n\n1234"),
            {"big.nrrd", "holds 4 bytes", "expected 80000000000"});
  readError(write("magic.nrrd", "NRRX0004\n"), {"magic.nrrd", "line 1", "NRRD000"});
  readError(write("text.nrrd",
                  "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\n"
                  "encoding: ascii\n\n1 2 3"),
            {"text.nrrd", "expected 8 values", "found 3"});
  readError(write("image.png", ""), {"image.png", "extension"});
}

}  // namespace
}  // namespace stroma::image
