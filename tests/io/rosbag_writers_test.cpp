// The rosbag2 export's writers on known answers: CDR alignment and strings byte for byte, the MCAP record
// sequence, lengths and CRCs walked with a plain reader and a bitwise CRC-32 of its own, message order errors.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "core/error.hpp"
#include "io/cdr_writer.hpp"
#include "io/mcap_writer.hpp"
#include "io/ros2_messages.hpp"
#include "io_test_util.hpp"

namespace silva::io {
namespace {

/// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320), bit by bit.
uint32_t reference_crc32(const uint8_t* p, size_t n) {
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

template <class T>
T read_le(const std::vector<uint8_t>& b, size_t at) {
  T v;
  std::memcpy(&v, b.data() + at, sizeof v);
  return v;
}

TEST(CdrWriter, AlignsFieldsFromTheEndOfTheEncapsulationHeader) {
  CdrWriter w;
  w.u8(7);
  w.u32(0x01020304);  // 3 bytes of padding: offset 1 -> 4
  w.string("ab");     // length 3 counts the NUL
  w.f64(1.0);         // offset 15 -> 16
  const std::vector<uint8_t> expected = {0x00, 0x01, 0x00, 0x00,  // CDR_LE
                                         7, 0, 0, 0, 0x04, 0x03, 0x02, 0x01, 3, 0, 0, 0, 'a', 'b', 0, 0,
                                         0, 0, 0, 0, 0, 0, 0xF0, 0x3F};
  EXPECT_EQ(w.data(), expected);
}

TEST(Ros2Messages, ImageHeaderStampSplitsIntoSecondsAndNanoseconds) {
  const std::vector<uint8_t> pixel = {9, 8, 7};
  const std::vector<uint8_t> m = encode_image({1'500'000'000ull, "f"}, 1, 1, "rgb8", 3, pixel);
  EXPECT_EQ(read_le<int32_t>(m, 4), 1);
  EXPECT_EQ(read_le<uint32_t>(m, 8), 500'000'000u);
  EXPECT_EQ(read_le<uint32_t>(m, 12), 2u);  // "f\0"
  EXPECT_EQ(std::vector<uint8_t>(m.end() - 3, m.end()), pixel);
  EXPECT_NE(ros_type_definition(RosType::Image).find("MSG: builtin_interfaces/Time\nint32 sec"), std::string::npos);
}

TEST(McapWriter, WritesRecordsWithLengthsAndCrcsAPlainReaderAccepts) {
  const auto path = test::scratch_dir("mcap_known") / "t.mcap";
  {
    McapWriter w(path, "ros2", "test");
    const uint16_t s = w.add_schema("pkg/msg/T", "ros2msg", "uint8 x\n");
    const uint16_t a = w.add_channel("/a", s, "cdr"), b = w.add_channel("/b", s, "cdr", {{"k", "v"}});
    const std::vector<uint8_t> payload = {1, 2, 3};
    w.write(a, 10, 10, payload);
    w.write(b, 10, 11, payload);
    w.write(a, 20, 20, payload);
    EXPECT_THROW(w.write(a, 19, 19, payload), InputError);
    EXPECT_THROW(w.add_channel("/late", s, "cdr"), InputError);
    w.close();
    EXPECT_EQ(w.message_counts().at(a), 2u);
  }
  std::ifstream in(path, std::ios::binary);
  const std::vector<uint8_t> f((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::vector<uint8_t> magic = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
  ASSERT_GT(f.size(), 16u + 29u);
  EXPECT_EQ(std::vector<uint8_t>(f.begin(), f.begin() + 8), magic);
  EXPECT_EQ(std::vector<uint8_t>(f.end() - 8, f.end()), magic);
  // Walk the records up to the footer: opcodes in order, each length landing on the next record.
  std::vector<int> ops;
  size_t at = 8, data_end = 0;
  const size_t footer = f.size() - 8 - 29;
  while (at < footer) {
    ops.push_back(f[at]);
    if (f[at] == 0x0F) data_end = at;
    at += 9 + read_le<uint64_t>(f, at + 1);
  }
  ASSERT_EQ(at, footer);
  ASSERT_EQ(f[footer], 0x02);
  // Header, schema, 2 channels, chunk, 2 message indexes, data end; summary: schema, 2 channels, statistics,
  // chunk index, then the summary offsets of those four groups.
  EXPECT_EQ(ops, (std::vector<int>{1, 3, 4, 4, 6, 7, 7, 15, 3, 4, 4, 11, 8, 14, 14, 14, 14}));
  EXPECT_EQ(read_le<uint32_t>(f, data_end + 9), reference_crc32(f.data(), data_end));
  const uint64_t summary_start = read_le<uint64_t>(f, footer + 9);
  EXPECT_EQ(summary_start, data_end + 13);
  EXPECT_EQ(read_le<uint32_t>(f, footer + 25),
            reference_crc32(f.data() + summary_start, footer + 25 - summary_start));
  // The chunk: start and end times, its records' CRC, three message records inside.
  const size_t chunk = 8 + 9 + read_le<uint64_t>(f, 9);  // after the header record
  size_t c = chunk;
  for (int skip = 0; skip < 3; ++skip) c += 9 + read_le<uint64_t>(f, c + 1);  // schema, channel, channel
  ASSERT_EQ(f[c], 0x06);
  EXPECT_EQ(read_le<uint64_t>(f, c + 9), 10u);
  EXPECT_EQ(read_le<uint64_t>(f, c + 17), 20u);
  const uint64_t size = read_le<uint64_t>(f, c + 25);
  const size_t records = c + 9 + 8 + 8 + 8 + 4 + 4 + 8;  // compression "" has a zero length only
  EXPECT_EQ(read_le<uint64_t>(f, records - 8), size);
  EXPECT_EQ(read_le<uint32_t>(f, c + 33), reference_crc32(f.data() + records, size));
  EXPECT_EQ(size, 3 * (9 + 2 + 4 + 8 + 8 + 3));
}

}  // namespace
}  // namespace silva::io
