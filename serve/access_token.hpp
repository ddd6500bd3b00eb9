#pragma once
// The access token a service listening beyond loopback needs from every request (docs/console.md,
// "Security"): 256 random bits as 64 hex digits, kept in a file of the user's (mode 0600) beside
// the state file, printed by `lfd serve --print-token`. A request carries it in the cookie the
// console's login form sets (`lfd_token`, HttpOnly, SameSite=Strict) or in an
// `Authorization: Bearer` header, never in a URL (URLs get logged). Compared in constant time.
#include <filesystem>
#include <string>
#include <string_view>

namespace lfd::serve {

class AccessToken {
 public:
  explicit AccessToken(std::string token) : token_(std::move(token)) {}
  // The token kept in `file`, made (random, written atomically, 0600) when the file is absent.
  // InputError naming the file when it holds something else than a token.
  static AccessToken load_or_create(const std::filesystem::path& file);
  // Whether `candidate` is the token, in time independent of where they differ.
  bool matches(std::string_view candidate) const;
  // Whether a request's Cookie or Authorization header carries the token.
  bool carried_by(std::string_view cookie_header, std::string_view authorization_header) const;
  const std::string& text() const { return token_; }

 private:
  std::string token_;
};

inline constexpr const char* kTokenCookie = "lfd_token";

// serve-token beside the state file (or in $XDG_STATE_HOME/lfd without one).
std::filesystem::path token_file_beside(const std::filesystem::path& state_file);

}  // namespace lfd::serve
