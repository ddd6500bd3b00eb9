// The access token for listeners beyond loopback (docs/console.md, "Security").
#include "serve/access_token.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <random>

#include <fmt/format.h>

#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::serve {

namespace {

constexpr std::size_t kTokenChars = 64;

bool is_token(std::string_view s) {
  return s.size() == kTokenChars && std::all_of(s.begin(), s.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

std::string trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\n' || s.back() == '\r')) s.remove_suffix(1);
  return std::string(s);
}

}  // namespace

AccessToken AccessToken::load_or_create(const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::exists(file, ec)) {
    const std::string text = trimmed(read_text_file(file));
    if (!is_token(text)) throw_input_error("{}: not an lfd serve token (64 hex digits)", file.string());
    return AccessToken(text);
  }
  std::random_device random;  // getrandom(2) on Linux
  std::string token;
  while (token.size() < kTokenChars) token += fmt::format("{:08x}", static_cast<std::uint32_t>(random()));
  write_file_atomic(file, [&](const std::filesystem::path& tmp) {
    // Made 0600 before a byte of the token is in it.
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd < 0) throw_input_error("{}: cannot write", file.string());
    const std::string line = token + "\n";
    const bool written = ::write(fd, line.data(), line.size()) == static_cast<ssize_t>(line.size());
    ::close(fd);
    if (!written) throw_input_error("{}: cannot write", file.string());
  });
  return AccessToken(token);
}

bool AccessToken::matches(std::string_view candidate) const {
  // Every character compared whatever the first difference; the length is public (64).
  if (candidate.size() != token_.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < token_.size(); ++i)
    diff |= static_cast<unsigned char>(token_[i] ^ candidate[i]);
  return diff == 0;
}

bool AccessToken::carried_by(std::string_view cookie_header, std::string_view authorization_header) const {
  bool found = false;
  // "a=b; lfd_token=T; c=d": each cookie of that name checked (a page may hold an old one).
  while (!cookie_header.empty()) {
    const std::size_t end = std::min(cookie_header.find(';'), cookie_header.size());
    std::string_view pair = cookie_header.substr(0, end);
    cookie_header.remove_prefix(std::min(end + 1, cookie_header.size()));
    while (!pair.empty() && pair.front() == ' ') pair.remove_prefix(1);
    const std::string prefix = std::string(kTokenCookie) + "=";
    if (pair.substr(0, prefix.size()) == prefix) found = matches(trimmed(pair.substr(prefix.size()))) || found;
  }
  constexpr std::string_view bearer = "Bearer ";
  if (authorization_header.substr(0, bearer.size()) == bearer)
    found = matches(trimmed(authorization_header.substr(bearer.size()))) || found;
  return found;
}

std::filesystem::path token_file_beside(const std::filesystem::path& state_file) {
  return state_file.parent_path() / "serve-token";
}

}  // namespace lfd::serve
