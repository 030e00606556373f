#include "assets/mesh_pack.hpp"

#include <algorithm>
#include <cstring>
#include <type_traits>

#include "core/rng.hpp"

namespace silva::assets {

namespace {

/// First bytes of a pack of meshes and of a mask.
constexpr char kLodsMagic[8] = {'S', 'I', 'L', 'V', 'A', 'L', 'O', 'D'};
constexpr char kMaskMagic[8] = {'S', 'I', 'L', 'V', 'A', 'M', 'S', 'K'};
/// Format version of both packs.
constexpr uint32_t kVersion = 1;

/// A 64-bit hash of bytes: four interleaved SplitMix chains over 8-byte words, then the tail.
uint64_t hash_bytes(std::string_view bytes) {
  uint64_t h[4] = {0x9e3779b97f4a7c15ULL, 0x632be59bd9b4e019ULL, 0x85ebca6b2c2b2ae3ULL, 0xc2b2ae3d27d4eb4fULL};
  size_t i = 0;
  for (; i + 32 <= bytes.size(); i += 32)
    for (int k = 0; k < 4; ++k) {
      uint64_t w;
      std::memcpy(&w, bytes.data() + i + size_t(k) * 8, 8);
      h[k] = mix64(h[k] ^ w);
    }
  uint64_t tail = bytes.size();
  for (; i < bytes.size(); ++i) tail = mix64(tail ^ uint8_t(bytes[i]));
  return mix64(h[0] ^ mix64(h[1] ^ mix64(h[2] ^ mix64(h[3] ^ tail))));
}

/// Appends plain values and arrays to a byte string.
struct Writer {
  std::string out;  ///< The bytes so far.
  /// Appends one trivially copyable value.
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  /// Appends an array's length and elements.
  template <class T>
  void put_array(const std::vector<T>& v) {
    put(uint64_t(v.size()));
    if (!v.empty()) out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
};

/// Reads what Writer wrote; any read past the end marks it failed and yields zeros.
struct Reader {
  std::string_view in;  ///< Bytes not read yet.
  bool ok = true;       ///< False once a read ran past the end.
  /// Reads one value.
  template <class T>
  T get() {
    T v{};
    if (in.size() < sizeof(T)) return ok = false, v;
    std::memcpy(&v, in.data(), sizeof(T));
    in.remove_prefix(sizeof(T));
    return v;
  }
  /// Reads an array of at most `limit` elements.
  template <class T>
  std::vector<T> get_array(uint64_t limit) {
    const uint64_t n = get<uint64_t>();
    if (!ok || n > limit || n > in.size() / sizeof(T)) return ok = false, std::vector<T>{};
    std::vector<T> v(n);
    if (n > 0) std::memcpy(static_cast<void*>(v.data()), in.data(), n * sizeof(T));
    in.remove_prefix(n * sizeof(T));
    return v;
  }
};

/// `payload` behind a header: magic, version, payload size and hash.
std::string framed(const char (&magic)[8], const std::string& payload) {
  Writer head;
  head.out.append(magic, sizeof(magic));
  head.put(kVersion);
  head.put(uint64_t(payload.size()));
  head.put(hash_bytes(payload));
  return head.out + payload;
}

/// The payload of framed() bytes, or nothing when the magic, version, size or hash is wrong.
std::optional<std::string_view> unframed(const char (&magic)[8], std::string_view bytes) {
  Reader r{bytes};
  char got[sizeof(magic)];
  for (char& c : got) c = r.get<char>();
  const auto version = r.get<uint32_t>();
  const auto size = r.get<uint64_t>();
  const auto hash = r.get<uint64_t>();
  if (!r.ok || std::memcmp(got, magic, sizeof(magic)) != 0 || version != kVersion || size != r.in.size() ||
      hash != hash_bytes(r.in))
    return std::nullopt;
  return r.in;
}

/// Appends a mask's size, cut-off, feature length and texels.
void put_mask(Writer& w, const AlphaMask& m) {
  w.put(int32_t(m.width));
  w.put(int32_t(m.height));
  w.put(m.cutoff);
  w.put(m.feature_length);
  w.put_array(m.alpha);
}

/// Appends one mesh; its parts name their masks by the hashes in `masks`.
void put_mesh(Writer& w, const Mesh& m, const std::vector<std::pair<uint64_t, const AlphaMask*>>& masks) {
  w.put_array(m.positions);
  w.put_array(m.normals);
  w.put_array(m.uvs);
  w.put_array(m.indices);
  w.put(uint64_t(m.parts.size()));
  for (const MeshPart& p : m.parts) {
    w.put(p.first_index);
    w.put(p.index_count);
    w.put(uint8_t(p.role));
    w.put(uint8_t(p.material));
    w.put(uint8_t(p.double_sided));
    w.put(uint8_t(p.overlay.has_value()));
    w.put(uint8_t(p.overlay ? p.overlay->role : Role{}));
    w.put(uint8_t(p.overlay ? p.overlay->material : Material{}));
    w.put(uint8_t(p.mask != nullptr));
    const auto at = std::find_if(masks.begin(), masks.end(), [&](const auto& e) { return e.second == p.mask.get(); });
    w.put(p.mask ? at->first : uint64_t(0));
  }
}

/// True when a role and material byte name real values.
bool valid_look(uint8_t role, uint8_t material) {
  return role < kRoleCount && material < uint8_t(Material::Count);
}

/// Reads one mask; nothing when its sizes disagree.
std::optional<AlphaMask> get_mask(Reader& r) {
  AlphaMask m;
  m.width = r.get<int32_t>();
  m.height = r.get<int32_t>();
  m.cutoff = r.get<float>();
  m.feature_length = r.get<float>();
  m.alpha = r.get_array<uint8_t>(r.in.size());
  if (!r.ok || m.width <= 0 || m.height <= 0 || m.alpha.size() != size_t(m.width) * size_t(m.height))
    return std::nullopt;
  return m;
}

/// Reads one mesh, its parts' masks from `lookup`; nothing when any count or range is out of bounds
/// or a mask is missing.
std::optional<Mesh> get_mesh(Reader& r, const MaskLookup& lookup) {
  Mesh m;
  m.positions = r.get_array<Vec3f>(UINT32_MAX);
  m.normals = r.get_array<Vec3f>(m.positions.size());
  m.uvs = r.get_array<Vec2f>(m.positions.size());
  m.indices = r.get_array<uint32_t>(r.in.size());
  const uint64_t parts = r.get<uint64_t>();
  if (!r.ok || parts > r.in.size() || m.indices.size() % 3 != 0 ||
      (!m.normals.empty() && m.normals.size() != m.positions.size()) ||
      (!m.uvs.empty() && m.uvs.size() != m.positions.size()) ||
      std::any_of(m.indices.begin(), m.indices.end(), [&](uint32_t i) { return i >= m.positions.size(); }))
    return std::nullopt;
  for (uint64_t k = 0; k < parts; ++k) {
    MeshPart p;
    p.first_index = r.get<uint32_t>();
    p.index_count = r.get<uint32_t>();
    const auto role = r.get<uint8_t>(), material = r.get<uint8_t>();
    p.double_sided = r.get<uint8_t>() != 0;
    const bool overlay = r.get<uint8_t>() != 0;
    const auto overlay_role = r.get<uint8_t>(), overlay_material = r.get<uint8_t>();
    const bool masked = r.get<uint8_t>() != 0;
    const auto mask = r.get<uint64_t>();
    if (masked) p.mask = lookup(mask);
    if (!r.ok || !valid_look(role, material) || !valid_look(overlay_role, overlay_material) ||
        (masked && !p.mask) || p.first_index % 3 != 0 || p.index_count % 3 != 0 ||
        uint64_t(p.first_index) + p.index_count > m.indices.size())
      return std::nullopt;
    p.role = Role(role);
    p.material = Material(material);
    if (overlay) p.overlay = PartOverlay{Role(overlay_role), Material(overlay_material)};
    m.parts.push_back(std::move(p));
  }
  return m;
}

}  // namespace

bool packable(std::span<const Mesh> lods) {
  return std::all_of(lods.begin(), lods.end(), [](const Mesh& m) {
    return std::none_of(m.parts.begin(), m.parts.end(), [](const MeshPart& p) { return p.base_color != nullptr; });
  });
}

uint64_t mask_hash(const AlphaMask& mask) {
  Writer w;
  put_mask(w, mask);
  return hash_bytes(w.out);
}

std::string pack_mask(const AlphaMask& mask) {
  Writer w;
  put_mask(w, mask);
  return framed(kMaskMagic, w.out);
}

std::optional<AlphaMask> unpack_mask(std::string_view bytes) {
  const std::optional<std::string_view> payload = unframed(kMaskMagic, bytes);
  if (!payload) return std::nullopt;
  Reader r{*payload};
  std::optional<AlphaMask> mask = get_mask(r);
  if (!r.in.empty()) return std::nullopt;
  return mask;
}

PackedLods pack_lods(std::span<const Mesh> lods) {
  PackedLods out;
  for (const Mesh& m : lods)
    for (const MeshPart& p : m.parts)
      if (p.mask && std::none_of(out.masks.begin(), out.masks.end(), [&](const auto& e) { return e.second == p.mask.get(); }))
        out.masks.emplace_back(mask_hash(*p.mask), p.mask.get());
  Writer w;
  w.put(uint64_t(lods.size()));
  for (const Mesh& m : lods) put_mesh(w, m, out.masks);
  out.bytes = framed(kLodsMagic, w.out);
  return out;
}

std::optional<std::vector<Mesh>> unpack_lods(std::string_view bytes, const MaskLookup& lookup) {
  const std::optional<std::string_view> payload = unframed(kLodsMagic, bytes);
  if (!payload) return std::nullopt;
  Reader r{*payload};
  const auto lod_count = r.get<uint64_t>();
  if (!r.ok || lod_count == 0 || lod_count > r.in.size()) return std::nullopt;
  std::vector<Mesh> lods;
  for (uint64_t k = 0; k < lod_count; ++k) {
    std::optional<Mesh> m = get_mesh(r, lookup);
    if (!m) return std::nullopt;
    lods.push_back(std::move(*m));
  }
  if (!r.in.empty()) return std::nullopt;
  return lods;
}

}  // namespace silva::assets
