#include "assets/mesh_cache.hpp"

#include <link.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <system_error>

#include "assets/library.hpp"
#include "assets/mesh_pack.hpp"

namespace silva::assets {

namespace fs = std::filesystem;

namespace {

/// Build folders kept beside the current one (the most recently written).
constexpr size_t kKeptBuilds = 3;

/// The masks this process has read from caches, by folder and content hash (one object per
/// distinct mask, as the generators share one mask per family).
class MaskPool {
 public:
  /// The mask of `hash` in `folder`: from the pool, else read from its file; null when missing or damaged.
  std::shared_ptr<const AlphaMask> get(const fs::path& folder, uint64_t hash);

 private:
  std::mutex mutex_;
  std::map<std::pair<fs::path, uint64_t>, std::shared_ptr<const AlphaMask>> masks_;  ///< By folder and hash.
};

/// Every folder's masks read by this process.
MaskPool& cached_masks() {
  static MaskPool pool;
  return pool;
}

/// The file of the mask with content hash `hash`.
fs::path mask_path(const fs::path& folder, uint64_t hash) {
  char name[24];
  std::snprintf(name, sizeof(name), "%016llx.mask", static_cast<unsigned long long>(hash));
  return folder / "masks" / name;
}

/// Prefix of a build's folder name (then its build id in hex); only such folders are ever pruned.
constexpr std::string_view kBuildPrefix = "build-";

/// True for a folder named kBuildPrefix and hex digits.
bool is_build_folder(const fs::path& p) {
  const std::string name = p.filename().string();
  return name.size() > kBuildPrefix.size() && name.starts_with(kBuildPrefix) &&
         std::all_of(name.begin() + std::ptrdiff_t(kBuildPrefix.size()), name.end(),
                     [](char c) { return std::isxdigit(uint8_t(c)) != 0; });
}

/// Removes all but the kKeptBuilds most recently written build folders under `root` other than `keep`.
void prune_builds(const fs::path& root, const fs::path& keep) {
  std::error_code ec;
  std::vector<std::pair<fs::file_time_type, fs::path>> builds;
  // Stepped with error codes: a folder another process removes meanwhile ends the listing, never throws.
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_directory(ec) && it->path() != keep && is_build_folder(it->path()))
      builds.emplace_back(it->last_write_time(ec), it->path());
  if (builds.size() <= kKeptBuilds) return;
  std::sort(builds.begin(), builds.end(), std::greater<>());
  for (size_t i = kKeptBuilds; i < builds.size(); ++i) fs::remove_all(builds[i].second, ec);
}

/// The entry's file name: generator, variant, seed and season.
std::string entry_name(const ProceduralSource& source, Season season) {
  char seed[17];
  std::snprintf(seed, sizeof(seed), "%016llx", static_cast<unsigned long long>(source.seed));
  return source.generator + "_" + std::to_string(source.variant) + "_" + seed + "_" + std::string(season_name(season)) +
         ".lods";
}

/// The whole file, or "" when it cannot be read.
std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return std::move(s).str();
}

/// Writes `bytes` to `path` through a temporary file renamed over it (readers see all or nothing),
/// creating its folder. Errors are ignored.
void store(const fs::path& path, const std::string& bytes) {
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  static std::atomic<uint64_t> writes{0};
  const fs::path tmp = path.string() + ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(writes++);
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out.write(bytes.data(), std::streamsize(bytes.size())) || !out.flush()) {
      out.close();
      fs::remove(tmp, ec);
      return;
    }
  }
  fs::rename(tmp, path, ec);
  if (ec) fs::remove(tmp, ec);
}

std::shared_ptr<const AlphaMask> MaskPool::get(const fs::path& folder, uint64_t hash) {
  {
    const std::lock_guard lock(mutex_);
    if (const auto it = masks_.find({folder, hash}); it != masks_.end()) return it->second;
  }
  std::optional<AlphaMask> mask = unpack_mask(read_file(mask_path(folder, hash)));
  if (!mask || mask_hash(*mask) != hash) return nullptr;
  const std::lock_guard lock(mutex_);
  return masks_.try_emplace({folder, hash}, std::make_shared<const AlphaMask>(std::move(*mask))).first->second;
}

/// dl_iterate_phdr callback: the GNU build id note of the first object (the executable) into `data`.
int find_build_id(dl_phdr_info* info, size_t, void* data) {
  auto& out = *static_cast<std::string*>(data);
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& ph = info->dlpi_phdr[i];
    if (ph.p_type != PT_NOTE) continue;
    const auto* p = reinterpret_cast<const uint8_t*>(info->dlpi_addr + ph.p_vaddr);
    const uint8_t* end = p + ph.p_memsz;
    while (p + sizeof(ElfW(Nhdr)) <= end) {
      const auto* note = reinterpret_cast<const ElfW(Nhdr)*>(p);
      const uint8_t* name = p + sizeof(ElfW(Nhdr));
      const uint8_t* desc = name + ((note->n_namesz + 3) & ~3u);
      if (note->n_type == NT_GNU_BUILD_ID && note->n_namesz == 4 && std::equal(name, name + 4, "GNU") &&
          desc + note->n_descsz <= end) {
        static constexpr char kHex[] = "0123456789abcdef";
        for (uint32_t k = 0; k < note->n_descsz; ++k) out += {kHex[desc[k] >> 4], kHex[desc[k] & 15]};
        return 1;
      }
      p = desc + ((note->n_descsz + 3) & ~3u);
    }
  }
  return 1;  // only the first object is the executable
}

}  // namespace

fs::path mesh_cache_root(const char* silva_mesh_cache, const char* xdg_cache_home, const char* home) {
  const auto set = [](const char* v) { return v != nullptr && *v != '\0'; };
  if (set(silva_mesh_cache)) return std::string(silva_mesh_cache) == "off" ? fs::path() : fs::path(silva_mesh_cache);
  if (set(xdg_cache_home)) return fs::path(xdg_cache_home) / "silva" / "meshes";
  if (set(home)) return fs::path(home) / ".cache" / "silva" / "meshes";
  return {};
}

std::string executable_build_id() {
  std::string id;
  dl_iterate_phdr(find_build_id, &id);
  return id;
}

const fs::path& process_mesh_cache() {
  static const fs::path folder = [] {
    const fs::path root =
        mesh_cache_root(std::getenv("SILVA_MESH_CACHE"), std::getenv("XDG_CACHE_HOME"), std::getenv("HOME"));
    const std::string id = executable_build_id();
    return root.empty() || id.empty() ? fs::path() : root / (std::string(kBuildPrefix) + id);
  }();
  return folder;
}

bool process_mesh_cache_warm() {
  std::error_code ec;
  return !process_mesh_cache().empty() && !fs::is_empty(process_mesh_cache() / "masks", ec) && !ec;
}

std::vector<Mesh> cached_lods(const fs::path& folder, const ProceduralSource& source, Season season,
                              const std::function<std::vector<Mesh>()>& make) {
  if (folder.empty()) return make();
  const fs::path path = folder / entry_name(source, season);
  const auto lookup = [&](uint64_t hash) { return cached_masks().get(folder, hash); };
  if (std::optional<std::vector<Mesh>> lods = unpack_lods(read_file(path), lookup)) return std::move(*lods);
  std::vector<Mesh> lods = make();
  if (!packable(lods)) return lods;
  const PackedLods packed = pack_lods(lods);
  std::error_code ec;
  if (fs::create_directories(folder, ec)) prune_builds(folder.parent_path(), folder);
  for (const auto& [hash, mask] : packed.masks)
    if (!fs::exists(mask_path(folder, hash), ec)) store(mask_path(folder, hash), pack_mask(*mask));
  store(path, packed.bytes);
  return lods;
}

}  // namespace silva::assets
