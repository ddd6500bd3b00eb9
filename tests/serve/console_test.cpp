// The console's pieces without a browser (docs/console.md): upload names, the access token, the
// console's origin and "from this machine", and the content library's uploads, renames and
// deletes, Studio sidecars and thumbnails against a real folder. The page itself is tested in Chromium (tests/serve/clients/
// console_test.js).
#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "serve/access_token.hpp"
#include "serve/content_library.hpp"
#include "serve/library_thumbnails.hpp"
#include "serve/memory_budget.hpp"
#include "serve/origin_policy.hpp"
#include "tests/serve/serve_test_support.hpp"
#include "util/error.hpp"
#include "util/image.hpp"
#include "util/png_codec.hpp"

namespace lfd::serve {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

TEST(LibraryFileName, KeepsPlainNamesAndRefusesPaths) {
  EXPECT_EQ(library_file_name("a_qs4x3a0.75.png"), "a_qs4x3a0.75.png");
  EXPECT_EQ(library_file_name("my photo (1).jpg"), "my_photo__1_.jpg");
  EXPECT_EQ(library_file_name(".hidden.png"), "_hidden.png");
  for (const char* bad : {"", "../x.png", "a/b.png", "a\\b.png", "..", "x\n.png"})
    EXPECT_THROW(library_file_name(bad), InputError) << bad;
  EXPECT_THROW(library_file_name(std::string(201, 'a')), InputError);
}

TEST(AccessToken, FoundInItsCookieOrBearerHeaderOnly) {
  const AccessToken token(std::string(64, 'b'));
  const std::string t = token.text();
  EXPECT_TRUE(token.matches(t));
  EXPECT_FALSE(token.matches(std::string(63, 'b')));
  EXPECT_FALSE(token.matches(std::string(63, 'b') + "c"));
  EXPECT_TRUE(token.carried_by("a=1; lfd_token=" + t + "; c=2", ""));
  EXPECT_TRUE(token.carried_by("lfd_token=old; lfd_token=" + t, ""));
  EXPECT_TRUE(token.carried_by("", "Bearer " + t));
  EXPECT_FALSE(token.carried_by("other_token=" + t, ""));
  EXPECT_FALSE(token.carried_by("", "Basic " + t));
  EXPECT_FALSE(token.carried_by("", ""));
}

TEST(AccessToken, MadeOnceKeptPrivateReadBack) {
  TempDir dir;
  const fs::path file = dir.path / "state" / "serve-token";
  const AccessToken made = AccessToken::load_or_create(file);
  EXPECT_EQ(made.text().size(), 64u);
  EXPECT_EQ(made.text().find_first_not_of("0123456789abcdef"), std::string::npos);
  struct stat st {};
  ASSERT_EQ(::stat(file.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_EQ(AccessToken::load_or_create(file).text(), made.text());
  EXPECT_NE(AccessToken::load_or_create(dir.path / "other").text(), made.text());
  std::ofstream(dir.path / "bad") << "not a token\n";
  EXPECT_THROW(AccessToken::load_or_create(dir.path / "bad"), InputError);
}

TEST(OriginPolicy, ConsoleOriginIsTheHostTheRequestWasSentTo) {
  OriginPolicy policy;
  EXPECT_FALSE(policy.allows("http://192.0.2.2:33334", "192.0.2.2:33334"));  // no console
  policy.set_console_port(33334);
  EXPECT_TRUE(policy.allows("http://192.0.2.2:33334", "192.0.2.2:33334"));
  EXPECT_TRUE(policy.allows("http://192.0.2.2:33334", "192.0.2.2:9724"));  // the event socket
  EXPECT_TRUE(policy.allows("http://[fd00::2]:33334", "[fd00::2]:9724"));
  EXPECT_FALSE(policy.allows("http://192.0.2.2:8080", "192.0.2.2:9724"));
  EXPECT_FALSE(policy.allows("https://evil.example", "192.0.2.2:33334"));
  EXPECT_FALSE(policy.allows("http://evil.example:33334", "192.0.2.2:33334"));
  EXPECT_TRUE(policy.allows("http://localhost:5173", "anything"));  // loopback pages, as before
}

TEST(OriginPolicy, OnlyLoopbackPeersNamingLoopbackHostsSkipTheToken) {
  EXPECT_TRUE(OriginPolicy::from_this_machine("127.0.0.1", "localhost:33334"));
  EXPECT_TRUE(OriginPolicy::from_this_machine("::1", "[::1]:9724"));
  EXPECT_TRUE(OriginPolicy::from_this_machine("::ffff:127.0.0.1", "127.0.0.1"));
  EXPECT_FALSE(OriginPolicy::from_this_machine("127.0.0.1", "evil.example:33334"));  // DNS rebinding
  EXPECT_FALSE(OriginPolicy::from_this_machine("192.0.2.5", "localhost:33334"));
  OriginPolicy policy;
  policy.require_token(AccessToken(std::string(64, 'c')));
  EXPECT_TRUE(policy.token_ok(true, "", ""));
  EXPECT_FALSE(policy.token_ok(false, "", ""));
  EXPECT_TRUE(policy.token_ok(false, "lfd_token=" + std::string(64, 'c'), ""));
}

// The bytes of a file, fed to an upload in chunks of 1000 as cpp-httplib would.
auto chunks(const std::string& bytes) {
  return [bytes](const std::function<bool(const char*, std::size_t)>& sink) {
    for (std::size_t at = 0; at < bytes.size(); at += 1000)
      if (!sink(bytes.data() + at, std::min<std::size_t>(1000, bytes.size() - at))) return false;
    return true;
  };
}

std::string png_file_bytes(const TempDir& dir, int width, int height) {
  Image8 picture(width, height, 3, 90);
  const fs::path file = dir.path / "made.png";
  write_png(file, picture);
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  fs::remove(file);
  return bytes;
}

std::vector<std::string> names_in(const fs::path& folder) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(folder)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ContentLibrary, UploadsAreProbedNamedByTheServiceAndNeverReplace) {
  TempDir dir;
  ContentLibrary library(dir.path / "content", 1u << 20, 0.75);
  const std::string quilt = png_file_bytes(dir, 400, 300);
  const LibraryItem a = library.upload("a_qs4x3a0.75.PNG.txt", chunks(quilt));  // the bytes say PNG
  EXPECT_EQ(a.name, "a_qs4x3a0.75.PNG.png");
  EXPECT_EQ(a.kind, "quilt");
  EXPECT_EQ(a.cols, 4);
  EXPECT_EQ(a.rows, 3);
  EXPECT_EQ(a.width, 400);
  const LibraryItem again = library.upload("a_qs4x3a0.75.PNG.txt", chunks(quilt));
  EXPECT_EQ(again.name, "a_qs4x3a0.75.PNG-2.png");
  EXPECT_EQ(library.upload("photo", chunks(quilt)).kind, "rgbd photo");
  EXPECT_EQ(library.items().size(), 3u);
  EXPECT_EQ(names_in(library.folder()), (std::vector<std::string>{"a_qs4x3a0.75.PNG-2.png", "a_qs4x3a0.75.PNG.png", "photo.png"}));
}

TEST(ContentLibrary, RefusedUploadsLeaveNothingBehind) {
  TempDir dir;
  ContentLibrary library(dir.path / "content", 100'000, 0.75);
  const std::string quilt = png_file_bytes(dir, 400, 300);
  EXPECT_THROW(library.upload("notes_qs4x3a0.75.png", chunks(std::string(5000, 'x'))), InputError);
  EXPECT_THROW(library.upload("../evil_qs4x3a0.75.png", chunks(quilt)), InputError);
  EXPECT_THROW(library.upload("empty.png", chunks("")), InputError);
  EXPECT_THROW(library.upload("big_qs4x3a0.75.png", chunks(quilt + std::string(200'000, '\0'))), InputError);
  EXPECT_THROW(library.upload("lie_qs20x20a0.75.png", chunks(quilt)), InputError);  // 20x15 px tiles
  EXPECT_THROW(library.upload("cut_qs4x3a0.75.png", [](const auto& sink) { return sink("\x89PNG", 4) && false; }),
               InputError);
  EXPECT_TRUE(names_in(library.folder()).empty());
}

TEST(ContentLibrary, RenameKeepsTheTypeDeleteRemovesOnlyItsItems) {
  TempDir dir;
  ContentLibrary library(dir.path / "content", 1u << 20, 0.75);
  library.upload("a_qs4x3a0.75.png", chunks(png_file_bytes(dir, 400, 300)));
  library.upload("b_qs4x3a0.75.png", chunks(png_file_bytes(dir, 400, 300)));
  EXPECT_EQ(library.rename("a_qs4x3a0.75.png", "tour one_qs4x3a0.75.jpg").name, "tour_one_qs4x3a0.75.png");
  EXPECT_THROW(library.rename("b_qs4x3a0.75.png", "tour_one_qs4x3a0.75"), InputError);  // taken
  EXPECT_THROW(library.rename("b_qs4x3a0.75.png", "../b"), InputError);
  EXPECT_THROW(library.remove("../content/b_qs4x3a0.75.png"), InputError);
  EXPECT_THROW(library.remove("missing.png"), InputError);
  std::ofstream(dir.path / "outside.png") << "x";
  EXPECT_THROW(library.item("../outside.png"), InputError);
  library.remove("b_qs4x3a0.75.png");
  EXPECT_EQ(names_in(library.folder()), std::vector<std::string>{"tour_one_qs4x3a0.75.png"});
  EXPECT_TRUE(fs::exists(dir.path / "outside.png"));
}

// A Looking Glass Studio sidecar (`<name>.json`, docs/serve.md "Studio playlists") gives the
// layout of a file whose name has no `_qs` tiling, goes with it when renamed or deleted, and is
// no item itself; a sidecar that is not one is refused naming it.
TEST(ContentLibrary, AStudioSidecarGivesTheLayoutOfAFileWithoutQsInItsName) {
  TempDir dir;
  ContentLibrary library(dir.path / "content", 1u << 20, 0.75);
  const std::string picture = png_file_bytes(dir, 400, 300);
  library.upload("hologram.png", chunks(picture));
  library.upload("photo.png", chunks(picture));
  const auto content = library.folder();
  std::ofstream(content / "hologram.png.json")
      << R"({"mediaType": "quilt", "quilt_settings": {"viewX": 5, "viewY": 3, "viewTotal": 15, "aspect": 0.5}})";
  std::ofstream(content / "photo.png.json") << R"({"mediaType": "rgbd", "depthiness": 1.5})";
  const LibraryItem quilt = library.item("hologram.png");
  EXPECT_EQ(quilt.kind, "quilt");
  EXPECT_EQ(quilt.cols, 5);
  EXPECT_EQ(quilt.rows, 3);
  EXPECT_EQ(quilt.views, 15);
  EXPECT_DOUBLE_EQ(quilt.aspect, 0.5);
  EXPECT_EQ(library.item("photo.png").kind, "rgbd photo");
  EXPECT_EQ(library.items().size(), 2u) << "the sidecars are not items";
  EXPECT_EQ(library.rename("hologram.png", "tour").name, "tour.png");
  EXPECT_EQ(library.item("tour.png").cols, 5) << "the sidecar went with its file";
  EXPECT_TRUE(fs::exists(content / "tour.png.json"));
  library.remove("tour.png");
  EXPECT_EQ(names_in(content), (std::vector<std::string>{"photo.png", "photo.png.json"}));
  std::ofstream(content / "photo.png.json") << R"({"mediaType": "movie"})";
  try {
    library.item("photo.png");
    ADD_FAILURE() << "a broken sidecar was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("photo.png.json: mediaType"), std::string::npos) << e.what();
  }
}

// Thumbnails: the centre view made small, kept per content, made again when the content changes.
TEST(LibraryThumbnails, TheCentreViewMadeSmallKeptPerContent) {
  TempDir dir;
  ContentLibrary library(dir.path / "content", 4u << 20, 0.75);
  MemoryBudget budget(64u << 20);
  LibraryThumbnails thumbnails(library, budget);
  // 4x3 views of 400x400 px; view v is grey level 10 v; the centre view (6) is 60.
  Image8 quilt(1600, 1200, 3);
  for (int v = 0; v < 12; ++v)
    for (int y = 0; y < 400; ++y)
      for (int x = 0; x < 400; ++x)
        for (int c = 0; c < 3; ++c) quilt.at((v % 4) * 400 + x, 1200 - (v / 4 + 1) * 400 + y, c) = std::uint8_t(10 * v);
  write_png(dir.path / "q.png", quilt);
  std::ifstream in(dir.path / "q.png", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  library.upload("views_qs4x3a1.png", chunks(bytes));
  const auto decode = [](const std::string& png) {
    std::FILE* f = fmemopen(const_cast<char*>(png.data()), png.size(), "rb");
    EXPECT_TRUE(png::has_png_signature(f));
    Image8 image = png::decode(f, "thumbnail", 3);
    std::fclose(f);
    return image;
  };
  const Image8 small = decode(thumbnails.png("views_qs4x3a1.png"));
  EXPECT_EQ(small.width, kThumbnailPx);
  EXPECT_EQ(small.height, kThumbnailPx);
  for (std::uint8_t v : small.pixels) ASSERT_EQ(v, 60) << "the centre view's grey, nothing of its neighbours";
  thumbnails.png("views_qs4x3a1.png");
  EXPECT_EQ(thumbnails.made(), 1u) << "the second ask is the kept one";
  EXPECT_EQ(budget.used(), 0u) << "the decoded picture's reservation went with it";
  // An RGB-D photo is made small whole; an item that is not one is refused.
  library.upload("photo", chunks(png_file_bytes(dir, 640, 320)));
  const Image8 photo = decode(thumbnails.png("photo.png"));
  EXPECT_EQ(photo.width, kThumbnailPx);
  EXPECT_EQ(photo.height, kThumbnailPx / 2);
  EXPECT_THROW(thumbnails.png("../q.png"), InputError);
  EXPECT_THROW(thumbnails.png("missing.png"), InputError);
  // Other content under the same name: made again.
  library.remove("views_qs4x3a1.png");
  library.upload("views_qs4x3a1.png", chunks(png_file_bytes(dir, 800, 600)));
  EXPECT_EQ(decode(thumbnails.png("views_qs4x3a1.png")).pixels[0], 90);
  EXPECT_EQ(thumbnails.made(), 3u);
}

TEST(LibraryThumbnails, ShrinkingKeepsTheAspectAndNeverEnlarges) {
  EXPECT_EQ(shrink_to_thumbnail(Image8(100, 50, 3)).width, 100);
  const Image8 wide = shrink_to_thumbnail(Image8(1000, 10, 3, 7));
  EXPECT_EQ(wide.width, kThumbnailPx);
  EXPECT_EQ(wide.height, 1);
  EXPECT_EQ(wide.pixels[0], 7);
  EXPECT_THROW(shrink_to_thumbnail(Image8()), InputError);
}

}  // namespace
}  // namespace lfd::serve
