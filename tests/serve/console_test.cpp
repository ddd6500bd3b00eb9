// The console's pieces without a browser (docs/console.md): upload names, the access token, the
// console's origin and "from this machine", and the content library's uploads, renames and
// deletes against a real folder. The page itself is tested in Chromium (tests/serve/clients/
// console_test.js).
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "serve/access_token.hpp"
#include "serve/content_library.hpp"
#include "serve/origin_policy.hpp"
#include "tests/serve/serve_test_support.hpp"
#include "util/error.hpp"
#include "util/image.hpp"

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

}  // namespace
}  // namespace lfd::serve
