// docs/gpu.md "Binding points" is the one table of the binding points: every
// LFD_IO_INT(k...Binding|Unit|Image, N) of a contract header (gpu/*/shaders/*_io.h, rgbd/, play/,
// live/ shaders/*_io.h) is a row with its kind, point and header, and no row names a point no
// header declares (scripts/binding-points-table.py writes the table).
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace lfd::gpu {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// name -> "kind point header", as the table writes them.
using Points = std::map<std::string, std::string>;

Points header_points(const fs::path& root) {
  const std::regex row(R"(LFD_IO_INT\((k\w+(Binding|Unit|Image)),\s*(\d+)\))");
  const std::map<std::string, std::string> kind{{"Binding", "storage"}, {"Unit", "texture"}, {"Image", "image"}};
  Points out;
  std::vector<fs::path> folders;
  for (const auto& module : fs::directory_iterator(root / "gpu")) folders.push_back(module.path() / "shaders");
  for (const char* module : {"rgbd", "play", "live"}) folders.push_back(root / module / "shaders");
  for (const fs::path& folder : folders) {
    if (!fs::is_directory(folder)) continue;
    for (const auto& file : fs::directory_iterator(folder)) {
      const std::string name = file.path().filename().string();
      if (name.size() < 5 || name.compare(name.size() - 5, 5, "_io.h") != 0) continue;
      const std::string text = read(file.path());
      const std::string header = fs::relative(file.path(), root).generic_string();
      for (std::sregex_iterator m(text.begin(), text.end(), row), end; m != end; ++m)
        out[(*m)[1]] = kind.at((*m)[2]) + " " + (*m)[3].str() + " " + header;
    }
  }
  return out;
}

Points documented_points(const std::string& docs) {
  const std::regex row(R"(\| (storage|texture|image) (\d+) \| `(k\w+)` \| `([^`]+)` \|)");
  Points out;
  for (std::sregex_iterator m(docs.begin(), docs.end(), row), end; m != end; ++m)
    out[(*m)[3]] = (*m)[1].str() + " " + (*m)[2].str() + " " + (*m)[4].str();
  return out;
}

TEST(BindingPointsDoc, TheTableListsEveryPointOfTheContractHeadersAsTheyDeclareIt) {
  const fs::path root = LFD_SOURCE_DIR;
  const Points headers = header_points(root);
  const Points docs = documented_points(read(root / "docs" / "gpu.md"));
  ASSERT_GT(headers.size(), 40u);  // the parse found the headers
  for (const auto& [name, declared] : headers) {
    const auto it = docs.find(name);
    if (it == docs.end())
      ADD_FAILURE() << name << " (" << declared << ") is missing from docs/gpu.md \"Binding points\""
                    << " (python3 scripts/binding-points-table.py)";
    else
      EXPECT_EQ(it->second, declared) << name << ": docs/gpu.md \"Binding points\" misstates it";
  }
  for (const auto& [name, documented] : docs)
    EXPECT_TRUE(headers.count(name)) << name << " (" << documented << ") is in docs/gpu.md but in no contract header";
}

}  // namespace
}  // namespace lfd::gpu
