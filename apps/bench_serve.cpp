// lfd bench serve: the bounded load test of a running lfd serve (serve/load_bench.hpp,
// docs/serve.md "Load"): a table, optional JSON, exit 1 when a request went unanswered or the
// service stopped answering.
//   lfd bench serve --quilt q_qs4x3a0.75.png --clients 64 --seconds 30 --json serve.json
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>

#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "media/quilt_name.hpp"
#include "serve/load_bench.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::apps {

int RunBenchServe(int argc, char** argv) {
  CLI::App app{"Load test of a running lfd serve on loopback: many clients at once asking HoloPlay info,\n"
               "showing a quilt sent as bytes, calling Bridge and casting the quilt file, opening event\n"
               "sockets and vanishing mid-handshake, for a fixed time. Prints per-request counts (answered,\n"
               "refused, unanswered) with latencies and the service's resident memory over the run.\n"
               "Start the service first (lfd serve ...). Example:\n"
               "  lfd bench serve --quilt a_qs4x3a0.75.png --clients 64 --seconds 30 --json serve.json",
               "serve"};
  serve::LoadBenchOptions o;
  std::string quilt, json_path;
  app.add_option("--quilt", quilt, "a quilt image named _qsCxRaA (shown and cast)")->required()->check(CLI::ExistingFile);
  app.add_option("--clients", o.clients, "clients at once")->capture_default_str()->check(CLI::Range(1, 1000));
  app.add_option("--seconds", o.seconds, "how long")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--listen", o.address.host, "the service's address")->capture_default_str();
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  if (auto code = parse(app, argc, argv)) return *code;

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
