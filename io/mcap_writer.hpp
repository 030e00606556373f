#pragma once
/// @file A streaming MCAP writer (the published MCAP format, major version 0): schemas and channels at the
/// start of the data section, messages in uncompressed chunks with a message index per channel after each
/// chunk, then a summary (schemas, channels, statistics, chunk indexes) with summary offsets, the footer and
/// CRC-32s of the data section, each chunk and the summary. Memory stays bounded by one chunk whatever the
/// number of messages.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace silva::io {

/// Writes one MCAP file: declare every schema and channel, write messages in log-time order, then close().
class McapWriter {
 public:
  /// Uncompressed bytes of messages after which a chunk is closed.
  static constexpr size_t kChunkBytes = size_t(4) << 20;

  /// Creates `path` (IoError when it cannot) and writes the magic and the header record.
  McapWriter(const std::filesystem::path& path, const std::string& profile, const std::string& library);
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  /// Declares a schema (name, encoding such as "ros2msg", its text); returns its id (1, 2, ...).
  uint16_t add_schema(const std::string& name, const std::string& encoding, const std::string& data);
  /// Declares a channel on `topic` with schema `schema_id`; returns its id (0, 1, ...). All schemas and channels
  /// come before the first message.
  uint16_t add_channel(const std::string& topic, uint16_t schema_id, const std::string& message_encoding,
                       const std::map<std::string, std::string>& metadata = {});
  /// Writes one message; log times must not decrease (InputError otherwise).
  void write(uint16_t channel, uint64_t log_time_ns, uint64_t publish_time_ns, std::span<const uint8_t> data);
  /// Closes the last chunk and writes the summary, footer and magic; IoError when the file cannot be written.
  void close();
  /// Messages written per channel id.
  const std::map<uint16_t, uint64_t>& message_counts() const { return counts_; }

 private:
  struct Schema {
    uint16_t id;
    std::string name, encoding, data;
  };
  struct Channel {
    uint16_t id, schema_id;
    std::string topic, encoding;
    std::map<std::string, std::string> metadata;
  };
  struct ChunkIndex {
    uint64_t start_time, end_time, offset, length, index_length, size;
    std::map<uint16_t, uint64_t> index_offsets;
  };
  void emit(const std::vector<uint8_t>& bytes);
  void flush_chunk();
  std::vector<uint8_t> schema_record(const Schema& s) const;
  std::vector<uint8_t> channel_record(const Channel& c) const;

  std::filesystem::path path_;
  std::ofstream out_;
  uint64_t offset_ = 0;
  uint32_t crc_ = 0;  ///< CRC-32 of everything written so far.
  bool started_ = false, closed_ = false;
  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  std::vector<uint8_t> chunk_;  ///< Message records of the open chunk.
  uint64_t chunk_start_ = 0, chunk_end_ = 0;
  std::map<uint16_t, std::vector<std::pair<uint64_t, uint64_t>>> chunk_index_;  ///< channel -> (time, offset)
  std::vector<ChunkIndex> chunks_;
  std::map<uint16_t, uint64_t> counts_;
  std::map<uint16_t, uint32_t> sequence_;
  uint64_t first_time_ = 0, last_time_ = 0, messages_ = 0;
};

}  // namespace silva::io
