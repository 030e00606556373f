#include "io/mcap_writer.hpp"

#include <cstring>

#include <libdeflate.h>

#include "core/error.hpp"

namespace silva::io {

namespace {

/// The magic that opens and closes every MCAP file (major version '0').
constexpr uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

/// Record opcodes of the MCAP format.
enum Op : uint8_t {
  kHeader = 0x01, kFooter = 0x02, kSchema = 0x03, kChannel = 0x04, kMessage = 0x05, kChunk = 0x06,
  kMessageIndex = 0x07, kChunkIndex = 0x08, kStatistics = 0x0B, kSummaryOffset = 0x0E, kDataEnd = 0x0F,
};

/// Little-endian field encoder of MCAP record contents.
struct Fields {
  std::vector<uint8_t> b;
  template <class T>
  Fields& num(T v) {
    const size_t at = b.size();
    b.resize(at + sizeof(T));
    std::memcpy(b.data() + at, &v, sizeof(T));
    return *this;
  }
  Fields& u8(uint8_t v) { return num(v); }
  Fields& u16(uint16_t v) { return num(v); }
  Fields& u32(uint32_t v) { return num(v); }
  Fields& u64(uint64_t v) { return num(v); }
  /// A String: uint32 byte length, then the bytes.
  Fields& str(const std::string& s) {
    u32(uint32_t(s.size()));
    b.insert(b.end(), s.begin(), s.end());
    return *this;
  }
  /// Raw bytes, no length.
  Fields& raw(std::span<const uint8_t> data) {
    b.insert(b.end(), data.begin(), data.end());
    return *this;
  }
  /// A length-prefixed group (Map, Array, Bytes) whose contents `inner` holds; `wide` for a uint64 prefix.
  Fields& group(const Fields& inner, bool wide = false) {
    wide ? u64(inner.b.size()) : u32(uint32_t(inner.b.size()));
    return raw(inner.b);
  }
};

/// One record: opcode, uint64 content length, content.
std::vector<uint8_t> record(Op op, const Fields& content) {
  Fields r;
  r.u8(op).u64(content.b.size()).raw(content.b);
  return std::move(r.b);
}

uint32_t crc32(uint32_t crc, std::span<const uint8_t> bytes) {
  return libdeflate_crc32(crc, bytes.data(), bytes.size());
}

}  // namespace

McapWriter::McapWriter(const std::filesystem::path& path, const std::string& profile, const std::string& library)
    : path_(path), out_(path, std::ios::binary | std::ios::trunc) {
  if (!out_) throw IoError("cannot create " + path.string());
  emit(std::vector<uint8_t>(std::begin(kMagic), std::end(kMagic)));
  emit(record(kHeader, Fields{}.str(profile).str(library)));
}

void McapWriter::emit(const std::vector<uint8_t>& bytes) {
  out_.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!out_) throw IoError("cannot write " + path_.string());
  crc_ = crc32(crc_, bytes);
  offset_ += bytes.size();
}

std::vector<uint8_t> McapWriter::schema_record(const Schema& s) const {
  Fields f;
  f.u16(s.id).str(s.name).str(s.encoding).str(s.data);  // data is uint32-length-prefixed Bytes
  return record(kSchema, f);
}

std::vector<uint8_t> McapWriter::channel_record(const Channel& c) const {
  Fields meta;
  for (const auto& [k, v] : c.metadata) meta.str(k).str(v);
  Fields f;
  f.u16(c.id).u16(c.schema_id).str(c.topic).str(c.encoding).group(meta);
  return record(kChannel, f);
}

uint16_t McapWriter::add_schema(const std::string& name, const std::string& encoding, const std::string& data) {
  if (started_) throw InputError("MCAP: schema " + name + " declared after the first message");
  schemas_.push_back({uint16_t(schemas_.size() + 1), name, encoding, data});
  emit(schema_record(schemas_.back()));
  return schemas_.back().id;
}

uint16_t McapWriter::add_channel(const std::string& topic, uint16_t schema_id, const std::string& message_encoding,
                                 const std::map<std::string, std::string>& metadata) {
  if (started_) throw InputError("MCAP: channel " + topic + " declared after the first message");
  channels_.push_back({uint16_t(channels_.size()), schema_id, topic, message_encoding, metadata});
  emit(channel_record(channels_.back()));
  counts_[channels_.back().id] = 0;
  return channels_.back().id;
}

void McapWriter::write(uint16_t channel, uint64_t log_time_ns, uint64_t publish_time_ns,
                       std::span<const uint8_t> data) {
  if (channel >= channels_.size()) throw InputError("MCAP: unknown channel " + std::to_string(channel));
  if (messages_ > 0 && log_time_ns < last_time_)
    throw InputError("MCAP: message on " + channels_[channel].topic + " goes back in time");
  if (messages_ == 0) first_time_ = log_time_ns;
  started_ = true;
  if (chunk_.empty()) chunk_start_ = log_time_ns;
  chunk_end_ = log_time_ns;
  chunk_index_[channel].emplace_back(log_time_ns, chunk_.size());
  Fields f;
  f.u16(channel).u32(sequence_[channel]++).u64(log_time_ns).u64(publish_time_ns).raw(data);
  const std::vector<uint8_t> r = record(kMessage, f);
  chunk_.insert(chunk_.end(), r.begin(), r.end());
  last_time_ = log_time_ns;
  ++messages_;
  ++counts_[channel];
  if (chunk_.size() >= kChunkBytes) flush_chunk();
}

void McapWriter::flush_chunk() {
  if (chunk_.empty()) return;
  ChunkIndex index{chunk_start_, chunk_end_, offset_, 0, 0, chunk_.size(), {}};
  Fields f;
  f.u64(chunk_start_).u64(chunk_end_).u64(chunk_.size()).u32(crc32(0, chunk_)).str("");
  f.u64(chunk_.size()).raw(chunk_);
  const std::vector<uint8_t> r = record(kChunk, f);
  emit(r);
  index.length = r.size();
  const uint64_t indexes_start = offset_;
  for (const auto& [channel, entries] : chunk_index_) {
    Fields list;
    for (const auto& [time, at] : entries) list.u64(time).u64(at);
    index.index_offsets[channel] = offset_;
    emit(record(kMessageIndex, Fields{}.u16(channel).group(list)));
  }
  index.index_length = offset_ - indexes_start;
  chunks_.push_back(std::move(index));
  chunk_.clear();
  chunk_index_.clear();
}

void McapWriter::close() {
  if (closed_) return;
  flush_chunk();
  emit(record(kDataEnd, Fields{}.u32(crc_)));
  const uint64_t summary_start = offset_;
  crc_ = 0;  // the summary CRC covers the summary section through the footer's summary_offset_start
  struct Group {
    Op op;
    uint64_t start, length;
  };
  std::vector<Group> groups;
  const auto group = [&](Op op, const auto& write_records) {
    const uint64_t start = offset_;
    write_records();
    if (offset_ > start) groups.push_back({op, start, offset_ - start});
  };
  group(kSchema, [&] { for (const Schema& s : schemas_) emit(schema_record(s)); });
  group(kChannel, [&] { for (const Channel& c : channels_) emit(channel_record(c)); });
  group(kStatistics, [&] {
    Fields counts;
    for (const auto& [channel, n] : counts_) counts.u16(channel).u64(n);
    Fields f;
    f.u64(messages_).u16(uint16_t(schemas_.size())).u32(uint32_t(channels_.size())).u32(0).u32(0);
    f.u32(uint32_t(chunks_.size())).u64(first_time_).u64(last_time_).group(counts);
    emit(record(kStatistics, f));
  });
  group(kChunkIndex, [&] {
    for (const ChunkIndex& c : chunks_) {
      Fields offsets;
      for (const auto& [channel, at] : c.index_offsets) offsets.u16(channel).u64(at);
      Fields f;
      f.u64(c.start_time).u64(c.end_time).u64(c.offset).u64(c.length).group(offsets).u64(c.index_length);
      f.str("").u64(c.size).u64(c.size);
      emit(record(kChunkIndex, f));
    }
  });
  const uint64_t summary_offset_start = offset_;
  for (const Group& g : groups) emit(record(kSummaryOffset, Fields{}.u8(g.op).u64(g.start).u64(g.length)));
  Fields footer;
  footer.u8(kFooter).u64(20).u64(summary_start).u64(summary_offset_start);
  crc_ = crc32(crc_, footer.b);
  footer.u32(crc_);
  out_.write(reinterpret_cast<const char*>(footer.b.data()), std::streamsize(footer.b.size()));
  offset_ += footer.b.size();
  out_.write(reinterpret_cast<const char*>(kMagic), sizeof kMagic);
  out_.flush();
  if (!out_) throw IoError("cannot write " + path_.string());
  out_.close();
  closed_ = true;
}

}  // namespace silva::io
