#include "report/gnuplot.hpp"

#include <cstdlib>
#include <iostream>

namespace lfd::report {

namespace {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string gnuplot_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

bool run_gnuplot(const std::filesystem::path& dir, const std::string& script_name,
                 const std::vector<std::string>& outputs) {
  const std::string command = "cd " + shell_quote(dir.string()) + " && gnuplot " +
                              shell_quote(script_name) + " > /dev/null 2> gnuplot.log";
  const int rc = std::system(command.c_str());
  bool ok = rc == 0;
  for (const auto& name : outputs) {
    const auto tmp = dir / (name + ".tmp");
    std::error_code ec;
    if (ok && std::filesystem::exists(tmp)) {
      std::filesystem::rename(tmp, dir / name, ec);
      if (ec) ok = false;
    } else {
      std::filesystem::remove(tmp, ec);
      ok = false;
    }
  }
  if (!ok)
    std::cerr << "warning: gnuplot failed or is not installed; figures not written (see "
              << (dir / "gnuplot.log").string() << ")\n";
  return ok;
}

}  // namespace lfd::report
