// common::Time (gazebo/common/Time.hh).
#include "gazebo/common/Time.hh"

#include <cmath>
#include <chrono>
#include <cstdio>
#include <thread>

namespace gazebo
{
namespace common
{
const Time Time::Zero(0, 0);
const int32_t Time::nsInSec = 1000000000;
const int32_t Time::nsInMs = 1000000;

Time::Time(const struct timeval& tv) : sec(static_cast<int32_t>(tv.tv_sec)), nsec(static_cast<int32_t>(tv.tv_usec * 1000))
{
  Correct();
}

Time::Time(const struct timespec& tv) : sec(static_cast<int32_t>(tv.tv_sec)), nsec(static_cast<int32_t>(tv.tv_nsec))
{
  Correct();
}

Time::Time(int32_t sec_, int32_t nsec_) : sec(sec_), nsec(nsec_) { Correct(); }

Time::Time(double seconds) { Set(seconds); }

void Time::Set(int32_t sec_, int32_t nsec_)
{
  sec = sec_;
  nsec = nsec_;
  Correct();
}

void Time::Set(double seconds)
{
  // A non-finite time is zero: a plugin's NaN never reaches the integers (undefined behaviour).
  if (!std::isfinite(seconds))
    seconds = 0.0;
  const double whole = std::trunc(seconds);
  sec = static_cast<int32_t>(whole);
  nsec = static_cast<int32_t>(std::llround((seconds - whole) * 1e9));
  Correct();
}

double Time::Double() const { return sec + nsec * 1e-9; }

float Time::Float() const { return static_cast<float>(Double()); }

const Time& Time::GetWallTime()
{
  static thread_local Time wall;
  wall.SetToWallTime();
  return wall;
}

const std::string& Time::GetWallTimeAsISOString()
{
  static thread_local std::string iso;
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[32];
  std::strftime(text, sizeof text, "%FT%T", &local);
  iso = text;
  return iso;
}

void Time::SetToWallTime()
{
  struct timespec now;
  clock_gettime(CLOCK_REALTIME, &now);
  *this = now;
}

Time Time::Sleep(const common::Time& time)
{
  if (time > Zero)
    std::this_thread::sleep_for(std::chrono::seconds(time.sec) + std::chrono::nanoseconds(time.nsec));
  return Zero;  // what is left of it: nothing, as Gazebo's on Linux after an uninterrupted sleep
}

Time Time::MSleep(unsigned int ms) { return Sleep(Time(static_cast<int32_t>(ms / 1000), static_cast<int32_t>((ms % 1000) * 1000000))); }

Time Time::NSleep(unsigned int ns) { return Sleep(Time(0, static_cast<int32_t>(ns % 1000000000u)) + Time(static_cast<int32_t>(ns / 1000000000u), 0)); }

Time Time::NSleep(Time time) { return Sleep(time); }

Time& Time::operator=(const struct timeval& tv) { return *this = Time(tv); }

Time& Time::operator=(const struct timespec& tv) { return *this = Time(tv); }

Time Time::operator+(const Time& time) const { return Time(sec + time.sec, nsec + time.nsec); }

const Time& Time::operator+=(const Time& time) { return *this = *this + time; }

Time Time::operator-(const Time& time) const { return Time(sec - time.sec, nsec - time.nsec); }

const Time& Time::operator-=(const Time& time) { return *this = *this - time; }

Time Time::operator*(const Time& time) const { return Time(Double() * time.Double()); }

const Time& Time::operator*=(const Time& time) { return *this = *this * time; }

Time Time::operator/(const Time& time) const
{
  // Gazebo prints an error and leaves the time as it is when dividing by zero.
  if (time == Zero)
  {
    std::fprintf(stderr, "[Err] [Time.cc] Time division by zero: the time is left as it was\n");
    return *this;
  }
  return Time(Double() / time.Double());
}

const Time& Time::operator/=(const Time& time) { return *this = *this / time; }

void Time::Correct()
{
  // Carry whole seconds out of nsec, then give sec and nsec one sign.
  int64_t total_sec = static_cast<int64_t>(sec) + nsec / nsInSec;
  int64_t rest = nsec % nsInSec;
  if (total_sec > 0 && rest < 0)
  {
    total_sec -= 1;
    rest += nsInSec;
  }
  else if (total_sec < 0 && rest > 0)
  {
    total_sec += 1;
    rest -= nsInSec;
  }
  sec = static_cast<int32_t>(total_sec);
  nsec = static_cast<int32_t>(rest);
}
}  // namespace common
}  // namespace gazebo
