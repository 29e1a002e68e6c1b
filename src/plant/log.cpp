#include "bullet_plant/log.h"

#include <cstdio>
#include <iostream>

namespace bullet_plant
{
const char* levelName(LogLevel level)
{
  switch (level)
  {
    case LogLevel::Debug: return "DEBUG";
    case LogLevel::Info: return "INFO";
    case LogLevel::Warn: return "WARN";
    case LogLevel::Error: return "ERROR";
  }
  return "?";
}

Log::Log()
  : sink_([](LogLevel level, const std::string& m) {
      if (level >= LogLevel::Info)
        std::cerr << "[" << levelName(level) << "] " << m << std::endl;
    })
{
}

void Log::emit(LogLevel level, const std::string& m) const
{
  if (sink_)
    sink_(level, m);
}

std::string formatNumber(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace bullet_plant
