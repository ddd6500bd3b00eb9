// lfd bench serve: the bounded load test of a running lfd serve (serve/load_bench.hpp,
// docs/serve.md "Load"): a table, optional JSON, exit 1 when a request went unanswered or the
// service stopped answering.
//   lfd bench serve --quilt q_qs4x3a0.75.png --clients 64 --seconds 30 --json serve.json
//   lfd bench serve --quilt-size go --clients 64 --seconds 30
#include <stdlib.h>

#include <cstdio>
#include <optional>
#include <fstream>
#include <iostream>
#include <iterator>

#include "apps/bench.hpp"
#include <fmt/format.h>

#include "apps/cli.hpp"
#include "media/quilt_name.hpp"
#include "media/synthetic_quilt.hpp"
#include "serve/load_bench.hpp"
#include "util/atomic_file.hpp"
#include "util/image.hpp"
#include "util/error.hpp"

namespace lfd::apps {
namespace {

// The synthetic quilt's file (a Bridge cast reads a file), removed at the end.
struct TempFolder {
  std::filesystem::path path;
  TempFolder() {
    std::string t = (std::filesystem::temp_directory_path() / "lfd-bench-serve-XXXXXX").string();
    if (!mkdtemp(t.data())) throw_input_error("{}: cannot make a temporary folder", t);
    path = t;
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

}  // namespace

int RunBenchServe(int argc, char** argv) {
  CLI::App app{"Load test of a running lfd serve on loopback: many clients at once asking HoloPlay info,\n"
               "showing a quilt sent as bytes, calling Bridge and casting the quilt file, opening event\n"
               "sockets and vanishing mid-handshake, for a fixed time. Prints per-request counts (answered,\n"
               "refused, unanswered) with latencies and the service's resident memory over the run.\n"
               "Busy answers (the service's memory budget in use) are counted apart. Start the service\n"
               "first (lfd serve ...). Examples:\n"
               "  lfd bench serve --quilt-size go --clients 64 --seconds 30\n"
               "  lfd bench serve --quilt a_qs4x3a0.75.png --clients 64 --seconds 30 --json serve.json",
               "serve"};
  serve::LoadBenchOptions o;
  std::string quilt, quilt_size, json_path;
  auto* quilt_option =
      app.add_option("--quilt", quilt, "a quilt image named _qsCxRaA (shown and cast)")->check(CLI::ExistingFile);
  std::string sizes;
  for (const auto& p : serve::quilt_size_presets()) sizes += (sizes.empty() ? "" : ", ") + p.name;
  app.add_option("--quilt-size", quilt_size, "a synthetic quilt of a unit's content instead: " + sizes)
      ->excludes(quilt_option);
  app.add_option("--clients", o.clients, "clients at once")->capture_default_str()->check(CLI::Range(1, 1000));
  app.add_option("--seconds", o.seconds, "how long")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--listen", o.address.host, "the service's address")->capture_default_str();
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  if (auto code = parse(app, argc, argv)) return *code;
  if (quilt.empty() && quilt_size.empty()) throw_input_error("--quilt or --quilt-size: which quilt to send");
  std::optional<TempFolder> made;
  if (!quilt_size.empty()) {
    const serve::QuiltSizePreset& p = serve::quilt_size_preset(quilt_size);
    made.emplace();
    const render::QuiltLayout layout{p.cols, p.rows, p.cols * p.rows, p.aspect, p.cols * p.tile_width,
                                     p.rows * p.tile_height};
    quilt = (made->path / fmt::format("bench-{}_qs{}x{}a{}.png", p.name, p.cols, p.rows, p.aspect)).string();
    write_png(quilt, media::synthetic_quilt(layout));
    o.quilt_description = fmt::format("{}: {}x{} tiles of {}x{} ({}x{}, {:.1f} MiB as PNG)", p.unit, p.cols, p.rows,
                                      p.tile_width, p.tile_height, layout.width, layout.height,
                                      std::filesystem::file_size(quilt) / double(1 << 20));
  } else {
    o.quilt_description = std::filesystem::path(quilt).filename().string();
  }

  const auto name = media::parse_quilt_name(std::filesystem::path(quilt).filename().string());
  if (!name) throw_input_error("{}: the name has no _qsCxRaA tiling", quilt);
  o.quilt = {name->cols, name->rows, name->cols * name->rows, name->aspect};
  std::ifstream in(quilt, std::ios::binary);
  o.quilt_png.assign(std::istreambuf_iterator<char>(in), {});
  o.quilt_file = std::filesystem::absolute(quilt).string();
  const serve::LoadBenchResult result = serve::run_load_bench(o);
  std::cout << serve::load_bench_table(result);
  if (!json_path.empty()) {
    write_text_atomic(json_path, serve::load_bench_json(result).dump(2) + "\n");
    std::cout << "wrote " << json_path << "\n";
  }
  return result.unanswered() == 0 && result.service_alive_after ? 0 : 1;
}

}  // namespace lfd::apps
