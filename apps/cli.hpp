#pragma once
// Shared command-line plumbing: parsing with CLI11 and the exit-code convention
// (0 success or --help, 2 bad usage/input, 1 other failures).
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace lfd::apps {

// Parses argv into `app`. Returns an exit code to return immediately (help printed: 0,
// bad usage: 2 after a one-line message), or nullopt to continue.
std::optional<int> parse(CLI::App& app, int argc, char** argv);

// Parses "X,Y,Z" (or "WxH" with sep 'x') into numbers; throws InputError naming `option`.
std::vector<double> parse_numbers(const std::string& text, char sep, size_t count,
                                  const std::string& option);

}  // namespace lfd::apps
