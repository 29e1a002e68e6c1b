// Where the plant's messages go: stderr by default, ROS_* in the node, a list in Python.
#pragma once

#include <functional>
#include <string>

namespace bullet_plant
{
enum class LogLevel { Debug, Info, Warn, Error };

using LogSink = std::function<void(LogLevel, const std::string&)>;

class Log
{
public:
  Log();
  void setSink(LogSink sink) { sink_ = std::move(sink); }
  void debug(const std::string& m) const { emit(LogLevel::Debug, m); }
  void info(const std::string& m) const { emit(LogLevel::Info, m); }
  void warn(const std::string& m) const { emit(LogLevel::Warn, m); }
  void error(const std::string& m) const { emit(LogLevel::Error, m); }

private:
  void emit(LogLevel level, const std::string& m) const;
  LogSink sink_;
};

const char* levelName(LogLevel level);
// A number as messages show it: 6 significant digits, no trailing zeros (printf's %g).
std::string formatNumber(double value);

}  // namespace bullet_plant
