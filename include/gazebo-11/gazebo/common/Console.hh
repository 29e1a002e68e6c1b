// Gazebo's console: gzmsg, gzwarn, gzerr, gzdbg and gzlog, streams as a plugin writes to them.
// Each line goes out with Gazebo's prefix ("[Msg] ", "[Wrn] [File.cc:12] ", "[Err] [File.cc:12] ",
// "[Dbg] [File.cc:12] "): messages and debug output to stdout, warnings and errors to stderr. As
// in gzserver without --verbose, messages and debug output are quiet until
// common::Console::SetQuiet(false); warnings and errors are always written.
#pragma once

#include <memory>
#include <ostream>
#include <string>

#include "gazebo/util/system.hh"

#define gzmsg (gazebo::common::Console::msg())
#define gzdbg (gazebo::common::Console::dbg(__FILE__, __LINE__))
#define gzwarn (gazebo::common::Console::warn(__FILE__, __LINE__))
#define gzerr (gazebo::common::Console::err(__FILE__, __LINE__))
#define gzlog (gazebo::common::Console::log())

namespace gazebo
{
namespace common
{
// One of the console's streams: a line is written with the stream's prefix once it ends.
class GZ_COMMON_VISIBLE Logger : public std::ostream
{
public:
  enum LogType { STDOUT, STDERR };

  Logger(const std::string& prefix, int color, LogType type);
  ~Logger() override;

  // The stream, its lines prefixed with `prefix` alone (gzmsg) or with [FILE:LINE] too.
  virtual Logger& operator()();
  virtual Logger& operator()(const std::string& file, int line);

private:
  class Buffer;
  std::unique_ptr<Buffer> buffer_;
  std::string prefix_;
};

class GZ_COMMON_VISIBLE Console
{
public:
  static void SetQuiet(bool quiet);
  static bool GetQuiet();

  static Logger msg;
  static Logger err;
  static Logger dbg;
  static Logger warn;
  // gzlog: Gazebo's log file; here the lines go to stdout with "[Log] ", quiet as messages are.
  static Logger log;
};
}  // namespace common
}  // namespace gazebo
