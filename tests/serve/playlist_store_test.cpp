// Playlists: limits, and the state file written atomically and read back.
#include <fstream>

#include <gtest/gtest.h>

#include "serve/playlist_store.hpp"
#include "tests/serve/serve_test_support.hpp"
#include "util/error.hpp"

namespace lfd::serve {
namespace {

TEST(PlaylistStore, KeepsTheLimitsAndLeavesNoTemporaryFile) {
  test::TempDir tmp;
  ServeLimits limits;
  limits.max_playlists = 2;
  limits.max_playlist_entries = 1;
  PlaylistStore store(tmp.path / "p.json", limits);
  store.instance("a", true);
  store.instance("b", false);
  EXPECT_THROW(store.instance("c", true), InputError);
  store.insert("a", -1, PlaylistEntry{});
  EXPECT_THROW(store.insert("a", -1, PlaylistEntry{}), InputError);
  EXPECT_THROW(store.insert("nope", -1, PlaylistEntry{}), InputError);
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(tmp.path)) ++files;
  EXPECT_EQ(files, 1);
  PlaylistStore again(tmp.path / "p.json", limits);
  EXPECT_EQ(again.size(), 2u);
  EXPECT_FALSE(again.get("b")->loop);
}

TEST(PlaylistStore, AnUnreadableStateFileStartsEmpty) {
  test::TempDir tmp;
  ServeLimits limits;
  std::ofstream(tmp.path / "p.json") << "{garbage";
  PlaylistStore store(tmp.path / "p.json", limits);
  EXPECT_EQ(store.size(), 0u);
}

}  // namespace
}  // namespace lfd::serve
