// A show replaced by a newer one before its frame is dropped, not queued
// (play/command_queue.hpp, the Player's queue that lfd serve's shows go through).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "play/command_queue.hpp"

namespace lfd::serve {
namespace {

using Log = std::vector<std::string>;

TEST(ReplacedShow, IsDroppedWithItsPictureAndTheOtherCommandsStayInOrder) {
  play::CommandQueue<Log> queue;
  auto first_picture = std::make_shared<std::vector<unsigned char>>(1 << 20);
  std::weak_ptr<std::vector<unsigned char>> first_alive = first_picture;
  queue.push_content([picture = std::move(first_picture)](Log& log) { log.push_back("show 1"); });
  queue.push([](Log& log) { log.push_back("aspect"); });
  queue.push_content([](Log& log) { log.push_back("show 2"); });
  EXPECT_TRUE(first_alive.expired());  // the replaced picture is freed at once, not at the frame
  queue.push([](Log& log) { log.push_back("pause"); });
  Log log;
  for (auto& command : queue.take()) command(log);
  EXPECT_EQ(log, (Log{"aspect", "show 2", "pause"}));
  EXPECT_EQ(queue.dropped(), 1u);
}

TEST(ReplacedShow, AShowTakenByAFrameIsNotDroppedByTheNextOne) {
  play::CommandQueue<Log> queue;
  queue.push_content([](Log& log) { log.push_back("show 1"); });
  Log log;
  for (auto& command : queue.take()) command(log);
  queue.push_content([](Log& log) { log.push_back("show 2"); });
  for (auto& command : queue.take()) command(log);
  EXPECT_EQ(log, (Log{"show 1", "show 2"}));
  EXPECT_EQ(queue.dropped(), 0u);
}

}  // namespace
}  // namespace lfd::serve
