// The live mode's "move the camera ... and press Enter": a line on stdin or Enter in the
// pattern window ends the wait; a closed stdin is an error, not a hang.
#include <unistd.h>

#include <gtest/gtest.h>

#include "live/console_prompt.hpp"
#include "util/error.hpp"

namespace lfd::live {
namespace {

// Replaces stdin by a pipe for the test's lifetime; `input` is written to it first.
class PipedStdin {
 public:
  explicit PipedStdin(const std::string& input) {
    int fds[2];
    EXPECT_EQ(::pipe(fds), 0);
    saved_ = ::dup(STDIN_FILENO);
    ::dup2(fds[0], STDIN_FILENO);
    ::close(fds[0]);
    write_end_ = fds[1];
    EXPECT_EQ(::write(write_end_, input.data(), input.size()), ssize_t(input.size()));
  }
  void close_write_end() {
    if (write_end_ >= 0) ::close(write_end_);
    write_end_ = -1;
  }
  ~PipedStdin() {
    close_write_end();
    ::dup2(saved_, STDIN_FILENO);
    ::close(saved_);
  }

 private:
  int saved_ = -1, write_end_ = -1;
};

TEST(ConsolePrompt, ALineOnStdinEndsTheWait) {
  PipedStdin in("\n");
  int polls = 0;
  wait_for_enter("press Enter", [&] { return ++polls > 100; });
  EXPECT_LE(polls, 1);  // answered by stdin, not by running out of polls
}

TEST(ConsolePrompt, EnterInTheWindowEndsTheWaitAndTheWindowKeepsBeingServed) {
  PipedStdin in("");
  int polls = 0;
  wait_for_enter("press Enter", [&] { return ++polls == 3; });
  EXPECT_EQ(polls, 3);
}

TEST(ConsolePrompt, AClosedStdinIsAnInputError) {
  PipedStdin in("");
  in.close_write_end();
  EXPECT_THROW(wait_for_enter("press Enter", [] { return false; }), InputError);
}

}  // namespace
}  // namespace lfd::live
