// The messages of one level a Log receives from now on (its sink), for tests that check what the
// plant says: `LogCapture errors(world.log(), LogLevel::Error);` then errors.messages.
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/log.h"

struct LogCapture
{
  LogCapture(bullet_plant::Log& log, bullet_plant::LogLevel level)
  {
    log.setSink([this, level](bullet_plant::LogLevel at, const std::string& m) {
      if (at == level)
        messages.push_back(m);
    });
  }
  std::vector<std::string> messages;
};

// A Log of its own with its warnings captured, for what is given a Log rather than a World.
struct WarningsCapture
{
  bullet_plant::Log log;
  LogCapture captured{log, bullet_plant::LogLevel::Warn};
  std::vector<std::string>& warnings = captured.messages;
};
