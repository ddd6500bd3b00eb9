// ZIP entries (libzip) and WebP images (libwebp) of a SOG scene; see sog_files.hpp.
#include "scene/sog_files.hpp"

#include <webp/decode.h>
#include <zip.h>

#include <fstream>
#include <memory>

#include "util/error.hpp"

namespace lfd::scene {

namespace {

// One entry of a SOG is at most this large (the biggest, meta.json with SH codebooks or a
// 16k x 16k WebP, is far smaller).
constexpr uint64_t kMaxEntryBytes = uint64_t(1) << 30;
// Deflate expands at most 1032:1 (RFC 1951); splat-transform stores entries uncompressed.
constexpr uint64_t kMaxDeflateRatio = 1032;

struct ZipArchive {
  zip_t* zip = nullptr;
  uint64_t archive_bytes = 0;
  std::string name;
  ~ZipArchive() {
    if (zip) zip_discard(zip);
  }
};

std::string read_zip_entry(const ZipArchive& archive, const std::string& file) {
  const zip_int64_t index = zip_name_locate(archive.zip, file.c_str(), 0);
  if (index < 0) throw_input_error("{}: SOG archive has no entry '{}'", archive.name, file);
  zip_stat_t st;
  zip_stat_init(&st);
  if (zip_stat_index(archive.zip, zip_uint64_t(index), 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
    throw_input_error("{}: SOG entry '{}': unreadable directory record", archive.name, file);
  if (st.size > kMaxEntryBytes || st.size / kMaxDeflateRatio > archive.archive_bytes)
    throw_input_error("{}: SOG entry '{}' claims {} bytes, more than the archive can hold",
                      archive.name, file, uint64_t(st.size));
  std::unique_ptr<zip_file_t, int (*)(zip_file_t*)> entry(
      zip_fopen_index(archive.zip, zip_uint64_t(index), 0), zip_fclose);
  if (!entry)
    throw_input_error("{}: SOG entry '{}': {}", archive.name, file,
                      zip_error_strerror(zip_get_error(archive.zip)));
  std::string bytes(size_t(st.size), '\0');
  const zip_int64_t got = zip_fread(entry.get(), bytes.data(), st.size);
  if (got < 0 || uint64_t(got) != st.size)
    throw_input_error("{}: SOG entry '{}': truncated or corrupt ({})", archive.name, file,
                      zip_error_strerror(zip_file_get_error(entry.get())));
  return bytes;
}

}  // namespace

SogFileSource sog_zip_source(std::string_view bytes, const std::string& name) {
  auto archive = std::make_shared<ZipArchive>();
  archive->name = name;
  archive->archive_bytes = bytes.size();
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
  if (source) archive->zip = zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error);
  if (!archive->zip) {
    if (source) zip_source_free(source);
    const std::string why = zip_error_strerror(&error);
    zip_error_fini(&error);
    throw_input_error("{}: not a readable SOG archive (ZIP: {})", name, why);
  }
  zip_error_fini(&error);
  return [archive](const std::string& file) { return read_zip_entry(*archive, file); };
}

SogFileSource sog_folder_source(const std::filesystem::path& folder, const std::string& name) {
  return [folder, name](const std::string& file) {
    const std::filesystem::path path = folder / file;
    std::error_code ec;
    if (file.find('/') != std::string::npos || file.find('\\') != std::string::npos ||
        !std::filesystem::is_regular_file(path, ec))
      throw_input_error("{}: SOG file '{}' named in meta.json is missing (it must lie beside it)",
                        name, file);
    const auto size = std::filesystem::file_size(path, ec);
    if (ec || size > kMaxEntryBytes)
      throw_input_error("{}: SOG file '{}' is unreadable or larger than {} bytes", name, file,
                        kMaxEntryBytes);
    std::ifstream in(path, std::ios::binary);
    std::string bytes(size_t(size), '\0');
    if (!in.read(bytes.data(), std::streamsize(size)))
      throw_input_error("{}: SOG file '{}': read error", name, file);
    return bytes;
  };
}

bool webp_dimensions(std::string_view bytes, int& width, int& height) {
  return WebPGetInfo(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), &width,
                     &height) != 0;
}

RgbaImage decode_webp(std::string_view bytes, size_t max_pixels, const std::string& scene,
                      const std::string& what) {
  const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
  RgbaImage image;
  if (!WebPGetInfo(data, bytes.size(), &image.width, &image.height))
    throw_input_error("{}: {}: not a WebP image", scene, what);
  if (image.pixels() > max_pixels)
    throw_input_error("{}: {}: {}x{} pixels, more than the {} the scene needs", scene, what,
                      image.width, image.height, max_pixels);
  image.rgba.resize(image.pixels() * 4);
  if (!WebPDecodeRGBAInto(data, bytes.size(), image.rgba.data(), image.rgba.size(),
                          image.width * 4))
    throw_input_error("{}: {}: corrupt or truncated WebP data", scene, what);
  return image;
}

}  // namespace lfd::scene
