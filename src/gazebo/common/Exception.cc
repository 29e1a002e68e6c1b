// common::Exception (gazebo/common/Exception.hh).
#include "gazebo/common/Exception.hh"

#include "gazebo/common/Console.hh"

namespace gazebo
{
namespace common
{
Exception::Exception() : std::runtime_error("") {}

Exception::Exception(const char* file, int line, std::string message)
  : std::runtime_error(message), file_(file ? file : ""), line_(line), message_(std::move(message))
{
  gzerr << message_ << std::flush;
}

Exception::~Exception() = default;

std::string Exception::GetErrorFile() const { return file_ + ":" + std::to_string(line_); }

std::string Exception::GetErrorStr() const { return message_; }
}  // namespace common
}  // namespace gazebo
