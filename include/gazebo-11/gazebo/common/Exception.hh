// common::Exception and gzthrow, as Gazebo 11's: gzthrow(stream text) throws an Exception with the
// file and line. Here it is also a std::runtime_error (what() is the text), so that whatever hosts a
// plugin that throws one names it; a plugin catches it as common::Exception as in Gazebo.
#pragma once

#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "gazebo/util/system.hh"

namespace gazebo
{
namespace common
{
#define gzthrow(msg)                                                                 \
  {                                                                                  \
    std::ostringstream throwStream;                                                  \
    throwStream << msg << std::endl << std::flush;                                   \
    throw gazebo::common::Exception(__FILE__, __LINE__, throwStream.str());          \
  }

class GZ_COMMON_VISIBLE Exception : public std::runtime_error
{
public:
  Exception();
  // Says the error on gzerr, as Gazebo's.
  Exception(const char* file, int line, std::string message);
  ~Exception() override;
  std::string GetErrorFile() const;
  std::string GetErrorStr() const;
  friend std::ostream& operator<<(std::ostream& out, const Exception& error) { return out << error.GetErrorStr(); }

private:
  std::string file_;
  int line_ = 0;
  std::string message_;
};
}  // namespace common
}  // namespace gazebo
