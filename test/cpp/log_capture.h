// A Log whose warnings a test reads back: for the checks that the plant says what it did.
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/log.h"

struct WarningsCapture
{
  bullet_plant::Log log;
  std::vector<std::string> warnings;
  WarningsCapture()
  {
    log.setSink([this](bullet_plant::LogLevel level, const std::string& m) {
      if (level == bullet_plant::LogLevel::Warn)
        warnings.push_back(m);
    });
  }
};
