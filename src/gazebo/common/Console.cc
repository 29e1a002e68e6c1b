// Gazebo's console streams (gazebo/common/Console.hh).
#include "gazebo/common/Console.hh"

#include <atomic>
#include <cstdio>
#include <mutex>
#include <streambuf>

namespace gazebo
{
namespace common
{
namespace
{
std::atomic<bool> quiet{true};
}

// Collects a line and writes it whole, prefixed, once it ends: lines of plugins on other threads do
// not interleave within a line.
class Logger::Buffer : public std::streambuf
{
public:
  Buffer(LogType type, bool quiet_when_quiet) : type_(type), obeys_quiet_(quiet_when_quiet) {}

  void setPrefix(const std::string& prefix)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (line_.empty())
      prefix_ = prefix;
    else
      pending_prefix_ = prefix;
  }

protected:
  int overflow(int c) override
  {
    if (c == traits_type::eof())
      return traits_type::not_eof(c);
    std::lock_guard<std::mutex> lock(mutex_);
    line_.push_back(static_cast<char>(c));
    if (c == '\n')
      writeLine();
    return c;
  }

  int sync() override
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!line_.empty())
    {
      line_.push_back('\n');
      writeLine();
    }
    return 0;
  }

private:
  void writeLine()
  {
    if (!(obeys_quiet_ && quiet))
    {
      FILE* out = type_ == STDERR ? stderr : stdout;
      std::fputs((prefix_ + line_).c_str(), out);
      std::fflush(out);
    }
    line_.clear();
    if (!pending_prefix_.empty())
    {
      prefix_ = pending_prefix_;
      pending_prefix_.clear();
    }
  }

  LogType type_;
  bool obeys_quiet_;
  std::mutex mutex_;
  std::string line_, prefix_, pending_prefix_;
};

Logger::Logger(const std::string& prefix, int /*color*/, LogType type)
  : std::ostream(nullptr), buffer_(new Buffer(type, type == STDOUT)), prefix_(prefix)
{
  rdbuf(buffer_.get());
}

Logger::~Logger() = default;

Logger& Logger::operator()()
{
  buffer_->setPrefix(prefix_);
  return *this;
}

Logger& Logger::operator()(const std::string& file, int line)
{
  const size_t slash = file.find_last_of('/');
  buffer_->setPrefix(prefix_ + "[" + (slash == std::string::npos ? file : file.substr(slash + 1)) + ":" +
                     std::to_string(line) + "] ");
  return *this;
}

void Console::SetQuiet(bool q) { quiet = q; }

bool Console::GetQuiet() { return quiet; }

Logger Console::msg("[Msg] ", 32, Logger::STDOUT);
Logger Console::err("[Err] ", 31, Logger::STDERR);
Logger Console::dbg("[Dbg] ", 36, Logger::STDOUT);
Logger Console::warn("[Wrn] ", 33, Logger::STDERR);
Logger Console::log("[Log] ", 0, Logger::STDOUT);
}  // namespace common
}  // namespace gazebo
